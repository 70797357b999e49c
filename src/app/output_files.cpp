#include "app/output_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "app/cli_util.h"

namespace pcf {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& option, const fs::path& path) {
    return option.empty() ? path.string() : option + " " + path.string();
}

}  // namespace

OutputFiles::~OutputFiles() {
    if (mCommitted) return;
    std::error_code ec;
    for (const fs::path& p : mNewFiles) fs::remove(p, ec);
    for (auto it = mCreatedDirs.rbegin(); it != mCreatedDirs.rend(); ++it) {
        fs::remove(*it, ec);  // only removes it when empty
    }
}

void OutputFiles::prepareDirectory(const std::string& option, const fs::path& target,
                                   const fs::path& dir) {
    // Walk up to the nearest folder that exists, then create the missing ones below it.
    std::vector<fs::path> missing;
    // "frames/" names the folder "frames": drop the empty last component the slash leaves.
    fs::path at = dir.empty() ? fs::path(".") : dir;
    while (!at.has_filename() && at.has_parent_path() && at.parent_path() != at) {
        at = at.parent_path();
    }
    std::error_code ec;
    while (!fs::exists(at, ec)) {
        missing.push_back(at);
        if (!at.has_parent_path() || at.parent_path() == at) break;
        at = at.parent_path();
    }
    if (fs::exists(at, ec) && !fs::is_directory(at, ec)) {
        throw UsageError(quoted(option, target) + ": " + at.string() + " is not a directory");
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        bool created = fs::create_directory(*it, ec);
        if (ec || !fs::is_directory(*it)) {
            std::string why = ec ? ec.message() : "cannot create it";
            throw UsageError(quoted(option, target) + ": cannot create folder " + it->string() +
                             " (" + why + ")");
        }
        if (created) mCreatedDirs.push_back(*it);  // one that appeared meanwhile is not ours
    }
    // Access checks say yes to root everywhere; only a real file proves the folder takes one.
    fs::path probe = (dir.empty() ? fs::path(".") : dir) /
                     (".pcfscope-probe-" + std::to_string(getpid()));
    int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) {
        int err = errno;
        std::string where = dir.empty() ? "the current folder" : dir.string();
        throw UsageError(quoted(option, target) + ": cannot write into " + where + " (" +
                         std::strerror(err) + ")");
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

void OutputFiles::add(const std::string& option, const fs::path& path) {
    if (path.empty()) throw UsageError(option + " needs a file name");
    std::error_code ec;
    // symlink_status: a link is the user's even when it points nowhere; never take it for free.
    bool exists = fs::symlink_status(path, ec).type() != fs::file_type::not_found;
    if (exists && fs::is_directory(path, ec)) {
        throw UsageError(quoted(option, path) + " is a directory, not a file");
    }
    if (exists && !mForce) {
        throw UsageError(quoted(option, path) + " already exists; pass --force to overwrite it");
    }
    prepareDirectory(option, path, path.parent_path());
    if (!exists) mNewFiles.push_back(path);
}

void OutputFiles::addDirectory(const std::string& option, const fs::path& dir) {
    if (dir.empty()) throw UsageError(option + " needs a directory");
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        throw UsageError(quoted(option, dir) + " is not a directory");
    }
    prepareDirectory(option, dir, dir);
}

void requireExtension(const std::string& option, const fs::path& path,
                      const std::string& extension) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != extension) {
        throw UsageError(quoted(option, path) + ": the file name must end in " + extension);
    }
}

}  // namespace pcf
