// Every pcfscope command shown in README.md and docs/*.md, in a code span or a fenced block, runs:
// a concrete command (`build/pcfscope export 3 -o slides ...`) is run as shown, in a folder of
// its own, and must succeed; a synopsis (`pcfscope view [LESSON] [--size WxH]`) names only
// options its command's --help lists; a bare command name in a sentence or table (`pcfscope
// render`) is a command whose --help works. What the text says a command shows is checked where
// it states a fact (the ten methods, the worked example's 0.8, one PNG and JSON per step, the
// main job's folder, pcss under a spot).
//
// Two kinds of command cannot run as shown, and are changed only as the docs themselves say:
// `view` opens a window, so it runs under an Xvfb of the test's own with `--screenshot F`, which
// "writes the frame after them and quits" (docs/user-guide.md); and a command too slow for a
// test runs with the options its doc names for a quick run (SHORTENED: the doc's own words are
// checked to be there).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"
#include "virtual_display.h"

namespace {

namespace fs = std::filesystem;

const fs::path SOURCE_DIR = PCFSCOPE_SOURCE_DIR;

std::vector<fs::path> documents() {
    std::vector<fs::path> docs{SOURCE_DIR / "README.md"};
    for (const auto& entry : fs::directory_iterator(SOURCE_DIR / "docs")) {
        if (entry.path().extension() == ".md") docs.push_back(entry.path());
    }
    std::sort(docs.begin(), docs.end());
    return docs;
}

// A command as a doc shows it.
struct Shown {
    std::string doc;  // "README.md", "docs/user-guide.md"
    std::string command;
    bool chained = false;  // after `&&`: runs where the command before it ran
};

std::string squeezed(const std::string& s) {
    std::istringstream in(s);
    std::string out;
    for (std::string w; in >> w;) out += (out.empty() ? "" : " ") + w;
    return out;
}

bool isCommand(const std::string& s) {
    return std::regex_search(s, std::regex("^(build/)?pcfscope( |$)"));
}

// The commands of one doc: fenced lines that start with (build/)pcfscope, with their `\`
// continuations and each side of a `&&`; and code spans outside the fences.
std::vector<Shown> commandsOf(const fs::path& path) {
    std::string doc = path.parent_path() == SOURCE_DIR ? path.filename().string()
                                                       : "docs/" + path.filename().string();
    std::string text = testutil::readAll(path);
    std::vector<Shown> out;
    std::istringstream in(text);
    std::string prose, pending;
    bool fenced = false;
    auto add = [&](const std::string& line) {
        std::string rest = line;
        bool chained = false;
        for (size_t amp; (amp = rest.find("&&")) != std::string::npos; chained = true) {
            out.push_back({doc, squeezed(rest.substr(0, amp)), chained});
            rest = rest.substr(amp + 2);
        }
        out.push_back({doc, squeezed(rest), chained});
    };
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("```")) {
            fenced = !fenced;
            prose += "\n";
            continue;
        }
        if (!fenced) {
            prose += line + "\n";
            continue;
        }
        std::string t = squeezed(line);
        if (pending.empty() && !isCommand(t)) continue;
        pending += (pending.empty() ? "" : " ") + t;
        if (!pending.empty() && pending.back() == '\\') {
            pending.pop_back();
            continue;
        }
        add(pending);
        pending.clear();
    }
    // (A span in double backticks, "`` `code span` ``", holds single ones: it goes first.)
    prose = std::regex_replace(prose, std::regex("``[^`]*(`[^`]+`[^`]*)*``"), " ");
    std::regex span("`([^`]+)`");
    for (std::sregex_iterator it(prose.begin(), prose.end(), span), end; it != end; ++it) {
        std::string c = squeezed((*it)[1]);
        if (isCommand(c)) out.push_back({doc, c, false});
    }
    return out;
}

