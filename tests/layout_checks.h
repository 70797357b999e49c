// The checks the layout tests share (layout_test.cpp, layout_chart_test.cpp, layout_text_test.cpp,
// layout_inspector_test.cpp): a plan's problems as readable lines (text outside its panel, a label
// or mark on a number or a text, type under its floor), what a step's pages left out of its
// trace, how a page of step text ends, the sizes a class meets, a small bilinear trace, and the
// GL context the steps are rendered with.
#pragma once

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

namespace pcf::testutil {

inline constexpr glm::ivec2 SIZES[] = {{1024, 768}, {1280, 720}, {1600, 900}, {1920, 1080}};

inline bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x - 0.01f && inner.y >= outer.y - 0.01f &&
           inner.right() <= outer.right() + 0.01f && inner.bottom() <= outer.bottom() + 0.01f;
}

inline bool isTextual(BoxKind k) {
    return k == BoxKind::Text || k == BoxKind::Number || k == BoxKind::Label;
}

// The problems of one plan, as readable lines (empty: none).
inline std::vector<std::string> problems(const FramePlan& plan, const InspectorLayout& l) {
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
inline std::vector<std::string> cropped(const std::vector<FramePlan>& pages, const Trace& tr) {
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

// A page of step text as a class reads it: its sentences end at '.', '?' or '!' followed by a
// space, a line's end or the text's (a closing bracket or quote may come between), not at an
// abbreviation's stop ("e.g."); table rows (two leading spaces) belong to the sentence that leads
// into them and end it, and a page that ends with one ends that sentence.
inline bool endsSentenceAt(std::string_view t, size_t k) {
    if (t[k] != '.' && t[k] != '?' && t[k] != '!') return false;
    size_t next = k + 1;
    while (next < t.size() && (t[next] == ')' || t[next] == '"')) ++next;
    if (next < t.size() && t[next] != ' ' && t[next] != '\n') return false;
    std::string_view before = t.substr(0, k + 1);
    return !before.ends_with("e.g.") && !before.ends_with("i.e.");
}

inline int sentencesIn(std::string_view text) {
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

inline bool endsCleanly(std::string_view text) {
    size_t last = text.rfind('\n');
    std::string_view line = last == std::string_view::npos ? text : text.substr(last + 1);
    if (line.starts_with("  ")) return true;
    while (!line.empty() && (line.back() == ')' || line.back() == '"')) line.remove_suffix(1);
    return !line.empty() && (line.back() == '.' || line.back() == '?' || line.back() == '!');
}

inline Trace syntheticTrace() {
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

// The GL context the layout tests render the lessons' steps with (EGL, llvmpipe in CI).
class Layout : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static inline std::unique_ptr<GlContext> sContext;
};

}  // namespace pcf::testutil
