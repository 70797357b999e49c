// The frame's layout, checked from the boxes it lists (inspector.h: planFrame, LayoutBox): for
// every step of every lesson, at the sizes a class meets (1024x768, 1280x720, 1600x900,
// 1920x1080), normal and presentation: no text outside its panel, no label or mark on a number or
// a text, type at or above its floor. The layout is a pure function of the frame size and the
// model, so each step is rendered and traced once (EGL, llvmpipe in CI) and laid out at all
// eight sizes without drawing.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/lesson_step.h"
#include "app/session.h"
#include "app/step_view.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "charts/speed_chart.h"
#include "charts/step_chart.h"
#include "draw/text_layout.h"
#include "kernel/methods.h"
#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_pick.h"
#include "lesson/lesson_text.h"
#include "measure/bench_report.h"
#include "overlay/inspector.h"
#include "render/gl_context.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"
#include "speed_chart_checks.h"

namespace pcf {
namespace {

constexpr glm::ivec2 SIZES[] = {{1024, 768}, {1280, 720}, {1600, 900}, {1920, 1080}};

bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x - 0.01f && inner.y >= outer.y - 0.01f &&
           inner.right() <= outer.right() + 0.01f && inner.bottom() <= outer.bottom() + 0.01f;
}

bool isTextual(BoxKind k) {
    return k == BoxKind::Text || k == BoxKind::Number || k == BoxKind::Label;
}

// The problems of one plan, as readable lines (empty: none).
std::vector<std::string> problems(const FramePlan& plan, const InspectorLayout& l) {
    std::vector<std::string> out;
    std::map<std::string, Rect> panels;
    for (const LayoutBox& b : plan.boxes) {
        if (b.kind == BoxKind::Panel) panels[b.panel] = b.rect;
    }
    auto name = [](const LayoutBox& b) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s %s/%s [%g %g %g %g] %gpx", boxKindName(b.kind),
                      b.panel.c_str(), b.role.c_str(), b.rect.x, b.rect.y, b.rect.w, b.rect.h,
                      b.fontPx);
        return std::string(buf);
    };
    TypeSizes t = typeSizes(l);
    for (const LayoutBox& b : plan.boxes) {
        if (b.kind == BoxKind::Panel) continue;
        const Rect& p = panels.at(b.panel);
        if (isTextual(b.kind) || b.kind == BoxKind::Mark) {
            Rect in = b.rect.intersect(p);
            if (std::abs(in.w - b.rect.w) > 0.5f || std::abs(in.h - b.rect.h) > 0.5f) {
                out.push_back(name(b) + " runs out of its panel");
            }
        }
        if (isTextual(b.kind)) {
            float floor = b.kind == BoxKind::Number  ? t.numberFloor
                          : b.kind == BoxKind::Label ? t.labelFloor
                                                     : std::min(t.bodyFloor, t.labelFloor);
            if (b.role == "step-text" || b.role == "step-title") floor = t.bodyFloor;
            if (b.fontPx + 0.01f < floor) out.push_back(name(b) + " below its floor");
        }
    }
    // Labels and marks never on a number or a text; and no two texts on each other. A chart
    // legend's mark is not on any text either, its own entry's words included.
    for (size_t i = 0; i < plan.boxes.size(); ++i) {
        const LayoutBox& a = plan.boxes[i];
        if (a.kind == BoxKind::Panel) continue;
        for (size_t j = 0; j < plan.boxes.size(); ++j) {
            const LayoutBox& b = plan.boxes[j];
            bool swatchOnText = a.role == "chart-swatch" && isTextual(b.kind);
            if (b.kind != BoxKind::Number && b.kind != BoxKind::Text && !swatchOnText) continue;
            bool textOnText = a.kind == BoxKind::Number || a.kind == BoxKind::Text;
            if (i == j || (textOnText && j < i)) continue;
            if (!a.rect.intersect(b.rect).empty()) {
                out.push_back(name(a) + " covers " + name(b));
            }
        }
    }
    return out;
}

// What a step's pages left out of what its trace read (empty: nothing): a texel without its
// cell, a fetch (gather, hardware tap, lookup, point read) without its mark, a formula that
// is never drawn whole. The pages' `drawn` lists (inspector.h: FramePlan) are what the export's
// JSON sidecar reports.
std::vector<std::string> cropped(const std::vector<FramePlan>& pages, const Trace& tr) {
    std::vector<std::string> out;
    std::set<std::pair<int, int>> texels;
    std::set<std::pair<int, int>> numbered;
    std::set<int> fetches;
    bool formula = false;
    for (const FramePlan& p : pages) {
        for (glm::ivec2 t : p.drawnTexels) texels.insert({t.x, t.y});
        for (glm::ivec2 t : p.numberedTexels) numbered.insert({t.x, t.y});
        fetches.insert(p.drawnFetches.begin(), p.drawnFetches.end());
        formula |= p.formulaWhole;
    }
    // A moment method's page draws the depths its moments average, not the moments texels:
    // every texel of its footprint is in the histogram, the moments read (its one fetch) in its
    // numbers, and its result (the "formula") whole.
    if (tr.depths.present) {
        for (const FootprintTexel& t : tr.depths.texels) {
            if (!texels.count({t.texel.x, t.texel.y})) {
                out.push_back("footprint texel (" + std::to_string(t.texel.x) + ", " +
                              std::to_string(t.texel.y) + ") not in the histogram");
            }
        }
    }
    for (const TapRecord& t : tr.taps) {
        if (tr.depths.present)
            break;  // (the moments texels have no cells, nor numbers of their own)
        // Drawn as its cell, or as a mark with its numbers (pcss's figures have no cells).
        if (!texels.count({t.texel.x, t.texel.y}) && !numbered.count({t.texel.x, t.texel.y})) {
            out.push_back("texel (" + std::to_string(t.texel.x) + ", " + std::to_string(t.texel.y) +
                          ") read but not drawn");
        }
        // Its bit, ref, depth and weight on some page: in its cell or in the texel table (12.2
        // at 1024x768 presentation showed only the weights).
        if (!numbered.count({t.texel.x, t.texel.y})) {
            out.push_back("texel (" + std::to_string(t.texel.x) + ", " + std::to_string(t.texel.y) +
                          ")'s numbers never drawn whole");
            numbered.insert({t.texel.x, t.texel.y});
        }
    }
    for (int k = 0; k < static_cast<int>(tr.fetches.size()); ++k) {
        if (!fetches.count(k)) out.push_back("fetch " + std::to_string(k + 1) + " not drawn");
    }
    if (!formula) out.push_back("the formula is never drawn whole");
    return out;
}

// The rings round a Poisson disk's lookup point (FramePlan::rings) as a lecturer reads them:
// each centred on the lookup point as drawn (7.1 drew the point 30 px off its ring's centre),
// and no ring's stroke, where it is drawn (its clip), across a number or a text (7.1's
// ring crossed the cells' numbers).
std::vector<std::string> ringProblems(const FramePlan& plan) {
    std::vector<std::string> out;
    for (const FramePlan::Ring& ring : plan.rings) {
        for (const LayoutBox& b : plan.boxes) {
            if (b.role == "lookup-point" && b.rect.w == b.rect.h &&
                glm::length(b.rect.centre() - ring.centre) > 1.0f) {
                out.push_back("the lookup point is drawn " +
                              std::to_string(glm::length(b.rect.centre() - ring.centre)) +
                              " px off its ring's centre");
            }
            if (b.kind != BoxKind::Number && b.kind != BoxKind::Text) continue;
            int n = static_cast<int>(std::ceil(6.2831853f * ring.radius));
            for (int k = 0; k < n; ++k) {
                float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(n);
                glm::vec2 p = ring.centre + ring.radius * glm::vec2(std::cos(a), std::sin(a));
                if (!ring.clip.contains(p)) continue;
                if (b.rect.expanded(0.5f * ring.width).contains(p)) {
                    out.push_back("a ring of radius " + std::to_string(ring.radius) +
                                  " px crosses " + b.role + " \"" + b.text + "\"");
                    break;
                }
            }
        }
    }
    return out;
}

// A table row or header as its columns: monospace cells apart by two spaces or more ("d - ref"
// and "(160, 116)" keep their single spaces).
std::vector<std::string> tableColumns(const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    for (size_t k = 0; k <= line.size(); ++k) {
        bool gap =
            k == line.size() || (line[k] == ' ' && k + 1 < line.size() && line[k + 1] == ' ');
        if (!gap) {
            if (!(cell.empty() && line[k] == ' ')) cell += line[k];
            continue;
        }
        if (!cell.empty()) out.push_back(cell);
        cell.clear();
        while (k + 1 < line.size() && line[k + 1] == ' ') ++k;
    }
    return out;
}

