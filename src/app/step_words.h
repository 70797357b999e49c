// step_words.h: what a step's words become when the viewer's keys have changed the state they
// were written for: the numbers are live, the sentences cannot be, so either a note says which
// state they are for, or, when the live numbers break one of the step's claims
// (lesson/lesson_claims.h), the words are withheld and only the live lookup is shown.
#pragma once

#include <string>

#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_text.h"

namespace pcf {

// "pcf-gather N=3   bias constant 0.02   cull back   map 256 32f": the state, in the status
// line's words.
std::string settingsSummary(const LessonSettings& s);

// The step's filled text (`text`) for the live settings: unchanged when they are the step's own
// or a state its `keys` invite and every claim holds; withheld, with the live lookup instead,
// when a claim fails (chart claims do not depend on the state); otherwise under a note naming
// both states.
std::string wordsForLiveState(const LessonStep& step, const LessonSettings& live,
                              const std::string& text, const Trace& trace, const StepContext& ctx,
                              const ClaimWorld& world);

}  // namespace pcf
