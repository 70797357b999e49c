// The frame's layout, checked from the boxes it lists (inspector.h: planFrame, LayoutBox): for
// every step of every lesson, at the sizes a class meets (1024x768, 1280x720, 1600x900,
// 1920x1080), normal and presentation: no text outside its panel, no label or mark on a number or
// a text, type at or above its floor. The layout is a pure function of the frame size and the
// model, so each step is rendered and traced once (EGL, llvmpipe in CI) and laid out at all
// eight sizes without drawing.
#include <gtest/gtest.h>

#include "layout_checks.h"

namespace pcf {
namespace {

using namespace testutil;

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

}  // namespace
}  // namespace pcf
