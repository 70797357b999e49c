// step_words.h: what a step's words become when the viewer's keys have changed the state they
// were written for: the numbers are live, the sentences cannot be, so either a note says which
// state they are for, or, when the live numbers break one of the step's claims
// (lesson/lesson_claims.h), the words are withheld and only the live lookup is shown.
#pragma once

#include <string>
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
// files' words ("constant_bias 0.005", "cull front"), in the parameter table's order, then the
// map's grid (origin_shift, snap) and the sun ("sun 35 deg up", "sun turned 15 deg", from the
// scene's light `sceneLight`). Empty when none does. The status line lists them.
std::vector<std::string> changedSettings(const LessonSettings& step, const LessonSettings& live,
                                         const Light& sceneLight);

// The step's filled text (`text`) for the live settings: unchanged when they are the step's own
// or a state its `keys` invite and every claim holds; withheld, with the live lookup instead,
// when a claim fails (chart claims do not depend on the state); otherwise under a note naming
// both states.
std::string wordsForLiveState(const LessonStep& step, const LessonSettings& live,
                              const std::string& text, const Trace& trace, const StepContext& ctx,
                              const ClaimWorld& world);

}  // namespace pcf
