// timeGpu: a positive median from real repetitions, with the timer that is honest here.
#include "render/gpu_timer.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "render/shader_loader.h"

namespace pcf {
namespace {

TEST(GpuTimer, TimesRealWorkWithTheRightTimer) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    OffscreenTarget target = createOffscreenTarget(512, 512, {GL_RGBA8});
    // Enough per-pixel work that a repetition cannot take zero time on any machine.
    GlProgram program =
        buildProgram({{GL_VERTEX_SHADER,
                       {},
                       "",
                       {{"full.vert",
                         "const vec2 C[3] = vec2[3](vec2(-1, -1), vec2(3, -1), vec2(-1, 3));\n"
                         "void main() { gl_Position = vec4(C[gl_VertexID], 0, 1); }\n"}}},
                      {GL_FRAGMENT_SHADER,
                       {},
                       "",
                       {{"busy.frag",
                         "out vec4 c;\nvoid main() {\n  float s = 0.0;\n"
                         "  for (int k = 0; k < 64; ++k) s += sin(gl_FragCoord.x * float(k));\n"
                         "  c = vec4(s * 1e-3, 0, 0, 1);\n}\n"}}}});
    GlVertexArray vao = createVertexArray();
    int calls = 0;
    auto draw = [&] {
        ++calls;
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
        glViewport(0, 0, 512, 512);
        glUseProgram(program.id());
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    TimingResult r = timeGpu(draw, 5);
    EXPECT_EQ(calls, 6);  // one warm-up, five measured
    ASSERT_EQ(r.samplesMs.size(), 5u);
    for (double s : r.samplesMs) EXPECT_GT(s, 0.0);
    EXPECT_GT(r.medianMs, 0.0);
    // The median of five samples is the third smallest.
    std::vector<double> sorted = r.samplesMs;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(r.medianMs, sorted[2]);
    // llvmpipe runs the work at glFinish, so only the wall clock sees it (docs/measurement.md,
    // "Speed against accuracy: bench"); a GPU's own timer query is honest there. The renderers
    // this suite runs on, by name:
    const std::string& name = context->renderer();
    bool software = name.starts_with("llvmpipe") || name.starts_with("softpipe");
    EXPECT_EQ(r.timer, software ? "glFinish+steady_clock" : "GL_TIME_ELAPSED") << name;
    // The process's CPU time per repetition comes with the wall clock where the CPU does the
    // work, and only there.
    EXPECT_EQ(r.cpuSamplesMs.size(), software ? 5u : 0u) << name;
    for (double s : r.cpuSamplesMs) EXPECT_GT(s, 0.0);
    std::printf("%s: median %.3f ms over %zu (%s)\n", context->renderer().c_str(), r.medianMs,
                r.samplesMs.size(), r.timer.c_str());
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST(GpuTimer, CpuTimeCountsTheWorkNotTheWait) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    if (!isSoftwareRenderer(context->renderer())) {
        // A GPU's timer query measures there; there is no CPU side to count.
        EXPECT_TRUE(timeGpu([] {}, 2).cpuSamplesMs.empty());
        return;
    }
    // A repetition that sleeps 30 ms: the wall clock sees the 30 ms, the CPU clock does not.
    TimingResult idle =
        timeGpu([] { std::this_thread::sleep_for(std::chrono::milliseconds(30)); }, 3, false);
    ASSERT_EQ(idle.cpuSamplesMs.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_GE(idle.samplesMs[k], 29.0) << k;
        EXPECT_LT(idle.cpuSamplesMs[k], 10.0) << k;
    }
    // A repetition that computes for 30 ms of wall clock on this thread: its CPU time is there.
    TimingResult busy = timeGpu(
        [] {
            auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(30);
            volatile double sink = 0.0;
            while (std::chrono::steady_clock::now() < until) sink = sink + 1.0;
        },
        3, false);
    ASSERT_EQ(busy.cpuSamplesMs.size(), 3u);
    double cpu = medianOf(busy.cpuSamplesMs);
    EXPECT_GT(cpu, 3.0);  // a share of the 30 ms even on a machine shared with others
    EXPECT_LE(cpu, medianOf(busy.samplesMs) + 1.0);  // one thread: never more than the wall clock
}

TEST(GpuTimer, RecognisesSoftwareRenderers) {
    EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(isSoftwareRenderer("softpipe"));
    EXPECT_FALSE(isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
}

TEST(GpuTimer, MedianOfOddAndEvenCounts) {
    EXPECT_EQ(medianOf({3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(medianOf({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(medianOf({}), 0.0);
}

// Hyndman and Fan's definition 7 (NumPy's default): h = (n - 1) p, linear between order stats.
TEST(GpuTimer, QuartilesInterpolateBetweenOrderStatistics) {
    // Sorted 1..9: q1 at h = 2 -> 3, median 5, q3 at h = 6 -> 7.
    Quartiles q = quartilesOf({9, 1, 8, 2, 7, 3, 6, 4, 5});
    EXPECT_EQ(q.q1, 3.0);
    EXPECT_EQ(q.median, 5.0);
    EXPECT_EQ(q.q3, 7.0);
    EXPECT_EQ(q.iqr(), 4.0);
    // 1, 2, 4, 10: q1 at h = 0.75 -> 1.75, median 3, q3 at h = 2.25 -> 5.5 (numpy agrees).
    Quartiles even = quartilesOf({10, 4, 2, 1});
    EXPECT_DOUBLE_EQ(even.q1, 1.75);
    EXPECT_DOUBLE_EQ(even.median, medianOf({10, 4, 2, 1}));
    EXPECT_DOUBLE_EQ(even.q3, 5.5);
    EXPECT_EQ(quartilesOf({2.5}).iqr(), 0.0);
    EXPECT_EQ(quartilesOf({}).median, 0.0);
}

TEST(GpuTimer, RejectsZeroRepeats) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    EXPECT_THROW(timeGpu([] {}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace pcf
