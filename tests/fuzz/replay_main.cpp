// replay_main.cpp: a fuzz target's main without libFuzzer (gcc builds): runs the target once on
// every file named, or on every file of every folder named, the way `target -runs=0 DIR` does.
// Flags (arguments starting with '-') are libFuzzer's and are ignored.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

int runFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "replay: cannot read %s\n", file.c_str());
        return 1;
    }
    std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // A copy of exactly `size` bytes, so ASan sees a read past the end as libFuzzer would.
    std::vector<uint8_t> data(bytes.begin(), bytes.end());
    LLVMFuzzerTestOneInput(data.data(), data.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    int files = 0;
    int failed = 0;
    for (int k = 1; k < argc; ++k) {
        std::string arg = argv[k];
        if (arg.starts_with("-")) continue;
        std::filesystem::path p(arg);
        if (std::filesystem::is_directory(p)) {
            for (const auto& entry : std::filesystem::directory_iterator(p)) {
                if (!entry.is_regular_file()) continue;
                failed += runFile(entry.path());
                ++files;
            }
        } else {
            failed += runFile(p);
            ++files;
        }
    }
    std::fprintf(stderr, "replay: %d inputs, none crashed\n", files);
    return failed == 0 && files > 0 ? 0 : 1;
}
