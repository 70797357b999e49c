// The trace: what the inspector and `pcfscope trace` show for one lookup.
#include "kernel/trace.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "json_lite.h"
#include "kernel/shading.h"
#include "kernel/trace_explain.h"
#include "kernel/trace_json.h"

namespace pcf {
namespace {

Trace exampleTrace(int method, int kernel = 3) {
    return traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f,
                       makeParams(method, kernel));
}

TEST(Trace, BilinearStepsWriteTheLerpWithTheNumbers) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    ASSERT_GE(explainTrace(tr).size(), 4u);
    std::string all;
    for (const TraceStep& s : explainTrace(tr)) all += s.title + "\n" + s.text + "\n";
    EXPECT_NE(all.find("base = floor(p) = (3, 2)"), std::string::npos) << all;
    EXPECT_NE(all.find("lerp(1, 0, 0.2) = 0.8"), std::string::npos) << all;
    EXPECT_NE(all.find("= 0.8."), std::string::npos) << all;
    EXPECT_EQ(explainTrace(tr).front().title, "Project the pixel into the shadow map");
    EXPECT_EQ(explainTrace(tr).back().title, "Result");
}

TEST(Trace, EveryMethodExplainsItselfAndEndsWithTheKernelsResult) {
    for (const MethodInfo& m : allMethods()) {
        Trace tr = exampleTrace(m.id);
        EXPECT_GE(explainTrace(tr).size(), 3u) << m.name;
        for (const TraceStep& s : explainTrace(tr)) {
            EXPECT_FALSE(s.title.empty()) << m.name;
            EXPECT_FALSE(s.text.empty()) << m.name;
        }
        EXPECT_NE(explainTrace(tr).back().text.find(formatNumber(tr.visibility)), std::string::npos)
            << m.name << ": " << explainTrace(tr).back().text;
    }
}

// tent's merged weight table is a grid: a header of the texel columns i, then one line per texel
// row j, every line as long as the others and every number ending in its column, each cell at
// most five characters (so that 7x7's eight columns fit a projector's inspector), and each cell
// the merged weight times the table's scale.
TEST(Trace, TentsMergedWeightTableIsAlignedInColumns) {
    for (int n : {3, 5, 7}) {
        Trace tr = exampleTrace(PCF_TENT, n);
        std::string text = explainTrace(tr).back().text;
        size_t at = text.find("Merged, the taps weigh the texels");
        ASSERT_NE(at, std::string::npos) << text;
        std::vector<std::string> rows;
        std::istringstream lines(text.substr(at));
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("  ", 0) == 0) rows.push_back(line);
        }
        ASSERT_EQ(rows.size(), static_cast<size_t>(tr.weights.size.y) + 1) << text;
        EXPECT_EQ(rows[0].find("j\\i"), rows[0].find_first_not_of(' ')) << rows[0];
        float scale = pcfTentNorm(n);
        for (size_t r = 0; r < rows.size(); ++r) {
            const std::string& row = rows[r];
            EXPECT_EQ(row.size(), rows[0].size()) << row << "\n" << rows[0];
            // Column ends: where a number is followed by a space or the line's end.
            std::vector<size_t> ends, firstEnds;
            std::istringstream words(row);
            std::vector<std::string> cells;
            for (std::string w; words >> w;) cells.push_back(w);
            for (size_t i = 0; i < row.size(); ++i) {
                if (row[i] != ' ' && (i + 1 == row.size() || row[i + 1] == ' ')) ends.push_back(i);
            }
            const std::string& f = rows[0];
            for (size_t i = 0; i < f.size(); ++i) {
                if (f[i] != ' ' && (i + 1 == f.size() || f[i + 1] == ' ')) firstEnds.push_back(i);
            }
            EXPECT_EQ(ends, firstEnds) << row << "\n" << f;
            ASSERT_EQ(cells.size(), static_cast<size_t>(tr.weights.size.x) + 1) << row;
            int j = tr.weights.origin.y + static_cast<int>(r) - 1;
            for (int i = 0; i < tr.weights.size.x; ++i) {
                const std::string& c = cells[static_cast<size_t>(i) + 1];
                EXPECT_LE(c.size(), 5u) << row;
                if (r == 0) {
                    EXPECT_EQ(c, std::to_string(tr.weights.origin.x + i)) << row;
                    continue;
                }
                EXPECT_EQ(cells[0], std::to_string(j)) << row;
                float w = tr.weights.at({tr.weights.origin.x + i, j}) * scale;
                // Four significant digits (three decimals at most), or its first digit.
                EXPECT_NEAR(std::stof(c), w, std::max(0.0006f, w * 0.15f)) << row;
                if (w >= 0.0005f) {
                    EXPECT_NEAR(std::stof(c), w, std::max(0.0006f, w * 6e-4f)) << row;
                }
            }
        }
    }
}

