// frame_files.h: a frame's files (its PNG and the JSON beside it) written on a thread of their
// own, in order, while the caller composes the next frame. PNG encoding is about as costly as
// composing a frame on llvmpipe: done in the frame loop it halved `animate --png`'s frames per
// second and left llvmpipe's threads idle meanwhile. `export` and `animate --png` write through
// it. A failed write (a full disk) is thrown at the next add() or at finish(); the destructor
// stops the thread without writing what is still queued, so nothing is written after the caller
// has given up (its OutputFiles takes back what an error left).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

namespace pcf {

class FrameFiles {
  public:
    // Up to `queued` frames wait for the writer (each held in memory: frame size x 4 bytes).
    explicit FrameFiles(int queued = 2);
    ~FrameFiles();
    FrameFiles(const FrameFiles&) = delete;
    FrameFiles& operator=(const FrameFiles&) = delete;

    // The frame (RGBA8, rows top-down) as the PNG `pngPath`, and `json` as `jsonPath` (none when
    // empty). Waits while the queue is full; throws the error of a write that failed before.
    void add(std::string pngPath, glm::ivec2 size, std::vector<uint8_t> rgba, std::string jsonPath,
             std::string json);
    // Waits until every frame is written; throws the first failure.
    void finish();

    // Seconds spent encoding and writing, on the writer's thread (steady clock), and seconds the
    // caller was held up by it (a full queue, finish()).
    double writeSeconds() const;
    double waitSeconds() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace pcf