// The texel table of one page as a lecturer reads it (issue 19: 8.4 at 1024x768 presentation cut
// its title with "..." and dropped its depth - ref column, the step's very subject): the title
// whole; every row has every column of the header, depth - ref among them, and the row's numbers
// are its texel's first read; the ref in its column or, when every read compares with the same
// one, in the title. Returns the problems and counts the rows checked.
std::vector<std::string> tableProblems(const FramePlan& plan, const Trace& tr, int& rowsChecked) {
    std::vector<std::string> out;
    std::vector<std::string> header;
    std::string title;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role == "table-title") {
            title = b.text;  // its lines joined
            std::replace(title.begin(), title.end(), '\n', ' ');
            if (b.shortened || b.text.find("...") != std::string::npos) {
                out.push_back("the table's title is shortened: " + b.text);
            }
        }
        if (b.role == "table-header") header = tableColumns(b.text);
    }
    auto column = [&](const std::string& name) {
        auto it = std::find(header.begin(), header.end(), name);
        return it == header.end() ? -1 : static_cast<int>(it - header.begin());
    };
    int margin = column("d - ref"), ref = column("ref"), depth = column("depth");
    bool pair = column("texel") == 0;
    // Without a ref column, the title says the one ref: "...; ref 0.5867 for all:".
    std::optional<float> titleRef;
    if (size_t at = title.rfind("ref "); at != std::string::npos) {
        titleRef = std::stof(title.substr(at + 4));
    }
    for (const LayoutBox& b : plan.boxes) {
        if (b.role != "table-row") continue;
        ++rowsChecked;
        std::vector<std::string> cells = tableColumns(b.text);
        if (margin < 0 || depth < 0 || cells.size() != header.size()) {
            out.push_back("table row \"" + b.text + "\" lacks a column of texel, bit, ref, " +
                          "depth, d - ref, w (header: " + std::to_string(header.size()) +
                          " columns)");
            continue;
        }
        glm::ivec2 texel(-1);
        if (pair) {
            std::sscanf(cells[0].c_str(), "(%d, %d)", &texel.x, &texel.y);
        } else {
            texel = {std::stoi(cells[column("i")]), std::stoi(cells[column("j")])};
        }
        const TapRecord* tap = nullptr;
        for (const TapRecord& t : tr.taps) {
            if (t.texel == texel && !tap) tap = &t;
        }
        if (!tap) {
            out.push_back("table row \"" + b.text + "\" names a texel the trace did not read");
            continue;
        }
        // Printed to 4 decimals (depth to 3).
        if (std::abs(std::stof(cells[margin]) - (tap->depth - tap->ref)) > 5.1e-5f ||
            std::abs(std::stof(cells[depth]) - tap->depth) > 5.1e-4f) {
            out.push_back("table row \"" + b.text + "\": depth or d - ref is not its read's");
        }
        // The weight to 3 decimals, and one above 0 never printed as 0 (a 7x7 tent's corners).
        float weight = tr.weights.at(texel), shownWeight = std::stof(cells.back());
        // pcss: a 0 is a texel only the blocker search read (its first taps), and the title
        // says so.
        if (tr.params.method == PCF_PCSS && shownWeight == 0.0f) {
            bool filtered = false;
            for (size_t k = PCF_PCSS_TAPS; k < tr.taps.size(); ++k) {
                filtered = filtered || tr.taps[k].texel == texel;
            }
            if (filtered ||
                title.find("w 0.000: read by the blocker search only") == std::string::npos) {
                out.push_back("table row \"" + b.text + "\": w 0 on a pcss table: " +
                              (filtered ? "the filter reads it" : "the title does not say why"));
            }
        }
        if (std::abs(shownWeight - weight) > 5.1e-4f || (weight > 0.0f) != (shownWeight > 0.0f)) {
            out.push_back("table row \"" + b.text + "\": its w is not its weight " +
                          std::to_string(weight));
        }
        float shownRef = ref >= 0 ? std::stof(cells[ref]) : titleRef.value_or(-1.0f);
        if (std::abs(shownRef - tap->ref) > 5.1e-5f) {
            out.push_back("table row \"" + b.text + "\": its ref " + std::to_string(tap->ref) +
                          " is neither in a ref column nor the title's (" + title + ")");
        }
    }
    return out;
}

// A page of step text as a class reads it: its sentences end at '.', '?' or '!' followed by a
// space, a line's end or the text's (a closing bracket or quote may come between), not at an
// abbreviation's stop ("e.g."); table rows (two leading spaces) belong to the sentence that leads
// into them and end it, and a page that ends with one ends that sentence.
bool endsSentenceAt(std::string_view t, size_t k) {
    if (t[k] != '.' && t[k] != '?' && t[k] != '!') return false;
    size_t next = k + 1;
    while (next < t.size() && (t[next] == ')' || t[next] == '"')) ++next;
    if (next < t.size() && t[next] != ' ' && t[next] != '\n') return false;
    std::string_view before = t.substr(0, k + 1);
    return !before.ends_with("e.g.") && !before.ends_with("i.e.");
}

int sentencesIn(std::string_view text) {
    int n = 0;
    bool pending = false;  // words since the last stop
    bool inTable = false;
    for (size_t start = 0; start <= text.size();) {
        size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        bool row = line.starts_with("  ");
        // A table ends the sentence that leads into it ("... weigh:" and its rows).
        if (inTable && !row && pending) ++n, pending = false;
        inTable = row;
        if (!row) {
            for (size_t k = 0; k < line.size(); ++k) {
                if (endsSentenceAt(line, k)) {
                    ++n, pending = false;
                } else if (line[k] != ' ' && line[k] != ')' && line[k] != '"') {
                    pending = true;
                }
            }
        } else {
            pending = true;
        }
        start = end + 1;
    }
    return n + pending;
}

// The preformatted rows of a drawn step text (two leading spaces): tables and formulas.
std::vector<std::string> tableRowsOf(const std::string& text) {
    std::vector<std::string> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("  ") && line.find_first_not_of(' ') != std::string::npos)
            rows.push_back(line);
    }
    return rows;
}

bool endsCleanly(std::string_view text) {
    size_t last = text.rfind('\n');
    std::string_view line = last == std::string_view::npos ? text : text.substr(last + 1);
    if (line.starts_with("  ")) return true;
    while (!line.empty() && (line.back() == ')' || line.back() == '"')) line.remove_suffix(1);
    return !line.empty() && (line.back() == '.' || line.back() == '?' || line.back() == '!');
}

// The texel table's grids of one page (issue 32: 6.4's 64 rows took three pages): under each
// header, a number's name and the texel columns i, the rows j, each cell the number of the texel
// (i, j)'s first read (depth to 3 decimals, d - ref and ref to 4, w as the cells print it).
std::vector<std::string> gridProblems(const FramePlan& plan, const Trace& tr, int& cellsChecked) {
    std::vector<std::string> out;
    std::string name;
    std::vector<int> columns;
    for (const LayoutBox& b : plan.boxes) {
        std::istringstream in(b.text);
        std::vector<std::string> words;
        for (std::string w; in >> w;) words.push_back(w);
        if (b.role == "grid-header") {
            name.clear();
            columns.clear();
            for (const std::string& w : words) {
                if (std::isdigit(static_cast<unsigned char>(w[0]))) {
                    columns.push_back(std::stoi(w));
                } else {
                    name += (name.empty() ? "" : " ") + w;
                }
            }
            continue;
        }
        if (b.role != "grid-row") continue;
        if (words.size() != columns.size() + 1) {
            out.push_back("grid row \"" + b.text + "\" has not one cell per column");
            continue;
        }
        int j = std::stoi(words[0]);
        for (size_t c = 0; c < columns.size(); ++c) {
            const TapRecord* tap = nullptr;
            for (const TapRecord& t : tr.taps) {
                if (t.texel == glm::ivec2(columns[c], j) && !tap) tap = &t;
            }
            if (!tap) {
                out.push_back("grid " + name + " names texel (" + std::to_string(columns[c]) +
                              ", " + std::to_string(j) + "), which the trace did not read");
                continue;
            }
            float shown = std::stof(words[c + 1]);
            float want = name == "depth"     ? tap->depth
                         : name == "d - ref" ? tap->depth - tap->ref
                         : name == "ref"     ? tap->ref
                                             : tr.weights.at(tap->texel);
            float tolerance = name == "depth" || name == "w" ? 5.1e-4f : 5.1e-5f;
            if (name == "w" && want > 0.0f && want < 5e-4f) tolerance = want * 0.5f;
            if (std::abs(shown - want) > tolerance || (name == "w" && (want > 0) != (shown > 0))) {
                out.push_back("grid " + name + " row " + std::to_string(j) + " column " +
                              std::to_string(columns[c]) + ": " + words[c + 1] + ", not " +
                              std::to_string(want));
            }
            ++cellsChecked;
        }
    }
    return out;
}

// The cells' index labels name both axes the same way (6.4, tent 7x7, at 1024x768 presentation
// had "115" over its columns and "j=135" beside its rows): "i=" and "j=" on both, or bare numbers
// on both and the axes named once in the corner.
std::vector<std::string> indexLabelProblems(const FramePlan& plan) {
    int prefixed = 0, bare = 0;
    bool axes = false;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role == "texel-index") (b.text.find('=') == std::string::npos ? bare : prefixed)++;
        if (b.role == "texel-axes") {
            axes = b.text.find('i') != std::string::npos && b.text.find('j') != std::string::npos;
        }
    }
    std::vector<std::string> out;
    if (prefixed > 0 && bare > 0) {
        out.push_back(std::to_string(prefixed) + " index labels say i= or j=, " +
                      std::to_string(bare) + " are bare numbers");
    }
    if (bare > 0 && !axes) out.push_back("bare index labels and no i/j caption in the corner");
    return out;
}

class Layout : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> Layout::sContext;

