// Predict steps (docs/teaching.md, "Predict, then reveal"; lesson/lesson_predict.h, app/predict.h):
// the question table is checked as it is read, a typed answer is judged, and on every predict step
// of the built-in lessons, at 1024x768 and 1280x720 in presentation mode and at 1600x900, the
// question's frames draw none of the numbers the answer needs (no box of a hidden role, no text
// holding the answer outside the choices) and the answer's frames show it. `export` writes both.
#include "app/predict.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "app/session.h"
#include "base/input_error.h"
#include "json_lite.h"
#include "lesson/lesson.h"
#include "lesson/lesson_catalogue.h"
#include "lesson/lesson_predict.h"
#include "overlay/inspector.h"
#include "render/gl_context.h"
#include "run_command.h"

namespace pcf {
namespace {

const std::string HEAD = R"(title = "t"
scene = "box-on-plane"
[settings]
method = "bilinear2x2"
[[step]]
title = "s"
text = "x"
)";

std::string parseError(const std::string& predict) {
    try {
        parseLessonString(HEAD + predict, "p.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(PredictTable, ReadWithItsChoicesAndTolerance) {
    Lesson l = parseLessonString(HEAD + R"([step.predict]
ask = "Which?"
choices = ["{visibility}", "{shadow}"]
answer = "{visibility}"
)",
                                 "p.toml");
    ASSERT_TRUE(l.steps[0].predict);
    EXPECT_EQ(l.steps[0].predict->choices.size(), 2u);
    EXPECT_EQ(l.steps[0].predict->line, 8);
    Lesson n = parseLessonString(
        HEAD + "predict = { ask = \"How much?\", answer = \"{visibility}\", tolerance = 0.1 }\n",
        "p.toml");
    EXPECT_DOUBLE_EQ(n.steps[0].predict->tolerance, 0.1);
}

TEST(PredictTable, BadTablesAreRefusedOnTheirLine) {
    EXPECT_NE(parseError("predict = { ask = \"a\", answer = \"0.8\", tolerance = 0 }\n")
                  .find("p.toml:8: step 1 predict: answer must be one placeholder"),
              std::string::npos);
    EXPECT_NE(parseError("predict = { ask = \"a\", answer = \"{visibility}\" }\n")
                  .find("needs a tolerance"),
              std::string::npos);
    EXPECT_NE(
        parseError("predict = { ask = \"a\", answer = \"{visibility}\", choices = [\"1\"] }\n")
            .find("choices must be 2 to 6"),
        std::string::npos);
    EXPECT_NE(
        parseError("predict = { ask = \"{nope}\", answer = \"{visibility}\", tolerance = 0 }\n")
            .find("ask: unknown placeholder {nope}"),
        std::string::npos);
    EXPECT_NE(parseError("predict = { ask = \"a\", answer = \"{method}\", tolerance = 0 }\n")
                  .find("answer {method}"),
              std::string::npos);
    EXPECT_NE(parseError("predict = { ask = \"a\", answer = \"{tap[9].weight}\", tolerance = 0 }\n")
                  .find("tap[9] is past the 4 reads"),
              std::string::npos);
    EXPECT_NE(parseError("predict = { ask = \"a\", answer = \"{visibility}\", tolerance = 0, x = 1 "
                         "}\n")
                  .find("unknown key 'x'"),
              std::string::npos);
}

TEST(PredictTable, TheAskMayNotPrintWhatTheAnswerHides) {
    StepPredict p{"Here {lit_count} pass: what visibility?", {}, "{visibility}", 0.1, 3};
    ASSERT_TRUE(predictStepProblem(p));
    EXPECT_NE(predictStepProblem(p)->find("{lit_count}"), std::string::npos);
    p.ask = "With ref = {ref}, what visibility?";
    EXPECT_FALSE(predictStepProblem(p));
    p.answer = "{kernel}";
    ASSERT_TRUE(predictStepProblem(p));
    EXPECT_NE(predictStepProblem(p)->find("not a number the lookup computes"), std::string::npos);
}

TEST(PredictTable, AnswersHideWhatGivesThemAway) {
    EXPECT_EQ(canonicalPlaceholder("tap[12].weight*9:2"), "tap[K].weight");
    EXPECT_EQ(canonicalPlaceholder("weight[1,0]"), "weight[I,J]");
    HiddenNumbers v = *hiddenForAnswer("visibility");
    EXPECT_TRUE(v.visibility && v.bits);
    EXPECT_FALSE(v.depths || v.refs || v.weights);
    HiddenNumbers f = *hiddenForAnswer("frac.x");
    EXPECT_TRUE(f.fraction && f.weights);
    EXPECT_TRUE(hiddenForAnswer("depth_bias")->refs);
    EXPECT_TRUE(hiddenForAnswer("texels")->counts);
    EXPECT_FALSE(hiddenForAnswer("uv.x"));
    std::vector<std::string> roles = hiddenRoles(v);
    EXPECT_EQ(std::set<std::string>(roles.begin(), roles.end()),
              (std::set<std::string>{"visibility", "cell-bit", "formula"}));
}

TEST(PredictJudge, NumbersWithinTheToleranceLettersAndChoices) {
    StepPredict number{"q", {}, "{visibility}", 0.0625, 1};
    FilledPredict f;
    f.answer = "0.8125";
    f.value = 0.8125;
    EXPECT_TRUE(judgePrediction(number, f, "0.75").right);
    EXPECT_TRUE(judgePrediction(number, f, "13/16").right);
    EXPECT_FALSE(judgePrediction(number, f, "0.7").right);
    EXPECT_TRUE(judgePrediction(number, f, "0.7").understood);
    EXPECT_FALSE(judgePrediction(number, f, "x").understood);
    EXPECT_FALSE(judgePrediction(number, f, "1/0").understood);
    StepPredict choice{"q", {"a", "b"}, "{depth_bias}", 0.0, 1};
    FilledPredict c;
    c.answer = "0.02";
    c.value = 0.02;
    c.choices = {"-0.02", "0.02"};
    c.choice = 1;
    EXPECT_TRUE(judgePrediction(choice, c, "b").right);
    EXPECT_TRUE(judgePrediction(choice, c, "0.020").right);
    EXPECT_FALSE(judgePrediction(choice, c, "A").right);
    EXPECT_FALSE(judgePrediction(choice, c, "C").understood);
    EXPECT_EQ(answerLine(choice, c, "a"), "Answer: B, 0.02. You said a: not this time.");
    EXPECT_EQ(answerLine(number, f), "Answer: 0.8125 (within 0.0625 counts as right).");
}

// ---- The built-in lessons' predict steps, on frames. ----

class PredictFrames : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> PredictFrames::sContext;

// The numbers a text holds: "-0.02", "0.8125", "16".
std::vector<std::string> numberTokens(const std::string& text) {
    static const std::regex number(R"(-?\d+(\.\d+)?)");
    std::vector<std::string> out;
    for (std::sregex_iterator it(text.begin(), text.end(), number), end; it != end; ++it) {
        out.push_back(it->str());
    }
    return out;
}

bool isTextual(BoxKind k) {
    return k == BoxKind::Text || k == BoxKind::Number || k == BoxKind::Label;
}

// The step panel's texts (the question, its choices, the answer, the words) inside the panel
// and clear of each other.
void expectStepPanelTidy(const std::vector<LayoutBox>& boxes) {
    const LayoutBox* panel = nullptr;
    std::vector<const LayoutBox*> texts;
    for (const LayoutBox& b : boxes) {
        if (b.kind == BoxKind::Panel && b.role == "steps") panel = &b;
        if (b.panel == "steps" && isTextual(b.kind) && b.rect.w > 0 && b.rect.h > 0) {
            texts.push_back(&b);
        }
    }
    ASSERT_TRUE(panel);
    for (size_t i = 0; i < texts.size(); ++i) {
        const Rect& r = texts[i]->rect;
        EXPECT_TRUE(r.x >= panel->rect.x && r.y >= panel->rect.y &&
                    r.right() <= panel->rect.right() + 0.5f &&
                    r.bottom() <= panel->rect.bottom() + 0.5f)
            << texts[i]->role << " leaves the step panel";
        for (size_t j = i + 1; j < texts.size(); ++j) {
            EXPECT_TRUE(r.intersect(texts[j]->rect).empty())
                << texts[i]->role << " overlaps " << texts[j]->role;
        }
    }
}

// The boxes of every page of the phase on screen.
std::vector<std::vector<LayoutBox>> phasePages(Session& session) {
    std::vector<std::vector<LayoutBox>> pages;
    session.setTextPage(0);
    session.compose();
    for (int page = 0; page < session.textPages(); ++page) {
        session.setTextPage(page);
        session.compose();
        pages.push_back(session.boxes());
    }
    return pages;
}

TEST_F(PredictFrames, QuestionsHideTheAnswerAndTheRevealShowsIt) {
    struct Frame {
        glm::ivec2 size;
        bool presentation;
    };
    const Frame frames[] = {{{1024, 768}, true}, {{1280, 720}, true}, {{1600, 900}, false}};
    std::set<std::string> lessons;
    int steps = 0;
    bool spotTheBug = false;
    for (const std::string& path : builtInLessons()) {
        Lesson lesson = parseLessonFile(path);
        for (size_t s = 0; s < lesson.steps.size(); ++s) {
            if (!lesson.steps[s].predict) continue;
            ++steps;
            lessons.insert(lesson.name);
            spotTheBug = spotTheBug || (lesson.name.starts_with("06-") &&
                                        lesson.steps[s].title == "Spot the bug");
            for (const Frame& fr : frames) {
                SCOPED_TRACE(lesson.name + " step " + std::to_string(s + 1) + " at " +
                             std::to_string(fr.size.x) + "x" + std::to_string(fr.size.y) +
                             (fr.presentation ? " presentation" : ""));
                Session session(fr.size, fr.presentation);
                session.loadLesson(path);
                session.goToStep(static_cast<int>(s));
                session.compose();
                ASSERT_TRUE(session.questionShown());
                std::optional<FilledPredict> f = session.filledPredict();
                ASSERT_TRUE(f);
                ASSERT_TRUE(f->value);
                std::vector<std::string> hidden = hiddenRoles(session.hiddenNumbers());
                ASSERT_FALSE(hidden.empty());
                jsonlite::Value q = jsonlite::parse(session.stepJson());
                EXPECT_EQ(q["predict"]["phase"].string, "question");
                ASSERT_EQ(q["predict"]["masked"].size(), hidden.size());
                for (size_t k = 0; k < hidden.size(); ++k) {
                    EXPECT_EQ(q["predict"]["masked"][k].string, hidden[k]);
                }
                bool asked = false;
                for (const auto& page : phasePages(session)) {
                    expectStepPanelTidy(page);
                    for (const LayoutBox& b : page) {
                        EXPECT_EQ(std::count(hidden.begin(), hidden.end(), b.role), 0)
                            << "a " << b.role << " box in the question: " << b.text;
                        asked = asked || b.role == "predict-ask";
                        if (!isTextual(b.kind) || b.role == "predict-choice") continue;
                        for (const std::string& token : numberTokens(b.text)) {
                            bool same =
                                token == f->answer || std::abs(std::stod(token) - *f->value) < 1e-9;
                            EXPECT_FALSE(same) << b.role << " box shows the answer " << f->answer
                                               << ": \"" << b.text << "\"";
                        }
                    }
                }
                EXPECT_TRUE(asked);
                // The reveal: the answer, and the numbers the question hid.
                session.setTextPage(0);
                session.setRevealed(true);
                session.compose();
                jsonlite::Value r = jsonlite::parse(session.stepJson());
                EXPECT_EQ(r["predict"]["phase"].string, "reveal");
                EXPECT_EQ(r["predict"]["masked"].size(), 0u);
                EXPECT_EQ(r["predict"]["answer"].string, f->answer);
                bool answered = false;
                std::set<std::string> shownRoles;
                for (const auto& page : phasePages(session)) {
                    expectStepPanelTidy(page);
                    for (const LayoutBox& b : page) {
                        shownRoles.insert(b.role);
                        if (b.role != "predict-answer") continue;
                        std::vector<std::string> tokens = numberTokens(b.text);
                        answered =
                            answered || std::count(tokens.begin(), tokens.end(), f->answer) > 0;
                    }
                }
                EXPECT_TRUE(answered) << "no answer box holds " << f->answer;
                int back = 0;
                for (const std::string& role : hidden) back += shownRoles.count(role) > 0;
                EXPECT_GT(back, 0) << "the reveal draws none of the hidden roles";
            }
        }
    }
    EXPECT_GE(steps, 8);
    EXPECT_GE(lessons.size(), 5u);
    EXPECT_TRUE(spotTheBug) << "6.6 Spot the bug asks before it tells";
}

TEST_F(PredictFrames, PagingOnGoesFromTheQuestionToTheAnswerAndBack) {
    Session session({1600, 900}, false);
    session.loadLesson(builtInLessons()[5]);  // lesson 6
    session.goToStep(5);
    session.compose();
    ASSERT_TRUE(session.questionShown());
    while (session.questionShown()) {
        ASSERT_TRUE(session.nextPage());
        session.compose();
    }
    EXPECT_TRUE(session.revealed());
    EXPECT_EQ(session.textPage(), 0);
    EXPECT_TRUE(session.previousPage());
    session.compose();
    EXPECT_TRUE(session.questionShown());
    session.goToStep(4);
    EXPECT_FALSE(session.predictStep());
    EXPECT_EQ(session.hiddenNumbers(), HiddenNumbers{});
}

TEST(PredictCheck, LessonCheckFindsAnAnswerThatIsNoChoice) {
    std::filesystem::path dir = testutil::makeTempDir("predict-check");
    std::ofstream(dir / "q.toml") << HEAD << R"(point = [0.978394, 0, -0.4338]
[step.predict]
ask = "Which?"
choices = ["{visibility*2}", "{shadow}"]
answer = "{visibility}"
)";
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + (dir / "q.toml").string());
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.out.find("q.toml:9: step 1 predict: the answer {visibility} = "), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("is none of the choices"), std::string::npos) << r.out;
    std::filesystem::remove_all(dir);
}

