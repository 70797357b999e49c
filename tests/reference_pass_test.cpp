// The reference passes (shaders/reference/, GpuLookup::drawReference) are real implementations
// of their methods: over the same random lookups on the same random map, each gives what the
// shared kernel's lookup pass gives, to float rounding. They are what bench --reference times
// the kernel against, so a reference that did less work than its method would flatter nothing
// and hide the kernel's overhead; this test is what keeps them honest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kernel/methods.h"
#include "kernel/moments.h"
#include "kernel/pcf.h"
#include "measure/conformance.h"
#include "random_map.h"
#include "render/gl_context.h"
#include "render/gpu_lookup.h"
#include "render/shader_loader.h"

namespace pcf {
namespace {

// Both passes run on the same GL; they differ only in the order of float operations (a sum
// divided at the end against weights scaled first), so 1e-5, the parity tests' tolerance. The
// moment methods' bound and reconstruction amplify that rounding (a variance that is a small
// difference of large moments; MSM's Cholesky solve), so they are held to MOMENT_TOLERANCE.
constexpr float REFERENCE_TOLERANCE = 1e-5f;

class ReferencePass : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> ReferencePass::sContext;

std::vector<PcfParams> referenceCases() {
    std::vector<PcfParams> cases;
    for (const MethodInfo& m : allMethods()) {
        if (m.id == PCF_TENT) {
            for (int n : {3, 5, 7}) cases.push_back(makeParams(m.id, n));
        } else if (m.reconstructs) {
            // MSM's Hankel matrix of a footprint with four depths or fewer (N = 1: the four texels
            // of the bilinear read) is singular but for the moment bias; at the default 3e-5 the
            // float solve's answer is decided by rounding (0.27 apart between two orders of the
            // same operations), so here the bias is 1e-3, where it is not.
            for (int n : {1, 2, 3, 4, 5, 8}) {
                PcfParams p = makeParams(m.id, n);
                p.momentBias = 1.0e-3f;
                cases.push_back(p);
            }
        } else if (m.usesKernel) {
            for (int n : {1, 2, 3, 4, 5, 8}) cases.push_back(makeParams(m.id, n));
        } else if (m.id == PCF_POISSON) {
            cases.push_back(makeParams(m.id, 1, 1.0f));
            cases.push_back(makeParams(m.id, 1, 2.5f));
        } else if (m.id == PCF_PCSS) {
            for (float scale : {0.0f, 30.0f}) {
                PcfParams p = makeParams(m.id, 1);
                p.penumbraScale = scale;
                cases.push_back(p);
            }
        } else {
            cases.push_back(makeParams(m.id, 1));
        }
    }
    return cases;
}

TEST_F(ReferencePass, EveryMethodGivesTheKernelsVisibility) {
    GpuLookup gpu;
    const glm::ivec2 size(61, 47);
    ShadowMap map = randomMap(size.x, size.y, 23);
    const int width = 64;
    std::vector<glm::vec4> lookups = randomLookups(size, width, 48, 24);
    gpu.setLookups(lookups, width);
    for (const PcfParams& prm : referenceCases()) {
        // A moment method reads the moments map the shared kernel's moments pass makes of it.
        gpu.setMap(mapForMethod(map, prm));
        std::string what = std::string(methodInfo(prm.method).name) +
                           " N=" + std::to_string(prm.kernel) + " R=" + std::to_string(prm.radius);
        gpu.draw(prm, false);
        std::vector<float> kernel = gpu.read();
        gpu.drawReference(prm);
        std::vector<float> reference = gpu.read();
        ASSERT_EQ(reference.size(), kernel.size());
        float worst = 0.0f;
        int partial = 0;  // strictly between 0 and 1: the filter's weights at work
        for (size_t k = 0; k < kernel.size(); ++k) {
            worst = std::max(worst, std::fabs(reference[k] - kernel[k]));
            partial += reference[k] > 0.0f && reference[k] < 1.0f;
        }
        EXPECT_LE(worst, readsMoments(prm.method) ? MOMENT_TOLERANCE : REFERENCE_TOLERANCE) << what;
        // Random depths against random refs: every method but nearest mixes bits in most
        // lookups, so a pass that wrote one constant or only hard bits fails here. A moment
        // method's bound is 1 wherever the receiver is at or before the mean (about half the
        // random refs), and evsm2's warp exp(40 (2z - 1)) leaves few values between 0 and 1
        // (177 of 3072 at N = 8): a twentieth.
        int least = static_cast<int>(kernel.size()) / (readsMoments(prm.method) ? 20 : 2);
        if (prm.method != PCF_NEAREST) {
            EXPECT_GT(partial, least) << what;
        }
    }
}

// Each method's entry in the method table names its reference pass (kernel/methods.h
// referencePass): a file embedded at build time that compiles for every kernel size the method
// takes, and draws.
TEST_F(ReferencePass, EveryMethodsEntryNamesAPassThatBuilds) {
    GpuLookup gpu;
    ShadowMap map = randomMap(9, 7, 5);
    gpu.setMap(map);
    gpu.setLookups(randomLookups(glm::ivec2(9, 7), 8, 2, 6), 8);
    for (const MethodInfo& m : allMethods()) {
        ASSERT_TRUE(m.referencePass.starts_with("reference/")) << m.name;
        EXPECT_NO_THROW(embeddedShader(m.referencePass)) << m.name;
        for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
            if (!kernelFits(m.id, n) || (!m.referenceTakesKernel && n > MIN_KERNEL)) continue;
            EXPECT_NO_THROW(gpu.drawReference(makeParams(m.id, n))) << m.name << " N=" << n;
            EXPECT_EQ(gpu.read().size(), 16u) << m.name;
        }
    }
}

}  // namespace
}  // namespace pcf