TEST_F(Layout, EveryStepAtEverySizeKeepsTextInPanelsMarksOffNumbersAndTypeAboveFloors) {
    auto start = std::chrono::steady_clock::now();
    int plans = 0;
    int framesAt1024 = 0;  // the frames every step makes at 1024x768 presentation
    int pagedPresentation = 0, depthLost = 0, pointDepthLost = 0, pointMoved = 0, split = 0;
    // Step-text pages of paged steps; of them, cut mid-sentence or holding a lone sentence.
    int textPageEnds = 0, midSentence = 0, loneSentence = 0;
    int tableRowsWhole = 0;  // the step texts' table rows checked to fit their column
    int gridCellsSeen = 0;   // the texel tables' grid cells checked against the trace
    // The texel tables' rows and the cells' index labels checked (tableProblems,
    // indexLabelProblems): some of each, bare labels among them, or the checks saw nothing.
    int tableRowsSeen = 0, indexLabelsSeen = 0, bareIndexLabelsSeen = 0, tablesPaged = 0;
    // Rendered once per step in the scene of a 1280x720 frame, the size a projector gets.
    glm::ivec2 renderScene(inspectorLayout({1280, 720}, false).scene.size());
    std::vector<std::string> lessons;
    for (const auto& e : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (e.path().extension() == ".toml") lessons.push_back(e.path().string());
    }
    std::sort(lessons.begin(), lessons.end());
    ASSERT_GE(lessons.size(), 10u);
    for (const std::string& path : lessons) {
        Lesson lesson = parseLessonFile(path);
        SceneRenderer renderer(lesson.scene);
        for (size_t k = 0; k < lesson.steps.size(); ++k) {
            const LessonStep& step = lesson.steps[k];
            const LessonSettings& s = step.settings;
            // The step rendered and its point traced as the session does it (step_view.h): its
            // map fit (grid shift, snap), its pinned point, its bias.
            std::optional<ScenePoint> pinned = stepPoint(lesson.scene, s);
            renderStepView(renderer, stepView(lesson.scene, s, pinned, renderScene));
            ShadowMap map = renderer.readShadowMap();
            glm::ivec2 px = stepPick(lesson.scene, s, renderScene).pixel;
            std::optional<PixelLookup> lookup = tracePixel(renderer, map, s, px);
            InspectorModel m;
            m.title = lesson.title;
            for (const LessonStep& st : lesson.steps) m.stepTitles.push_back(st.title);
            m.currentStep = static_cast<int>(k);
            m.map = &map;
            m.showScene = step.chart.empty();
            m.highlightFetch = step.highlightFetch - 1;
            m.focus = stepFocus(step);
            m.status =
                "pcf-gather N=3   bias constant 0.002   cull back   map 1024 32f   scene "
                "1152x648";
            if (lookup) {
                m.trace = lookup->trace;
                StepContext ctx =
                    makeStepContext(s, px, pinned ? lightAngleDeg(lesson.scene, *pinned) : -1.0f);
                m.stepText = fillText(step.text, *m.trace, ctx);
            } else {
                m.stepText = step.text;
            }
            for (glm::ivec2 size : SIZES) {
                for (bool presentation : {false, true}) {
                    InspectorLayout l = inspectorLayout(size, presentation);
                    m.presentation = presentation;
                    m.sceneSize = glm::ivec2(l.scene.size());
                    m.pixel = stepPick(lesson.scene, s, m.sceneSize).pixel;
                    // A step lays out as the session composes it, for its focus; a chart
                    // step's chart texts are boxes of the frame's layout, checked like the rest.
                    l = focusLayout(l, m.focus);
                    std::vector<LayoutBox> chartBoxes = stepChartBoxes(step, l);
                    auto withChart = [&](FramePlan p) {
                        p.boxes.insert(p.boxes.end(), chartBoxes.begin(), chartBoxes.end());
                        return p;
                    };
                    FramePlan plan = withChart(planFrame(l, m));
                    ++plans;
                    std::string where = lesson.name + " step " + std::to_string(k + 1) + " at " +
                                        std::to_string(size.x) + "x" + std::to_string(size.y) +
                                        (presentation ? " presentation" : "");
                    std::string stepTextShown;  // every page's step text, lines kept
                    // Every page of the step, not only the first; over its pages, everything
                    // the trace read is drawn and the formula once whole.
                    std::vector<FramePlan> pages;
                    for (int page = 0; page < plan.textPages; ++page) {
                        FramePlan p = plan;
                        if (page > 0) {
                            m.textPage = page;
                            p = withChart(planFrame(l, m));
                            m.textPage = 0;
                        }
                        for (const std::string& problem : problems(p, l)) {
                            ADD_FAILURE() << where << " page " << page + 1 << ": " << problem;
                        }
                        // The 1600x900 handout's step text stays at 14 px or more (13.3 and
                        // 14.1 fell to 12-13 px).
                        for (const LayoutBox& b : p.boxes) {
                            if (b.role == "step-text" && !presentation &&
                                size == glm::ivec2(1600, 900)) {
                                EXPECT_GE(b.fontPx, 14.0f) << where << " page " << page + 1;
                            }
                        }
                        std::vector<std::string> found = indexLabelProblems(p);
                        for (std::string& problem : ringProblems(p))
                            found.push_back(std::move(problem));
                        if (m.trace) {
                            for (std::string& problem : tableProblems(p, *m.trace, tableRowsSeen))
                                found.push_back(std::move(problem));
                            for (std::string& problem : gridProblems(p, *m.trace, gridCellsSeen))
                                found.push_back(std::move(problem));
                        }
                        for (const LayoutBox& b : p.boxes) {
                            indexLabelsSeen += b.role == "texel-index";
                            bareIndexLabelsSeen +=
                                b.role == "texel-index" && b.text.find('=') == std::string::npos;
                        }
                        for (const std::string& problem : found) {
                            ADD_FAILURE() << where << " page " << page + 1 << ": " << problem;
                        }
                        // Every table row of the step text whole on one line (6.4's weight
                        // table wrapped each of its rows at 1024x768 presentation).
                        for (const LayoutBox& b : p.boxes) {
                            if (b.role == "step-text") stepTextShown += b.text + "\n";
                        }
                        // How the step text's pages end: at a sentence's end or a table's
                        // last row, never in the middle of a sentence; and none holds a lone
                        // sentence where the step has more than one.
                        for (const LayoutBox& b : p.boxes) {
                            if (b.role != "step-text" || plan.textPages == 1) continue;
                            ++textPageEnds;
                            if (page + 1 < plan.textPages && !endsCleanly(b.text)) {
                                ++midSentence;
                                ADD_FAILURE()
                                    << where << " page " << page + 1 << " ends mid-sentence: \"..."
                                    << b.text.substr(b.text.size() - 30) << "\"";
                            }
                            if (sentencesIn(b.text) < 2 &&
                                sentencesIn(drawnStepText(m.stepText)) > 1) {
                                ++loneSentence;
                                ADD_FAILURE() << where << " page " << page + 1
                                              << " holds one sentence: " << b.text;
                            }
                        }
                        pages.push_back(std::move(p));
                    }
                    for (const std::string& row : tableRowsOf(drawnStepText(m.stepText))) {
                        ++tableRowsWhole;
                        if (stepTextShown.find("\n" + row + "\n") == std::string::npos &&
                            !stepTextShown.starts_with(row + "\n")) {
                            ADD_FAILURE() << where << ": the table row \"" << row
                                          << "\" does not fit its column";
                        }
                    }
                    // A texel table over several pages shares its rows out evenly: 4.4 at
                    // 1024x768 presentation gave its 25th row a slide of its own. (Unless its
                    // last page holds the formula too: then the pages before are full.)
                    std::vector<int> rowsPerTablePage;
                    bool formulaWithRows = false;
                    for (const FramePlan& p : pages) {
                        int rows = 0, formulaBoxes = 0;
                        for (const LayoutBox& b : p.boxes) {
                            rows += b.role == "table-row";
                            formulaBoxes += b.role == "formula";
                        }
                        if (rows > 0) rowsPerTablePage.push_back(rows);
                        formulaWithRows |= rows > 0 && formulaBoxes > 0;
                    }
                    if (rowsPerTablePage.size() > 1 && !formulaWithRows) {
                        auto [few, most] =
                            std::minmax_element(rowsPerTablePage.begin(), rowsPerTablePage.end());
                        EXPECT_LE(*most - *few, 1)
                            << where << ": table pages of " << *most << " and " << *few << " rows";
                        ++tablesPaged;
                    }
                    // A frame with more pages says so on its first (the step text's "more"
                    // mark or the inspector's "next page" line): 4.3 at 1024x768 presentation
                    // had its texel table on pages 2-3 and nothing on page 1 to say so.
                    if (plan.textPages > 1) {
                        bool more = false;
                        for (const LayoutBox& b : pages.front().boxes) more |= b.role == "more";
                        EXPECT_TRUE(more) << where << ": page 1 of " << plan.textPages
                                          << " gives no sign that more follows";
                    }
                    if (m.trace && !l.inspector.empty()) {
                        for (const std::string& problem : cropped(pages, *m.trace)) {
                            ADD_FAILURE() << where << ": " << problem;
                        }
                        split += plan.textPages > 1;
                    }
                    if (presentation && plan.textPages > 1) ++pagedPresentation;
                    // A projector's slides: at most three frames a step at 1024x768 (6.4 made
                    // five, its texel table on three).
                    if (presentation && size == glm::ivec2(1024, 768)) {
                        EXPECT_LE(plan.textPages, 3) << where;
                        framesAt1024 += plan.textPages;
                    }
                    // The cells and the step text are there at every size.
                    bool stepText = false;
                    int cellNumbers = 0, cellDepths = 0;
                    for (const LayoutBox& b : plan.boxes) {
                        stepText |= b.role == "step-text";
                        cellNumbers += b.role.starts_with("cell-");
                        cellDepths += b.role == "cell-depth";
                    }
                    // Texels too small for their numbers give them rows of a table page instead,
                    // pcss its figures' depths (cropped() checks every read is there).
                    int tableRows = 0;
                    for (const FramePlan& p : pages) {
                        // (pcss's figures: each tap's depth beside its mark.)
                        for (const LayoutBox& b : p.boxes) {
                            tableRows += b.role == "table-row" || b.role == "search-depth" ||
                                         b.role == "filter-depth";
                        }
                    }
                    EXPECT_TRUE(stepText) << where;
                    // (A chart step in presentation gives the chart the inspector's room.)
                    // A moment method's page has no cells: its figure instead (cropped()
                    // checks its histogram holds the footprint).
                    if (m.trace && !l.inspector.empty() && plan.moments) {
                        EXPECT_TRUE(plan.moments->hasFootprint) << where;
                    } else if (m.trace && !l.inspector.empty()) {
                        EXPECT_GE(cellNumbers + tableRows, 4) << where;
                        // The lookup point sits beside its cell's numbers, never in place of
                        // one: that cell keeps its depth (1600x900 13.1 lost it).
                        const Trace& tr = *m.trace;
                        Neighbourhood view = neighbourhoodView(l, m);
                        Rect area = neighbourhoodArea(l, m);
                        glm::ivec2 point(glm::floor(tr.uv * glm::vec2(tr.map.size)));
                        Rect cell = texelCellRect(view, area, point);
                        bool pointShown = point.x >= view.origin.x && point.y >= view.origin.y &&
                                          point.x < view.origin.x + view.size.x &&
                                          point.y < view.origin.y + view.size.y;
                        bool depthThere = false;
                        for (const LayoutBox& b : plan.boxes) {
                            depthThere |= b.role == "cell-depth" && inside(b.rect, cell);
                        }
                        // Where the cells show bits, every read texel's cell shows its bit: a
                        // mark that leaves no room for it moves into a lane (6.4 at 1280x720
                        // lost three bits to tent taps).
                        std::set<std::pair<int, int>> bitless;
                        int withBit = 0;
                        for (const TapRecord& tap : tr.taps) {
                            Rect c = texelCellRect(view, area, tap.texel);
                            bool bit = false, number = false;
                            for (const LayoutBox& b : plan.boxes) {
                                bit |= b.role == "cell-bit" && inside(b.rect, c);
                                number |= b.role.starts_with("cell-") && inside(b.rect, c);
                            }
                            if (bit) {
                                ++withBit;
                            } else {
                                bitless.insert({tap.texel.x, tap.texel.y});
                            }
                            // A read cell that shows numbers shows its bit among them (12.3 at
                            // 1024x768 presentation showed the weights alone).
                            EXPECT_TRUE(bit || !number)
                                << where << ": cell (" << tap.texel.x << ", " << tap.texel.y
                                << ") shows numbers without its bit";
                        }
                        // A Poisson disk's ring and points stay where the math puts them (no
                        // mark moves into a lane: the points would leave their ring), so a cell
                        // they crowd may keep its numbers, even its bit, for the texel table
                        // (cropped() checks that they are there); its fill still says lit or not.
                        bool disk = !plan.rings.empty();
                        if (withBit > 0 && !disk) {
                            EXPECT_TRUE(bitless.empty())
                                << where << ": " << bitless.size()
                                << " read cells show no bit, from (" << bitless.begin()->first
                                << ", " << bitless.begin()->second << ")";
                        }
                        if (pointShown && !depthThere && cellDepths > 0 && !disk) {
                            ++pointDepthLost;
                            std::printf("  %s: the lookup point's cell shows no depth\n",
                                        where.c_str());
                        }
                        // The lookup point stays in its own cell; where it moved off the
                        // numbers, ticks in the cell's border band show its true place: one at
                        // its true x for a move in x, one at its true y for a move in y.
                        glm::vec2 truePt =
                            glm::vec2(area.x, area.y) +
                            (tr.uv * glm::vec2(tr.map.size) - glm::vec2(view.origin)) * cell.w;
                        for (const LayoutBox& b : plan.boxes) {
                            if (b.role != "lookup-point") continue;
                            glm::vec2 drawn = b.rect.centre();
                            EXPECT_TRUE(cell.contains(drawn)) << where;
                            bool tickX = false, tickY = false;
                            for (const LayoutBox& tk : plan.boxes) {
                                if (tk.role != "lookup-point-tick") continue;
                                glm::vec2 c = tk.rect.centre();
                                tickX |= tk.rect.h > tk.rect.w && std::abs(c.x - truePt.x) < 1.0f;
                                tickY |= tk.rect.w > tk.rect.h && std::abs(c.y - truePt.y) < 1.0f;
                            }
                            // (A box clipped to the cells is not square: its centre is not the
                            // point's; the cell check above still holds.)
                            if (b.rect.w == b.rect.h) {
                                if (std::abs(drawn.x - truePt.x) > 2.5f) {
                                    EXPECT_TRUE(tickX) << where;
                                }
                                if (std::abs(drawn.y - truePt.y) > 2.5f) {
                                    EXPECT_TRUE(tickY) << where;
                                }
                            }
                            if (tickX || tickY) ++pointMoved;
                        }
                        if (where == "13-shimmer-and-snapping step 1 at 1600x900") {
                            EXPECT_TRUE(pointShown && depthThere) << where;
                        }
                        // Marks (the point with lookup dots or rings in one small cell) never
                        // crowd a depth out: counted, and none allowed below.
                        int inMap = 0;
                        for (int j = 0; j < view.size.y; ++j) {
                            for (int i = 0; i < view.size.x; ++i) {
                                glm::ivec2 t = view.origin + glm::ivec2(i, j);
                                inMap += t.x >= 0 && t.y >= 0 && t.x < tr.map.size.x &&
                                         t.y < tr.map.size.y;
                            }
                        }
                        // (Cells too small for any depth at this size show their bits.)
                        if (cellDepths > 0 && cellDepths < inMap && !disk) {
                            ++depthLost;
                            std::printf("  %s: %d of %d cells show their depth\n", where.c_str(),
                                        cellDepths, inMap);
                        }
                    }
                }
            }
        }
    }
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "layout: %d plans checked in %.1f s; %d presentation frames page their text; "
        "%d frames drop a cell's depth for other marks; %d steps' frames split into pages; "
        "%d of %d pages of paged step texts end mid-sentence\n",
        plans, seconds, pagedPresentation, depthLost, split, midSentence, textPageEnds);
    // A page cut at a fixed count of lines ended mid-sentence on 36 of 225 (3.6 at 1280x720
    // presentation stopped at "p = uv * size", its "- 0.5" on the next page); pages now start
    // where a sentence does, and a lone sentence goes back to its neighbours.
    std::printf("layout: %d frames at 1024x768 presentation; %d step-text pages, %d lone\n",
                framesAt1024, textPageEnds, loneSentence);
    EXPECT_GT(textPageEnds, 20);
    EXPECT_GT(tableRowsWhole, 100);
    std::printf("layout: %d texel-grid cells checked\n", gridCellsSeen);
    EXPECT_GT(gridCellsSeen, 100);
    EXPECT_EQ(midSentence, 0) << "of " << textPageEnds << " step-text pages";
    EXPECT_EQ(loneSentence, 0) << "of " << textPageEnds << " step-text pages";
    std::printf(
        "layout: %d texel-table rows (%d tables over several pages) and %d index labels (%d "
        "bare) checked\n",
        tableRowsSeen, tablesPaged, indexLabelsSeen, bareIndexLabelsSeen);
    EXPECT_GT(tableRowsSeen, 100);
    EXPECT_GT(tablesPaged, 0);
    EXPECT_GT(bareIndexLabelsSeen, 0);
    EXPECT_GT(indexLabelsSeen, bareIndexLabelsSeen);
    // No cell loses a number to a mark: the lookup point's cell shows its depth, and so does
    // every cell in the map (a point mark that crowds a cell moves into a lane at its edge).
    EXPECT_EQ(pointDepthLost, 0);
    std::printf(
        "layout: the lookup point moved off the numbers (ticks at its true place) in %d "
        "frames\n",
        pointMoved);
    EXPECT_EQ(depthLost, 0);
}