TEST(Trace, TapsCarryTheirOwnRefAndFetchIndex) {
    Trace tr = exampleTrace(PCF_NAIVE);
    ASSERT_EQ(tr.taps.size(), 36u);
    ASSERT_EQ(tr.fetches.size(), 9u);
    for (size_t k = 0; k < tr.taps.size(); ++k) {
        EXPECT_EQ(tr.taps[k].ref, 0.5f);
        EXPECT_EQ(tr.taps[k].fetch, static_cast<int>(k / 4));  // 4 reads per bilinear lookup
    }
}

TEST(Trace, GatherRecordsTheComponentOrder) {
    Trace tr = exampleTrace(PCF_GATHER);
    ASSERT_EQ(tr.taps.size(), 16u);
    // Each gather reports x = (0,1), y = (1,1), z = (1,0), w = (0,0) of its 2x2 block.
    for (int g = 0; g < 4; ++g) {
        ivec2 corner = tr.taps[g * 4 + 3].texel;
        EXPECT_EQ(tr.taps[g * 4 + 0].texel, corner + ivec2(0, 1));
        EXPECT_EQ(tr.taps[g * 4 + 1].texel, corner + ivec2(1, 1));
        EXPECT_EQ(tr.taps[g * 4 + 2].texel, corner + ivec2(1, 0));
    }
}

TEST(Trace, JsonHasTheDesignFieldsAndItsNumbersAreTheKernels) {
    for (const MethodInfo& m : allMethods()) {
        Trace tr = exampleTrace(m.id);
        jsonlite::Value j = jsonlite::parse(traceToJson(tr));
        for (const char* key : {"method", "kernel", "uv", "z", "ref", "texel", "base", "frac",
                                "taps", "weights", "fetches", "visibility", "steps"}) {
            EXPECT_TRUE(j.has(key)) << m.name << " lacks " << key;
        }
        EXPECT_EQ(j["method"].string, std::string(m.name));
        EXPECT_EQ(j["taps"].size(), tr.taps.size());
        EXPECT_EQ(j["fetches"]["texels"].number, tr.counts.texels);
        EXPECT_EQ(j["fetches"]["gathers"].number, tr.counts.gathers);
        EXPECT_EQ(j["fetches"]["hw_taps"].number, tr.counts.hwTaps);
        EXPECT_FLOAT_EQ(static_cast<float>(j["visibility"].number), tr.visibility);
        double sum = 0.0;
        for (const jsonlite::Value& t : j["taps"].array)
            sum += t["weight"].number * t["lit"].number;
        EXPECT_NEAR(sum, tr.visibility, 1e-5) << m.name;
        const jsonlite::Value& w = j["weights"];
        EXPECT_EQ(w["values"].size(),
                  static_cast<size_t>(w["size"][0].number * w["size"][1].number));
        EXPECT_EQ(j["steps"].size(), explainTrace(tr).size());
        EXPECT_EQ(j["steps"][0]["title"].string, explainTrace(tr)[0].title);
    }
}

// A cascaded map's trace carries the blend band's second lookup beside the taps of the layer
// read: the next cascade, its weight, its own visibility and the blended result; a map of one
// layer has no band.
TEST(Trace, JsonOfACascadedMapCarriesTheBlendBand) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    EXPECT_FALSE(jsonlite::parse(traceToJson(tr)).has("cascade_blend"));
    tr.map.layers.push_back(tr.map.layers.front());
    tr.map.layers[0].viewDepth = vec2(0.1f, 10.0f);
    tr.map.layers[1].viewDepth = vec2(10.0f, 40.0f);
    tr.cascadeBlend = {1, 0.25f, 0.4f, pcfCascadeBlend(tr.visibility, 0.4f, 0.25f)};
    jsonlite::Value j = jsonlite::parse(traceToJson(tr));
    ASSERT_TRUE(j.has("cascade_blend"));
    const jsonlite::Value& b = j["cascade_blend"];
    EXPECT_EQ(b["next_layer"].number, 1);
    EXPECT_FLOAT_EQ(static_cast<float>(b["weight"].number), 0.25f);
    EXPECT_FLOAT_EQ(static_cast<float>(b["next_visibility"].number), 0.4f);
    // 0.8 (the layer read's) * 0.75 + 0.4 * 0.25
    EXPECT_NEAR(b["visibility"].number, 0.7, 1e-6);
    EXPECT_FLOAT_EQ(static_cast<float>(j["visibility"].number), tr.visibility);
}

TEST(Trace, TextShowsStepsTableAndResult) {
    std::string text = traceToText(exampleTrace(PCF_BILINEAR2X2));
    EXPECT_NE(text.find("1. Project the pixel"), std::string::npos) << text;
    EXPECT_NE(text.find("j=2"), std::string::npos) << text;
    EXPECT_NE(text.find("i=4"), std::string::npos) << text;
    EXPECT_NE(text.find("visibility = 0.8\n"), std::string::npos) << text;
}

