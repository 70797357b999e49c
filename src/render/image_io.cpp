#include "render/image_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <random>
#include <system_error>

#include "base/input_error.h"
#include "render/image_codec.h"
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

// Writes `bytes` to a new temporary file next to `target` and renames it over `target`. Every
// write, the close and the rename are checked: a full disk (ENOSPC) or the file size limit
// (EFBIG, SIGXFSZ being ignored, see app/output_files.h) throws with the system's reason, and
// the temporary file is removed, so nothing half written ever carries a final name.
void writeBytesAtomically(const std::string& path, const std::string& target,
                          std::span<const unsigned char> bytes, const char* what) {
    std::string temp = tempPathFor(target);
    auto fail = [&](int err) {
        ::unlink(temp.c_str());
        throw ImageError(path + ": cannot write " + what + " (" + std::strerror(err) + ")");
    };
    // 0666 less the umask, as any new file: the rename gives the target these permissions.
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        int err = errno;
        throw ImageError(path + ": cannot write " + what + " (" + std::strerror(err) + ")");
    }
    size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            int err = n < 0 ? errno : ENOSPC;
            ::close(fd);
            fail(err);
        }
        done += static_cast<size_t>(n);
    }
    if (::close(fd) != 0) fail(errno);
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) fail(ec.value());
}

// Writes the bytes an encoder made (through the codec module, render/image_codec.h) with
// writeBytesAtomically, under the write gate. `encode` returns "" or the encoder's reason.
template <class Encode>
void writeImageAtomically(const std::string& path, Encode encode) {
    std::shared_lock gate(outputWriteGate());
    std::vector<unsigned char> bytes;
    std::string error = encode(imageCodec(), bytes);
    if (!error.empty()) throw ImageError(path + ": cannot write image (" + firstLine(error) + ")");
    writeBytesAtomically(path, resolveLinks(path), bytes, "image");
}

}  // namespace

std::shared_mutex& outputWriteGate() {
    static std::shared_mutex gate;
    return gate;
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::shared_lock gate(outputWriteGate());
    auto bytes = std::as_bytes(std::span(text));
    writeBytesAtomically(path, resolveLinks(path),
                         {reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()},
                         "file");
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
    writeImageAtomically(path, [&](const ImageCodec& codec, std::vector<unsigned char>& bytes) {
        return codec.encodePng(path, width, height, rgba.data(), bytes);
    });
}

void writeExr(const std::string& path, int width, int height, int channels,
              std::span<const float> data, const std::vector<std::string>& channelNames) {
    if (channels < 1 || static_cast<size_t>(channels) != channelNames.size()) {
        throw ImageError(path + ": cannot write image (" + std::to_string(channels) +
                         " channels, " + std::to_string(channelNames.size()) + " names)");
    }
    checkSize(path, width, height, data.size(), static_cast<size_t>(channels));
    writeImageAtomically(path, [&](const ImageCodec& codec, std::vector<unsigned char>& bytes) {
        return codec.encodeExr(path, width, height, data.data(), channelNames, bytes);
    });
}

