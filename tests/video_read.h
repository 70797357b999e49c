// video_read.h: what FFmpeg's libavformat and libavcodec read back from a video file: the
// container's codec, the frame size and the number of frames decoded. The video tests check
// animate's MP4 and GIF through it, as a player would open them (expectMp4, expectGif).
#pragma once

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
}

#include <string>

namespace testutil {

struct VideoInfo {
    bool opened = false;
    std::string codec;  // "h264", "gif"
    std::string pixelFormat;
    int width = 0, height = 0;
    int frames = 0;  // decoded
};

inline VideoInfo readVideo(const std::string& path) {
    VideoInfo info;
    AVFormatContext* in = nullptr;
    if (avformat_open_input(&in, path.c_str(), nullptr, nullptr) < 0) return info;
    if (avformat_find_stream_info(in, nullptr) < 0) {
        avformat_close_input(&in);
        return info;
    }
    int s = av_find_best_stream(in, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (s < 0) {
        avformat_close_input(&in);
        return info;
    }
    const AVCodecParameters* par = in->streams[s]->codecpar;
    const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
    AVCodecContext* dec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(dec, par);
    avcodec_open2(dec, decoder, nullptr);
    info.opened = true;
    info.codec = avcodec_get_name(par->codec_id);
    const char* pf = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format));
    info.pixelFormat = pf ? pf : "";
    info.width = par->width;
    info.height = par->height;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    auto drain = [&] {
        while (avcodec_receive_frame(dec, frame) == 0) ++info.frames;
    };
    while (av_read_frame(in, packet) >= 0) {
        if (packet->stream_index == s) {
            // A decoder with full output takes the packet only once its frames are taken.
            while (avcodec_send_packet(dec, packet) == AVERROR(EAGAIN)) drain();
            drain();
        }
        av_packet_unref(packet);
    }
    avcodec_send_packet(dec, nullptr);
    drain();
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&dec);
    avformat_close_input(&in);
    return info;
}

// The checks every test of a written video makes: it opened, its codec (and for an MP4 the
// yuv420p that browsers and slide software play), its size and every frame decoded.
inline void expectVideo(const VideoInfo& v, const std::string& codec, int width, int height,
                        int frames) {
    ASSERT_TRUE(v.opened) << "FFmpeg could not open the video";
    EXPECT_EQ(v.codec, codec);
    if (codec == "h264") {
        EXPECT_EQ(v.pixelFormat, "yuv420p");
    }
    EXPECT_EQ(v.width, width);
    EXPECT_EQ(v.height, height);
    EXPECT_EQ(v.frames, frames);
}
inline void expectMp4(const VideoInfo& v, int width, int height, int frames) {
    expectVideo(v, "h264", width, height, frames);
}
inline void expectGif(const VideoInfo& v, int width, int height, int frames) {
    expectVideo(v, "gif", width, height, frames);
}

}  // namespace testutil
