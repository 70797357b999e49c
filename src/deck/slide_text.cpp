// slide_text.cpp: a frame's sidecar read for the deck: the words, the question or the answer,
// and the trace as a table of the texels read, with the numbers the question hides as "?".
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "deck/deck.h"

namespace pcf {

namespace {

using nlohmann::json;

std::string fixed(double v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

bool hidden(const std::vector<std::string>& masked, const char* role) {
    return std::find(masked.begin(), masked.end(), role) != masked.end();
}

// The merged weight of texel (i, j) from the trace's weight grid.
double mergedWeight(const json& weights, int i, int j) {
    int ox = weights["origin"][0], oy = weights["origin"][1];
    int w = weights["size"][0], h = weights["size"][1];
    if (i < ox || j < oy || i >= ox + w || j >= oy + h) return 0.0;
    return weights["values"][static_cast<size_t>((j - oy) * w + (i - ox))];
}

// The table: one row per texel read (its first read), in read order.
void traceTable(const json& tr, const std::vector<std::string>& masked, SlideText& out) {
    bool bits = hidden(masked, "cell-bit"), weights = hidden(masked, "cell-weight");
    bool refs = hidden(masked, "cell-ref"), depths = hidden(masked, "cell-depth");
    auto mask = [](bool h, const std::string& s) { return h ? std::string("?") : s; };
    out.header = {"texel", "depth", "ref", "bit", "weight"};
    std::vector<std::pair<int, int>> seen;
    for (const json& tap : tr["taps"]) {
        std::pair<int, int> texel{tap["texel"][0], tap["texel"][1]};
        if (std::find(seen.begin(), seen.end(), texel) != seen.end()) continue;
        seen.push_back(texel);
        double lit = tap["lit"];
        std::string bit = lit == 0.0 || lit == 1.0 ? fixed(lit, 0) : fixed(lit, 2);
        out.rows.push_back(
            {"(" + std::to_string(texel.first) + ", " + std::to_string(texel.second) + ")",
             mask(depths, fixed(tap["depth"], 4)), mask(refs, fixed(tap["ref"], 4)),
             mask(bits, bit),
             mask(weights, fixed(mergedWeight(tr["weights"], texel.first, texel.second), 4))});
    }
    std::string method = tr["method"];
    int kernel = tr["kernel"];
    out.summary = method + " N=" + std::to_string(kernel) + "   uv (" + fixed(tr["uv"][0], 4) +
                  ", " + fixed(tr["uv"][1], 4) + ")   ref " + mask(refs, fixed(tr["ref"], 4)) +
                  "   visibility " + mask(hidden(masked, "visibility"), fixed(tr["visibility"], 4));
}

}  // namespace

SlideText slideText(const std::string& text) {
    SlideText out;
    try {
        json j = json::parse(text);
        out.step = j["step"];
        // A split view's frame (app/compare_view.h) names its parts instead.
        if (j.contains("compare")) {
            out.stepTitle = "split view, " + j["compare"].get<std::string>();
            out.words =
                "The same point with " + j["compare"].get<std::string>() + ", side by side.";
            return out;
        }
        out.stepTitle = j["step_title"];
        out.words = j["text"];
        out.textPage = j["text_page"];
        out.textPages = j["text_pages"];
        std::vector<std::string> masked;
        if (j.contains("predict")) {
            const json& p = j["predict"];
            out.phase = p["phase"];
            for (const json& m : p["masked"]) masked.push_back(m);
            if (p.contains("choices")) {
                for (const json& c : p["choices"]) out.choices.push_back(c);
            }
            if (p.contains("answer_line")) out.answer = p["answer_line"];
        }
        if (!j["trace"].is_null()) traceTable(j["trace"], masked, out);
    } catch (const json::exception& e) {
        throw std::runtime_error(std::string("a frame's JSON sidecar: ") + e.what());
    }
    return out;
}

}  // namespace pcf
