#include "base/input_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "base/input_error.h"

namespace pcf {

std::string readInputFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // status follows links: a link to a lesson is a lesson. Asked before opening, because
    // opening a FIFO for reading blocks until someone writes to it.
    fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw InputError(path, 0, "cannot open file");
    if (fs::is_directory(status)) throw InputError(path, 0, "cannot open file (it is a directory)");
    if (!fs::is_regular_file(status)) {
        throw InputError(path, 0, "not a regular file (a FIFO, device or socket)");
    }
    std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > MAX_INPUT_FILE_BYTES) {
        throw InputError(path, 0,
                         "is " + std::to_string(size) + " bytes; the limit for an input file is " +
                             std::to_string(MAX_INPUT_FILE_BYTES));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot open file");
    // One byte past the limit tells a file that grew since the size was asked.
    std::string text;
    text.resize(MAX_INPUT_FILE_BYTES + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) throw InputError(path, 0, "cannot read file");
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > MAX_INPUT_FILE_BYTES) {
        throw InputError(path, 0,
                         "is over " + std::to_string(MAX_INPUT_FILE_BYTES) +
                             " bytes, the limit for an input file");
    }
    return text;
}

}  // namespace pcf
