#include "render/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <random>
#include <system_error>

#include "base/input_error.h"
#include "render/sanitizer_build.h"

namespace pcf {

namespace {

// OIIO's messages can run over several lines (and quote a path with a newline in it); ours are
// one line: trailing line ends dropped, the rest escaped (oneLine), nothing cut.
std::string firstLine(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '\n')) s.pop_back();
    return s.empty() ? "unknown error" : oneLine(s);
}

// PATH.tmp-XXXXXX next to PATH (same directory, so the rename is atomic). Not mkstemp: that
// creates the file 0600, and the rename would carry those permissions to the image.
std::string tempPathFor(const std::string& path) {
    static const char LETTERS[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    static std::mutex mutex;
    static std::mt19937 random{std::random_device{}()};
    std::lock_guard lock(mutex);
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof LETTERS) - 2);
    for (;;) {
        std::string temp = path + ".tmp-";
        for (int k = 0; k < 6; ++k) temp += LETTERS[pick(random)];
        std::error_code ec;
        if (std::filesystem::symlink_status(temp, ec).type() ==
            std::filesystem::file_type::not_found) {
            return temp;
        }
    }
}

// An output that is a symbolic link is written through: the file it points at is replaced and
// the link stays (a link the user made is theirs). Relative targets are taken from the link's
// folder, as the kernel does; a loop of links gives up after 40, as the kernel does.
std::string resolveLinks(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path at(path);
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(at, ec)); ++hops) {
        fs::path target = fs::read_symlink(at, ec);
        if (ec) break;
        at = target.is_absolute() ? target : at.parent_path() / target;
    }
    return at.string();
}

// Writes through a temporary file and renames it over `path`. The plugin is chosen from the
// final path's extension: the temporary name has none OIIO knows.
void writeImageAtomically(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                          const void* data) {
    std::shared_lock gate(outputWriteGate());
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw ImageError(path + ": cannot write image (" + firstLine(OIIO::geterror()) + ")");
    const std::string target = resolveLinks(path);
    std::string temp = tempPathFor(target);
    std::string reason;
    if (!out->open(temp, spec) || !out->write_image(type, data) || !out->close()) {
        reason = out->geterror();
        // The temporary name is ours, not the user's: report the path they asked for.
        for (size_t at; (at = reason.find(temp)) != std::string::npos;) {
            reason.replace(at, temp.size(), path);
        }
        reason = firstLine(reason);
    }
    out.reset();
    std::error_code ec;
    if (reason.empty()) {
        std::filesystem::rename(temp, target, ec);
        if (ec) reason = ec.message();
    }
    if (!reason.empty()) {
        std::filesystem::remove(temp, ec);
        throw ImageError(path + ": cannot write image (" + reason + ")");
    }
}

}  // namespace

std::shared_mutex& outputWriteGate() {
    static std::shared_mutex gate;
    return gate;
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::shared_lock gate(outputWriteGate());
    const std::string target = resolveLinks(path);
    std::string temp = tempPathFor(target);
    std::error_code ec;
    {
        std::ofstream f(temp, std::ios::binary | std::ios::trunc);
        f << text;
        f.close();
        if (!f) {
            std::filesystem::remove(temp, ec);
            throw ImageError(path + ": cannot write file");
        }
    }
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw ImageError(path + ": cannot write file (" + ec.message() + ")");
    }
}

namespace {

void checkSize(const std::string& path, int width, int height, size_t have, size_t perPixel) {
    if (width <= 0 || height <= 0) {
        throw ImageError(path + ": cannot write image (size " + std::to_string(width) + " x " +
                         std::to_string(height) + ")");
    }
    size_t need = static_cast<size_t>(width) * height * perPixel;
    if (have != need) {
        throw ImageError(path + ": cannot write image (" + std::to_string(have) + " values for " +
                         std::to_string(need) + ")");
    }
}

}  // namespace

void writePngRgba8(const std::string& path, int width, int height, std::span<const uint8_t> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    // The bytes are PNG's own straight (unassociated) alpha: without this OIIO would take them
    // as premultiplied and divide the colour by alpha on the way out.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // zlib level 1: exported frames are flat UI colours and compress well anyway, and at the
    // default level 6 compression was a third of an export's time.
    spec.attribute("png:compressionLevel", 1);
    writeImageAtomically(path, spec, OIIO::TypeDesc::UINT8, rgba.data());
}

