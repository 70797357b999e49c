// lesson_words.h: what a step's typed words may not say about its own lookup. A number of the
// step belongs in a placeholder and a statement about it in a claim (lesson_claims.h); words
// typed instead go stale when a key changes the state, or are simply false. `lesson check` reads
// the text against the step's trace and refuses:
//
//   a number named by a quantity: "visibility 1", "ref = 0.5", "fx of 0.25" (visibility, ref, z,
//     fx, fy: the placeholder if it is the step's value, a false sentence if it is not; depth:
//     when it is a read's depth);
//   a decimal equal to one of the step's quantities as typed ("0.601" where {visibility} is
//     0.6013: to the typed number's last digit when it has three decimals or more, else to the
//     placeholder's four): visibility, ref, z, the fractions, a read's depth, ref or weight ...;
//   a count phrase with a typed count of the step: "3 of the 4 reads" where 3 reads pass and
//     the method makes 4 ({lit_count}, {shadowed_count}; {taps}, {texels}, {distinct} ...);
//   a state word about the point that its state contradicts: "fully lit", "in shadow", "in the
//     penumbra" where the subject is the point ("the point is lit", "it stays in shadow") or the
//     words sit beside its visibility ("visibility {visibility}: in shadow", "fully lit,
//     visibility ..."); checked as the claims `lit`, `shadowed` and `penumbra` are.
//
// Not read: placeholders, `code spans`, words in "double quotes" (another's words: an article's
// worked example), a number that is an operand of + - * / x ^ < > (a formula's constant: "uv *
// size - 0.5"), the result of arithmetic on typed numbers ("1 - 0.2 = 0.8"), and a number in a
// list of three or more ("0, 0.25, 0.5, 0.75 or 1": the values something can take).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/trace.h"
#include "lesson/lesson_text.h"

namespace pcf {

struct WordProblem {
    std::size_t offset = 0;  // where in the text the offending words start
    std::string problem;     // what is wrong and what to write instead
};

// The typed words of a step's text that state its numbers or its state, against its trace.
std::vector<WordProblem> typedWordProblems(std::string_view text, const Trace& trace,
                                           const StepContext& ctx);

}  // namespace pcf
