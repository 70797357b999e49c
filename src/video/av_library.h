// av_library.h: FFmpeg's libraries (libavcodec, libavformat, libavutil, libswscale) opened when a
// video is first written, not when pcfscope starts. Linked directly, they and the 130 shared
// objects they need were resolved by every command, `pcfscope methods` included; through dlopen
// only `animate` and an export of an animated step pay for them. The functions video_writer.cpp
// calls are looked up by name here, typed by FFmpeg's own declarations.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace pcf {

// Every FFmpeg function video_writer.cpp calls: X(library, function).
#define PCF_AV_FUNCTIONS(X)                     \
    X(avutil, av_dict_free)                     \
    X(avutil, av_dict_set)                      \
    X(avutil, av_frame_alloc)                   \
    X(avutil, av_frame_free)                    \
    X(avutil, av_frame_get_buffer)              \
    X(avutil, av_frame_make_writable)           \
    X(avutil, av_log_set_level)                 \
    X(avutil, av_opt_set)                       \
    X(avutil, av_strerror)                      \
    X(avcodec, av_packet_alloc)                 \
    X(avcodec, av_packet_free)                  \
    X(avcodec, av_packet_rescale_ts)            \
    X(avcodec, avcodec_alloc_context3)          \
    X(avcodec, avcodec_find_encoder_by_name)    \
    X(avcodec, avcodec_free_context)            \
    X(avcodec, avcodec_open2)                   \
    X(avcodec, avcodec_parameters_from_context) \
    X(avcodec, avcodec_receive_packet)          \
    X(avcodec, avcodec_send_frame)              \
    X(avformat, av_interleaved_write_frame)     \
    X(avformat, av_write_trailer)               \
    X(avformat, avformat_alloc_output_context2) \
    X(avformat, avformat_free_context)          \
    X(avformat, avformat_new_stream)            \
    X(avformat, avformat_write_header)          \
    X(avformat, avio_closep)                    \
    X(avformat, avio_flush)                     \
    X(avformat, avio_open)                      \
    X(swscale, sws_freeContext)                 \
    X(swscale, sws_getContext)                  \
    X(swscale, sws_scale)

// The functions, one pointer each, named as FFmpeg names them.
struct AvLibrary {
#define PCF_AV_POINTER(library, function) decltype(&::function) function = nullptr;
    PCF_AV_FUNCTIONS(PCF_AV_POINTER)
#undef PCF_AV_POINTER
};

// The libraries, opened on the first call (by the sonames of the headers built against:
// libavcodec.so.59 for FFmpeg 5.1) and kept open. Throws VideoError (video_writer.h) naming the
// library or function that is missing, in one line.
const AvLibrary& avLibrary();

}  // namespace pcf