std::vector<Shown> shownCommands() {
    std::vector<Shown> all;
    for (const fs::path& doc : documents()) {
        for (Shown& s : commandsOf(doc)) all.push_back(std::move(s));
    }
    return all;
}

// The words after `pcfscope`.
std::vector<std::string> wordsOf(const std::string& command) {
    std::istringstream in(command);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    words.erase(words.begin());
    return words;
}

const std::set<std::string> SUBCOMMANDS = {"view",  "export",  "render",    "trace",    "methods",
                                           "truth", "bench",   "stability", "verify",   "lesson",
                                           "check", "animate", "pick",      "exercise", "advise"};

// A synopsis: optional parts in brackets, alternatives, or placeholders in capitals (LESSON,
// DIR, WxH) where a value goes.
bool isSynopsis(const std::string& command) {
    if (command.find_first_of("[|<") != std::string::npos) return true;
    for (const std::string& w : wordsOf(command)) {
        if (std::regex_match(w, std::regex("[A-Z][A-Z]+|WxH|.*=V1.*"))) return true;
    }
    return false;
}

// A command named in a sentence or a table: only subcommand words (`pcfscope render`).
bool isName(const std::string& command) {
    if (command.starts_with("build/")) return false;
    std::vector<std::string> words = wordsOf(command);
    return !words.empty() && std::all_of(words.begin(), words.end(), [](const std::string& w) {
        return SUBCOMMANDS.count(w) > 0;
    });
}

// The subcommand words a command starts with ("lesson check").
std::string subcommandOf(const std::string& command) {
    std::string sub;
    for (const std::string& w : wordsOf(command)) {
        if (!SUBCOMMANDS.count(w)) break;
        sub += (sub.empty() ? "" : " ") + w;
    }
    return sub;
}

// Commands that take minutes as shown run with what their doc says makes a quick run: the doc,
// the command's start, what is added, and the doc's words that say so.
struct Shortened {
    const char* doc;
    const char* starts;
    const char* added;
    const char* docSays;
};
const Shortened SHORTENED[] = {
    {"README.md", "build/pcfscope bench", "--quick", "`--quick` gives a first look in seconds"},
    {"README.md", "build/pcfscope stability", "--quick", "`--quick` gives a first look in seconds"},
    {"docs/measurement.md", "build/pcfscope stability", "--quick", "`--quick` about"},
    {"docs/measurement.md", "build/pcfscope bench --scene post-in-sun", "--size 160x90 --repeats 1",
     "`--size 160x90 --repeats 1` runs the same recipe"},
    {"docs/user-guide.md", "pcfscope animate", "--frames 12 --size 640x360",
     "`--frames 12 --size 640x360` makes a quick draft of any animation here"},
};

// `args` with the options of `added` ("--size 160x90 --quick"): an option it already has takes
// the new value, another is appended.
std::string withOptions(std::string args, const std::string& added) {
    std::istringstream in(added);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    for (size_t k = 0; k < words.size(); ++k) {
        bool valued = k + 1 < words.size() && !words[k + 1].starts_with("--");
        std::string flag = " " + words[k] + " ";
        size_t at = (args + " ").find(flag);
        if (at == std::string::npos || !valued) {
            if (at == std::string::npos)
                args += " " + words[k] + (valued ? " " + words[k + 1] : "");
        } else {
            size_t value = at + flag.size();
            size_t end = args.find(' ', value);
            args.replace(value, end == std::string::npos ? std::string::npos : end - value,
                         words[k + 1]);
        }
        k += valued;
    }
    return args;
}

// The shell command a test runs for a doc's command, in its folder.
std::string runnable(const Shown& s, int index, const std::string& display) {
    std::string args = s.command.substr(s.command.find("pcfscope") + 8);
    for (const Shortened& sh : SHORTENED) {
        if (s.doc == sh.doc && s.command.starts_with(sh.starts)) args = withOptions(args, sh.added);
    }
    std::string env;
    if (subcommandOf(s.command) == "view") {
        args += " --screenshot view-" + std::to_string(index) + ".png";
        env = "DISPLAY=" + display;
    } else {
        env = "DISPLAY=";  // the main job exports when there is no display
    }
    return env + " " + PCFSCOPE_EXE + args;
}

