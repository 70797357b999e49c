// The conformance envelope (measure/conformance.h) and `pcfscope verify`, issue 10.
#include "measure/conformance.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/trace_json.h"
#include "render/image_io.h"
#include "run_command.h"

namespace pcf {
namespace {

using testutil::makeTempDir;
using testutil::runPcfscope;

ShadowMap randomMap(int w, int h, uint32_t seed, int bits) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ShadowMap map(w, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) map.setDepth(i, j, u(rng) < 0.5f ? 0.3f : 0.3f + u(rng));
    }
    map.setTexelKind(bits == 16 ? TexelKind::D16 : bits == 24 ? TexelKind::D24 : TexelKind::D32F);
    return map;
}

std::vector<PcfParams> cases() {
    std::vector<PcfParams> all;
    for (const MethodInfo& m : allMethods())
        all.push_back(makeParams(m.id, m.id == PCF_TENT ? 5 : 3));
    PcfParams g = makeParams(PCF_GATHER, 4);
    g.weights = PCF_WEIGHTS_GAUSSIAN;
    all.push_back(g);
    return all;
}

// Both models pcfscope knows (exact = llvmpipe, hw8 = NVIDIA/AMD) are conformant: the envelope
// holds them, for every method, format and ref, also refs outside [0,1].
TEST(Conformance, EnvelopeHoldsTheExactAndTheHw8Results) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-0.05f, 1.05f);
    std::uniform_real_distribution<float> r(-0.2f, 1.2f);
    for (int bits : {0, 16, 24}) {
        ShadowMap map = randomMap(37, 23, 5, bits);
        for (PcfParams prm : cases()) {
            for (int k = 0; k < 1500; ++k) {
                vec2 uv(u(rng), u(rng));
                float ref = r(rng);
                VisibilityEnvelope env = visibilityEnvelope(map, uv, ref, prm);
                ASSERT_LE(env.lo, env.hi);
                float exact = filterVisibility(map, uv, ref, prm);
                PcfParams hw8 = prm;
                hw8.precision = PCF_PRECISION_HW8;
                float quantised = filterVisibility(map, uv, ref, hw8);
                EXPECT_TRUE(env.contains(exact)) << methodInfo(prm.method).name << " " << exact
                                                 << " [" << env.lo << ", " << env.hi << "]";
                EXPECT_TRUE(env.contains(quantised)) << methodInfo(prm.method).name;
            }
        }
    }
}

// The envelope is tight where nothing is uncertain and opens only where a texture unit has
// freedom: near an edge, a hardware tap may return anything within 2^-subTexelBits texel of
// its position, a texelFetch method nothing but its own result.
TEST(Conformance, EnvelopeOpensOnlyWhereTheTextureUnitHasFreedom) {
    ShadowMap map(8, 8, 0.9f);
    for (int j = 0; j < 8; ++j) {
        for (int i = 4; i < 8; ++i) map.setDepth(i, j, 0.1f);
    }
    // Far from the edge: one answer.
    VisibilityEnvelope flat =
        visibilityEnvelope(map, vec2(0.1f, 0.5f), 0.5f, makeParams(PCF_HW2X2));
    EXPECT_EQ(flat.lo, 1.0f);
    EXPECT_EQ(flat.hi, 1.0f);
    // On the edge's lerp (p.x = 3.3): 0.7 exactly, +- 1/16 + 1/256 with Vulkan's 4 bits.
    vec2 uv((3.3f + 0.5f) / 8.0f, 0.5f);
    VisibilityEnvelope hw = visibilityEnvelope(map, uv, 0.5f, makeParams(PCF_HW2X2));
    EXPECT_NEAR(hw.lo, 0.7f - 1.0f / 16 - 1.0f / 256, 1e-5f);
    EXPECT_NEAR(hw.hi, 0.7f + 1.0f / 16 + 1.0f / 256, 1e-5f);
    ConformancePrecision eight{8, 8, 0};
    VisibilityEnvelope hw8 = visibilityEnvelope(map, uv, 0.5f, makeParams(PCF_HW2X2), eight);
    EXPECT_LT(hw8.hi - hw8.lo, hw.hi - hw.lo);
    VisibilityEnvelope fetch = visibilityEnvelope(map, uv, 0.5f, makeParams(PCF_BILINEAR2X2));
    EXPECT_NEAR(fetch.lo, 0.7f, 1e-6f);
    EXPECT_NEAR(fetch.hi, 0.7f, 1e-6f);
    EXPECT_FALSE(hw.contains(0.6f));
    // A comparison within the reference tolerance may go either way.
    VisibilityEnvelope tie =
        visibilityEnvelope(map, vec2(0.1f, 0.5f), 0.9f + 1e-8f, makeParams(PCF_NEAREST));
    EXPECT_EQ(tie.lo, 0.0f);
    EXPECT_EQ(tie.hi, 1.0f);
}