void writeExr(const std::string& path, int width, int height, int channels,
              std::span<const float> data, const std::vector<std::string>& channelNames) {
    if (channels < 1 || static_cast<size_t>(channels) != channelNames.size()) {
        throw ImageError(path + ": cannot write image (" + std::to_string(channels) +
                         " channels, " + std::to_string(channelNames.size()) + " names)");
    }
    checkSize(path, width, height, data.size(), static_cast<size_t>(channels));
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    // OIIO stamps "DateTime" (the time of writing) into every EXR unless told otherwise: with
    // it two runs of the same command give different bytes. An empty value writes no header.
    spec.attribute("DateTime", "");
    spec.channelnames = channelNames;
    spec.alpha_channel = -1;
    spec.z_channel = -1;
    for (int c = 0; c < channels; ++c) {
        if (channelNames[c] == "A") spec.alpha_channel = c;
        if (channelNames[c] == "Z") spec.z_channel = c;
    }
    writeImageAtomically(path, spec, OIIO::TypeDesc::FLOAT, data.data());
}

void writeDepthImage(const std::string& path, const ShadowMap& map) {
    writeExr(path, map.width(), map.height(), 1, map.depths(), {"Z"});
}

namespace {

// libpng prints its own "libpng error: ..." line on stderr before OpenImageIO reports the same
// problem to us, which would make a bad map two lines. While a depth image is read, stderr goes
// to /dev/null; the message still reaches the user through OIIO's error, in our one line.
// Not in sanitizer builds: a report from inside a decoder (what fuzzing looks for) must show.
class QuietStderr {
  public:
    QuietStderr() {
#if !PCFSCOPE_ASAN
        std::fflush(stderr);
        mSaved = ::dup(2);
        int null = ::open("/dev/null", O_WRONLY);
        if (mSaved >= 0 && null >= 0) ::dup2(null, 2);
        if (null >= 0) ::close(null);
#endif
    }
    ~QuietStderr() {
        if (mSaved < 0) return;
        std::fflush(stderr);
        ::dup2(mSaved, 2);
        ::close(mSaved);
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

  private:
    int mSaved = -1;
};

}  // namespace

FloatImage readFloatImage(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw ImageError(path + ": cannot read image (" + firstLine(OIIO::geterror()) + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep || spec.width <= 0 || spec.height <= 0 || spec.depth > 1) {
        throw ImageError(path + ": cannot read image (not a flat 2D image)");
    }
    FloatImage img{spec.width, spec.height, spec.nchannels, {}};
    img.data.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.data.data())) {
        throw ImageError(path + ": cannot read image (" + firstLine(in->geterror()) + ")");
    }
    return img;
}

ShadowMap readDepthImage(const std::string& path) {
    // A FIFO or device would block OIIO forever (or never end): only regular files, which is
    // what a depth map written by pcfscope or a paint program is.
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        throw ImageError(
            path + ": cannot read image (" +
            (std::filesystem::is_directory(status) ? "it is a directory" : "not a regular file") +
            ")");
    }
    QuietStderr quiet;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw ImageError(path + ": cannot read image (" + firstLine(OIIO::geterror()) + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 1) {
        throw ImageError(path + ": has " + std::to_string(spec.nchannels) +
                         " channels; a depth map has 1");
    }
    OIIO::TypeDesc::BASETYPE base = static_cast<OIIO::TypeDesc::BASETYPE>(spec.format.basetype);
    if (base != OIIO::TypeDesc::HALF && base != OIIO::TypeDesc::FLOAT &&
        base != OIIO::TypeDesc::DOUBLE) {
        throw ImageError(path + ": holds " + std::string(spec.format.c_str()) +
                         " integers; a depth map holds floats (half or float)");
    }
    if (spec.deep || spec.width <= 0 || spec.height <= 0 || spec.depth > 1) {
        throw ImageError(path + ": cannot read image (not a flat 2D image)");
    }
    if (spec.width > MAX_DEPTH_IMAGE_SIDE || spec.height > MAX_DEPTH_IMAGE_SIDE) {
        throw ImageError(path + ": is " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height) + " texels; a depth map is at most " +
                         std::to_string(MAX_DEPTH_IMAGE_SIDE) + " on a side");
    }
    std::vector<float> depths(static_cast<size_t>(spec.width) * spec.height);
    // OIIO hands scanlines in file order, first scanline first: that is ShadowMap's row 0.
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, depths.data())) {
        throw ImageError(path + ": cannot read image (" + firstLine(in->geterror()) + ")");
    }
    ShadowMap map(spec.width, spec.height, std::move(depths));
    if (std::optional<std::string> bad = map.findInvalidTexel()) {
        throw ImageError(path + ": " + *bad);
    }
    return map;
}

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

}  // namespace pcf
