#include "render/gpu_timer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>

#include "render/gl_objects.h"

namespace pcf {

bool isSoftwareRenderer(std::string_view renderer) {
    return renderer.find("llvmpipe") != std::string_view::npos ||
           renderer.find("softpipe") != std::string_view::npos;
}

double medianOf(std::vector<double> samples) {
    if (samples.empty()) return 0.0;
    std::sort(samples.begin(), samples.end());
    size_t mid = samples.size() / 2;
    if (samples.size() % 2 == 1) return samples[mid];
    return 0.5 * (samples[mid - 1] + samples[mid]);
}

Quartiles quartilesOf(std::vector<double> samples) {
    Quartiles q;
    if (samples.empty()) return q;
    std::sort(samples.begin(), samples.end());
    auto at = [&](double p) {
        double h = static_cast<double>(samples.size() - 1) * p;
        size_t lo = static_cast<size_t>(h);
        size_t hi = std::min(lo + 1, samples.size() - 1);
        return samples[lo] + (h - static_cast<double>(lo)) * (samples[hi] - samples[lo]);
    };
    q.q1 = at(0.25);
    q.median = at(0.5);
    q.q3 = at(0.75);
    return q;
}

namespace {

// CPU time of the whole process (every thread), ms.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace

TimingResult timeGpu(const std::function<void()>& draw, int repeats, bool warmUp) {
    if (repeats < 1) {
        throw std::invalid_argument("timeGpu: repeats must be at least 1, got " +
                                    std::to_string(repeats));
    }
    const GLubyte* rendererString = glGetString(GL_RENDERER);
    std::string_view renderer =
        rendererString != nullptr ? reinterpret_cast<const char*>(rendererString) : "";
    TimingResult result;
    if (warmUp) draw();
    glFinish();
    if (isSoftwareRenderer(renderer)) {
        result.timer = TIMER_WALL_CLOCK;
        for (int k = 0; k < repeats; ++k) {
            auto start = std::chrono::steady_clock::now();
            double cpuStart = processCpuMs();
            draw();
            glFinish();
            double cpuEnd = processCpuMs();
            auto end = std::chrono::steady_clock::now();
            result.samplesMs.push_back(
                std::chrono::duration<double, std::milli>(end - start).count());
            result.cpuSamplesMs.push_back(cpuEnd - cpuStart);
        }
    } else {
        result.timer = TIMER_GPU_QUERY;
        // One query per repetition, read after the last: waiting on each would drain the
        // pipeline between repetitions, which real frames do not do.
        std::vector<GlQuery> queries;
        for (int k = 0; k < repeats; ++k) {
            queries.push_back(createQuery(GL_TIME_ELAPSED));
            glBeginQuery(GL_TIME_ELAPSED, queries.back().id());
            draw();
            glEndQuery(GL_TIME_ELAPSED);
        }
        for (const GlQuery& q : queries) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(q.id(), GL_QUERY_RESULT, &ns);
            result.samplesMs.push_back(static_cast<double>(ns) * 1e-6);
        }
    }
    result.medianMs = medianOf(result.samplesMs);
    return result;
}

}  // namespace pcf
