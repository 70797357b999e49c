#include "measure/failure_measures.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "scene/camera.h"
#include "scene/light.h"

namespace pcf {

namespace {

// Rows [0, rows) split over the worker threads, a row at a time from a shared counter.
template <class F>
void parallelRows(int rows, int threads, F&& work) {
    std::atomic<int> next{0};
    auto loop = [&] {
        for (int y; (y = next.fetch_add(1)) < rows;) work(y);
    };
    int n = std::max(1, std::min(resolveThreadCount(threads), rows));
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(loop);
    loop();
    for (std::thread& t : pool) t.join();
}

// Whether every footprint point of the hit is lit (wantLit) or shadowed (!wantLit).
bool footprintIs(const Scene& scene, const Hit& h, const glm::mat4& shadowClip, int mapSize,
                 float reach, bool wantLit) {
    std::vector<glm::vec3> points =
        footprintPoints(scene, shadowClip, mapSize, h.posWs, h.frontFace ? h.normalWs : -h.normalWs,
                        reach, FOOTPRINT_GRID);
    if (points.empty()) return false;  // edge-on to the light: no footprint to speak of
    for (glm::vec3 p : points) {
        Hit moved = h;
        moved.posWs = p;
        if (litByLight(scene, moved) != wantLit) return false;
    }
    return true;
}

}  // namespace

std::vector<std::optional<Hit>> centreHits(const Scene& scene, glm::ivec2 size, int threads) {
    std::vector<std::optional<Hit>> hits(static_cast<size_t>(size.x) * size.y);
    float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    parallelRows(size.y, threads, [&](int y) {
        int rowTopDown = size.y - 1 - y;
        for (int x = 0; x < size.x; ++x) {
            Ray ray = cameraRay(scene.camera, pixelCentreNdc({x, y}, size), aspect);
            hits[static_cast<size_t>(rowTopDown) * size.x + x] = intersect(scene, ray);
        }
    });
    return hits;
}

std::vector<uint8_t> cleanPixelMask(const Scene& scene, const GroundTruth& truth,
                                    const ErrorRegions& regions,
                                    const std::vector<std::optional<Hit>>& hits,
                                    const glm::mat4& shadowClip, int mapSize, float reachTexels,
                                    bool wantLit, int threads, int stride) {
    stride = std::max(1, stride);
    std::vector<uint8_t> mask(truth.pixelCount(), 0);
    parallelRows(truth.size.y, threads, [&](int row) {
        if (row % stride != 0) return;
        for (int x = 0; x < truth.size.x; x += stride) {
            size_t k = truth.index(x, row);
            if (!regions.compared[k] || !hits[k]) continue;
            float v = truth.visibility[k];
            if (wantLit ? v < 1.0f : v > 0.0f) continue;
            mask[k] = footprintIs(scene, *hits[k], shadowClip, mapSize, reachTexels, wantLit);
        }
    });
    return mask;
}

FailureRate falseShadow(const std::vector<float>& visibility,
                        const std::vector<uint8_t>& cleanLit) {
    FailureRate r;
    double dark = 0.0;
    int bad = 0;
    for (size_t k = 0; k < visibility.size() && k < cleanLit.size(); ++k) {
        if (!cleanLit[k]) continue;
        ++r.count;
        dark += 1.0 - visibility[k];
        if (visibility[k] < FULLY_LIT_LEVEL) ++bad;
    }
    if (r.count > 0) {
        r.share = static_cast<double>(bad) / r.count;
        r.mean = dark / r.count;
    }
    return r;
}

FailureRate falseLight(const std::vector<float>& visibility,
                       const std::vector<uint8_t>& cleanUmbra) {
    FailureRate r;
    double light = 0.0;
    int bad = 0;
    for (size_t k = 0; k < visibility.size() && k < cleanUmbra.size(); ++k) {
        if (!cleanUmbra[k]) continue;
        ++r.count;
        light += visibility[k];
        if (visibility[k] > LEAK_LEVEL) ++bad;
    }
    if (r.count > 0) {
        r.share = static_cast<double>(bad) / r.count;
        r.mean = light / r.count;
    }
    return r;
}

double quantileOf(std::vector<float>& values, double q) {
    if (values.empty()) return 0.0;
    size_t k = std::min(values.size() - 1, static_cast<size_t>(q * (values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

double curveFlicker(const std::vector<float>& curve) {
    if (curve.size() < 2) return 0.0;
    double s = 0.0;
    for (size_t t = 1; t < curve.size(); ++t) s += std::abs(curve[t] - curve[t - 1]);
    return s / static_cast<double>(curve.size() - 1);
}

double meanOf(const std::vector<float>& values) {
    if (values.empty()) return 0.0;
    double s = 0.0;
    for (float v : values) s += v;
    return s / static_cast<double>(values.size());
}

LeakWidth leakWidth(const std::vector<float>& visibility, const std::vector<uint8_t>& cleanUmbra,
                    const std::vector<float>& texels, const std::vector<float>& world,
                    glm::ivec2 size, int minRun, int stride) {
    size_t n = static_cast<size_t>(size.x) * static_cast<size_t>(size.y);
    stride = std::max(1, stride);
    std::vector<uint8_t> seen(n, 0);
    auto leaking = [&](size_t k) { return cleanUmbra[k] && visibility[k] > LEAK_LEVEL; };
    LeakWidth out;
    std::vector<size_t> run, stack;
    for (size_t start = 0; start < n; ++start) {
        if (seen[start] || !leaking(start)) continue;
        // One connected run, flood-filled over the 8 neighbours.
        run.clear();
        stack.assign(1, start);
        seen[start] = 1;
        while (!stack.empty()) {
            size_t k = stack.back();
            stack.pop_back();
            run.push_back(k);
            int x = static_cast<int>(k % size.x), y = static_cast<int>(k / size.x);
            for (int dy = -stride; dy <= stride; dy += stride) {
                for (int dx = -stride; dx <= stride; dx += stride) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= size.x || ny >= size.y) continue;
                    size_t q = static_cast<size_t>(ny) * size.x + static_cast<size_t>(nx);
                    if (seen[q] || !leaking(q)) continue;
                    seen[q] = 1;
                    stack.push_back(q);
                }
            }
        }
        int count = static_cast<int>(run.size());
        if (count < minRun) {
            out.stray += count;
            continue;
        }
        out.support += count;
        for (size_t k : run) {
            out.texels = std::max(out.texels, static_cast<double>(texels[k]));
            out.world = std::max(out.world, static_cast<double>(world[k]));
        }
    }
    return out;
}

ShimmerStats shimmerStats(const std::vector<std::vector<float>>& frames,
                          const std::vector<uint8_t>& compared) {
    ShimmerStats s;
    if (frames.size() < 2) return s;
    std::vector<uint8_t> flickers(compared.size(), 0);
    int comparedCount = 0, flickering = 0;
    for (size_t k = 0; k < compared.size(); ++k) {
        if (!compared[k]) continue;
        ++comparedCount;
        for (size_t t = 1; t < frames.size() && !flickers[k]; ++t) {
            flickers[k] = std::abs(frames[t][k] - frames[t - 1][k]) > VISIBLE_CHANGE ? 1 : 0;
        }
        flickering += flickers[k];
    }
    std::vector<float> changes, flickerChanges, peak(compared.size(), 0.0f);
    for (size_t t = 1; t < frames.size(); ++t) {
        for (size_t k = 0; k < compared.size(); ++k) {
            if (!compared[k]) continue;
            float d = std::abs(frames[t][k] - frames[t - 1][k]);
            changes.push_back(d);
            peak[k] = std::max(peak[k], d);
            if (flickers[k]) flickerChanges.push_back(d);
        }
    }
    std::vector<float> peaks;
    for (size_t k = 0; k < compared.size(); ++k) {
        if (compared[k]) peaks.push_back(peak[k]);
    }
    s.peakP99 = quantileOf(peaks, 0.99);
    s.flickerShare = comparedCount > 0 ? static_cast<double>(flickering) / comparedCount : 0.0;
    s.mean = meanOf(changes);
    s.flickerMean = meanOf(flickerChanges);
    s.max = quantileOf(changes, 1.0);
    s.p99 = quantileOf(changes, 0.99);
    s.flickerP99 = quantileOf(flickerChanges, 0.99);
    return s;
}

std::vector<glm::vec3> footprintPoints(const Scene& scene, const glm::mat4& shadowClipFromWorld,
                                       int mapSize, glm::vec3 posWs, glm::vec3 normalWs,
                                       float reachTexels, int gridSide) {
    // One texel across the map at p's depth, as world vectors: the inverse of the shadow
    // matrix applied to clip + (2 w / mapSize) along x (and y), minus p.
    glm::mat4 worldFromClip = glm::inverse(shadowClipFromWorld);
    glm::vec4 clip = shadowClipFromWorld * glm::vec4(posWs, 1.0f);
    float step = 2.0f * clip.w / static_cast<float>(mapSize);
    auto unproject = [&](glm::vec4 c) {
        glm::vec4 w = worldFromClip * c;
        return glm::vec3(w) / w.w;
    };
    glm::vec3 texelU = unproject(clip + glm::vec4(step, 0, 0, 0)) - posWs;
    glm::vec3 texelV = unproject(clip + glm::vec4(0, step, 0, 0)) - posWs;
    glm::vec3 toLight = towardLight(scene.light, posWs).dirWs;
    float nDotL = glm::dot(normalWs, toLight);
    std::vector<glm::vec3> points;
    if (std::abs(nDotL) < 1e-4f) return points;
    int side = std::max(gridSide, 2);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            float a = reachTexels * (2.0f * i / (side - 1) - 1.0f);
            float b = reachTexels * (2.0f * j / (side - 1) - 1.0f);
            glm::vec3 o = a * texelU + b * texelV;
            // Along the light (which keeps the map position) back onto the surface's plane:
            // dot(n, o + t * toLight) = 0.
            float t = -glm::dot(normalWs, o) / nDotL;
            points.push_back(posWs + o + t * toLight);
        }
    }
    return points;
}

std::optional<glm::vec3> nearestCasterPoint(const Scene& scene, glm::vec3 p) {
    std::optional<glm::vec3> best;
    float bestD = 1e30f;
    for (const SceneObject& o : scene.objects) {
        if (!o.castsShadow) continue;
        glm::vec3 q;
        if (const Box* box = std::get_if<Box>(&o.shape)) {
            glm::vec3 local = boxLocalFromWorld(*box, p);
            q = boxWorldFromLocal(*box, glm::clamp(local, -box->halfExtents, box->halfExtents));
        } else if (const Sphere* s = std::get_if<Sphere>(&o.shape)) {
            glm::vec3 d = p - s->centreWs;
            float len = glm::length(d);
            q = len > 0.0f ? s->centreWs + d * (s->radius / len) : s->centreWs;
        } else {
            continue;
        }
        float d = glm::length(p - q);
        if (d < bestD) {
            bestD = d;
            best = q;
        }
    }
    return best;
}

std::vector<uint8_t> nearContactMask(const Scene& scene,
                                     const std::vector<std::optional<Hit>>& hits,
                                     std::span<const uint8_t> pixels, float distance) {
    std::vector<uint8_t> out(hits.size(), 0);
    for (size_t k = 0; k < hits.size(); ++k) {
        if (!pixels[k] || !hits[k]) continue;
        std::optional<glm::vec3> q = nearestCasterPoint(scene, hits[k]->posWs);
        out[k] = q && glm::length(hits[k]->posWs - *q) <= distance;
    }
    return out;
}

CasterDistances casterDistances(const Scene& scene, const GroundTruth& truth,
                                const ErrorRegions& regions,
                                const std::vector<std::optional<Hit>>& hits,
                                const glm::mat4& shadowClip, int mapSize) {
    CasterDistances d;
    d.world.assign(truth.pixelCount(), 0.0f);
    d.texels.assign(truth.pixelCount(), 0.0f);
    float size = static_cast<float>(mapSize);
    for (size_t k = 0; k < d.world.size(); ++k) {
        if (!regions.compared[k] || truth.visibility[k] > 0.0f || !hits[k]) continue;
        glm::vec3 p = hits[k]->posWs;
        std::optional<glm::vec3> q = nearestCasterPoint(scene, p);
        if (!q) continue;
        d.world[k] = glm::length(p - *q);
        d.texels[k] =
            glm::length(shadowCoord(shadowClip, p).uvSm - shadowCoord(shadowClip, *q).uvSm) * size;
    }
    return d;
}

}  // namespace pcf
