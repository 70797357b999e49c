#include "measure/ground_truth.h"

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

#include "measure/ground_truth_area.h"
#include "measure/ground_truth_conics.h"
#include "measure/ground_truth_edges.h"
#include "measure/ground_truth_rays.h"
#include "measure/light_visibility.h"
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
constexpr double MIN_PIECE_PX = 1.0 / 4096.0;  // 1/16 px halved 8 times
constexpr int FIRST_PANELS = 4;

struct ScanlineWalk {
    const Scene& scene;
    const CameraRays& rays;
    glm::ivec2 pixel;
    int object;
    double y;  // window coordinate of the scanline
    Scanline line;

    SampleState state(double x) const {
        return sampleState(scene, rays.at({static_cast<double>(pixel.x) + x, y}), object);
    }
    void addPiece(double x0, double x1, SampleState st) {
        if (x1 > x0) add(st, x1 - x0);
    }
    void add(SampleState st, double length) {
        if (st == OFF) return;
        line.on += length;
        if (st == LIT) line.lit += length;
    }
    // The piece [lo, hi] holding a crossing, placed to within its length: half to each end's
    // state, its whole length to the error.
    void crossing(double lo, SampleState s0, double hi, SampleState s1) {
        double length = hi - lo;
        add(s0, 0.5 * length);
        add(s1, 0.5 * length);
        line.litErr += length;
        if (s0 == OFF || s1 == OFF) line.onErr += length;
    }
    // [x0, x1] whose ends differ: the crossing by bisection to 1/4096 px.
    void differentEnds(double x0, SampleState s0, double x1, SampleState s1) {
        double lo = x0;
        double hi = x1;
        while (hi - lo > MIN_PIECE_PX * (1.0 + 1e-9)) {
            double mid = 0.5 * (lo + hi);
            (state(mid) == s0 ? lo : hi) = mid;
        }
        addPiece(x0, lo, s0);
        crossing(lo, s0, hi, s1);
        addPiece(hi, x1, s1);
    }
    // WALK_POINTS + 1 points across the pixel; between two whose states differ the crossing is
    // found by bisection against the exact ray cast, to 1/4096 px.
    void walk() {
        double x0 = 0.0;
        SampleState s0 = state(0.0);
        for (int i = 1; i <= WALK_POINTS; ++i) {
            double x1 = static_cast<double>(i) / WALK_POINTS;
            SampleState s1 = state(x1);
            if (s0 == s1) {
                addPiece(x0, x1, s0);
            } else {
                differentEnds(x0, s0, x1, s1);
            }
            x0 = x1;
            s0 = s1;
        }
    }
};

Scanline scanline(const Scene& scene, const CameraRays& rays, glm::ivec2 pixel, int object,
                  double v) {
    ScanlineWalk w{scene, rays, pixel, object, static_cast<double>(pixel.y) + v, {}};
    w.walk();
    return w.line;
}

// The exact scanline (ground_truth_conics.h): cut at every root of the pixel's conics, each
// piece read at its middle with the ray caster.
Scanline exactScanline(const Scene& scene, const CameraRays& rays, glm::ivec2 pixel, int object,
                       const std::vector<Conic>& conics, double v) {
    thread_local std::vector<double> xs;
    xs.assign(1, 0.0);
    for (const Conic& q : conics) scanlineCuts(q, v, xs);
    xs.push_back(1.0);
    std::sort(xs.begin(), xs.end());
    double y = static_cast<double>(pixel.y) + v;
    Scanline line;
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        double length = xs[i + 1] - xs[i];
        if (!(length > 0.0)) continue;
        double x = static_cast<double>(pixel.x) + 0.5 * (xs[i] + xs[i + 1]);
        SampleState st = sampleState(scene, rays.at({x, y}), object);
        if (st != OFF) line.on += length;
        if (st == LIT) line.lit += length;
        if (length < UNSURE_PX) {
            line.litErr += length;
            line.onErr += length;
        }
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
    // the error bound of the fine one: 2 |fine - coarse| for lit plus the same for on; placed:
    // the share of the scanlines' own errors (their crossings' pieces).
    double lit, on, placed, err;
};

