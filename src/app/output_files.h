// output_files.h: the files a command is going to write, checked before any work starts and
// taken back if the command fails half way, so that the user never finds half an output.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pcf {

void installInterruptCleanup();

// Every live OutputFiles is known to the interrupt cleanup (installInterruptCleanup below), so
// Ctrl-C takes back what an error would have taken back.
class OutputFiles {
  public:
    // force: files that exist may be overwritten (otherwise they are refused).
    explicit OutputFiles(bool force);
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Checks that `path` (given by `option`) can be written: it must not exist unless force, it
    // must not be a directory, and its folder must be (or become) a writable directory. Missing
    // folders are created now and a probe file is written there and removed. The folder is
    // locked until this set is destroyed: a second pcfscope adding an output in the same folder
    // meanwhile is refused ("another pcfscope is writing into DIR"). Throws UsageError naming
    // the option, the path and the reason; nothing is left behind on failure.
    void add(const std::string& option, const std::filesystem::path& path);
    // The same for a directory the command writes into (created now if missing). A path added as
    // a file and as a directory is refused (UsageError naming both options); one added again as
    // the same kind is the same output.
    void addDirectory(const std::string& option, const std::filesystem::path& dir);
    // add() for each of `paths`, the files one option names (animate's -o list): two that are the
    // same file by any spelling ("a.mp4", "./a.mp4") are refused before any is added: the
    // command would write one over the other.
    void addEach(const std::string& option, const std::vector<std::filesystem::path>& paths);
    // The directory and each of `names` in it (a command's set of files in -o).
    void addFilesIn(const std::string& option, const std::filesystem::path& dir,
                    const std::vector<std::string>& names);

    // Records a file the command reads (call before add): add() then refuses an output that is this
    // file (see requireNotInput), --force or not.
    void addInput(const std::string& option, const std::filesystem::path& path);

    // Refuses (UsageError) when `output` is `input` or the same file by another name (a link,
    // a hard link, ./x): the command would overwrite what it reads, --force or not. Inputs
    // that do not exist are skipped (their own check reports them).
    static void requireNotInput(const std::string& outputOption,
                                const std::filesystem::path& output, const std::string& inputOption,
                                const std::filesystem::path& input);

    // The command succeeded: keep everything.
    void commit();

    // Moves each of `names` from `stagingDir` to the same name in `outDir`, then commits, all
    // under image_io's write gate: an interrupt finds either nothing moved (and takes the set
    // back) or the set committed, never half the files in place. A failed move throws (the set
    // is then taken back as on any error).
    void commitStaged(const std::filesystem::path& stagingDir, const std::filesystem::path& outDir,
                      const std::vector<std::string>& names);

    // The same for files staged in several folders: each (staged, final) pair renamed, then the
    // set committed, under the one gate (a video staged beside each of its final names).
    void commitMoves(
        const std::vector<std::pair<std::filesystem::path, std::filesystem::path>>& moves);

    // Removes what this set created (files, then its folders, then scratch folders named
    // ".pcfscope-*-PID" of this process inside them). Called by the destructor unless committed,
    // and by the interrupt cleanup.
    void takeBack();

  private:
    friend void installInterruptCleanup();

    void prepareDirectory(const std::string& option, const std::filesystem::path& target,
                          const std::filesystem::path& dir);
    void lockFolder(const std::string& option, const std::filesystem::path& target,
                    const std::filesystem::path& dir);
    bool claim(const std::string& option, const std::filesystem::path& path, bool directory);

    // A path this set was given, as given and as compared (absolute, links resolved).
    struct Claim {
        std::string option;
        std::filesystem::path path;
        std::filesystem::path key;
        bool directory = false;
    };
    void unlockFolders();

    bool mForce;
    bool mCommitted = false;
    std::vector<std::filesystem::path> mNewFiles;     // did not exist when added
    std::vector<std::filesystem::path> mCreatedDirs;  // made by us, parents first
    std::vector<std::pair<std::string, std::filesystem::path>> mInputs;
    std::vector<std::filesystem::path> mDirs;     // folders written into (scratch may be there)
    std::vector<std::pair<dev_t, ino_t>> mLocks;  // output folders locked (lockFolder)
    std::vector<Claim> mClaims;                   // every file and folder added (claim)
};

// A scratch folder ".pcfscope-<what>-<pid>" inside DIR that a command stages its outputs in (and
// with `subdir`, that folder inside it too); removed, with whatever is still in it, when it goes
// out of scope. The interrupt cleanup finds it by that name.
class StagingDir {
  public:
    StagingDir(const std::filesystem::path& outDir, const std::string& what,
               const std::string& subdir = "");
    ~StagingDir();
    StagingDir(const StagingDir&) = delete;
    StagingDir& operator=(const StagingDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }

  private:
    std::filesystem::path mPath;
};

// Ctrl-C (SIGINT) and SIGTERM leave no half output. Called once by main before any thread
// starts: both signals are blocked in every thread and one thread waits for them. On a signal it
// takes image_io's write gate exclusively (so no image or text write is half done and no
// temporary file exists), takes back every OutputFiles not yet committed, prints one line and
// exits with 128 + the signal's number: 130 for SIGINT, 143 for SIGTERM (the shell's
// convention). Commands need no checks of their own.
void installInterruptCleanup();

// `message` with the scratch folders of this process taken out of its paths: a failure while
// writing a staged file (a full disk) names the file the user asked for, "out/bench.csv", not
// "out/.pcfscope-bench-4711/bench.csv". The command line says every error through it.
std::string withFinalNames(std::string message);

// Throws UsageError unless `path` ends in `extension` (".png", ".exr"; any case): the file's
// name should say what is in it.
void requireExtension(const std::string& option, const std::filesystem::path& path,
                      const std::string& extension);

}  // namespace pcf