// Under every bias mode the envelope holds the kernel's own result (each tap with its plane's
// ref, soft fractions, the interpolated comparison), and the receiver plane's per-tap refs move
// it: a steep plane and a flat one give different envelopes for the same lookup.
TEST(Conformance, EnvelopeUnderEveryBiasModeHoldsTheKernelsResult) {
    std::mt19937 rng(33);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_real_distribution<float> slope(-2.0f, 2.0f);
    for (int bits : {0, 16, 24}) {
        ShadowMap map = randomMap(29, 31, 8, bits);
        for (int mode = 0; mode < PCF_BIAS_COUNT; ++mode) {
            for (PcfParams prm : cases()) {
                if (validateBias(mode, prm.method)) continue;
                for (int k = 0; k < 300; ++k) {
                    vec2 uv(u(rng), u(rng));
                    float ref = 0.25f + u(rng);
                    PcfBias b(mode, vec2(slope(rng), slope(rng)), 40.0f, PCF_DZDUV_UNCLAMPED);
                    VisibilityEnvelope env = visibilityEnvelope(map, uv, ref, prm, b);
                    float v = filterVisibility(map, uv, ref, prm, b);
                    EXPECT_TRUE(env.contains(v))
                        << biasName(mode) << " " << methodInfo(prm.method).name << " " << v << " ["
                        << env.lo << ", " << env.hi << "] bits " << bits;
                }
            }
        }
    }
    // A receiver plane rising by 0.5 per uv unit across a step edge: the taps right of the
    // lookup compare against a deeper ref than the lookup's own.
    ShadowMap edge(8, 8, 0.51f);
    for (int j = 0; j < 8; ++j) {
        for (int i = 4; i < 8; ++i) edge.setDepth(i, j, 0.53f);
    }
    vec2 uv((3.5f + 0.5f) / 8.0f, 0.5f);
    PcfParams prm = makeParams(PCF_BILINEAR2X2);
    VisibilityEnvelope flat = visibilityEnvelope(
        edge, uv, 0.5f, prm, PcfBias(PCF_BIAS_RECEIVER_PLANE, vec2(0.0f), 0, PCF_DZDUV_UNCLAMPED));
    VisibilityEnvelope steep = visibilityEnvelope(
        edge, uv, 0.5f, prm,
        PcfBias(PCF_BIAS_RECEIVER_PLANE, vec2(0.5f, 0.0f), 0, PCF_DZDUV_UNCLAMPED));
    EXPECT_NEAR(flat.lo, 1.0f, 1e-6f);   // ref 0.5 < every depth
    EXPECT_NEAR(steep.hi, 0.5f, 1e-6f);  // the right column's ref 0.5 + 0.5/8 > 0.53
}

// `render --raw` records the bias mode, and verify repeats each pixel under it: a receiver-plane
// frame (every tap its own ref, from dzduv.exr) passes in every depth format.
TEST(Conformance, VerifyRepeatsTheReceiverPlaneOfEveryPixel) {
    std::filesystem::path dir = makeTempDir("verify-plane");
    for (const char* format : {"16", "24", "32f"}) {
        std::string raw = (dir / format).string();
        auto r = runPcfscope(
            "render --scene grazing --method pcf-gather --kernel 3 --bias receiver-plane "
            "--map-size 128 --depth-format " +
            std::string(format) + " --size 160x90 --raw " + raw);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        auto v = runPcfscope("verify " + raw);
        EXPECT_EQ(v.exitCode, 0) << format << ": " << v.out << v.err;
        EXPECT_NE(v.out.find("bias receiver-plane"), std::string::npos) << v.out;
        EXPECT_NE(v.out.find("(100.0000 %)"), std::string::npos) << format << ": " << v.out;
    }
    std::filesystem::remove_all(dir);
}

