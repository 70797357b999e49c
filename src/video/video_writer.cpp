#include "video/video_writer.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "video/av_library.h"

namespace pcf {

std::optional<VideoFormat> videoFormatFromPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".mp4") return VideoFormat::Mp4;
    if (ext == ".gif") return VideoFormat::Gif;
    return std::nullopt;
}

std::string_view videoFormatName(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4:
            return "mp4";
        case VideoFormat::Gif:
            return "gif";
    }
    return "?";
}

std::optional<std::string> videoSizeProblem(VideoFormat format, int width, int height) {
    if (format == VideoFormat::Mp4 && (width % 2 != 0 || height % 2 != 0)) {
        return "an MP4 (H.264, yuv420p) needs even sides, got " + std::to_string(width) + "x" +
               std::to_string(height);
    }
    return std::nullopt;
}

namespace {

// The 4 x 4 Bayer matrix, thresholds (k + 0.5) / 16 - 0.5 in units of one level step.
constexpr int BAYER4[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

int quantise(uint8_t value, int levels, float dither) {
    float steps = static_cast<float>(levels - 1);
    float q = static_cast<float>(value) / 255.0f * steps + dither;
    return std::clamp(static_cast<int>(q + 0.5f), 0, levels - 1);
}

uint8_t levelValue(int level, int levels) {
    return static_cast<uint8_t>((level * 255 + (levels - 1) / 2) / (levels - 1));
}

std::string avError(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    avLibrary().av_strerror(code, buf, sizeof buf);
    return buf;
}

// Frames waiting for the encoder's thread: enough that a frame composed while the encoder is busy
// is not held up, few enough to bound the memory (4 frames of 1600 x 900 RGBA are 23 MB).
constexpr size_t QUEUE_FRAMES = 4;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

uint8_t gifPaletteIndex(uint8_t r, uint8_t g, uint8_t b, int x, int y) {
    float dither = (static_cast<float>(BAYER4[y & 3][x & 3]) + 0.5f) / 16.0f - 0.5f;
    int ri = quantise(r, GIF_LEVELS_R, dither);
    int gi = quantise(g, GIF_LEVELS_G, dither);
    int bi = quantise(b, GIF_LEVELS_B, dither);
    return static_cast<uint8_t>((ri * GIF_LEVELS_G + gi) * GIF_LEVELS_B + bi);
}

std::vector<uint32_t> gifPalette() {
    std::vector<uint32_t> palette(256, 0xff000000u);
    for (int r = 0; r < GIF_LEVELS_R; ++r) {
        for (int g = 0; g < GIF_LEVELS_G; ++g) {
            for (int b = 0; b < GIF_LEVELS_B; ++b) {
                uint32_t argb = 0xff000000u | (uint32_t{levelValue(r, GIF_LEVELS_R)} << 16) |
                                (uint32_t{levelValue(g, GIF_LEVELS_G)} << 8) |
                                levelValue(b, GIF_LEVELS_B);
                palette[static_cast<size_t>((r * GIF_LEVELS_G + g) * GIF_LEVELS_B + b)] = argb;
            }
        }
    }
    return palette;
}

struct VideoWriter::Impl {
    const AvLibrary& av = avLibrary();  // FFmpeg, opened by the first video
    std::filesystem::path path;
    VideoFormat format = VideoFormat::Mp4;
    int width = 0, height = 0;
    AVFormatContext* output = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* scaler = nullptr;
    int64_t next = 0;
    int frames = 0;
    bool headerWritten = false;
    bool finished = false;
    double seconds = 0.0;      // converting and encoding, on the encoder's thread
    double waitSeconds = 0.0;  // the caller held up: a full queue, and finish()

    // The encoder's thread and the frames queued for it, in order (one thread, so the bytes do
    // not depend on timing). A failure there is kept and thrown to the caller at its next call.
    std::thread worker;
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<std::vector<uint8_t>> queue;
    // Frames the worker is done with, kept for the next addFrame to copy into: a fresh 3.7 MB
    // buffer per 1280 x 720 frame costs the kernel its page faults (0.7 s a 120-frame clip).
    std::vector<std::vector<uint8_t>> spare;
    bool busy = false;  // the worker holds a frame taken off the queue
    bool stopping = false;
    std::exception_ptr error;

    [[noreturn]] void fail(const std::string& what, int code) const {
        throw VideoError(path.string() + ": " + what + ": " + avError(code));
    }
    void check(int code, const std::string& what) const {
        if (code < 0) fail(what, code);
    }

    void openCodec(int fps) {
        const char* name = format == VideoFormat::Mp4 ? "libx264" : "gif";
        const AVCodec* c = av.avcodec_find_encoder_by_name(name);
        if (!c) {
            throw VideoError(path.string() + ": FFmpeg has no " + name + " encoder");
        }
        codec = av.avcodec_alloc_context3(c);
        codec->width = width;
        codec->height = height;
        // A GIF counts its frame delays in 1/100 s.
        codec->time_base = format == VideoFormat::Gif ? AVRational{1, 100} : AVRational{1, fps};
        codec->framerate = AVRational{fps, 1};
        codec->pix_fmt = format == VideoFormat::Mp4 ? AV_PIX_FMT_YUV420P : AV_PIX_FMT_PAL8;
        if (format == VideoFormat::Mp4) {
            codec->gop_size = 2 * fps;
            // crf 18: visually lossless for these flat-shaded frames; "fast" keeps the encoder's
            // share of an annotated frame's time small on two cores.
            av.av_opt_set(codec->priv_data, "preset", "fast", 0);
            av.av_opt_set(codec->priv_data, "crf", "18", 0);
        }
        if (output->oformat->flags & AVFMT_GLOBALHEADER) {
            codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        }
        check(av.avcodec_open2(codec, c, nullptr),
              std::string("cannot open the ") + name + " encoder");
        stream = av.avformat_new_stream(output, nullptr);
        if (!stream) throw VideoError(path.string() + ": cannot add a video stream");
        stream->time_base = codec->time_base;
        check(av.avcodec_parameters_from_context(stream->codecpar, codec), "codec parameters");
    }

    void open(int fps) {
        std::string file = path.string();
        const char* muxer = format == VideoFormat::Mp4 ? "mp4" : "gif";
        check(av.avformat_alloc_output_context2(&output, nullptr, muxer, file.c_str()),
              "cannot make the output");
        openCodec(fps);
        check(av.avio_open(&output->pb, file.c_str(), AVIO_FLAG_WRITE), "cannot open");
        AVDictionary* options = nullptr;
        // The index in front, so a browser starts playing before the whole file has arrived.
        if (format == VideoFormat::Mp4) av.av_dict_set(&options, "movflags", "+faststart", 0);
        int r = av.avformat_write_header(output, &options);
        av.av_dict_free(&options);
        check(r, "cannot write the header");
        headerWritten = true;
        frame = av.av_frame_alloc();
        packet = av.av_packet_alloc();
        frame->format = codec->pix_fmt;
        frame->width = width;
        frame->height = height;
        check(av.av_frame_get_buffer(frame, 0), "frame buffer");
        if (format == VideoFormat::Mp4) {
            scaler = av.sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height,
                                       AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
            if (!scaler) throw VideoError(path.string() + ": no RGBA -> yuv420p");
        }
    }

    // Writes every packet the encoder has ready.
    void drain() {
        for (;;) {
            int r = av.avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "encoding");
            // Each frame lasts one frame: without it the MP4's edit list ends at the last
            // frame's start and players drop that frame.
            if (format == VideoFormat::Mp4) packet->duration = 1;
            av.av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            r = av.av_interleaved_write_frame(output, packet);
            check(r, "write");
            if (output->pb->error < 0) fail("write", output->pb->error);
        }
    }

    void fillFrame(const std::vector<uint8_t>& rgba) {
        check(av.av_frame_make_writable(frame), "frame buffer");
        if (format == VideoFormat::Mp4) {
            const uint8_t* src[1] = {rgba.data()};
            int stride[1] = {4 * width};
            av.sws_scale(scaler, src, stride, 0, height, frame->data, frame->linesize);
            frame->pts = next++;
            return;
        }
        if (gifLut.empty()) buildGifTables();
        for (int y = 0; y < height; ++y) {
            uint8_t* row = frame->data[0] + static_cast<ptrdiff_t>(y) * frame->linesize[0];
            const uint8_t* in = rgba.data() + static_cast<size_t>(y) * width * 4;
            for (int x = 0; x < width; ++x, in += 4) {
                // gifPaletteIndex through its tables: one per dither position and channel.
                const uint8_t* lut = &gifLut[static_cast<size_t>((y & 3) * 4 + (x & 3)) * 768];
                row[x] = static_cast<uint8_t>(lut[in[0]] + lut[256 + in[1]] + lut[512 + in[2]]);
            }
        }
        std::copy(gifColours.begin(), gifColours.end(),
                  reinterpret_cast<uint32_t*>(frame->data[1]));
        // Frame k at round(k * 100 / fps) hundredths: the delays add up to the clip's length.
        frame->pts =
            (next * 100 * codec->time_base.num + codec->framerate.num / 2) / codec->framerate.num;
        ++next;
    }

    // gifPaletteIndex split by channel: for each of the 16 dither positions, each channel's
    // value -> its share of the index (r * 42, g * 6, b), which add up to the index.
    std::vector<uint8_t> gifLut;
    std::vector<uint32_t> gifColours;
    void buildGifTables() {
        gifColours = gifPalette();
        gifLut.resize(16 * 768);
        for (int pos = 0; pos < 16; ++pos) {
            int x = pos & 3, y = pos >> 2;
            for (int v = 0; v < 256; ++v) {
                uint8_t c = static_cast<uint8_t>(v);
                uint8_t* lut = &gifLut[static_cast<size_t>(pos) * 768];
                lut[v] = gifPaletteIndex(c, 0, 0, x, y);
                lut[256 + v] = gifPaletteIndex(0, c, 0, x, y);
                lut[512 + v] = gifPaletteIndex(0, 0, c, x, y);
            }
        }
    }

    void encode(const std::vector<uint8_t>& rgba) {
        auto start = std::chrono::steady_clock::now();
        fillFrame(rgba);
        check(av.avcodec_send_frame(codec, frame), "encoding");
        drain();
        seconds += secondsSince(start);
    }

    // The worker: frames off the queue into the encoder until stopped; after a failure it only
    // drops what is queued, so that the caller never waits on it.
    void run() {
        std::unique_lock lock(mutex);
        for (;;) {
            changed.wait(lock, [this] { return stopping || !queue.empty(); });
            if (queue.empty()) return;
            std::vector<uint8_t> rgba = std::move(queue.front());
            queue.pop_front();
            busy = true;
            bool failed = error != nullptr;
            lock.unlock();
            std::exception_ptr caught;
            if (!failed) {
                try {
                    encode(rgba);
                } catch (...) {
                    caught = std::current_exception();
                }
            }
            lock.lock();
            if (caught) error = caught;
            spare.push_back(std::move(rgba));
            busy = false;
            changed.notify_all();
        }
    }

    // Holds the caller until `done` (under the lock), counting the time as waiting.
    template <class Done>
    void waitFor(std::unique_lock<std::mutex>& lock, Done done) {
        if (done()) return;
        auto start = std::chrono::steady_clock::now();
        changed.wait(lock, done);
        waitSeconds += secondsSince(start);
    }

    // Ends the worker once its frame is done; frames still queued are dropped (finish() has waited
    // for them; on the way out of an error there is no video to make).
    void stopWorker() {
        if (!worker.joinable()) return;
        {
            std::lock_guard lock(mutex);
            queue.clear();
            stopping = true;
        }
        changed.notify_all();
        worker.join();
    }

    void close() {
        stopWorker();
        if (output && output->pb) av.avio_closep(&output->pb);
        av.sws_freeContext(scaler);
        av.av_packet_free(&packet);
        av.av_frame_free(&frame);
        av.avcodec_free_context(&codec);
        av.avformat_free_context(output);
        output = nullptr;
        scaler = nullptr;
    }
};

VideoWriter::VideoWriter(const std::filesystem::path& path, VideoFormat format, int width,
                         int height, int fps)
    : mImpl(std::make_unique<Impl>()) {
    mImpl->path = path;
    mImpl->format = format;
    mImpl->width = width;
    mImpl->height = height;
    if (auto problem = videoSizeProblem(format, width, height)) {
        throw VideoError(path.string() + ": " + *problem);
    }
    if (fps < 1 || fps > 60) throw VideoError(path.string() + ": fps must be 1..60");
    mImpl->av.av_log_set_level(AV_LOG_ERROR);
    try {
        mImpl->open(fps);
    } catch (...) {
        mImpl->close();
        throw;
    }
    mImpl->worker = std::thread([impl = mImpl.get()] { impl->run(); });
}

VideoWriter::~VideoWriter() { mImpl->close(); }

void VideoWriter::addFrame(const std::vector<uint8_t>& rgba) {
    Impl& m = *mImpl;
    if (rgba.size() != static_cast<size_t>(m.width) * m.height * 4) {
        throw VideoError(m.path.string() + ": a frame of the wrong size");
    }
    std::unique_lock lock(m.mutex);
    m.waitFor(lock, [&m] { return m.error || m.queue.size() < QUEUE_FRAMES; });
    if (m.error) std::rethrow_exception(m.error);
    std::vector<uint8_t> copy;
    if (!m.spare.empty()) {
        copy = std::move(m.spare.back());
        m.spare.pop_back();
    }
    lock.unlock();
    copy.assign(rgba.begin(), rgba.end());  // only this thread adds frames: the order holds
    lock.lock();
    m.queue.push_back(std::move(copy));
    ++m.frames;
    lock.unlock();
    m.changed.notify_all();
}

void VideoWriter::finish() {
    Impl& m = *mImpl;
    if (m.finished) return;
    {
        // Every queued frame encoded (or a failure) before the encoder is flushed here.
        std::unique_lock lock(m.mutex);
        m.waitFor(lock, [&m] { return m.error || (m.queue.empty() && !m.busy); });
    }
    m.stopWorker();
    if (m.error) std::rethrow_exception(m.error);
    auto start = std::chrono::steady_clock::now();
    m.check(m.av.avcodec_send_frame(m.codec, nullptr), "flushing the encoder");
    m.drain();
    m.check(m.av.av_write_trailer(m.output), "cannot write the trailer");
    m.av.avio_flush(m.output->pb);
    if (m.output->pb->error < 0) m.fail("write", m.output->pb->error);
    m.check(m.av.avio_closep(&m.output->pb), "cannot close");
    m.finished = true;
    double flush = secondsSince(start);
    m.seconds += flush;
    m.waitSeconds += flush;
}

int VideoWriter::framesWritten() const { return mImpl->frames; }
double VideoWriter::encodeSeconds() const { return mImpl->seconds; }
double VideoWriter::waitSeconds() const { return mImpl->waitSeconds; }

}  // namespace pcf
