// advise_read.h: an advise output folder read back (what advise_report.h writes): advise.csv's
// settings and measures, and from advise.json beside it the budget, the scene, the truth, the
// renderer and the grid's size. The choice, the runner-up and the binding constraint are derived
// again from those (advise.h: chooseAdvice, adviseBinding), and a file whose `broken`, `feasible`
// or `chosen` columns disagree with what its own budget gives is refused, so a lesson's words
// about the folder cannot rest on a file edited by hand into saying something else. No GL, no
// files: text in, InputError (file:line) out.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "measure/advise.h"
#include "measure/bench.h"

namespace pcf {

// The folder's files' names: the CSV a lesson step's chart names, and the JSON beside it.
inline constexpr const char* ADVISE_CSV_NAME = "advise.csv";
inline constexpr const char* ADVISE_JSON_NAME = "advise.json";

struct AdviseReport {
    AdviseResult result;         // measured in the CSV's order; choice, runner-up, ties derived
    std::vector<BenchRow> rows;  // rows[k]: measured[k]'s bench row (its errors, times, renderer)
    AdviseBudget budget;
    std::string scene;
    std::string truth;  // "hard (the light's centre)"
    std::string glRenderer;
    std::string binding;  // adviseBinding of the result
};

// Both files' texts with the names they are reported by. Throws InputError naming the file
// (and the CSV's line) for a malformed file, one inconsistent with the other, or a CSV whose
// marks disagree with the budget.
AdviseReport parseAdviseReport(std::string_view csvText, const std::string& csvSource,
                               std::string_view jsonText, const std::string& jsonSource);

}  // namespace pcf