TEST(Conformance, VerifyPassesOnTheRendererAndCatchesAWrongPixel) {
    std::filesystem::path dir = makeTempDir("verify");
    std::string raw = (dir / "raw").string();
    auto r = runPcfscope(
        "render --scene sphere-over-plane --method tent --kernel 5 --map-size 100 "
        "--depth-format 24 --size 200x120 --raw " +
        raw);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto v = runPcfscope("verify " + raw);
    EXPECT_EQ(v.exitCode, 0) << v.out << v.err;
    EXPECT_NE(v.out.find("(100.0000 %)"), std::string::npos) << v.out;

    // One pixel moved well outside what any texture unit may return.
    FloatImage ls = readFloatImage(raw + "/lightspace.exr");
    FloatImage vis = readFloatImage(raw + "/visibility.exr");
    size_t pick = 0;
    for (size_t k = 0; k < vis.data.size(); ++k) {
        if (ls.data[4 * k + 3] == 1.0f && vis.data[k] > 0.99f) {
            pick = k;
            break;
        }
    }
    vis.data[pick] = 0.25f;
    writeExr(raw + "/visibility.exr", vis.width, vis.height, 1, vis.data, {"Y"});
    auto bad = runPcfscope("verify " + raw);
    EXPECT_EQ(bad.exitCode, 1) << bad.out << bad.err;
    std::string where = "pixel (" + std::to_string(pick % vis.width) + ", " +
                        std::to_string(pick / vis.width) + ")";
    EXPECT_NE(bad.out.find("worst outlier: " + where), std::string::npos) << bad.out;

    auto missing = runPcfscope("verify " + (dir / "nothing").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(missing.err), 1) << missing.err;
    std::filesystem::remove_all(dir);
}

// `render --raw` + `verify` for every method that reads moments (issue 33): the moments map read
// back is what verify runs the CPU kernel on, each pixel within the moment methods' tolerance;
// 32f and 16f moments, box and Gaussian blurs.
TEST(Conformance, VerifyPassesForEveryMomentMethod) {
    std::filesystem::path dir = makeTempDir("verify-moments");
    int methods = 0;
    for (const MethodInfo& m : allMethods()) {
        if (!readsMoments(m.id)) continue;
        ++methods;
        for (std::string options :
             {std::string(" --kernel 3"),
              std::string(" --kernel 5 --weights gaussian --moment-format 16f")}) {
            std::string raw =
                (dir / (std::string(m.name) + std::to_string(options.size()))).string();
            auto r = runPcfscope("render --scene box-on-plane --method " + std::string(m.name) +
                                 options + " --map-size 96 --size 160x96 --raw " + raw);
            ASSERT_EQ(r.exitCode, 0) << m.name << options << ": " << r.err;
            auto v = runPcfscope("verify " + raw);
            EXPECT_EQ(v.exitCode, 0) << m.name << options << ": " << v.out << v.err;
            EXPECT_NE(v.out.find("(100.0000 %)"), std::string::npos) << m.name << options << v.out;
        }
    }
    EXPECT_EQ(methods, 5);
    std::filesystem::remove_all(dir);
}

