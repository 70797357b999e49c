// The documentation against the code: the README stays a front door (at most 12 KiB), the user
// guide's key table is the viewer's own key list, the authoring guide documents every
// placeholder the lesson text knows, and every relative link of README.md and docs/*.md leads
// to a file that exists (and, with a #fragment, to a heading of that file).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "lesson/lesson.h"
#include "lesson/lesson_catalogue.h"
#include "lesson/lesson_text.h"
#include "overlay/inspector.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

const fs::path SOURCE_DIR = PCFSCOPE_SOURCE_DIR;

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// The lines strictly between `<!-- NAME:begin -->` and `<!-- NAME:end -->`.
std::vector<std::string> markedLines(const std::string& text, const std::string& name) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
        if (line == "<!-- " + name + ":end -->") break;
        if (inside) lines.push_back(line);
        if (line == "<!-- " + name + ":begin -->") inside = true;
    }
    return lines;
}

// The cells of a Markdown table row, trimmed; "\|" inside a cell is a literal bar.
std::vector<std::string> cellsOf(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    for (size_t i = 1; i < row.size(); ++i) {
        if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
            cell += '|';
            ++i;
        } else if (row[i] == '|') {
            cell.erase(0, cell.find_first_not_of(' '));
            cell.erase(cell.find_last_not_of(' ') + 1);
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += row[i];
        }
    }
    return cells;
}

// The body rows of the marked table (the header and the rule line dropped).
std::vector<std::vector<std::string>> tableRows(const std::string& text, const std::string& name) {
    std::vector<std::vector<std::string>> rows;
    for (const std::string& line : markedLines(text, name)) {
        if (!line.starts_with("|")) continue;
        rows.push_back(cellsOf(line));
    }
    if (rows.size() >= 2) rows.erase(rows.begin(), rows.begin() + 2);
    return rows;
}

// GitHub's anchor for a heading: lower case, spaces to '-', punctuation but '-' and '_' dropped.
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (unsigned char c : heading) {
        if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) {
            anchor += static_cast<char>(std::tolower(c));
        } else if (c == ' ') {
            anchor += '-';
        }
    }
    return anchor;
}

std::set<std::string> anchorsOf(const std::string& text) {
    std::set<std::string> anchors;
    std::istringstream in(text);
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("```")) fenced = !fenced;
        if (fenced || !line.starts_with("#")) continue;
        size_t start = line.find_first_not_of('#');
        if (start == std::string::npos || line[start] != ' ') continue;
        anchors.insert(anchorOf(line.substr(start + 1)));
    }
    return anchors;
}

std::vector<fs::path> documents() {
    std::vector<fs::path> docs{SOURCE_DIR / "README.md"};
    for (const auto& entry : fs::directory_iterator(SOURCE_DIR / "docs")) {
        if (entry.path().extension() == ".md") docs.push_back(entry.path());
    }
    std::sort(docs.begin(), docs.end());
    return docs;
}

TEST(Docs, ReadmeIsAFrontDoorOfAtMost12KiB) {
    std::uintmax_t size = fs::file_size(SOURCE_DIR / "README.md");
    EXPECT_LE(size, 12u * 1024u) << "README.md is " << size
                                 << " bytes: the detail belongs in docs/";
    EXPECT_GT(size, 1024u);
}

TEST(Docs, TheUserGuidesKeyTableIsTheViewersKeyList) {
    std::vector<std::vector<std::string>> rows =
        tableRows(readFile(SOURCE_DIR / "docs/user-guide.md"), "keys");
    const auto& keys = viewerKeys();
    ASSERT_EQ(rows.size(), keys.size()) << "docs/user-guide.md's key table has " << rows.size()
                                        << " rows, the viewer " << keys.size() << " keys";
    for (size_t i = 0; i < keys.size(); ++i) {
        ASSERT_EQ(rows[i].size(), 2u) << "row " << i;
        EXPECT_EQ(rows[i][0], keys[i].first) << "row " << i;
        EXPECT_EQ(rows[i][1], keys[i].second) << "row " << i;
    }
}

TEST(Docs, EveryPlaceholderIsDocumented) {
    // The backquoted names of the first column, e.g. `tap[K].depth`.
    std::set<std::string> documented;
    std::regex code("`([^`]+)`");
    for (const auto& row :
         tableRows(readFile(SOURCE_DIR / "docs/lesson-authoring.md"), "placeholders")) {
        ASSERT_FALSE(row.empty());
        for (std::sregex_iterator it(row[0].begin(), row[0].end(), code), end; it != end; ++it) {
            documented.insert((*it)[1]);
        }
    }
    std::vector<std::string> names = placeholderNames();
    ASSERT_GT(names.size(), 20u);
    for (const std::string& name : names) {
        EXPECT_TRUE(documented.count(name)) << "{" << name << "} is not documented in "
                                            << "docs/lesson-authoring.md";
    }
    for (const std::string& name : documented) {
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end())
            << "docs/lesson-authoring.md documents {" << name << "}, which the code does not know";
    }
}