struct Outcome {
    int exitCode = -1;
    std::string out, err;
};

Outcome runIn(const fs::path& dir, const std::string& shell) {
    fs::path out = dir / ".out", err = dir / ".err";
    std::string cmd = "cd '" + dir.string() + "' && " + shell + " >'" + out.string() + "' 2>'" +
                      err.string() + "' </dev/null";
    int status = std::system(cmd.c_str());
    Outcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, testutil::readAll(out),
              testutil::readAll(err)};
    fs::remove(out);
    fs::remove(err);
    return r;
}

// The first ```toml block of docs/lesson-authoring.md: the worked example, my-lesson.toml.
std::string workedExample() {
    std::istringstream doc(testutil::readAll(SOURCE_DIR / "docs/lesson-authoring.md"));
    std::string example;
    bool inside = false;
    for (std::string line; std::getline(doc, line);) {
        if (!inside && line == "```toml") {
            inside = true;
        } else if (inside && line == "```") {
            break;
        } else if (inside) {
            example += line + "\n";
        }
    }
    return example;
}

class DocCommands : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("docs-commands"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    fs::path mDir;
};

TEST(DocCommandsFound, EveryDocsCommandIsFoundAndSorted) {
    std::vector<Shown> all = shownCommands();
    int synopses = 0, names = 0, runs = 0;
    std::set<std::string> texts;
    for (const Shown& s : all) {
        texts.insert(s.command);
        if (isSynopsis(s.command)) {
            ++synopses;
        } else if (isName(s.command)) {
            ++names;
        } else {
            ++runs;
        }
    }
    // Commands of each kind, from code spans, fenced blocks and `&&` lines.
    EXPECT_GT(synopses, 10);
    EXPECT_GT(names, 10);
    EXPECT_GT(runs, 15);
    for (const char* c :
         {"build/pcfscope export 3 -o slides --size 1280x720 --presentation",
          "pcfscope trace --example --method pcf-gather --kernel 3 --json", "pcfscope verify D",
          "pcfscope view [LESSON] [--size WxH] [--presentation]", "pcfscope", "pcfscope render"}) {
        EXPECT_TRUE(texts.count(c)) << c;
    }
    // A message (`pcfscope: interrupted ...`) and the frames folder are not commands.
    for (const std::string& t : texts) EXPECT_FALSE(t.starts_with("pcfscope:")) << t;
    EXPECT_TRUE(isSynopsis("pcfscope verify DIR"));
    EXPECT_FALSE(isSynopsis("pcfscope verify D"));
    EXPECT_TRUE(isName("pcfscope lesson check"));
    EXPECT_FALSE(isName("build/pcfscope methods"));
}

// Each shortened command is in its doc, and the doc says the quick run in its own words.
TEST(DocCommandsFound, QuickRunsReplaceOrAddOptions) {
    EXPECT_EQ(withOptions(" bench --size 480x270 --repeats 3 -o x", "--size 160x90 --repeats 1"),
              " bench --size 160x90 --repeats 1 -o x");
    EXPECT_EQ(withOptions(" bench", "--quick"), " bench --quick");
    EXPECT_EQ(withOptions(" animate 1 --frames 72", "--frames 12 --size 640x360"),
              " animate 1 --frames 12 --size 640x360");
}

TEST(DocCommandsFound, EveryShortenedCommandIsOneItsDocPermits) {
    std::vector<Shown> all = shownCommands();
    for (const Shortened& sh : SHORTENED) {
        EXPECT_NE(testutil::readAll(SOURCE_DIR / sh.doc).find(sh.docSays), std::string::npos)
            << sh.doc << " does not say " << sh.docSays;
        bool shown = std::any_of(all.begin(), all.end(), [&](const Shown& s) {
            return s.doc == sh.doc && s.command.starts_with(sh.starts);
        });
        EXPECT_TRUE(shown) << sh.doc << " shows no " << sh.starts;
    }
}

