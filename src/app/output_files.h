// output_files.h: the files a command is going to write, checked before any work starts and
// taken back if the command fails half way, so that the user never finds half an output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pcf {

class OutputFiles {
public:
    // force: files that exist may be overwritten (otherwise they are refused).
    explicit OutputFiles(bool force) : mForce(force) {}
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Checks that `path` (given by `option`) can be written: it must not exist unless force, it
    // must not be a directory, and its folder must be (or become) a writable directory. Missing
    // folders are created now and a probe file is written there and removed. Throws UsageError
    // naming the option, the path and the reason; nothing is left behind on failure.
    void add(const std::string& option, const std::filesystem::path& path);
    // The same for a directory the command writes into (created now if missing).
    void addDirectory(const std::string& option, const std::filesystem::path& dir);

    // The command succeeded: keep everything.
    void commit() { mCommitted = true; }

private:
    void prepareDirectory(const std::string& option, const std::filesystem::path& target,
                          const std::filesystem::path& dir);

    bool mForce;
    bool mCommitted = false;
    std::vector<std::filesystem::path> mNewFiles;     // did not exist when added
    std::vector<std::filesystem::path> mCreatedDirs;  // made by us, parents first
};

// Throws UsageError unless `path` ends in `extension` (".png", ".exr"; any case): the file's
// name should say what is in it.
void requireExtension(const std::string& option, const std::filesystem::path& path,
                      const std::string& extension);

}  // namespace pcf
