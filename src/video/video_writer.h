// video_writer.h: frames (RGBA8, rows top-down) into a video file through FFmpeg's libavcodec and
// libavformat: MP4 (H.264 by libx264, yuv420p, which browsers and slide software play) or an
// animated GIF (libavcodec's gif encoder fed a fixed palette, so the same frames give the same
// bytes). Knows nothing of pcfscope's scenes: app/ hands it pixels.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pcf {

enum class VideoFormat { Mp4, Gif };

// A video that cannot be written (no encoder, a failed write, a full disk): the message names the
// file and FFmpeg's reason, in one line.
class VideoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// ".mp4" -> Mp4, ".gif" -> Gif (any case); nullopt for anything else.
std::optional<VideoFormat> videoFormatFromPath(const std::filesystem::path& path);
std::string_view videoFormatName(VideoFormat format);  // "mp4", "gif"

// Why a frame size cannot be encoded in `format`, or nullopt: H.264 in yuv420p halves the
// chroma planes, so an MP4's sides must be even.
std::optional<std::string> videoSizeProblem(VideoFormat format, int width, int height);

// The GIF's fixed palette: 6 x 7 x 6 levels of red, green and blue (green gets the extra level:
// the eye tells green steps apart best), 252 colours, entries 252..255 black. Index of the
// level triple (r, g, b): r * 42 + g * 6 + b.
constexpr int GIF_LEVELS_R = 6, GIF_LEVELS_G = 7, GIF_LEVELS_B = 6;
// The palette index of one pixel at (x, y): each channel quantised to its levels after a 4 x 4
// ordered (Bayer) dither offset, so gradients do not band and the result depends on nothing
// but the pixel and its position (no error diffusion from frame to frame).
uint8_t gifPaletteIndex(uint8_t r, uint8_t g, uint8_t b, int x, int y);
// The palette as 0xAARRGGBB, 256 entries.
std::vector<uint32_t> gifPalette();

class VideoWriter {
  public:
    // Opens `path` for writing (it is created or truncated). fps: frames per second (1..60; a
    // GIF stores delays in 1/100 s, so 30 fps plays at 3.33 -> 3 cs). Throws VideoError
    // naming the path and FFmpeg's reason.
    VideoWriter(const std::filesystem::path& path, VideoFormat format, int width, int height,
                int fps);
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // One frame, width * height * 4 bytes, rows top-down: copied into a queue of a few frames
    // that the writer's own thread encodes in order, so the caller composes the next frame
    // meanwhile (it waits only while the queue is full). Throws VideoError on an encoder or
    // write failure (a full disk included), at the first call after it happened.
    void addFrame(const std::vector<uint8_t>& rgba);
    // Encodes what is queued, flushes the encoder, writes the trailer and closes the file; every
    // write checked, a failure of a queued frame thrown here. Without it (an exception, Ctrl-C)
    // the file is incomplete: callers write to a staging name.
    void finish();

    // Frames taken (queued or encoded).
    int framesWritten() const;
    // Seconds spent converting and encoding (steady clock, on the writer's thread).
    double encodeSeconds() const;
    // Seconds the caller was held up by the encoder (a full queue, and finish()): the encoder's
    // share of the caller's time.
    double waitSeconds() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace pcf