// A synopsis and a command's bare name: the command exists and every option the synopsis names
// is one its --help lists.
TEST(DocCommandsFound, EverySynopsisNamesOptionsItsCommandHas) {
    std::map<std::string, std::string> help;
    int checked = 0;
    for (const Shown& s : shownCommands()) {
        if (!isSynopsis(s.command) && !isName(s.command)) continue;
        std::string sub = subcommandOf(s.command);
        if (!help.count(sub)) {
            testutil::CommandResult r = testutil::runPcfscope(sub + " --help");
            ASSERT_EQ(r.exitCode, 0) << s.doc << ": `" << s.command << "`: " << r.err;
            help[sub] = r.out;
        }
        std::regex option("(^|[ \\[(|])(--?[a-zA-Z][a-zA-Z0-9-]*)");
        std::string c = s.command;
        for (std::sregex_iterator it(c.begin(), c.end(), option), end; it != end; ++it) {
            std::string name = (*it)[2];
            EXPECT_TRUE(std::regex_search(help[sub], std::regex("(^|[ ,])" + name + "([ ,={]|$)")))
                << s.doc << ": `" << s.command << "` names " << name << ", which `pcfscope " << sub
                << " --help` does not list";
            ++checked;
        }
    }
    EXPECT_GT(checked, 40);
}