TEST(Trace, FormatNumberTrimsZeros) {
    EXPECT_EQ(formatNumber(0.8f), "0.8");
    EXPECT_EQ(formatNumber(0.25f), "0.25");
    EXPECT_EQ(formatNumber(1.0f), "1");
    EXPECT_EQ(formatNumber(-0.0f), "0");
    EXPECT_EQ(formatNumber(0.071111f), "0.0711");
    EXPECT_EQ(formatNumber(-0.00001f), "0");
}

// The split (trace.h records, trace_explain.h words, trace_json.h writes): consumers switch on
// the step kind, so every method's steps carry the kinds its explanation promises.
TEST(TraceSplit, StepKindsNameWhatEachMethodExplains) {
    auto kinds = [](const Trace& tr) {
        std::vector<TraceStepKind> out;
        for (const TraceStep& s : explainTrace(tr)) out.push_back(s.kind);
        return out;
    };
    using K = TraceStepKind;
    EXPECT_EQ(kinds(exampleTrace(PCF_BILINEAR2X2)),
              (std::vector<K>{K::Project, K::TexelPosition, K::CompareTexels, K::Lerp, K::Result}));
    EXPECT_EQ(kinds(exampleTrace(PCF_HW2X2)),
              (std::vector<K>{K::Project, K::TexelPosition, K::HardwareTap, K::Lerp, K::Result}));
    EXPECT_EQ(kinds(exampleTrace(PCF_NEAREST)),
              (std::vector<K>{K::Project, K::ReadTexel, K::Result}));
    EXPECT_EQ(kinds(exampleTrace(PCF_GATHER)),
              (std::vector<K>{K::Project, K::WeightTable, K::Gather, K::Result}));
    EXPECT_EQ(kinds(exampleTrace(PCF_TENT)),
              (std::vector<K>{K::Project, K::TentTaps, K::TentHardwareTaps, K::Result}));
    for (const MethodInfo& m : allMethods()) {
        Trace tr = exampleTrace(m.id);
        ASSERT_FALSE(explainTrace(tr).empty()) << m.name;
        // The last step states the visibility: box2x2's average is its result.
        K last = m.id == PCF_BOX2X2 ? K::AverageBits : K::Result;
        EXPECT_EQ(explainTrace(tr).back().kind, last) << m.name;
        // Only the bilinear lookups lerp two rows of bits in a step of their own.
        bool lerps = m.id == PCF_BILINEAR2X2 || m.id == PCF_HW2X2;
        bool hasLerp = false;
        for (const TraceStep& s : explainTrace(tr)) {
            EXPECT_EQ(s.title, stepTitle(s.kind)) << m.name;
            hasLerp = hasLerp || s.kind == K::Lerp;
        }
        EXPECT_EQ(hasLerp, lerps) << m.name;
    }
}

TEST(TraceSplit, ExplainingTheRecordAgainGivesTheSameSteps) {
    for (const MethodInfo& m : allMethods()) {
        Trace tr = exampleTrace(m.id);
        std::vector<TraceStep> again = explainTrace(tr);
        ASSERT_EQ(again.size(), explainTrace(tr).size()) << m.name;
        for (size_t k = 0; k < again.size(); ++k) {
            EXPECT_EQ(again[k].kind, explainTrace(tr)[k].kind) << m.name;
            EXPECT_EQ(again[k].text, explainTrace(tr)[k].text) << m.name;
        }
    }
}

// The explanation prints the footprint the record holds: change the record and the words follow
// (nothing is derived a second time from uv).
TEST(TraceSplit, GatherWordsReadTheRecordedFootprint) {
    Trace tr = exampleTrace(PCF_GATHER);
    PcfFootprint kernel = pcfKernelFootprint(tr.uv, tr.map.size, tr.params.kernel);
    EXPECT_EQ(tr.footprint.origin, kernel.origin);
    EXPECT_EQ(tr.footprint.frac, kernel.frac);
    tr.footprint.origin = ivec2(40, 50);
    tr.footprint.frac = vec2(0.25f, 0.75f);
    std::string words = explainTrace(tr)[1].text;
    EXPECT_NE(words.find("= (40.25, 50.75), origin = floor(q) = (40, 50)"), std::string::npos)
        << words;
}

TEST(TraceSplit, JsonStepsCarryTheKindId) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    jsonlite::Value j = jsonlite::parse(traceToJson(tr));
    ASSERT_EQ(j["steps"].size(), explainTrace(tr).size());
    EXPECT_EQ(j["steps"][0]["kind"].string, "project");
    EXPECT_EQ(j["steps"][3]["kind"].string, "lerp");
    EXPECT_EQ(j["steps"][4]["kind"].string, "result");
    std::set<std::string> names;
    for (int k = 0; k <= static_cast<int>(TraceStepKind::Result); ++k) {
        names.insert(stepKindName(static_cast<TraceStepKind>(k)));
    }
    EXPECT_EQ(names.size(), static_cast<size_t>(TraceStepKind::Result) + 1);  // all distinct
}

}  // namespace
}  // namespace pcf
