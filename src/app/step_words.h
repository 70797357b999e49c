// step_words.h: what a step's words become on a frame other than the step's own still: after the
// viewer's keys changed the state they were written for, and on every frame of an animation.
// The numbers are live, the sentences cannot be, so the step's claims (lesson/lesson_claims.h)
// are checked on the frame: where one fails, the words are withheld and a caption in plain words
// says what the frame shows instead; where all hold, the words stand (under a note naming the
// state they were written for, when the keys changed it).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_text.h"
#include "scene/light.h"

namespace pcf {

// "pcf-gather N=3   bias constant 0.02   cull back   map 256 32f": the state, in the status
// line's words (with "sun -5 deg" when the keys moved the sun from the scene's).
// hideBiasAmounts: the bias mode's amounts as "?" (a question that hides the ref: predict.h).
std::string settingsSummary(const LessonSettings& s, bool hideBiasAmounts = false);

// Every setting of `live` that differs from the step's (`step`), as "key value" in the lesson
// files' words ("constant_bias 0.005", "cull front"), in the parameter table's order (but the
// shading, which the line's settings show), then the
// map's grid (origin_shift, snap) and the sun ("sun 35 deg up", "sun turned 15 deg", from the
// scene's light `sceneLight`). Empty when none does. The status line lists them.
std::vector<std::string> changedSettings(const LessonSettings& step, const LessonSettings& live,
                                         const Light& sceneLight);

// Equal in what a step's words can talk about: a kernel size or radius the method does not use
// (a kernel change under bilinear2x2 leaves its text true), the picked point and the shading
// (which changes the picture, not the lookup) aside.
bool sameForTheWords(LessonSettings a, const LessonSettings& b);

// How a frame's words came to be: the step's own, the step's under a note that the keys
// changed the state they were written for, or a caption in their place because one of the
// step's claims fails on this frame (the frame JSON's "words": "step", "noted", "caption").
enum class WordsShown { Step, Noted, Caption };
std::string_view wordsShownName(WordsShown shown);

struct FrameWords {
    std::string text;
    WordsShown shown = WordsShown::Step;
};

// One frame's words and what decides them: the step, the state its words are checked against
// (`live`: the keys' state; on a moving frame the state the sweep started from), the step's
// filled text, the frame's trace and context and what the claims read besides (`world`).
// `interactive`: the window, whose notes may name its keys; an exported frame or video never
// does.
struct WordsInput {
    const LessonStep& step;
    const LessonSettings& live;
    const std::string& text;
    const Trace& trace;
    const StepContext& ctx;
    const ClaimWorld& world;
    bool interactive = false;
};

// The step's claims that fail on this frame (chart claims, which the state does not change, are
// not checked; a motion claim fails when `world` says so).
std::vector<const StepClaim*> failingClaims(const WordsInput& in);

// What the ringed point does now, in plain words: "Under nearest the ringed point is fully
// lit: visibility 1, 1 of 1 reads pass."
std::string pointNowWords(const Trace& trace, const ShadowSettings& s);

// The words of a still frame whose state the keys changed: the step's text unchanged when the
// state is the step's own, or one its `keys` invite, and every claim holds; in its place, when a
// claim fails, a note of both states, why the words are not shown (in plain words) and the live
// lookup; otherwise under a note naming both states.
FrameWords wordsForLiveState(const WordsInput& in);

// The words of a moving frame (an animation's: `swept` says what moves and its value now): the
// step's text where every claim holds on this frame (under a note when the sweep started from a
// state the keys changed), else a caption for the motion: what is swept and its value, what the
// ringed point does now and why the step's words are not shown.
FrameWords wordsForMovingFrame(const WordsInput& in, const std::string& swept);

}  // namespace pcf