Panel makePanel(double a, double b, const Scanline& fa, const Scanline& fm, const Scanline& fb) {
    Panel p{a, b, fa, fm, fb, 0.0, 0.0, 0.0, 0.0};
    double h = b - a;
    auto coarse = [&](double Scanline::*f) { return 0.5 * h * (fa.*f + fb.*f); };
    auto fine = [&](double Scanline::*f) { return 0.25 * h * (fa.*f + 2.0 * fm.*f + fb.*f); };
    p.lit = fine(&Scanline::lit);
    p.on = fine(&Scanline::on);
    p.placed =
        0.25 * h * (fa.litErr + fa.onErr + 2.0 * (fm.litErr + fm.onErr) + fb.litErr + fb.onErr);
    p.err = 2.0 * std::fabs(p.lit - coarse(&Scanline::lit)) +
            2.0 * std::fabs(p.on - coarse(&Scanline::on));
    return p;
}

// The first panels' ends: 0, the breaks and 1 (rows closer than 1e-12 merged), the widest panel
// halved until there are FIRST_PANELS.
void firstPanelEnds(const std::vector<double>& breaks, std::vector<double>& ends) {
    ends.assign(1, 0.0);
    ends.insert(ends.end(), breaks.begin(), breaks.end());
    ends.push_back(1.0);
    std::sort(ends.begin(), ends.end());
    ends.erase(
        std::unique(ends.begin(), ends.end(), [](double a, double b) { return b - a <= 1e-12; }),
        ends.end());
    ends.back() = 1.0;
    while (ends.size() < FIRST_PANELS + 1) {
        size_t widest = 0;
        for (size_t k = 0; k + 1 < ends.size(); ++k) {
            if (ends[k + 1] - ends[k] > ends[widest + 1] - ends[widest]) widest = k;
        }
        ends.insert(ends.begin() + static_cast<long>(widest) + 1,
                    0.5 * (ends[widest] + ends[widest + 1]));
    }
}

