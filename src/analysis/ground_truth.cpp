#include "analysis/ground_truth.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "scene/camera.h"
#include "scene/light.h"
#include "scene/raycast.h"

namespace pcf {

namespace {

// A 32-bit integer hash (the "lowbias32" finaliser of Chris Wellons' hash-prospector): good
// avalanche for neighbouring inputs, so the jitter of neighbouring cells is uncorrelated.
uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// 24 bits of the hash as a float in [0,1): exact in float, and never 1.
float unitFloat(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

// Camera rays from window coordinates in double: the basis of cameraRay (camera.h) computed once,
// and the sub-pixel position kept in double until the direction is normalised, so a bisection
// step of 1/4096 px is not lost to float rounding of the window position.
struct CameraRays {
    glm::dvec3 f, s, u;
    glm::vec3 eye;
    double tanHalfFov, aspect;
    glm::dvec2 size;
    CameraRays(const Camera& camera, glm::ivec2 frameSize)
        : eye(camera.eyeWs),
          tanHalfFov(std::tan(0.5 * glm::radians(static_cast<double>(camera.fovYDeg)))),
          aspect(static_cast<double>(frameSize.x) / static_cast<double>(frameSize.y)),
          size(frameSize) {
        f = glm::normalize(glm::dvec3(camera.targetWs) - glm::dvec3(camera.eyeWs));
        s = glm::normalize(glm::cross(f, glm::dvec3(camera.upWs)));
        u = glm::cross(s, f);
    }
    // window: GL window coordinates in pixels (y up), e.g. (x + 0.5, y + 0.5) for a centre.
    Ray at(glm::dvec2 window) const {
        glm::dvec2 ndc = window / size * 2.0 - 1.0;
        glm::dvec3 dir = f + s * (ndc.x * aspect * tanHalfFov) + u * (ndc.y * tanHalfFov);
        return Ray{eye, glm::vec3(glm::normalize(dir))};
    }
};

enum SampleState : uint8_t { UNLIT = 0, LIT = 1, OFF = 2 };  // OFF: not on the centre's object

SampleState sampleState(const Scene& scene, const Ray& ray, int object) {
    std::optional<Hit> hit = intersect(scene, ray);
    if (!hit || hit->object != object) return OFF;
    return litByLight(scene, *hit) ? LIT : UNLIT;
}

// What the first pass knows of a pixel.
enum PixelClass : uint8_t { ALL_UNLIT = 0, ALL_LIT = 1, MIXED = 2, NO_HIT = 3 };

struct FirstPass {
    float visibility;
    PixelClass cls;
    int object;  // the centre's object, -1 for none
    bool receiver;
    bool facesLight;
};

// The first pass over one pixel (GL window coordinates, y up): the centre's object, and the
// K x K stratified samples on it.
FirstPass firstPass(const Scene& scene, const CameraRays& rays, glm::ivec2 pixel, glm::ivec2 size,
                    float aspect, int spp) {
    Ray centreRay = cameraRay(scene.camera, pixelCentreNdc(pixel, size), aspect);
    std::optional<Hit> centre = intersect(scene, centreRay);
    if (!centre) return {1.0f, NO_HIT, -1, false, false};
    const SceneObject& object = scene.objects[static_cast<size_t>(centre->object)];
    LightSample toLight = towardLight(scene.light, centre->posWs);
    glm::vec3 facing = centre->frontFace ? centre->normalWs : -centre->normalWs;
    bool faces = toLight.insideCone && glm::dot(facing, toLight.dirWs) > 0.0f;

    int lit = 0;
    int unlit = 0;
    for (int j = 0; j < spp; ++j) {
        for (int i = 0; i < spp; ++i) {
            glm::dvec2 offset(stratifiedSample(pixel, i, j, spp));
            SampleState st =
                sampleState(scene, rays.at(glm::dvec2(pixel) + offset), centre->object);
            lit += st == LIT ? 1 : 0;
            unlit += st == UNLIT ? 1 : 0;
        }
    }
    FirstPass p{1.0f, ALL_LIT, centre->object, object.receivesShadow, faces};
    if (lit + unlit == 0) {
        bool centreLit = litByLight(scene, *centre);
        p.visibility = centreLit ? 1.0f : 0.0f;
        p.cls = centreLit ? ALL_LIT : ALL_UNLIT;
    } else {
        p.visibility = static_cast<float>(lit) / static_cast<float>(lit + unlit);
        p.cls = lit == 0 ? ALL_UNLIT : unlit == 0 ? ALL_LIT : MIXED;
    }
    return p;
}

// The refinement (see ground_truth.h): walk points per scanline, bisection steps per crossing.
constexpr int WALK_POINTS = 16;
constexpr int BISECTION_STEPS = 8;  // 1/16 px halved 8 times: 1/4096 px
constexpr double CROSSING_ERROR_PX = 1.0 / 4096.0;
constexpr int FIRST_PANELS = 4;

struct Scanline {
    double lit = 0.0;  // lit length on the centre's object, pixels
    double on = 0.0;   // length on the centre's object, pixels
    int crossings = 0;
};

Scanline scanline(const Scene& scene, const CameraRays& rays, glm::ivec2 pixel, int object,
                  double v) {
    double y = static_cast<double>(pixel.y) + v;
    auto state = [&](double x) {
        return sampleState(scene, rays.at({static_cast<double>(pixel.x) + x, y}), object);
    };
    Scanline line;
    auto add = [&](SampleState st, double length) {
        if (st == OFF) return;
        line.on += length;
        if (st == LIT) line.lit += length;
    };
    SampleState prev = state(0.0);
    for (int i = 1; i <= WALK_POINTS; ++i) {
        double x0 = static_cast<double>(i - 1) / WALK_POINTS;
        double x1 = static_cast<double>(i) / WALK_POINTS;
        SampleState next = state(x1);
        if (next == prev) {
            add(prev, x1 - x0);
        } else {
            // The crossing lies in (lo, hi): lo has prev's state, hi does not.
            double lo = x0;
            double hi = x1;
            for (int step = 0; step < BISECTION_STEPS; ++step) {
                double mid = 0.5 * (lo + hi);
                (state(mid) == prev ? lo : hi) = mid;
            }
            double cross = 0.5 * (lo + hi);
            add(prev, cross - x0);
            add(next, x1 - cross);
            ++line.crossings;
        }
        prev = next;
    }
    return line;
}

struct Refined {
    float visibility;
    float bound;
};

// One panel [a, b] of the adaptive trapezoid rule, with its scanlines at a, the middle and b.
struct Panel {
    double a, b;
    Scanline fa, fm, fb;
    // The panel's share of the integrals (coarse: trapezoid on a, b; fine: on a, m, b), and
    // the error bound of the fine one: 2 |fine - coarse| for lit plus the same for on.
    double lit, on, crossings, err;
};

Panel makePanel(double a, double b, const Scanline& fa, const Scanline& fm, const Scanline& fb) {
    Panel p{a, b, fa, fm, fb, 0.0, 0.0, 0.0, 0.0};
    double h = b - a;
    auto coarse = [&](double Scanline::*f) { return 0.5 * h * (fa.*f + fb.*f); };
    auto fine = [&](double Scanline::*f) { return 0.25 * h * (fa.*f + 2.0 * fm.*f + fb.*f); };
    p.lit = fine(&Scanline::lit);
    p.on = fine(&Scanline::on);
    p.crossings = 0.25 * h * (fa.crossings + 2.0 * fm.crossings + fb.crossings);
    p.err = 2.0 * std::fabs(p.lit - coarse(&Scanline::lit)) +
            2.0 * std::fabs(p.on - coarse(&Scanline::on));
    return p;
}

Refined refinePixel(const Scene& scene, const CameraRays& rays, glm::ivec2 pixel,
                    const FirstPass& first, float target) {
    auto line = [&](double v) { return scanline(scene, rays, pixel, first.object, v); };
    // FIRST_PANELS panels over v in [0,1]: 2 * FIRST_PANELS + 1 scanlines.
    std::array<Scanline, 2 * FIRST_PANELS + 1> start;
    for (int r = 0; r <= 2 * FIRST_PANELS; ++r) {
        start[r] = line(static_cast<double>(r) / (2 * FIRST_PANELS));
    }
    // One list per thread, reused pixel after pixel (no allocation per refined pixel).
    thread_local std::vector<Panel> panels;
    panels.clear();
    for (int k = 0; k < FIRST_PANELS; ++k) {
        panels.push_back(makePanel(static_cast<double>(k) / FIRST_PANELS,
                                   static_cast<double>(k + 1) / FIRST_PANELS, start[2 * k],
                                   start[2 * k + 1], start[2 * k + 2]));
    }
    int scanlines = 2 * FIRST_PANELS + 1;
    for (;;) {
        double lit = 0.0, on = 0.0, crossings = 0.0, err = 0.0;
        size_t worst = 0;
        for (size_t k = 0; k < panels.size(); ++k) {
            lit += panels[k].lit;
            on += panels[k].on;
            crossings += panels[k].crossings;
            err += panels[k].err;
            if (panels[k].err > panels[worst].err) worst = k;
        }
        if (on <= 0.0) {
            // No scanline met the centre's object (a sliver of it around the centre): the
            // centre's own answer, with no claim.
            return {first.visibility, 1.0f};
        }
        // See ground_truth.h: |V - V*| <= (err_lit + err_on) / on, plus the crossings' share.
        double bound = (err + 2.0 * crossings * CROSSING_ERROR_PX) / on;
        if (bound <= target || scanlines + 2 > MAX_TRUTH_SCANLINES) {
            return {static_cast<float>(lit / on), static_cast<float>(bound)};
        }
        // Split the panel with the largest error: two new scanlines, at its quarters.
        Panel p = panels[worst];
        double m = 0.5 * (p.a + p.b);
        Scanline q1 = line(0.5 * (p.a + m));
        Scanline q3 = line(0.5 * (m + p.b));
        scanlines += 2;
        panels[worst] = makePanel(p.a, m, p.fa, q1, p.fm);
        panels.push_back(makePanel(m, p.b, p.fm, q3, p.fb));
    }
}

// Runs rowWork(y) for y in [0, rows) on `threads` workers, rows handed out one at a time from a
// shared counter (rows near the horizon, mostly background, are cheap; rows full of receivers
// and edges are not, so a fixed split would idle). tick() is called on the calling thread about
// ten times a second with the rows done so far.
void parallelRows(int rows, int threads, const std::function<void(int)>& rowWork,
                  const std::function<void(int)>& tick) {
    std::atomic<int> nextRow{0};
    std::atomic<int> rowsDone{0};
    std::mutex mutex;
    std::condition_variable finished;
    auto work = [&] {
        for (int y; (y = nextRow.fetch_add(1)) < rows;) {
            rowWork(y);
            if (rowsDone.fetch_add(1) + 1 == rows) {
                std::lock_guard lock(mutex);
                finished.notify_all();
            }
        }
    };
    int threadCount = std::min(threads, rows);
    std::vector<std::thread> workers;
    workers.reserve(static_cast<size_t>(threadCount));
    for (int t = 0; t < threadCount; ++t) workers.emplace_back(work);
    {
        std::unique_lock lock(mutex);
        while (!finished.wait_for(lock, std::chrono::milliseconds(100),
                                  [&] { return rowsDone.load() == rows; })) {
            if (tick) tick(rowsDone.load());
        }
    }
    for (std::thread& w : workers) w.join();
}

}  // namespace

glm::vec2 stratifiedSample(glm::ivec2 pixel, int i, int j, int spp) {
    uint32_t key = hash32(static_cast<uint32_t>(pixel.x) * 0x9e3779b1u ^
                          hash32(static_cast<uint32_t>(pixel.y) + 0x632be5abu));
    key = hash32(key ^ static_cast<uint32_t>(j * spp + i) * 0x85ebca6bu);
    float jx = unitFloat(key);
    float jy = unitFloat(hash32(key ^ 0x27d4eb2fu));
    float k = static_cast<float>(spp);
    // min() keeps the offset inside the pixel when (i + jx) / K rounds up to 1 in float.
    return glm::min(glm::vec2((static_cast<float>(i) + jx) / k, (static_cast<float>(j) + jy) / k),
                    glm::vec2(0.99999994f));
}

int resolveThreadCount(int threads) {
    if (threads > 0) return threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

void checkTruthArguments(glm::ivec2 frameSize, const GroundTruthOptions& options) {
    if (frameSize.x < 1 || frameSize.y < 1) {
        throw std::invalid_argument("computeGroundTruth: frame size must be positive");
    }
    if (options.spp < 1 || options.spp > MAX_TRUTH_SPP) {
        throw std::invalid_argument("computeGroundTruth: spp " + std::to_string(options.spp) +
                                    " is out of range (1.." + std::to_string(MAX_TRUTH_SPP) + ")");
    }
    if (std::isnan(options.targetBound)) {
        throw std::invalid_argument("computeGroundTruth: the target bound is NaN");
    }
}

// Pass 2 refines a pixel whose first pass was mixed, or one of whose 8 neighbours hit the scene
// with another answer: the edge may cross it between the first pass's samples.
bool needsRefinement(const std::vector<FirstPass>& first, glm::ivec2 frameSize, int x, int y) {
    const FirstPass& p = first[static_cast<size_t>(y) * frameSize.x + x];
    if (p.cls == NO_HIT) return false;
    if (p.cls == MIXED) return true;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = x + dx;
            int ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= frameSize.x || ny >= frameSize.y) continue;
            PixelClass c = first[static_cast<size_t>(ny) * frameSize.x + nx].cls;
            if (c != NO_HIT && c != p.cls) return true;
        }
    }
    return false;
}

}  // namespace