TEST(PredictExport, WritesTheQuestionThenTheAnswer) {
    std::filesystem::path dir = testutil::makeTempDir("predict-export");
    testutil::CommandResult r =
        testutil::runPcfscope("export 6 --steps 5-6 -o " + (dir / "f").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string stem = (dir / "f" / "06-hardware-taps-and-tent-step06").string();
    jsonlite::Value q = jsonlite::parse(testutil::readAll(stem + ".json"));
    jsonlite::Value a = jsonlite::parse(testutil::readAll(stem + "-reveal.json"));
    EXPECT_EQ(q["predict"]["phase"].string, "question");
    EXPECT_EQ(a["predict"]["phase"].string, "reveal");
    EXPECT_EQ(a["predict"]["answer"].string, "0.02");
    EXPECT_NE(q["text"].string.find("Which sign must depth_bias have"), std::string::npos);
    // Step 5 asks nothing: one frame, no reveal, no predict key.
    std::string five = (dir / "f" / "06-hardware-taps-and-tent-step05").string();
    EXPECT_FALSE(jsonlite::parse(testutil::readAll(five + ".json")).has("predict"));
    EXPECT_FALSE(std::filesystem::exists(five + "-reveal.png"));
    // A second export refuses to write over the answer frame (and the question's).
    testutil::CommandResult again =
        testutil::runPcfscope("export 6 --steps 6 -o " + (dir / "f").string());
    EXPECT_EQ(again.exitCode, 2);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pcf