// The pixel's integral over v of line(v) (a Scanline), the adaptive rule of ground_truth.h.
// `fallback`: the answer when no scanline meets the object.
// `breaks`: rows in (0,1) that must be panel ends (criticalRows), sorted or not.
template <typename LineFn>
Refined integrateRows(const LineFn& line, float fallback, float target,
                      const std::vector<double>& breaks) {
    thread_local std::vector<double> ends;
    firstPanelEnds(breaks, ends);
    // More rows that must be ends than the scanlines allow: no claim.
    if (2 * ends.size() - 1 > MAX_TRUTH_SCANLINES) return {fallback, 1.0f};
    // One list per thread, reused pixel after pixel (no allocation per refined pixel).
    thread_local std::vector<Panel> panels;
    panels.clear();
    Scanline low = line(ends[0]);
    for (size_t k = 0; k + 1 < ends.size(); ++k) {
        Scanline mid = line(0.5 * (ends[k] + ends[k + 1]));
        Scanline high = line(ends[k + 1]);
        panels.push_back(makePanel(ends[k], ends[k + 1], low, mid, high));
        low = high;
    }
    int scanlines = static_cast<int>(2 * panels.size() + 1);
    for (;;) {
        double lit = 0.0, on = 0.0, placed = 0.0, err = 0.0;
        size_t worst = 0;
        for (size_t k = 0; k < panels.size(); ++k) {
            lit += panels[k].lit;
            on += panels[k].on;
            placed += panels[k].placed;
            err += panels[k].err;
            if (panels[k].err > panels[worst].err) worst = k;
        }
        if (on <= 0.0) {
            // No scanline met the centre's object (a sliver of it around the centre): the
            // centre's own answer, with no claim.
            return {fallback, 1.0f};
        }
        // See ground_truth.h: |V - V*| <= (err_lit + err_on) / on, plus the placed pieces' share.
        double bound = (err + placed) / on;
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

// The hard light's pixel: exact scanlines between the conics' critical rows where the object's
// edges are conics (ground_truth_conics.h), else the walk.
Refined refinePixel(const Scene& scene, const CameraRays& rays, const EdgeConics& conics,
                    glm::ivec2 pixel, const FirstPass& first, float target) {
    thread_local std::vector<double> breaks;
    breaks.clear();
    if (!conics.exact(first.object)) {
        auto line = [&](double v) { return scanline(scene, rays, pixel, first.object, v); };
        return integrateRows(line, first.visibility, target, breaks);
    }
    thread_local std::vector<Conic> here;
    conics.pixelConics(first.object, true, rays.rawAt(glm::dvec2(pixel)), rays.stepX(),
                       rays.stepY(), here);
    criticalRows(here, breaks);
    auto line = [&](double v) { return exactScanline(scene, rays, pixel, first.object, here, v); };
    return integrateRows(line, first.visibility, target, breaks);
}

// The area light's pixel: a quarter of the target to each f and to each x-integral, the rest
// to the integral over v.
Refined refineAreaPixel(const Scene& scene, const CameraRays& rays, const EdgeConics& conics,
                        glm::ivec2 pixel, const FirstPass& first, float target, bool bySlices) {
    thread_local std::vector<Conic> outline;
    conics.pixelConics(first.object, false, rays.rawAt(glm::dvec2(pixel)), rays.stepX(),
                       rays.stepY(), outline);
    thread_local std::vector<double> breaks;
    breaks.clear();
    criticalRows(outline, breaks);
    AreaLine line{scene,         rays,          pixel,    first.object,
                  0.25 * target, 0.25 * target, &outline, bySlices};
    return integrateRows(line, first.visibility, target, breaks);
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

void checkTruthArguments(const Scene& scene, glm::ivec2 frameSize,
                         const GroundTruthOptions& options) {
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
    if (options.area) {
        if (!hasSize(scene.light)) {
            throw std::invalid_argument(
                "computeGroundTruth: the area-light truth needs a light with a size (a "
                "directional light's angular diameter, a spot light's radius)");
        }
        checkSpotDiskCasters(scene);
        if (!(options.targetBound > 0.0f)) {
            throw std::invalid_argument("computeGroundTruth: the area-light truth needs a bound");
        }
    }
}

// Pass 2 refines a pixel whose first pass was mixed, one of whose 8 neighbours hit the scene
// with another answer, or one the geometry cannot clear of edges (ground_truth_edges.h): an edge
// may cross it between the first pass's samples.
RayCone pixelCone(const CameraRays& rays, int x, int y) {
    glm::dvec2 corners[4] = {{x, y}, {x + 1, y}, {x, y + 1}, {x + 1, y + 1}};
    return coneThrough(
        rays.eyeD, [&](glm::dvec2 w) { return rays.dirAt(w); }, corners, 4);
}

// firstAt(x, y): the first pass of pixel (x, y), GL order, or nullptr outside the frame.
template <typename FirstAt>
bool needsRefinement(const FirstAt& firstAt, int x, int y, const CameraRays& rays,
                     const EdgeFinder& edges) {
    const FirstPass& p = *firstAt(x, y);
    if (p.cls == NO_HIT) return false;
    if (p.cls == MIXED) return true;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const FirstPass* n = firstAt(x + dx, y + dy);
            if (n && n->cls != NO_HIT && n->cls != p.cls) return true;
        }
    }
    return edges.litMayChange(pixelCone(rays, x, y), p.object);
}

struct PassTwo {
    float visibility;
    float bound;
    bool refined;
};

// Pass 2 on pixel (x, y) (GL order): the first pass's answer, refined where it may not hold.
// The area light's pixels skip the first pass's classes: its penumbra is not an edge the hard
// samples see.
template <typename FirstAt>
PassTwo passTwo(const Scene& scene, const CameraRays& rays, const EdgeFinder& edges,
                const EdgeConics& conics, const FirstAt& firstAt, int x, int y,
                const GroundTruthOptions& options) {
    const FirstPass& p = *firstAt(x, y);
    float target = options.targetBound;
    if (!(target > 0.0f)) return {p.visibility, p.cls == MIXED ? 1.0f : 0.0f, false};
    if (options.area) {
        if (p.cls == NO_HIT) return {1.0f, 0.0f, false};
        double tanHalf =
            std::tan(0.5 * glm::radians(static_cast<double>(scene.light.angularDiameterDeg)));
        int state = edges.areaState(pixelCone(rays, x, y), p.object, tanHalf);
        if (state >= 0) return {static_cast<float>(state), 0.0f, false};
        Refined r = refineAreaPixel(scene, rays, conics, {x, y}, p, target, options.areaBySlices);
        return {r.visibility, r.bound, true};
    }
    if (needsRefinement(firstAt, x, y, rays, edges)) {
        Refined r = refinePixel(scene, rays, conics, {x, y}, p, target);
        return {r.visibility, r.bound, true};
    }
    return {p.visibility, 0.0f, false};
}

// The truth before either pass: every pixel lit, no receiver, bound 0.
GroundTruth emptyGroundTruth(glm::ivec2 frameSize, const GroundTruthOptions& options) {
    GroundTruth truth;
    truth.size = frameSize;
    truth.spp = options.spp;
    truth.targetBound = options.targetBound;
    truth.visibility.assign(truth.pixelCount(), 1.0f);
    truth.receiver.assign(truth.pixelCount(), 0);
    truth.facesLight.assign(truth.pixelCount(), 0);
    truth.bound.assign(truth.pixelCount(), 0.0f);
    return truth;
}

}  // namespace