// A chart step on a projector: the chart takes the inspector's room too, every one of its texts
// (ticks, axis names, the dots' names, the legend; the stability charts' of lessons 13 and 14
// too) is at least 18 px (the presentation number floor; normal mode keeps the normal floors)
// and inside the chart, the dots the step rings are named, and no two texts lie on each other.
// (At 617 x 347, the scene panel's size, they were 8 px.)
TEST_F(Layout, ChartStepsInPresentationSetTheChartAtProjectorSize) {
    int chartSteps = 0, stabilitySteps = 0, adviseSteps = 0;
    std::vector<LessonStep> steps;
    for (const char* file :
         {"11-speed-and-accuracy", "13-shimmer-and-snapping", "14-bias-trade-off",
          "18-which-setting-a-scene-needs", "20-light-bleeding", "21-cascades-and-splits"}) {
        Lesson lesson =
            parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + std::string(file) + ".toml");
        for (const LessonStep& step : lesson.steps) steps.push_back(step);
    }
    for (const LessonStep& step : steps) {
        if (step.chart.empty()) continue;
        ++chartSteps;
        // A stability chart (lessons 13, 14: "stability.csv#view") has no dots to name; an
        // advise chart (lesson 18: "DIR/advise.csv") names its own marks.
        StepChartKind kind = stepChartRef(step.chart).kind;
        bool stability = kind == StepChartKind::Stability;
        stabilitySteps += stability;
        adviseSteps += kind == StepChartKind::Advise;
        for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
            for (bool presentation : {true, false}) {
                std::string where = step.title + " at " + std::to_string(size.x) + "x" +
                                    std::to_string(size.y) + (presentation ? " presentation" : "");
                InspectorLayout l = chartStepLayout(inspectorLayout(size, presentation));
                const float floor = presentation ? 18.0f : 12.0f;
                if (presentation) {
                    EXPECT_EQ(l.scene.w, static_cast<float>(size.x)) << where;
                    EXPECT_GE(l.scene.h, 0.5f * size.y) << where;
                    EXPECT_TRUE(l.inspector.empty()) << where;
                }
                std::vector<LayoutBox> boxes = stepChartBoxes(step, l);
                std::map<std::string, int> roles;
                std::vector<const LayoutBox*> names;
                for (const LayoutBox& b : boxes) {
                    ++roles[b.role];
                    // (A legend's mark has no type; the pairs below keep it off every text.)
                    if (b.kind != BoxKind::Mark) {
                        EXPECT_GE(b.fontPx, floor)
                            << where << ": " << b.role << " '" << b.text << "'";
                    }
                    EXPECT_TRUE(inside(b.rect, l.scene)) << where << ": " << b.text;
                    if (b.role == "chart-label" || b.role == "chart-key") names.push_back(&b);
                }
                EXPECT_GE(roles["chart-tick"], 4) << where;
                // (The bar chart of lesson 13 names its groups instead of an x axis.)
                EXPECT_EQ(roles["chart-axis"], stability && roles["chart-label"] > 0 ? 1 : 2)
                    << where;
                EXPECT_GE(roles["chart-legend"], 3) << where;
                EXPECT_GE(roles["chart-swatch"], 3) << where;
                // No text of the chart on another (ticks, names, legend, titles), and no legend
                // mark on a text (the front's ring ran into "Pareto front" at 18 px type).
                for (size_t i = 0; i < boxes.size(); ++i) {
                    for (size_t j = i + 1; j < boxes.size(); ++j) {
                        // (Two legend marks with their clearances may touch: a column of marks.)
                        if (boxes[i].kind == BoxKind::Mark && boxes[j].kind == BoxKind::Mark) {
                            continue;
                        }
                        const Rect &a = boxes[i].rect, &b = boxes[j].rect;
                        EXPECT_TRUE(a.intersect(b).empty())
                            << where << ": '" << boxes[i].text << "' [" << a.x << " " << a.y << " "
                            << a.w << " " << a.h << "] on '" << boxes[j].text << "' [" << b.x << " "
                            << b.y << " " << b.w << " " << b.h << "]";
                    }
                }
                if (stability) {
                    EXPECT_GE(roles["chart-title"], 1) << where;
                } else if (presentation && kind == StepChartKind::Bench) {
                    // Every ringed dot is named, beside it or in the key (and, on a projector,
                    // only the ringed: a label for each of the ~80 dots would bury the plot).
                    std::vector<BenchRow> rows =
                        parseBenchCsv(readInputFile(step.chart), step.chart);
                    if (!step.chartHighlight.empty()) {
                        for (size_t k : chartRowsMatching(rows, step.chartHighlight)) {
                            std::string label = chartLabel(rows[k].point);
                            bool named = false;
                            for (const LayoutBox* b : names) named |= b->text.starts_with(label);
                            EXPECT_TRUE(named) << where << ": " << label;
                        }
                    }
                    EXPECT_LT(names.size(), 30u) << where;
                }
                for (size_t i = 0; i < names.size(); ++i) {
                    for (size_t j = i + 1; j < names.size(); ++j) {
                        EXPECT_TRUE(names[i]->rect.intersect(names[j]->rect).empty())
                            << where << ": '" << names[i]->text << "' on '" << names[j]->text
                            << "'";
                    }
                }
            }
        }
    }
    EXPECT_GE(chartSteps, 6);
    EXPECT_GE(stabilitySteps, 3);
    EXPECT_GE(adviseSteps, 3);
}

