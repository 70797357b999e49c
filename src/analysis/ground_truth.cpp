#include "analysis/ground_truth.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

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

struct PixelTruth {
    float visibility;
    bool receiver;
    bool facesLight;
};

// The truth of one pixel (GL window coordinates, y up); see ground_truth.h for the definition.
PixelTruth pixelTruth(const Scene& scene, glm::ivec2 pixel, glm::ivec2 size, float aspect,
                      int spp) {
    Ray centreRay = cameraRay(scene.camera, pixelCentreNdc(pixel, size), aspect);
    std::optional<Hit> centre = intersect(scene, centreRay);
    if (!centre) return {1.0f, false, false};
    const SceneObject& object = scene.objects[static_cast<size_t>(centre->object)];
    LightSample toLight = towardLight(scene.light, centre->posWs);
    glm::vec3 facing = centre->frontFace ? centre->normalWs : -centre->normalWs;
    bool faces = toLight.insideCone && glm::dot(facing, toLight.dirWs) > 0.0f;

    int lit = 0;
    int counted = 0;
    glm::vec2 sizeF(size);
    for (int j = 0; j < spp; ++j) {
        for (int i = 0; i < spp; ++i) {
            glm::vec2 offset = stratifiedSample(pixel, i, j, spp);
            glm::vec2 ndc = (glm::vec2(pixel) + offset) / sizeF * 2.0f - 1.0f;
            std::optional<Hit> hit = intersect(scene, cameraRay(scene.camera, ndc, aspect));
            if (!hit || hit->object != centre->object) continue;
            ++counted;
            lit += litByLight(scene, *hit) ? 1 : 0;
        }
    }
    float visibility = counted > 0 ? static_cast<float>(lit) / static_cast<float>(counted)
                                   : (litByLight(scene, *centre) ? 1.0f : 0.0f);
    return {visibility, object.receivesShadow, faces};
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

GroundTruth computeGroundTruth(const Scene& scene, glm::ivec2 frameSize,
                               const GroundTruthOptions& options) {
    if (frameSize.x < 1 || frameSize.y < 1) {
        throw std::invalid_argument("computeGroundTruth: frame size must be positive");
    }
    if (options.spp < 1 || options.spp > MAX_TRUTH_SPP) {
        throw std::invalid_argument("computeGroundTruth: spp " + std::to_string(options.spp) +
                                    " is out of range (1.." + std::to_string(MAX_TRUTH_SPP) + ")");
    }
    GroundTruth truth;
    truth.size = frameSize;
    truth.spp = options.spp;
    truth.visibility.assign(truth.pixelCount(), 1.0f);
    truth.receiver.assign(truth.pixelCount(), 0);
    truth.facesLight.assign(truth.pixelCount(), 0);
    float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);

    // Rows are handed out one at a time from a shared counter: rows near the horizon (mostly
    // background) are cheap and rows full of receivers are not, so a fixed split would idle.
    std::atomic<int> nextRow{0};
    std::atomic<int> rowsDone{0};
    std::mutex mutex;
    std::condition_variable finished;
    auto work = [&] {
        for (int y; (y = nextRow.fetch_add(1)) < frameSize.y;) {
            int rowTopDown = frameSize.y - 1 - y;
            for (int x = 0; x < frameSize.x; ++x) {
                PixelTruth p = pixelTruth(scene, {x, y}, frameSize, aspect, options.spp);
                size_t k = truth.index(x, rowTopDown);
                truth.visibility[k] = p.visibility;
                truth.receiver[k] = p.receiver ? 1 : 0;
                truth.facesLight[k] = p.facesLight ? 1 : 0;
            }
            if (rowsDone.fetch_add(1) + 1 == frameSize.y) {
                std::lock_guard lock(mutex);
                finished.notify_all();
            }
        }
    };
    int threadCount = std::min(resolveThreadCount(options.threads), frameSize.y);
    std::vector<std::thread> workers;
    workers.reserve(static_cast<size_t>(threadCount));
    for (int t = 0; t < threadCount; ++t) workers.emplace_back(work);
    {
        std::unique_lock lock(mutex);
        while (!finished.wait_for(lock, std::chrono::milliseconds(100),
                                  [&] { return rowsDone.load() == frameSize.y; })) {
            if (options.progress) options.progress(rowsDone.load(), frameSize.y);
        }
    }
    for (std::thread& w : workers) w.join();
    if (options.progress) options.progress(frameSize.y, frameSize.y);
    return truth;
}

}  // namespace pcf
