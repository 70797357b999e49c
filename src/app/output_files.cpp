#include "app/output_files.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <shared_mutex>
#include <thread>

#include "app/cli_util.h"
#include "render/image_io.h"

namespace pcf {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& option, const fs::path& path) {
    return option.empty() ? path.string() : option + " " + path.string();
}

// The live sets, for the interrupt cleanup. Guards each set's lists too: the cleanup thread
// reads them while the command's thread may be adding to them.
std::mutex& registryMutex() {
    static std::mutex m;
    return m;
}

std::vector<OutputFiles*>& registry() {
    static std::vector<OutputFiles*> sets;
    return sets;
}

// Scratch folders a command stages its outputs in: ".pcfscope-<what>-<pid>" (cmd_bench's).
bool isOurScratch(const fs::path& p) {
    std::string name = p.filename().string();
    // Appended, not "-" + ...: GCC 12 at -O3 warns (-Wrestrict, a false positive) on that.
    std::string suffix = "-";
    suffix += std::to_string(getpid());
    return name.starts_with(".pcfscope-") && name.ends_with(suffix);
}

// The output folders this process holds locked: one flock per folder (by device and inode, so
// "out", "./out" and a link to it are one), counted, since one command may write several files
// into a folder and nested OutputFiles (the viewer's) may share it.
struct FolderLock {
    int fd = -1;
    int users = 0;
};

std::map<std::pair<dev_t, ino_t>, FolderLock>& folderLocks() {
    static std::map<std::pair<dev_t, ino_t>, FolderLock> locks;
    return locks;
}

}  // namespace

// One writer per output folder: an advisory flock on the folder itself (no lock file left in
// the user's folder; the kernel drops it when the process ends, however it ends). Taken before
// any name is checked, so a second pcfscope writing into the same folder is refused up front,
// before it has claimed, rendered or removed anything. Called under registryMutex.
void OutputFiles::lockFolder(const std::string& option, const fs::path& target,
                             const fs::path& dir) {
    fs::path at = dir.empty() ? fs::path(".") : dir;
    int fd = ::open(at.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || ::fstat(fd, &st) != 0) {
        int err = errno;
        if (fd >= 0) ::close(fd);
        throw UsageError(quoted(option, target) + ": cannot open folder " + at.string() + " (" +
                         std::strerror(err) + ")");
    }
    auto key = std::make_pair(st.st_dev, st.st_ino);
    FolderLock& lock = folderLocks()[key];
    if (lock.users == 0) {
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            int err = errno;
            ::close(fd);
            folderLocks().erase(key);
            if (err == EWOULDBLOCK) {
                throw UsageError(quoted(option, target) + ": another pcfscope is writing into " +
                                 at.string() + "; wait for it to finish or choose another folder");
            }
            throw UsageError(quoted(option, target) + ": cannot lock folder " + at.string() + " (" +
                             std::strerror(err) + ")");
        }
        lock.fd = fd;
    } else {
        ::close(fd);
    }
    if (std::find(mLocks.begin(), mLocks.end(), key) == mLocks.end()) {
        ++lock.users;
        mLocks.push_back(key);
    }
}

void OutputFiles::unlockFolders() {
    for (const auto& key : mLocks) {
        auto it = folderLocks().find(key);
        if (it == folderLocks().end()) continue;
        if (--it->second.users == 0) {
            ::close(it->second.fd);  // closing the only descriptor releases the flock
            folderLocks().erase(it);
        }
    }
    mLocks.clear();
}

OutputFiles::OutputFiles(bool force) : mForce(force) {
    std::lock_guard lock(registryMutex());
    registry().push_back(this);
}

OutputFiles::~OutputFiles() {
    {
        std::lock_guard lock(registryMutex());
        std::erase(registry(), this);
    }
    if (!mCommitted) takeBack();
    std::lock_guard lock(registryMutex());
    unlockFolders();
}

void OutputFiles::commit() {
    std::lock_guard lock(registryMutex());
    mCommitted = true;
}