// A chart step's dots keep their names, at every size and mode: each drawn name or badge is nearer
// its own dot than any other, within reach of it, on no dot, ring, bar or other name, and every
// ringed dot has one (speedChartLabelFaults). Before badges, lesson 11 at 1024x768 presentation
// put "nearest 2048" beside the nearest-256 dot, 160 px from its own, and 11.3's four names far
// out on leaders across the plot; at 1280x720 presentation 11.2's "hw2x2 2048" sat by a nearest
// dot; in 16.5 to 17.5 the bars struck names through. Every dot's time has a labelled tick near
// it (17.4's four dots past "10" had none).
TEST_F(Layout, ChartStepsNameEachDotBesideItAndLabelItsTime) {
    int charts = 0, adviseCharts = 0, names = 0, badges = 0;
    for (const char* file : {"11-speed-and-accuracy", "16-contact-hardening",
                             "17-pcss-under-a-spot", "18-which-setting-a-scene-needs"}) {
        Lesson lesson =
            parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + std::string(file) + ".toml");
        for (const LessonStep& step : lesson.steps) {
            if (step.chart.empty()) continue;
            for (glm::ivec2 size : SIZES) {
                for (bool presentation : {true, false}) {
                    std::string where = step.title + " at " + std::to_string(size.x) + "x" +
                                        std::to_string(size.y) +
                                        (presentation ? " presentation" : "");
                    InspectorLayout l = chartStepLayout(inspectorLayout(size, presentation));
                    std::optional<SpeedChartLayout> chart = stepSpeedChartLayout(
                        stepChart(step, presentation), glm::ivec2(l.scene.size()));
                    if (!chart) continue;
                    // (An advise chart rings its choice itself, and names the front's dots.)
                    bool advise = stepChartRef(step.chart).kind == StepChartKind::Advise;
                    ++(advise ? adviseCharts : charts);
                    names += static_cast<int>(
                        std::count(chart->labelShown.begin(), chart->labelShown.end(), true));
                    badges += static_cast<int>(chart->keyRows.size());
                    // The dots the step rings are the ones it names.
                    if (!advise) {
                        std::vector<size_t> ringed = chartRowsMatching(
                            parseBenchCsv(readInputFile(stepChartRef(step.chart).path), step.chart),
                            step.chartHighlight);
                        EXPECT_EQ(chart->mustName, ringed) << where;
                    }
                    for (const std::string& f : speedChartLabelFaults(*chart)) {
                        ADD_FAILURE() << where << ": " << f;
                    }
                    for (const std::string& f : speedChartTickFaults(*chart)) {
                        ADD_FAILURE() << where << ": " << f;
                    }
                }
            }
        }
    }
    // The 8 bench chart steps (4 of lesson 11; 16.5, 16.6, 17.4, 17.5), each at 4 sizes, 2 modes.
    EXPECT_EQ(charts, 8 * 8);
    // Lesson 18's 3 advise chart steps, the speed chart under their marks.
    EXPECT_EQ(adviseCharts, 3 * 8);
    EXPECT_GE(names, charts);
    // Badges are for a crowd: lesson 11's 72 dots in a 1024x768 frame's chart.
    std::printf("layout: %d names and %d badges on the %d bench charts\n", names, badges, charts);
}

// Each step shows something its neighbour does not: consecutive steps that render the same scene
// at the same pixel with the same settings, the same chart and a focus that composes the same
// frame export the same picture beside different words, even when one of them outlines another
// fetch in orange (5.3 and 5.4 were such a pair: the weight table and the four gathers on one
// picture, one box apart). The step text and the step list always differ; the scene, the cells,
// the formula and the chart are what a class looks at. A step that moves (animate) differs; a
// split view (compare) is a frame of its own beside the step's, which it does not change.
TEST(LessonSteps, ConsecutiveStepsShowDifferentPictures) {
    // What the focus composes: the panels' places at every size and mode, and whether the cells
    // keep the formula's room (two focus names may compose one frame: "formula" and
    // "neighbourhood+formula").
    auto composition = [](const LessonStep& step) {
        Focus focus = stepFocus(step);
        std::vector<float> out{cellsAlone(focus) ? 1.0f : 0.0f};
        for (glm::ivec2 size : SIZES) {
            for (bool presentation : {false, true}) {
                InspectorLayout l = focusLayout(inspectorLayout(size, presentation), focus);
                for (const Rect& r : {l.scene, l.steps, l.inspector}) {
                    out.insert(out.end(), {r.x, r.y, r.w, r.h});
                }
            }
        }
        return out;
    };
    std::vector<std::string> lessons;
    for (const auto& e : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (e.path().extension() == ".toml") lessons.push_back(e.path().string());
    }
    std::sort(lessons.begin(), lessons.end());
    ASSERT_GE(lessons.size(), 10u);
    int pairs = 0;
    for (const std::string& path : lessons) {
        Lesson lesson = parseLessonFile(path);
        for (size_t k = 1; k < lesson.steps.size(); ++k) {
            const LessonStep& a = lesson.steps[k - 1];
            const LessonStep& b = lesson.steps[k];
            ++pairs;
            bool same = a.settings == b.settings && a.chart == b.chart &&
                        a.chartHighlight == b.chartHighlight && composition(a) == composition(b) &&
                        !a.animate && !b.animate;
            EXPECT_FALSE(same) << lesson.name << " steps " << k << " and " << k + 1
                               << " show the same picture (an orange outline apart): change "
                                  "the pixel, a setting, or the focus to what each text talks "
                                  "about";
        }
    }
    EXPECT_GE(pairs, 60);
}

// A chart step shows its chart where the scene goes (in presentation mode over the inspector's
// room too): a click there picks no pixel of the hidden scene; on a scene step it does.
TEST_F(Layout, ClicksOnAChartPickNoScenePixel) {
    for (bool presentation : {true, false}) {
        Session session({1280, 720}, presentation);
        session.loadLesson(PCFSCOPE_SOURCE_DIR "/lessons/11-speed-and-accuracy.toml");
        int chartStep = -1, sceneStep = -1;
        for (int k = 0; k < session.stepCount(); ++k) {
            bool chart = !session.lesson().steps[static_cast<size_t>(k)].chart.empty();
            if (chart && chartStep < 0) chartStep = k;
            if (!chart && sceneStep < 0) sceneStep = k;
        }
        ASSERT_GE(chartStep, 0);
        ASSERT_GE(sceneStep, 0);
        session.goToStep(sceneStep);
        // Where the scene step draws its scene (an inset when its focus is the neighbourhood:
        // a click there picks the scene pixel under it, scaled back).
        Rect scene = session.stepLayout().scene;
        glm::vec2 at = scene.position() + glm::vec2(7.0f, 5.0f);
        glm::ivec2 picked(glm::floor(glm::vec2(7.0f, 5.0f) * session.layout().scene.w / scene.w));
        session.goToStep(chartStep);
        EXPECT_FALSE(session.sceneShown());
        glm::ivec2 before = session.pixel();
        ASSERT_NE(before, picked);
        EXPECT_FALSE(session.clickFrame(at));
        EXPECT_EQ(session.pixel(), before) << presentation;
        session.goToStep(sceneStep);
        EXPECT_TRUE(session.sceneShown());
        EXPECT_TRUE(session.clickFrame(at));
        EXPECT_EQ(session.pixel(), picked) << presentation;
        // Off the scene (the inspector's side): nothing.
        EXPECT_FALSE(session.clickFrame({scene.right() + 5.0f, scene.y + 5.0f}));
        EXPECT_EQ(session.pixel(), picked);
    }
}