void writeDepthImage(const std::string& path, const ShadowMap& map) {
    int channels = map.spec().texel().channels;
    if (channels == 1) {
        writeExr(path, map.width(), map.height(), 1, map.depths(), {"Z"});
    } else if (channels == 2) {
        writeExr(path, map.width(), map.height(), 2, map.depths(), {"M1", "M2"});
    } else {
        writeExr(path, map.width(), map.height(), 4, map.depths(), {"M1", "M2", "M3", "M4"});
    }
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

namespace {

// An OpenEXR file starts with these four bytes (OpenEXR's "File Layout": magic number 20000630).
constexpr unsigned char EXR_MAGIC[4] = {0x76, 0x2f, 0x31, 0x01};

// OpenEXR sizes each header attribute with an int32 and allocates that much before reading it:
// a 584-byte file claiming a 1.77 GB attribute cost 1.8 GiB and seconds. Walks the header(s)
// (name, type, int32 size, value; an empty name ends a header; a multi-part file, version flag
// 0x1000, has headers until an empty one) and refuses an attribute larger than what follows it
// in the file. Layout from OpenEXR's "File Layout" document (Kainz, Bogart, 2004-2013).
void checkExrHeader(const std::string& path, std::ifstream& in, std::uintmax_t fileSize) {
    auto bad = [&](const std::string& why) {
        throw ImageError(path + ": cannot read image (" + why + ")");
    };
    auto readName = [&](std::string& name) {
        name.clear();
        for (char c; in.get(c);) {
            if (c == '\0') return;
            if (name.size() >= 255) bad("a header name is longer than 255 bytes");
            name += c;
        }
        bad("the header is cut short");
    };
    unsigned char version[4] = {};
    in.read(reinterpret_cast<char*>(version), 4);
    bool multiPart = (version[1] & 0x10) != 0;
    std::string name, type;
    for (bool headerStart = true;;) {
        readName(name);
        if (name.empty()) {
            if (!multiPart || headerStart) return;
            headerStart = true;
            continue;
        }
        headerStart = false;
        readName(type);
        int32_t size = 0;
        in.read(reinterpret_cast<char*>(&size), 4);
        if (!in) bad("the header is cut short");
        auto at = static_cast<std::uintmax_t>(in.tellg());
        if (size < 0 || static_cast<std::uintmax_t>(size) > fileSize - at) {
            bad("header attribute '" + name + "' claims " + std::to_string(size) +
                " bytes; the file has " + std::to_string(fileSize - at) + " after it");
        }
        in.seekg(size, std::ios::cur);
    }
}

// An image opened by the codec module, closed when it goes.
class OpenImage {
  public:
    OpenImage(const ImageCodec& codec, void* handle, ImageCodecSpec spec)
        : mCodec(codec), mHandle(handle), mSpec(std::move(spec)) {}
    ~OpenImage() { mCodec.close(mHandle); }
    OpenImage(const OpenImage&) = delete;
    OpenImage& operator=(const OpenImage&) = delete;
    const ImageCodecSpec& spec() const { return mSpec; }
    // The first `channels` channels as floats; throws ImageError.
    void read(const std::string& path, int channels, float* out) const {
        std::string error = mCodec.readFloats(mHandle, channels, out);
        if (!error.empty()) {
            throw ImageError(path + ": cannot read image (" + firstLine(error) + ")");
        }
    }

  private:
    const ImageCodec& mCodec;
    void* mHandle;
    ImageCodecSpec mSpec;
};

// The one way an image input is opened (`trace --map`, `verify`'s folder): a regular file (a
// FIFO or a device would block OIIO or never end), at most MAX_IMAGE_FILE_BYTES, an EXR's
// header attribute sizes within the file, a flat 2D image of at most MAX_IMAGE_SIDE per side.
// All of it is asked before a pixel is allocated. `what` names the thing in the side message.
std::unique_ptr<OpenImage> openImageInput(const std::string& path, const char* unit,
                                          const char* what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::file_status status = fs::status(path, ec);
    if (!ec && fs::exists(status) && !fs::is_regular_file(status)) {
        throw ImageError(path + ": cannot read image (" +
                         (fs::is_directory(status) ? "it is a directory" : "not a regular file") +
                         ")");
    }
    if (!ec && fs::exists(status)) {
        std::uintmax_t size = fs::file_size(path, ec);
        if (!ec && size > MAX_IMAGE_FILE_BYTES) {
            throw ImageError(path + ": is " + std::to_string(size) +
                             " bytes; the limit for an image input is " +
                             std::to_string(MAX_IMAGE_FILE_BYTES));
        }
        std::ifstream in(path, std::ios::binary);
        unsigned char magic[4] = {};
        in.read(reinterpret_cast<char*>(magic), 4);
        if (!ec && in && std::memcmp(magic, EXR_MAGIC, 4) == 0) checkExrHeader(path, in, size);
    }
    const ImageCodec& codec = imageCodec();
    void* handle = nullptr;
    ImageCodecSpec spec;
    std::string error = codec.open(path, handle, spec);
    if (!error.empty()) throw ImageError(path + ": cannot read image (" + firstLine(error) + ")");
    auto in = std::make_unique<OpenImage>(codec, handle, std::move(spec));
    const ImageCodecSpec& s = in->spec();
    if (s.deep || s.width <= 0 || s.height <= 0 || s.depth > 1) {
        throw ImageError(path + ": cannot read image (not a flat 2D image)");
    }
    if (s.width > MAX_IMAGE_SIDE || s.height > MAX_IMAGE_SIDE) {
        throw ImageError(path + ": is " + std::to_string(s.width) + " x " +
                         std::to_string(s.height) + " " + unit + "; " + what + " is at most " +
                         std::to_string(MAX_IMAGE_SIDE) + " on a side");
    }
    return in;
}

}  // namespace

FloatImage readFloatImage(const std::string& path) {
    QuietStderr quiet;
    std::unique_ptr<OpenImage> in = openImageInput(path, "pixels", "an image");
    const ImageCodecSpec& spec = in->spec();
    if (spec.channels < 1 || spec.channels > 4) {
        throw ImageError(path + ": has " + std::to_string(spec.channels) +
                         " channels; an image has 1 to 4");
    }
    FloatImage img{spec.width, spec.height, spec.channels, {}};
    img.data.resize(static_cast<size_t>(spec.width) * spec.height * spec.channels);
    in->read(path, spec.channels, img.data.data());
    return img;
}

ShadowMap readDepthImage(const std::string& path) {
    QuietStderr quiet;
    std::unique_ptr<OpenImage> in = openImageInput(path, "texels", "a depth map");
    const ImageCodecSpec& spec = in->spec();
    if (spec.channels != 1) {
        throw ImageError(path + ": has " + std::to_string(spec.channels) +
                         " channels; a depth map has 1");
    }
    if (!spec.floats) {
        throw ImageError(path + ": holds " + spec.formatName +
                         " integers; a depth map holds floats (half or float)");
    }
    std::vector<float> depths(static_cast<size_t>(spec.width) * spec.height);
    // Scanlines in file order, first scanline first: that is ShadowMap's row 0.
    in->read(path, 1, depths.data());
    ShadowMap map(spec.width, spec.height, std::move(depths));
    if (std::optional<std::string> bad = map.findInvalidTexel()) {
        throw ImageError(path + ": " + *bad);
    }
    return map;
}

ShadowMap readMapImage(const std::string& path) {
    int channels = 1;
    {
        QuietStderr quiet;
        channels = openImageInput(path, "texels", "a map")->spec().channels;
    }
    if (channels == 1) return readDepthImage(path);
    if (channels != 2 && channels != 4) {
        throw ImageError(path + ": has " + std::to_string(channels) +
                         " channels; a map has 1 (depth), 2 or 4 (moments)");
    }
    QuietStderr quiet;
    std::unique_ptr<OpenImage> in = openImageInput(path, "texels", "a map");
    const ImageCodecSpec& spec = in->spec();
    if (!spec.floats) {
        throw ImageError(path + ": holds " + spec.formatName +
                         " integers; a moments map holds floats (half or float)");
    }
    std::vector<float> texels(static_cast<size_t>(spec.width) * spec.height * channels);
    // Scanlines in file order, first scanline first: that is ShadowMap's row 0.
    in->read(path, channels, texels.data());
    MapSpec map;
    map.size = {spec.width, spec.height};
    map.texels = channels == 2 ? TexelKind::Moments2F32 : TexelKind::Moments4F32;
    ShadowMap out(map, std::move(texels));
    if (std::optional<std::string> bad = out.findInvalidTexel()) {
        throw ImageError(path + ": " + *bad);
    }
    return out;
}

std::string outputTarget(const std::string& path) { return resolveLinks(path); }

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

}  // namespace pcf