// Staged files replace what their final names lead to, as every writer does (image_io.h
// outputTarget): a final name that is a link is written through, not replaced by a file.
void OutputFiles::commitStaged(const fs::path& stagingDir, const fs::path& outDir,
                               const std::vector<std::string>& names) {
    std::shared_lock gate(outputWriteGate());
    for (const std::string& name : names) {
        fs::rename(stagingDir / name, outputTarget((outDir / name).string()));
    }
    commit();
}

void OutputFiles::commitMoves(const std::vector<std::pair<fs::path, fs::path>>& moves) {
    std::shared_lock gate(outputWriteGate());
    for (const auto& [staged, final] : moves) fs::rename(staged, outputTarget(final.string()));
    commit();
}

void OutputFiles::takeBack() {
    std::error_code ec;
    for (const fs::path& p : mNewFiles) fs::remove(p, ec);
    for (const fs::path& dir : mDirs) {
        for (const auto& entry : fs::directory_iterator(dir, ec)) {
            if (isOurScratch(entry.path())) fs::remove_all(entry.path(), ec);
        }
    }
    for (auto it = mCreatedDirs.rbegin(); it != mCreatedDirs.rend(); ++it) {
        fs::remove(*it, ec);  // only removes it when empty
    }
}

void OutputFiles::addInput(const std::string& option, const fs::path& path) {
    std::lock_guard lock(registryMutex());
    mInputs.emplace_back(option, path);
}