// lesson_pixels_test checks the lessons' pixel claims in presentation mode's scenes at the
// projector sizes: these.
TEST_F(Layout, PresentationScenesAreTheCheckedSizes) {
    EXPECT_EQ(glm::ivec2(inspectorLayout({1280, 720}, true).scene.size()), glm::ivec2(617, 347));
    EXPECT_EQ(glm::ivec2(inspectorLayout({1024, 768}, true).scene.size()), glm::ivec2(512, 288));
}

// Presentation type is a projector's at the small sizes: 22 px step text, 18 px numbers.
TEST_F(Layout, PresentationTypeIsLargeAtProjectorSizes) {
    for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
        TypeSizes t = typeSizes(inspectorLayout(size, true));
        EXPECT_GE(t.body, 22.0f);
        EXPECT_GE(t.bodyFloor, 22.0f);
        EXPECT_GE(t.number, 18.0f);
        EXPECT_GE(t.numberFloor, 18.0f);
        TypeSizes normal = typeSizes(inspectorLayout(size, false));
        EXPECT_GT(t.body, normal.body);
        EXPECT_GT(t.number, normal.number);
    }
}

Trace syntheticTrace() {
    Trace tr;
    tr.map.size = {64, 64};
    tr.uv = {0.5f, 0.5f};
    tr.pos.base = {31, 31};
    tr.pos.frac = {0.5f, 0.5f};
    tr.params.method = PCF_BILINEAR2X2;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            tr.taps.push_back({{31 + i, 31 + j}, 0.5f, 0.4f, 1.0f, 0.25f, 0});
        }
    }
    tr.weights.origin = {31, 31};
    tr.weights.size = {2, 2};
    tr.weights.values = {0.25f, 0.25f, 0.25f, 0.25f};
    tr.visibility = 1.0f;
    return tr;
}

// Text that cannot fit pages, says so with a "more" mark, and every page stays in its panel.
TEST_F(Layout, LongStepTextPagesWithAMoreMarkInsteadOfClipping) {
    InspectorModel m;
    m.title = "Paging";
    m.stepTitles = {"One", "Two"};
    m.trace = syntheticTrace();
    std::string text;
    for (int k = 0; k < 120; ++k) text += "Sentence " + std::to_string(k) + " of a long step. ";
    m.stepText = text;
    InspectorLayout l = inspectorLayout({1280, 720}, true);
    m.presentation = true;
    m.sceneSize = glm::ivec2(l.scene.size());
    FramePlan plan = planFrame(l, m);
    ASSERT_GT(plan.textPages, 1);
    bool more = false;
    for (const LayoutBox& b : plan.boxes) {
        more |= b.role == "more";
        if (b.role == "step-text") {
            EXPECT_TRUE(b.shortened);
            EXPECT_GE(b.fontPx, 22.0f);
        }
    }
    EXPECT_TRUE(more);
    // In the window the mark names the keys that turn the page: on an animation step Space
    // plays, so Right. A written frame (export, animate) names no key: it has none.
    for (bool plays : {false, true}) {
        m.plays = plays;
        for (bool interactive : {false, true}) {
            m.interactive = interactive;
            int marks = 0;
            for (const LayoutBox& b : planFrame(l, m).boxes) {
                if (b.role != "more") continue;
                ++marks;
                EXPECT_EQ(b.text.starts_with("more Space/Right"), interactive && !plays) << b.text;
                EXPECT_EQ(b.text.starts_with("more Right"), interactive && plays) << b.text;
                if (!interactive) {
                    EXPECT_EQ(b.text, "more (1/" + std::to_string(plan.textPages) + ")");
                }
            }
            EXPECT_EQ(marks, 1);
        }
    }
    m.plays = false;
    m.interactive = false;
    // The last page holds the last sentence's words (nothing is dropped between pages).
    m.textPage = plan.textPages - 1;
    FramePlan last = planFrame(l, m);
    EXPECT_TRUE(problems(last, l).empty());
    // A short text is one page, not shortened, no mark.
    m.stepText = "Short.";
    m.textPage = 0;
    FramePlan one = planFrame(l, m);
    EXPECT_EQ(one.textPages, 1);
    for (const LayoutBox& b : one.boxes) {
        EXPECT_NE(b.role, "more");
        if (b.role == "step-text") {
            EXPECT_FALSE(b.shortened);
        }
    }
}

// A page of step text ends where a sentence or a paragraph ends, and a preformatted block (a
// table, a formula) stays on one page: a slide that stopped at "p = uv * size" with "- 0.5" on
// the next (3.6 at 1280x720 presentation) stated another formula than the lesson's.
TEST_F(Layout, PagesEndAtSentencesAndKeepTablesWhole) {
    InspectorModel m;
    m.title = "Paging";
    m.stepTitles = {"One", "Two"};
    m.trace = syntheticTrace();
    m.presentation = true;
    std::string text;
    for (int k = 0; k < 14; ++k) {
        text += "Sentence " + std::to_string(k) +
                " runs on over more than one line of the step panel, so that a page that is cut "
                "at a fixed count of lines ends in its middle. ";
        if (k == 6) text += "The rows:\n  a     b     c\n  1.0   2.0   3.0\n  4.0   5.0   6.0\n";
    }
    m.stepText = text;
    for (glm::ivec2 size : {glm::ivec2{1024, 768}, glm::ivec2{1280, 720}}) {
        InspectorLayout l = inspectorLayout(size, true);
        m.sceneSize = glm::ivec2(l.scene.size());
        m.textPage = 0;
        int pages = planFrame(l, m).textPages;
        ASSERT_GT(pages, 2) << size.x;
        std::string all;
        int tablePage = -1;
        for (int page = 0; page < pages; ++page) {
            m.textPage = page;
            FramePlan plan = planFrame(l, m);
            EXPECT_TRUE(problems(plan, l).empty()) << size.x << " page " << page + 1;
            std::string shown;
            for (const LayoutBox& b : plan.boxes) {
                if (b.role == "step-text") shown = b.text;
            }
            ASSERT_FALSE(shown.empty()) << size.x << " page " << page + 1;
            // At a sentence's end or after the table that ends one; never one sentence alone.
            if (page + 1 < pages) {
                EXPECT_TRUE(endsCleanly(shown)) << size.x << " page " << page + 1 << " ends \""
                                                << shown.substr(shown.size() - 20) << "\"";
            }
            EXPECT_GE(sentencesIn(shown), 2) << size.x << " page " << page + 1 << ": " << shown;
            size_t rows = 0;
            for (const char* row : {"  a ", "  1.0 ", "  4.0 "})
                rows += shown.find(row) != std::string::npos;
            if (rows > 0) {
                EXPECT_EQ(rows, 3u) << size.x << " page " << page + 1 << ": the table is split";
                // With the words that lead into it.
                EXPECT_NE(shown.find("The rows:\n  a "), std::string::npos) << shown;
                tablePage = page;
            }
            for (char c : shown) all += c == '\n' ? ' ' : c;
            all += ' ';
        }
        EXPECT_GE(tablePage, 0) << size.x;
        // Nothing is dropped between pages: every sentence is on one of them.
        for (int k = 0; k < 14; ++k) {
            EXPECT_NE(all.find("Sentence " + std::to_string(k) + " "), std::string::npos) << k;
        }
    }
}

// The ring drawn round poisson's and pcss's points is the disk they fill: the widely copied
// 16-point set reaches 1.234 of its radius (8 points lie outside radius 1), and a ring of radius
// R left half of them outside it (lesson 7, "the disk, radius R").
TEST(PoissonDisk, TheDrawnRingHoldsEveryPointAndTouchesTheFarthest) {
    constexpr int MAP = 32;
    ShadowMap map(MAP, MAP, 0.9f);
    for (int j = 0; j < MAP; ++j) {
        for (int i = 0; i < MAP / 2; ++i) map.setDepth(i, j, 0.2f);
    }
    for (float radius : {1.0f, 2.5f}) {
        for (bool rotated : {false, true}) {
            PcfParams prm = makeParams(PCF_POISSON, 3, radius);
            if (rotated) prm.rotation = vec2(0.38268343f, 0.92387953f);  // 67.5 degrees
            Trace tr =
                traceLookup(map, (vec2(15.3f, 16.6f) + vec2(0.5f)) / float(MAP), 0.5f, 0.5f, prm);
            InspectorLayout l = inspectorLayout({1280, 720}, true);
            InspectorModel m;
            m.stepTitles = {"one"};
            m.stepText = "text";
            m.trace = tr;
            m.presentation = true;
            m.sceneSize = glm::ivec2(l.scene.size());
            FramePlan plan = planFrame(l, m);
            ASSERT_EQ(plan.diskRadii.size(), 1u);
            ASSERT_EQ(tr.fetches.size(), 16u);
            float farthest = 0.0f;
            for (const FetchRecord& f : tr.fetches) {
                vec2 p = f.uv * float(MAP) - vec2(0.5f);
                farthest = std::max(farthest, glm::length(p - tr.pos.p));
            }
            EXPECT_GT(farthest, 1.2f * radius);  // the set is not a unit disk
            EXPECT_GE(plan.diskRadii[0], farthest - 1e-4f) << radius << (rotated ? " rotated" : "");
            EXPECT_LE(plan.diskRadii[0], farthest + 1e-3f) << radius << (rotated ? " rotated" : "");
            // The cells reach round the whole ring (texel i spans p in [i - 0.5, i + 0.5)), so it
            // is never cut by the cells' edge (7.2 at 1280x720 lost its left and bottom).
            Neighbourhood view = neighbourhoodView(l, m);
            vec2 lo = tr.pos.p - vec2(plan.diskRadii[0]) + vec2(0.5f);
            vec2 hi = tr.pos.p + vec2(plan.diskRadii[0]) + vec2(0.5f);
            EXPECT_LE(view.origin.x, int(std::floor(lo.x))) << radius;
            EXPECT_LE(view.origin.y, int(std::floor(lo.y))) << radius;
            EXPECT_GE(view.origin.x + view.size.x - 1, int(std::floor(hi.x))) << radius;
            EXPECT_GE(view.origin.y + view.size.y - 1, int(std::floor(hi.y))) << radius;
        }
    }
}