GroundTruth computeGroundTruth(const Scene& scene, glm::ivec2 frameSize,
                               const GroundTruthOptions& options) {
    checkTruthArguments(frameSize, options);
    GroundTruth truth;
    truth.size = frameSize;
    truth.spp = options.spp;
    truth.targetBound = options.targetBound;
    truth.visibility.assign(truth.pixelCount(), 1.0f);
    truth.receiver.assign(truth.pixelCount(), 0);
    truth.facesLight.assign(truth.pixelCount(), 0);
    truth.bound.assign(truth.pixelCount(), 0.0f);
    float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);
    CameraRays rays(scene.camera, frameSize);
    int threads = resolveThreadCount(options.threads);
    const int rows = frameSize.y;
    // The first pass counts as half the work, the refinement as the other half.
    auto tickFirst = [&](int done) {
        if (options.progress) options.progress(done / 2, rows);
    };
    auto tickSecond = [&](int done) {
        if (options.progress) options.progress((rows + done) / 2, rows);
    };

    // Pass 1, per pixel in GL order (index y * W + x, y up).
    std::vector<FirstPass> first(truth.pixelCount());
    parallelRows(
        rows, threads,
        [&](int y) {
            for (int x = 0; x < frameSize.x; ++x) {
                first[static_cast<size_t>(y) * frameSize.x + x] =
                    firstPass(scene, rays, {x, y}, frameSize, aspect, options.spp);
            }
        },
        tickFirst);

    // Pass 2: refine where the pixel or a neighbour is not plainly the same uniform answer.
    const bool refine = options.targetBound > 0.0f;
    std::atomic<int> refined{0};
    parallelRows(
        rows, threads,
        [&](int y) {
            int rowTopDown = frameSize.y - 1 - y;
            int refinedHere = 0;
            for (int x = 0; x < frameSize.x; ++x) {
                const FirstPass& p = first[static_cast<size_t>(y) * frameSize.x + x];
                size_t k = truth.index(x, rowTopDown);
                truth.visibility[k] = p.visibility;
                truth.receiver[k] = p.receiver ? 1 : 0;
                truth.facesLight[k] = p.facesLight ? 1 : 0;
                if (!refine) {
                    truth.bound[k] = p.cls == MIXED ? 1.0f : 0.0f;
                } else if (needsRefinement(first, frameSize, x, y)) {
                    Refined r = refinePixel(scene, rays, {x, y}, p, options.targetBound);
                    truth.visibility[k] = r.visibility;
                    truth.bound[k] = r.bound;
                    ++refinedHere;
                }
            }
            refined.fetch_add(refinedHere);
        },
        tickSecond);
    truth.refinedPixels = refined.load();
    truth.maxBound =
        truth.bound.empty() ? 0.0f : *std::max_element(truth.bound.begin(), truth.bound.end());
    if (options.progress) options.progress(rows, rows);
    return truth;
}

}  // namespace pcf
