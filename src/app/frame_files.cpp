#include "app/frame_files.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "render/image_io.h"

namespace pcf {

struct FrameFiles::Impl {
    struct Job {
        std::string pngPath;
        glm::ivec2 size{0, 0};
        std::vector<uint8_t> rgba;
        std::string jsonPath;
        std::string json;
    };
    static double since(std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    int queued = 2;
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<Job> queue;
    bool busy = false;  // the writer holds a job taken off the queue
    bool stopping = false;
    std::exception_ptr error;
    double writeSeconds = 0.0;
    double waitSeconds = 0.0;
    std::thread worker;

    // Jobs off the queue, in order, until stopped; after a failure the rest are dropped.
    void run() {
        std::unique_lock lock(mutex);
        for (;;) {
            changed.wait(lock, [this] { return stopping || !queue.empty(); });
            if (stopping) return;
            Job job = std::move(queue.front());
            queue.pop_front();
            busy = true;
            lock.unlock();
            auto start = std::chrono::steady_clock::now();
            std::exception_ptr failed;
            try {
                writePngRgba8(job.pngPath, job.size.x, job.size.y, job.rgba);
                if (!job.jsonPath.empty()) writeTextFile(job.jsonPath, job.json);
            } catch (...) {
                failed = std::current_exception();
            }
            double seconds = since(start);
            lock.lock();
            writeSeconds += seconds;
            busy = false;
            if (failed && !error) error = failed;
            if (error) queue.clear();
            changed.notify_all();
        }
    }

    // Waits (the caller's time counted) until `ready` holds; rethrows a failure.
    template <class Ready>
    void waitFor(std::unique_lock<std::mutex>& lock, Ready ready) {
        auto start = std::chrono::steady_clock::now();
        changed.wait(lock, [&] { return error || ready(); });
        waitSeconds += since(start);
        if (error) std::rethrow_exception(error);
    }
};

FrameFiles::FrameFiles(int queued) : mImpl(std::make_unique<Impl>()) {
    mImpl->queued = queued < 1 ? 1 : queued;
    mImpl->worker = std::thread([impl = mImpl.get()] { impl->run(); });
}

FrameFiles::~FrameFiles() {
    {
        std::lock_guard lock(mImpl->mutex);
        mImpl->stopping = true;
        mImpl->queue.clear();
    }
    mImpl->changed.notify_all();
    mImpl->worker.join();
}

void FrameFiles::add(std::string pngPath, glm::ivec2 size, std::vector<uint8_t> rgba,
                     std::string jsonPath, std::string json) {
    Impl& m = *mImpl;
    std::unique_lock lock(m.mutex);
    m.waitFor(lock, [&m] { return static_cast<int>(m.queue.size()) < m.queued; });
    m.queue.push_back(
        {std::move(pngPath), size, std::move(rgba), std::move(jsonPath), std::move(json)});
    m.changed.notify_all();
}

void FrameFiles::finish() {
    Impl& m = *mImpl;
    std::unique_lock lock(m.mutex);
    m.waitFor(lock, [&m] { return m.queue.empty() && !m.busy; });
}

double FrameFiles::writeSeconds() const {
    std::lock_guard lock(mImpl->mutex);
    return mImpl->writeSeconds;
}

double FrameFiles::waitSeconds() const {
    std::lock_guard lock(mImpl->mutex);
    return mImpl->waitSeconds;
}

}  // namespace pcf
