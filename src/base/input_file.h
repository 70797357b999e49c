// input_file.h: reading a text input (a lesson, a scene file, a chart's bench.csv) whole, with
// the checks every such file gets: it must be a regular file (a FIFO or a device would block or
// never end) and at most MAX_INPUT_FILE_BYTES long.
#pragma once

#include <cstddef>
#include <string>

namespace pcf {

// Lessons are a few KB and a bench.csv of every method, kernel and map size ~100 KB.
constexpr std::size_t MAX_INPUT_FILE_BYTES = 1 << 20;

// The bytes of the file at `path`. Throws InputError(path, 0, ...): "cannot open file",
// "cannot open file (it is a directory)", "not a regular file (a FIFO, device or socket)",
// "is 3000000 bytes; the limit for an input file is 1048576".
std::string readInputFile(const std::string& path);

}  // namespace pcf