GroundTruth computeGroundTruth(const Scene& scene, glm::ivec2 frameSize,
                               const GroundTruthOptions& options) {
    checkTruthArguments(scene, frameSize, options);
    GroundTruth truth = emptyGroundTruth(frameSize, options);
    float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);
    CameraRays rays(scene.camera, frameSize);
    EdgeFinder edges(scene);
    EdgeConics conics(scene, rays.eyeD);
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

    auto firstAt = [&](int x, int y) -> const FirstPass* {
        if (x < 0 || y < 0 || x >= frameSize.x || y >= frameSize.y) return nullptr;
        return &first[static_cast<size_t>(y) * frameSize.x + x];
    };
    // Pass 2: refine where the pixel or a neighbour is not plainly the same uniform answer.
    std::atomic<int> refined{0};
    parallelRows(
        rows, threads,
        [&](int y) {
            int rowTopDown = frameSize.y - 1 - y;
            int refinedHere = 0;
            for (int x = 0; x < frameSize.x; ++x) {
                const FirstPass& p = first[static_cast<size_t>(y) * frameSize.x + x];
                size_t k = truth.index(x, rowTopDown);
                truth.receiver[k] = p.receiver ? 1 : 0;
                truth.facesLight[k] = p.facesLight ? 1 : 0;
                PassTwo r = passTwo(scene, rays, edges, conics, firstAt, x, y, options);
                truth.visibility[k] = r.visibility;
                truth.bound[k] = r.bound;
                refinedHere += r.refined ? 1 : 0;
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

GroundTruthPixel groundTruthAt(const Scene& scene, glm::ivec2 frameSize, glm::ivec2 pixelTopDown,
                               const GroundTruthOptions& options) {
    checkTruthArguments(scene, frameSize, options);
    if (pixelTopDown.x < 0 || pixelTopDown.y < 0 || pixelTopDown.x >= frameSize.x ||
        pixelTopDown.y >= frameSize.y) {
        throw std::invalid_argument("groundTruthAt: the pixel is outside the frame");
    }
    float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);
    CameraRays rays(scene.camera, frameSize);
    EdgeFinder edges(scene);
    EdgeConics conics(scene, rays.eyeD);
    glm::ivec2 pixel(pixelTopDown.x, frameSize.y - 1 - pixelTopDown.y);  // GL order
    // The first pass of the pixel and its 8 neighbours, as computeGroundTruth has them.
    std::array<FirstPass, 9> block;
    std::array<bool, 9> inside{};
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            glm::ivec2 q = pixel + glm::ivec2(dx, dy);
            int k = (dy + 1) * 3 + dx + 1;
            inside[k] = q.x >= 0 && q.y >= 0 && q.x < frameSize.x && q.y < frameSize.y;
            if (inside[k]) block[k] = firstPass(scene, rays, q, frameSize, aspect, options.spp);
        }
    }
    auto firstAt = [&](int x, int y) -> const FirstPass* {
        int k = (y - pixel.y + 1) * 3 + x - pixel.x + 1;
        return inside[k] ? &block[k] : nullptr;
    };
    const FirstPass& p = block[4];
    PassTwo r = passTwo(scene, rays, edges, conics, firstAt, pixel.x, pixel.y, options);
    return {r.visibility, r.bound, p.receiver, p.facesLight, r.refined};
}

}  // namespace pcf