// verify recomputes every pixel's lookup (u, v, depth before bias, ref) from its position and
// normal under the bias render.json names, every mode exactly: each mode's render passes, and a
// render.json that says another amount or another mode is refused (a slope_bias 50 times the
// rendered one, or slope for a constant-bias render, passed as "as rendered" when slope was
// checked as a range).
TEST(Conformance, VerifyRecomputesEveryBiasModeAndRefusesAnotherLabel) {
    std::filesystem::path dir = makeTempDir("verify-bias");
    auto rendered = [&](const std::string& name, const std::string& args) {
        std::string raw = (dir / name).string();
        auto r = runPcfscope("render " + args + " --map-size 128 --size 160x90 --raw " + raw);
        EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
        return raw;
    };
    auto relabelled = [](const std::string& raw, const std::string& key, const Json& value) {
        std::string path = raw + "/render.json";
        Json j = Json::parse(testutil::readAll(path));
        j[key] = value;
        std::ofstream(path) << j.dump();
        return j;
    };
    const std::pair<std::string, std::string> modes[] = {
        {"none", "--scene grazing --bias none"},
        {"constant", "--scene grazing --bias constant"},
        {"slope", "--scene grazing --bias slope --slope-bias 0.001"},
        {"normal", "--scene post-under-spot --bias normal"},
        {"receiver-plane", "--scene grazing --bias receiver-plane"},
        {"soft", "--scene grazing --method pcf-gather --bias soft"},
        {"interpolated", "--scene grazing --method nearest --bias interpolated"},
        {"spot-slope", "--scene post-under-spot --method pcss --bias slope"}};
    for (const auto& [name, args] : modes) {
        auto v = runPcfscope("verify " + rendered(name, args));
        EXPECT_EQ(v.exitCode, 0) << name << ": " << v.out << v.err;
        EXPECT_NE(v.out.find("recomputed from position, normal and bias: as rendered"),
                  std::string::npos)
            << name << ": " << v.out;
    }
    auto refused = [&](const std::string& raw, const std::string& why) {
        auto v = runPcfscope("verify " + raw);
        EXPECT_EQ(v.exitCode, 2) << why << ": " << v.out << v.err;
        EXPECT_EQ(testutil::lineCount(v.err), 1) << v.err;
        EXPECT_NE(v.err.find("render.json does not describe these images: pixel ("),
                  std::string::npos)
            << why << ": " << v.err;
        return v.err;
    };
    Json slope = Json::parse(testutil::readAll(dir / "slope" / "render.json"));
    relabelled((dir / "slope").string(), "slope_bias", slope["slope_bias"].get<double>() * 50);
    EXPECT_NE(refused((dir / "slope").string(), "slope_bias x 50").find("under bias slope"),
              std::string::npos);
    relabelled((dir / "slope").string(), "slope_bias", slope["slope_bias"]);
    relabelled((dir / "slope").string(), "bias", "constant");
    refused((dir / "slope").string(), "slope labelled constant");
    relabelled((dir / "constant").string(), "bias", "slope");
    EXPECT_NE(refused((dir / "constant").string(), "constant labelled slope").find("has ref"),
              std::string::npos);
    Json normal = Json::parse(testutil::readAll(dir / "normal" / "render.json"));
    relabelled((dir / "normal").string(), "normal_offset",
               normal["normal_offset"].get<double>() * 2);
    refused((dir / "normal").string(), "normal_offset x 2");
    relabelled((dir / "normal").string(), "normal_offset", normal["normal_offset"]);
    relabelled((dir / "normal").string(), "bias", "constant");
    refused((dir / "normal").string(), "normal labelled constant");

    // A folder without the normals (render --raw before it wrote them): ref from the depth
    // before bias where the mode needs nothing else; slope, which needs each pixel's angle, is
    // refused in one line.
    std::filesystem::remove(dir / "receiver-plane" / "normals.exr");
    auto plane = runPcfscope("verify " + (dir / "receiver-plane").string());
    EXPECT_EQ(plane.exitCode, 0) << plane.err;
    EXPECT_NE(plane.out.find("from depth and bias (the folder has no normals"), std::string::npos)
        << plane.out;
    relabelled((dir / "slope").string(), "bias", "slope");
    std::filesystem::remove(dir / "slope" / "normals.exr");
    auto noNormals = runPcfscope("verify " + (dir / "slope").string());
    EXPECT_EQ(noNormals.exitCode, 2);
    EXPECT_NE(noNormals.err.find("bias slope depends on each pixel's angle to the light"),
              std::string::npos)
        << noNormals.err;
    std::filesystem::remove_all(dir);
}

// Which render.json keys a folder may lack is the parameter table's column (rawJsonMayLack):
// each such key left out is its default; any other key left out is refused.
TEST(Conformance, VerifyTakesTheKeysAFolderMayLackFromTheTable) {
    std::filesystem::path dir = makeTempDir("verify-keys");
    std::string raw = (dir / "raw").string();
    auto r = runPcfscope(
        "render --scene grazing --bias constant --map-size 64 --size 96x54 --raw " + raw);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string path = raw + "/render.json";
    const Json full = Json::parse(testutil::readAll(path));
    int mayLack = 0;
    for (const ParamInfo& p : allParams()) {
        if (!p.rawJson) continue;
        Json j = full;
        j.erase(std::string(p.key));
        std::ofstream(path) << j.dump();
        auto v = runPcfscope("verify " + raw);
        if (p.rawJsonMayLack) {
            ++mayLack;
            EXPECT_EQ(v.exitCode, 0) << p.key << ": " << v.err;
        } else {
            EXPECT_EQ(v.exitCode, 2) << p.key;
            EXPECT_NE(v.err.find("render.json has no \"" + std::string(p.key) + "\""),
                      std::string::npos)
                << v.err;
        }
    }
    EXPECT_GE(mayLack, 6);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pcf