TEST(Docs, EveryRelativeLinkLeadsToAFileAndHeading) {
    std::regex link(R"(\]\(([^)\s]+)\))");
    int checked = 0;
    for (const fs::path& doc : documents()) {
        std::string text = readFile(doc);
        for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
            std::string target = (*it)[1];
            if (target.find("://") != std::string::npos) continue;
            std::string file = target.substr(0, target.find('#'));
            std::string fragment =
                target.find('#') == std::string::npos ? "" : target.substr(target.find('#') + 1);
            fs::path resolved = file.empty() ? doc : doc.parent_path() / file;
            SCOPED_TRACE(doc.filename().string() + ": " + target);
            ASSERT_TRUE(fs::exists(resolved)) << resolved;
            if (!fragment.empty()) {
                EXPECT_TRUE(anchorsOf(readFile(resolved)).count(fragment))
                    << "no heading #" << fragment << " in " << resolved;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 10);
}

// The commands of a page's ```sh blocks, in order.
std::vector<std::string> shellCommands(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    bool sh = false;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("```")) {
            sh = !sh && line == "```sh";
            continue;
        }
        if (sh && !line.empty()) out.push_back(line);
    }
    return out;
}

TEST(Docs, EveryCommandOfTheTeachingPageRuns) {
    std::vector<std::string> commands = shellCommands(readFile(SOURCE_DIR / "docs/teaching.md"));
    ASSERT_GE(commands.size(), 5u);
    fs::path dir = testutil::makeTempDir("teaching");
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    int views = 0;
    for (const std::string& command : commands) {
        SCOPED_TRACE(command);
        ASSERT_TRUE(command.starts_with("pcfscope ")) << "a command that is not pcfscope's";
        std::string args = command.substr(9);
        // The viewer runs as written; --screenshot closes its window after the keys.
        if (args.starts_with("view ")) {
            args += " --screenshot view" + std::to_string(++views) + ".png";
        }
        testutil::CommandResult r =
            testutil::runPcfscope(args, "cd " + dir.string() + " && DISPLAY=" + x.display());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    // What the page says the commands leave.
    for (const char* file :
         {"lecture/06-hardware-taps-and-tent.html", "lecture/06-hardware-taps-and-tent.pdf",
          "handout/06-hardware-taps-and-tent-handout.pdf", "tutorial/worksheet.pdf",
          "tutorial/answers.pdf", "tutorial/answers/answers.json",
          "tutorial/worksheet/item08.png"}) {
        EXPECT_TRUE(fs::exists(dir / file)) << file;
    }
    EXPECT_EQ(views, 2);
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

// The steps that ask before they tell, as the teaching page and the user guide list them:
// "2.2, 3.2, ..." against the lessons' `predict` steps.
TEST(Docs, ThePredictStepsListedAreTheLessonsOwn) {
    std::vector<std::string> actual;
    for (const std::string& path : builtInLessons()) {
        Lesson lesson = parseLessonFile(path);
        int number = std::stoi(lesson.name.substr(0, 2));
        for (size_t k = 0; k < lesson.steps.size(); ++k) {
            if (lesson.steps[k].predict) {
                actual.push_back(std::to_string(number) + "." + std::to_string(k + 1));
            }
        }
    }
    std::regex listed(R"(((?:\d+\.\d+, )+\d+\.\d+ and \d+\.\d+))");
    for (const char* page : {"docs/teaching.md", "docs/user-guide.md"}) {
        std::string text = readFile(SOURCE_DIR / page);
        size_t at = text.find("predict step (");
        if (at == std::string::npos) at = text.find("Steps ");
        std::smatch m;
        std::string from = text.substr(at);
        ASSERT_TRUE(std::regex_search(from, m, listed)) << page;
        std::vector<std::string> named;
        std::regex step(R"(\d+\.\d+)");
        std::string list = m[1];
        for (std::sregex_iterator it(list.begin(), list.end(), step), end; it != end; ++it) {
            named.push_back(it->str());
        }
        EXPECT_EQ(named, actual) << page;
    }
}

}  // namespace
}  // namespace pcf