// Presentation mode keeps the step list's neighbours of the current step, at 18 px or more at
// projector sizes: the previous step on the left, the next on the right.
TEST_F(Layout, PresentationShowsTheNeighbouringStepsAtReadableSize) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"First step", "Second step", "Third step"};
    m.stepText = "Short.";
    m.presentation = true;
    for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
        InspectorLayout l = inspectorLayout(size, true);
        m.sceneSize = glm::ivec2(l.scene.size());
        for (int current : {0, 1, 2}) {
            m.currentStep = current;
            FramePlan plan = planFrame(l, m);
            std::vector<LayoutBox> items;
            for (const LayoutBox& b : plan.boxes) {
                if (b.role == "step-list") items.push_back(b);
            }
            ASSERT_EQ(items.size(), current == 1 ? 2u : 1u) << current;
            for (const LayoutBox& b : items) {
                EXPECT_GE(b.fontPx, 18.0f);
                EXPECT_FALSE(b.shortened);
            }
            if (current == 1) {
                EXPECT_LT(items[0].rect.x, items[1].rect.x);  // previous, next
            }
            EXPECT_TRUE(problems(plan, l).empty());
        }
    }
}

// Preformatted rows (two leading spaces) keep their columns: cells padded to the widest.
TEST_F(Layout, TableRowsKeepTheirColumnsInMonospace) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"Table"};
    m.stepText = "Weights:\n  0.1171   1   0.0678\n  1   0.6333   1\nend";
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    m.sceneSize = glm::ivec2(l.scene.size());
    FramePlan plan = planFrame(l, m);
    // Draw into a recording canvas is GL; instead check the rows' widths: equal in monospace.
    // The step-text box is as wide as its widest line; both rows pad to "0.1171   0.6333   ..."
    // so that the width of the block equals the measured row of the widest cells.
    float rowW = measureText(FontFace::Mono, typeSizes(l).body, "  0.1171   0.6333   0.0678").x;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role == "step-text") {
            EXPECT_GE(b.rect.w + 0.5f, rowW);
        }
    }
}

// A `code span` in the step text is set in monospace without its backticks: the one-line block is
// as wide as its prose in Sans plus its span in Mono.
TEST_F(Layout, CodeSpansInStepTextAreMonospaceWithoutBackticks) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"Span"};
    m.stepText = "Set `origin_shift = 0.25` now.";
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    m.sceneSize = glm::ivec2(l.scene.size());
    FramePlan plan = planFrame(l, m);
    bool found = false;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role != "step-text") continue;
        found = true;
        float px = b.fontPx;
        float expected = measureText(FontFace::Sans, px, "Set ").x +
                         measureText(FontFace::Mono, px, "origin_shift = 0.25").x +
                         measureText(FontFace::Sans, px, " now.").x;
        EXPECT_NEAR(b.rect.w, expected, 1.0f);
        EXPECT_GT(std::fabs(b.rect.w - measureText(FontFace::Sans, px, m.stepText).x), 2.0f);
        EXPECT_FALSE(b.shortened);
    }
    EXPECT_TRUE(found);
    EXPECT_TRUE(problems(plan, l).empty());
}

// The step JSON's `text` is the text as drawn: code spans lose their backticks, a lone backtick
// stays, preformatted rows keep theirs and their columns line up as drawn.
TEST(DrawnStepText, DropsCodeSpanBackticksAsTheFrameDraws) {
    EXPECT_EQ(drawnStepText("Set `origin_shift = 0.25` now."), "Set origin_shift = 0.25 now.");
    EXPECT_EQ(drawnStepText("a `b` and `c`\nit's 5` wide"), "a b and c\nit's 5` wide");
    EXPECT_EQ(drawnStepText("Rows:\n  `x`  1\n  `yy`  0.5\nend `z`"),
              "Rows:\n  `x`    1\n  `yy`   0.5\nend z");
    EXPECT_EQ(drawnStepText(""), "");
}

// A title of 200,000 characters is laid out in linear time (it once took minutes: wrapping
// re-measured the growing line for every word).
TEST_F(Layout, LongTitlesLayOutInLinearTime) {
    auto timeFor = [](size_t chars) {
        InspectorModel m;
        std::string title;
        while (title.size() < chars) title += "word ";
        m.title = title;
        m.stepTitles = {title, "short"};
        m.stepText = title;
        m.trace = syntheticTrace();
        InspectorLayout l = inspectorLayout({1280, 720}, false);
        m.sceneSize = glm::ivec2(l.scene.size());
        auto start = std::chrono::steady_clock::now();
        FramePlan plan = planFrame(l, m);
        EXPECT_FALSE(plan.boxes.empty());
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    timeFor(1000);  // atlases warm
    double small = timeFor(50000);
    double large = timeFor(200000);
    std::printf("layout of a 50,000-char title %.3f s, 200,000-char %.3f s\n", small, large);
    EXPECT_LT(large, 5.0);
    // Linear: 4x the text, well under 16x the time (allow noise on a shared machine).
    EXPECT_LT(large, 10.0 * small + 0.2);
}

// A light-space buffer (uv, depth, receiver) of the square of pixels `radius` round a picked
// pixel, `pixelsPerTexel` screen pixels to a texel of a 64 x 64 map, centred on uv 0.5.
std::vector<float> syntheticLightSpace(int radius, float pixelsPerTexel) {
    std::vector<float> ls;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            ls.push_back(0.5f + x / pixelsPerTexel / 64.0f);
            ls.push_back(0.5f + y / pixelsPerTexel / 64.0f);
            ls.push_back(0.4f);
            ls.push_back(1.0f);
        }
    }
    return ls;
}

// A model whose picked pixel is the scene's centre with a light-space buffer round it.
InspectorModel gridModel(const InspectorLayout& l, int& radius) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"Grid"};
    m.stepText = "Grid.";
    m.sceneSize = glm::ivec2(l.scene.size());
    m.pixel = m.sceneSize / 2;
    radius = gridRadius(m.sceneSize) + 1;
    m.lightSpaceOrigin = m.pixel - glm::ivec2(radius);
    m.lightSpaceSize = glm::ivec2(2 * radius + 1);
    return m;
}

// The texel grid is drawn where a texel spans several pixels, and hidden (or off) otherwise.
TEST_F(Layout, GridHiddenWhenTexelsAreSmallOrTurnedOff) {
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    int radius = 0;
    InspectorModel m = gridModel(l, radius);
    std::vector<float> big = syntheticLightSpace(radius, 9.0f);
    std::vector<float> tiny = syntheticLightSpace(radius, 1.5f);
    m.lightSpace = &big;
    EXPECT_TRUE(planFrame(l, m).gridShown);
    m.lightSpace = &tiny;
    EXPECT_FALSE(planFrame(l, m).gridShown);
    m.lightSpace = &big;
    m.grid = false;
    EXPECT_FALSE(planFrame(l, m).gridShown);
}

// The legend names the texels read "on the scene" only where the scene shows them: tinted and
// outlined at any texel size, the grid on or off, but not on a scene drawn as a scaled inset,
// which leaves the tint out.
TEST_F(Layout, LegendNamesTheSceneTintOnlyWhereItIsDrawn) {
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    int radius = 0;
    InspectorModel m = gridModel(l, radius);
    std::vector<float> tiny = syntheticLightSpace(radius, 1.5f);
    m.lightSpace = &tiny;
    auto named = [](const FramePlan& plan) {
        for (const LayoutBox& b : plan.boxes) {
            if (b.text == "texels read, on the scene") return true;
        }
        return false;
    };
    FramePlan full = planFrame(l, m);
    EXPECT_TRUE(full.footprintShown);
    EXPECT_TRUE(named(full));
    m.grid = false;
    EXPECT_TRUE(named(planFrame(l, m)));
    l.sceneInset = true;
    FramePlan inset = planFrame(l, m);
    EXPECT_FALSE(inset.footprintShown);
    EXPECT_FALSE(named(inset));
    // A scene whose pixels round the pick are not receivers: nothing tinted, nothing named.
    l.sceneInset = false;
    std::vector<float> none = tiny;
    for (size_t k = 3; k < none.size(); k += 4) none[k] = 0.0f;
    m.lightSpace = &none;
    FramePlan empty = planFrame(l, m);
    EXPECT_FALSE(empty.footprintShown);
    EXPECT_FALSE(named(empty));
}

// A focus names one or two parts; anything else is refused (loadLessonChecked turns that into
// one line at the key's file:line).
TEST(Focus, ParsesOneOrTwoKnownParts) {
    ASSERT_TRUE(parseFocus("neighbourhood"));
    EXPECT_EQ(*parseFocus("neighbourhood"), Focus{.neighbourhood = true});
    EXPECT_EQ(*parseFocus("scene+formula"), (Focus{.scene = true, .formula = true}));
    EXPECT_EQ(focusName(*parseFocus("formula+neighbourhood")), "neighbourhood+formula");
    EXPECT_FALSE(parseFocus(""));
    EXPECT_FALSE(parseFocus("neighborhood"));
    EXPECT_FALSE(parseFocus("scene+scene"));
    EXPECT_FALSE(parseFocus("scene+formula+chart"));
    EXPECT_FALSE(parseFocus("scene+"));
}