TEST_F(DocCommands, EveryConcreteCommandRunsAndShowsWhatItsDocSays) {
    testutil::VirtualDisplay display;
    ASSERT_FALSE(display.display().empty()) << "Xvfb did not start";
    // The inputs the docs' commands name: the authoring guide's worked example, and a depth map.
    std::ofstream(mDir / "my-lesson.toml") << workedExample();
    Outcome made =
        runIn(mDir, std::string(PCFSCOPE_EXE) +
                        " render --scene box-on-plane --size 320x180 -o map.png --raw raw");
    ASSERT_EQ(made.exitCode, 0) << made.err;
    fs::copy_file(mDir / "raw/shadowmap.exr", mDir / "depth.exr");
    // Each command in a folder of its own (two write the default bench/), with the inputs.
    std::set<std::string> done;
    std::map<std::string, Outcome> results;
    std::map<std::string, fs::path> folders;
    fs::path lastDir;
    int index = 0;
    for (const Shown& s : shownCommands()) {
        if (isSynopsis(s.command) || isName(s.command) || done.count(s.command)) continue;
        done.insert(s.command);
        fs::path dir = s.chained ? lastDir : mDir / ("run" + std::to_string(index));
        lastDir = dir;
        if (!s.chained) {
            fs::create_directory(dir);
            for (const char* input : {"my-lesson.toml", "depth.exr"}) {
                fs::create_hard_link(mDir / input, dir / input);
            }
        }
        Outcome r = runIn(dir, runnable(s, index++, display.display()));
        EXPECT_EQ(r.exitCode, 0) << s.doc << ": `" << s.command << "` failed:\n" << r.err;
        results[s.command] = r;
        folders[s.command] = dir;
    }
    EXPECT_GT(index, 15);
    auto result = [&](const std::string& c) -> const Outcome& {
        EXPECT_TRUE(results.count(c)) << "no doc shows `" << c << "` any more";
        return results[c];
    };
    std::string readme = testutil::readAll(SOURCE_DIR / "README.md");
    // "`build/pcfscope methods` lists the fifteen methods": one line each, up to the first blank.
    {
        std::istringstream out(result("build/pcfscope methods").out);
        std::string line;
        std::getline(out, line);  // the header
        int methods = 0;
        while (std::getline(out, line) && !line.empty()) ++methods;
        EXPECT_EQ(methods, 15);
        EXPECT_NE(readme.find("`build/pcfscope methods` lists the fifteen methods"),
                  std::string::npos);
    }
    // The worked example's visibility of 0.8.
    EXPECT_NE(readme.find("give a visibility of 0.8"), std::string::npos);
    EXPECT_NE(result("build/pcfscope trace --example --method bilinear2x2").out.find("= 0.8."),
              std::string::npos);
    // "one PNG per step ..., and a JSON beside each": lesson 3 has six steps.
    fs::path slides = folders["build/pcfscope export 3 -o slides --size 1280x720 --presentation"];
    for (int step = 1; step <= 6; ++step) {
        std::string stem = "slides/03-bilinear-lerp-step0" + std::to_string(step);
        EXPECT_TRUE(fs::exists(slides / (stem + ".png")) && fs::exists(slides / (stem + ".json")))
            << stem;
    }
    EXPECT_TRUE(fs::exists(
        folders["build/pcfscope render --scene box-on-plane --method tent --kernel 5 -o tent.png"] /
        "tent.png"));
    // The main job without a display: lesson 1's frames in a new folder under pcfscope-frames/,
    // and where they went printed.
    EXPECT_NE(result("pcfscope").out.find("pcfscope-frames/01-hard-shadows"), std::string::npos)
        << result("pcfscope").out;
    EXPECT_TRUE(fs::exists(folders["pcfscope"] /
                           "pcfscope-frames/01-hard-shadows/01-hard-shadows-step01.png"));
    // The worked example's claims hold; pick prints a point as a lesson's `point` takes it.
    EXPECT_NE(result("pcfscope lesson check my-lesson.toml").out.find("claims hold"),
              std::string::npos);
    EXPECT_TRUE(std::regex_search(result("pcfscope pick 3 --step 2 --pixel 300,200").out,
                                  std::regex("pixel \\(\\d+, \\d+\\): point = \\[-?\\d+\\.\\d{6}, "
                                             "-?\\d+\\.\\d{6}, -?\\d+\\.\\d{6}\\]")));
    // The window's screenshot, of every `view` command.
    int views = 0;
    for (const auto& [command, dir] : folders) {
        if (subcommandOf(command) != "view") continue;
        ++views;
        bool shot = false;
        for (const auto& e : fs::directory_iterator(dir)) {
            shot |= e.path().filename().string().starts_with("view-");
        }
        EXPECT_TRUE(shot) << "`" << command << "` wrote no screenshot";
    }
    EXPECT_GE(views, 2);
}

// docs/user-guide.md: the light's size shapes pcss under a spot too (a spot light's radius; lesson
// 17 teaches it). On post-under-spot (a spot of radius 0.3) pcss is not poisson with radius 1,
// which it is for a light of size 0 (docs/methods.md).
TEST_F(DocCommands, PcssUnderASpotUsesTheSpotsRadiusAsTheUserGuideSays) {
    std::string guide = squeezed(testutil::readAll(SOURCE_DIR / "docs/user-guide.md"));
    EXPECT_NE(guide.find("`pcss`: a directional light's angular diameter, and a spot light's "
                         "radius"),
              std::string::npos);
    EXPECT_EQ(guide.find("does not model the size"), std::string::npos);
    std::string common = " render --scene post-under-spot --size 320x180 --map-size 256";
    Outcome pcss = runIn(mDir, PCFSCOPE_EXE + common + " --method pcss -o pcss.png");
    Outcome poisson = runIn(mDir, PCFSCOPE_EXE + common + " --method poisson --radius 1 -o p.png");
    ASSERT_EQ(pcss.exitCode, 0) << pcss.err;
    ASSERT_EQ(poisson.exitCode, 0) << poisson.err;
    EXPECT_NE(testutil::readAll(mDir / "pcss.png"), testutil::readAll(mDir / "p.png"));
}

}  // namespace