void OutputFiles::requireNotInput(const std::string& outputOption, const fs::path& output,
                                  const std::string& inputOption, const fs::path& input) {
    std::error_code ec;
    if (input.empty() || output.empty()) return;
    // equivalent: the same file by any name (a link, a hard link, ./x). Only files that exist
    // can be the same; a new output is never an input.
    if (fs::equivalent(output, input, ec) && !ec) {
        throw UsageError(quoted(outputOption, output) + " is the file " + inputOption + " " +
                         input.string() + " reads; write the output elsewhere");
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
    fs::path probe =
        (dir.empty() ? fs::path(".") : dir) / (".pcfscope-probe-" + std::to_string(getpid()));
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

namespace {

// A path as outputs are compared: absolute, its links resolved as far as it exists.
fs::path claimKey(const fs::path& path) {
    std::error_code ec;
    fs::path key = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path).lexically_normal() : key;
}

}  // namespace

// One path as a file and as a folder (`-o X --png X`, where the folder made for --png then made
// -o "a directory") is refused before anything is made. A file added again is the same output
// (a command's own second look at it: export's page files); a folder may be named again (several
// outputs in one folder). Returns whether `path` is new to this set. Called under registryMutex.
bool OutputFiles::claim(const std::string& option, const fs::path& path, bool directory) {
    fs::path key = claimKey(path);
    for (const Claim& c : mClaims) {
        if (c.key != key) continue;
        if (c.directory == directory) return false;
        throw UsageError(quoted(option, path) + " and " + quoted(c.option, c.path) +
                         " are the same path, as a file and as a folder");
    }
    mClaims.push_back({option, path, key, directory});
    return true;
}

void OutputFiles::addEach(const std::string& option, const std::vector<fs::path>& paths) {
    for (size_t k = 0; k < paths.size(); ++k) {
        for (size_t before = 0; before < k; ++before) {
            if (claimKey(paths[before]) == claimKey(paths[k])) {
                throw UsageError(quoted(option, paths[k]) + " is given twice");
            }
        }
    }
    for (const fs::path& path : paths) add(option, path);
}

void OutputFiles::add(const std::string& option, const fs::path& path) {
    if (path.empty()) throw UsageError(option + " needs a file name");
    std::lock_guard lock(registryMutex());
    if (!claim(option, path, false)) return;
    std::error_code ec;
    // symlink_status: a link is the user's even when it points nowhere; never take it for free.
    bool exists = fs::symlink_status(path, ec).type() != fs::file_type::not_found;
    if (exists && fs::is_directory(path, ec)) {
        throw UsageError(quoted(option, path) + " is a directory, not a file");
    }
    for (const auto& [inputOption, input] : mInputs) {
        requireNotInput(option, path, inputOption, input);
    }
    // The folder first (made if missing, then locked), then the name: whether it exists is
    // only settled once no other pcfscope can be writing there.
    prepareDirectory(option, path, path.parent_path());
    lockFolder(option, path, path.parent_path());
    exists = fs::symlink_status(path, ec).type() != fs::file_type::not_found;
    if (exists && !mForce) {
        throw UsageError(quoted(option, path) + " already exists; pass --force to overwrite it");
    }
    if (!exists) mNewFiles.push_back(path);
}

void OutputFiles::addFilesIn(const std::string& option, const fs::path& dir,
                             const std::vector<std::string>& names) {
    addDirectory(option, dir);
    for (const std::string& name : names) add(option, dir / name);
}

void OutputFiles::addDirectory(const std::string& option, const fs::path& dir) {
    if (dir.empty()) throw UsageError(option + " needs a directory");
    std::lock_guard lock(registryMutex());
    if (!claim(option, dir, true)) return;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        throw UsageError(quoted(option, dir) + " is not a directory");
    }
    prepareDirectory(option, dir, dir);
    lockFolder(option, dir, dir);
    mDirs.push_back(dir);
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

void installInterruptCleanup() {
    // Past `ulimit -f` the kernel sends SIGXFSZ, whose default ends the process on the spot
    // (exit 153, temporary files and scratch folders left). Ignored, the write fails with EFBIG
    // instead, which every writer checks: one line, exit 2, outputs taken back.
    std::signal(SIGXFSZ, SIG_IGN);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    // Blocked here, before any thread exists, so every thread (GL drivers' and the ground
    // truth's included) inherits the mask and only the waiter below ever sees these signals.
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set] {
        int sig = 0;
        while (sigwait(&set, &sig) != 0) {
        }
        // No write is half done once the gate is ours, and none starts after: the command
        // thread waits at the gate until the process ends.
        std::unique_lock gate(outputWriteGate());
        std::lock_guard lock(registryMutex());
        bool removed = false;
        for (OutputFiles* files : registry()) {
            if (files->mCommitted) continue;
            removed = removed || !files->mNewFiles.empty() || !files->mCreatedDirs.empty();
            files->takeBack();
        }
        endProgressLine();  // a line of its own, not after "animate [###...] 4/3600"
        std::fprintf(stderr, "pcfscope: interrupted (%s)%s\n", sig == SIGINT ? "SIGINT" : "SIGTERM",
                     removed ? "; removed the files this command had written" : "");
        std::fflush(stderr);
        _exit(128 + sig);
    }).detach();
}

std::string withFinalNames(std::string message) {
    // ".pcfscope-WHAT-PID/", WHAT lower-case letters: StagingDir's names, this process's.
    const std::string prefix = ".pcfscope-";
    const std::string end = "-" + std::to_string(getpid()) + "/";
    for (size_t at = message.find(prefix); at != std::string::npos; at = message.find(prefix, at)) {
        size_t word = at + prefix.size();
        size_t stop = word;
        while (stop < message.size() && std::islower(static_cast<unsigned char>(message[stop]))) {
            ++stop;
        }
        if (stop > word && message.compare(stop, end.size(), end) == 0) {
            message.erase(at, stop + end.size() - at);
        } else {
            at = word;
        }
    }
    return message;
}

StagingDir::StagingDir(const fs::path& outDir, const std::string& what, const std::string& subdir)
    : mPath(outDir / (".pcfscope-" + what + "-" + std::to_string(getpid()))) {
    fs::create_directories(subdir.empty() ? mPath : mPath / subdir);
}

StagingDir::~StagingDir() {
    std::error_code ec;
    fs::remove_all(mPath, ec);
}

}  // namespace pcf