TEST(Focus, UnknownFocusInALessonNamesItsLine) {
    std::string dir = testing::TempDir() + "/focus_lesson";
    std::filesystem::create_directories(dir);
    std::string path = dir + "/bad.toml";
    std::ofstream(path) << "title = \"T\"\nscene = \"box-on-plane\"\n[[step]]\ntitle = \"S\"\n"
                           "text = \"x\"\nfocus = \"texels\"\n";
    try {
        loadLessonChecked(path);
        ADD_FAILURE() << "accepted focus = \"texels\"";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.toml:6"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("texels"), std::string::npos) << e.what();
    }
    // Derived where the lesson says nothing: a filter's step is about its neighbourhood.
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/05-gather-weights.toml");
    EXPECT_EQ(stepFocus(lesson.steps[0]), (Focus{.neighbourhood = true, .formula = true}));
    Lesson acne = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/08-acne-and-bias.toml");
    EXPECT_TRUE(stepFocus(acne.steps[3]).scene);
}

// A neighbourhood focus gives the inspector the room and the scene an inset of the same 16:9,
// inside the frame and clear of the other panels; a scene focus keeps the frame as it was.
TEST(Focus, NeighbourhoodFocusGivesTheInspectorTheRoom) {
    for (glm::ivec2 size : SIZES) {
        for (bool presentation : {false, true}) {
            InspectorLayout base = inspectorLayout(size, presentation);
            InspectorLayout n = focusLayout(base, Focus{.neighbourhood = true});
            // (Presentation's inspector already has half the width; normal mode's 40%.)
            float gain = presentation ? 1.15f : 1.3f;
            EXPECT_GT(n.inspector.w * n.inspector.h, gain * base.inspector.w * base.inspector.h);
            EXPECT_TRUE(n.sceneInset);
            EXPECT_LT(n.scene.w, base.scene.w);
            EXPECT_NEAR(n.scene.w / n.scene.h, 16.0f / 9.0f, 0.02f);
            Rect frame{0, 0, static_cast<float>(size.x), n.status.y};
            EXPECT_TRUE(inside(n.scene, frame) && inside(n.steps, frame));
            EXPECT_TRUE(n.scene.intersect(n.inspector).empty());
            EXPECT_TRUE(n.steps.intersect(n.inspector).empty());
            EXPECT_TRUE(n.scene.intersect(n.steps).empty());
            InspectorLayout s = focusLayout(base, Focus{.scene = true, .neighbourhood = true});
            EXPECT_EQ(s.inspector.w, base.inspector.w);
            EXPECT_FALSE(s.sceneInset);
        }
    }
}

// A focus on the neighbourhood alone gives the cells the formula's room: bigger cells on the first
// page, the formula whole on the next (5.4, the four gathers, beside 5.3's table and sum).
TEST_F(Layout, NeighbourhoodAloneGivesTheCellsTheFormulasRoom) {
    InspectorModel m;
    m.title = "Focus";
    m.stepTitles = {"One", "Two"};
    m.stepText = "Short.";
    m.trace = syntheticTrace();
    int larger = 0;
    for (glm::ivec2 size : SIZES) {
        for (bool presentation : {false, true}) {
            std::string where = std::to_string(size.x) + "x" + std::to_string(size.y) +
                                (presentation ? " presentation" : "");
            InspectorLayout base = inspectorLayout(size, presentation);
            m.presentation = presentation;
            m.sceneSize = glm::ivec2(base.scene.size());
            auto formulaOn = [&](const InspectorLayout& l, int page) {
                m.textPage = page;
                FramePlan plan = planFrame(l, m);
                EXPECT_TRUE(problems(plan, l).empty()) << where << " page " << page + 1;
                bool formula = false;
                for (const LayoutBox& b : plan.boxes) formula |= b.role == "formula";
                return formula;
            };
            Focus both{.neighbourhood = true, .formula = true};
            InspectorLayout lb = focusLayout(base, both);
            m.focus = both;
            EXPECT_TRUE(formulaOn(lb, 0)) << where;
            Rect shared = neighbourhoodArea(lb, m);
            Focus cells{.neighbourhood = true};
            ASSERT_TRUE(cellsAlone(cells));
            EXPECT_FALSE(cellsAlone(both));
            InspectorLayout lc = focusLayout(base, cells);
            m.focus = cells;
            EXPECT_FALSE(formulaOn(lc, 0)) << where;
            EXPECT_TRUE(formulaOn(lc, 1)) << where;
            Rect alone = neighbourhoodArea(lc, m);
            EXPECT_GE(alone.w, shared.w) << where;
            larger += alone.w > shared.w + 8.0f;
        }
    }
    EXPECT_GE(larger, 6);
}

// ---- A moment method's page (overlay/inspector_moment_page.cpp). ----

// A moment method's step on box-on-plane, its point in the box's penumbra (the footprint
// straddles the box's edge), with `extra` settings lines.
Lesson momentLesson(const std::string& method, const std::string& extra) {
    std::string text = "title = \"moments\"\nscene = \"box-on-plane\"\n[settings]\nmethod = \"" +
                       method + "\"\nmap_size = 128\nkernel = 5\npoint = [0.9794, 0, -0.4338]\n" +
                       extra +
                       "\n[[step]]\ntitle = \"Look\"\ntext = \"visibility = {visibility}\"\n";
    return parseLessonString(text, "moments.toml");
}

// Every page of a moment method's frame at the sizes a class meets (1024x768 and 1280x720 on a
// projector, 1600x900 on a screen, and 960x540, where the bound goes on a page of its own): its
// texts inside the panel, over no other text or number, at or above their floors; the histogram
// holding every depth texel its moments average; its numbers and the "lit: ref <= depth" legend of
// cells it no longer draws gone.
TEST_F(Layout, MomentPagesFitAndShowTheFootprintAtEverySize) {
    struct Case {
        const char* method;
        const char* extra;
    };
    const Case cases[] = {{"vsm", ""},
                          {"vsm", "lbr = 0.3"},
                          {"evsm4", "evsm_exponents = \"40,5\""},
                          {"msm", ""},
                          {"msm-hausdorff", ""}};
    glm::ivec2 renderScene(inspectorLayout({1280, 720}, false).scene.size());
    int pagedFrames = 0;  // frames whose figure took two pages (960x540's, at least)
    for (const Case& c : cases) {
        Lesson lesson = momentLesson(c.method, c.extra);
        const LessonSettings& s = lesson.steps[0].settings;
        SceneRenderer renderer(lesson.scene);
        std::optional<ScenePoint> pinned = stepPoint(lesson.scene, s);
        renderStepView(renderer, stepView(lesson.scene, s, pinned, renderScene));
        ShadowMap map = renderer.readShadowMap();
        glm::ivec2 px = stepPick(lesson.scene, s, renderScene).pixel;
        std::optional<PixelLookup> lookup = tracePixel(renderer, map, s, px);
        ASSERT_TRUE(lookup) << c.method;
        const Trace& tr = lookup->trace;
        // The footprint straddles the edge: (N + 1)^2 texels, not all one depth.
        ASSERT_TRUE(tr.depths.present) << c.method;
        EXPECT_EQ(tr.depths.texels.size(), 36u) << c.method;
        InspectorModel m;
        m.title = lesson.title;
        m.stepTitles = {"Look"};
        m.map = &map;
        m.trace = tr;
        m.stepText = "visibility";
        for (auto [size, presentation] :
             {std::pair{glm::ivec2(1024, 768), true}, std::pair{glm::ivec2(1280, 720), true},
              std::pair{glm::ivec2(1600, 900), false},
              // (Too small for the whole: the bound goes on a page of its own.)
              std::pair{glm::ivec2(960, 540), true}}) {
            InspectorLayout l = inspectorLayout(size, presentation);
            m.presentation = presentation;
            m.sceneSize = glm::ivec2(l.scene.size());
            m.pixel = stepPick(lesson.scene, s, m.sceneSize).pixel;
            std::string where = std::string(c.method) + " " + c.extra + " at " +
                                std::to_string(size.x) + "x" + std::to_string(size.y);
            FramePlan first = planFrame(l, m);
            EXPECT_LE(first.textPages, 2) << where;
            pagedFrames += first.textPages > 1;
            std::vector<FramePlan> pages;
            int histograms = 0, curves = 0;
            // PCF of the same footprint, read off beside the bound at t (not for msm: no curve).
            std::string pcfLabel = "pcf " + formatNumber(tr.depths.pcfVisibility);
            bool pcfShown = false;
            for (int page = 0; page < first.textPages; ++page) {
                m.textPage = page;
                pages.push_back(planFrame(l, m));
                for (const std::string& problem : problems(pages.back(), l)) {
                    ADD_FAILURE() << where << " page " << page + 1 << ": " << problem;
                }
                for (const LayoutBox& b : pages.back().boxes) {
                    histograms += b.role == "moment-histogram";
                    curves += b.role == "moment-curve";
                    pcfShown |= b.role == "moment-value" && b.text == pcfLabel;
                    EXPECT_EQ(b.text.find("ref <= depth"), std::string::npos) << where;
                    EXPECT_FALSE(b.role.starts_with("cell-")) << where << ": " << b.role;
                }
                ASSERT_TRUE(pages.back().moments) << where;
            }
            m.textPage = 0;
            for (const std::string& problem : cropped(pages, tr)) {
                ADD_FAILURE() << where << ": " << problem;
            }
            EXPECT_EQ(histograms, 1) << where;
            // vsm one curve, evsm4 one per warp; msm none (its points stand on the histogram).
            bool msm = methodInfo(tr.params.method).reconstructs;
            int warps = methodInfo(tr.params.method).warps;
            EXPECT_EQ(curves, msm ? 0 : std::max(1, warps)) << where;
            EXPECT_EQ(pcfShown, !msm) << where;
        }
    }
    EXPECT_GT(pagedFrames, 0);
}

}  // namespace
}  // namespace pcf
