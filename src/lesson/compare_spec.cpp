#include "lesson/compare_spec.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "lesson/lesson.h"

namespace pcf {

void addCompareKey(CompareSpec& spec, const std::string& key, std::vector<std::string> values) {
    if (!findParam(key)) {
        std::string known;
        for (const ParamInfo& p : allParams())
            known += (known.empty() ? "" : ", ") + std::string(p.key);
        throw std::invalid_argument("compare: unknown setting '" + key + "' (known: " + known +
                                    ")");
    }
    if (std::find(spec.keys.begin(), spec.keys.end(), key) != spec.keys.end()) {
        throw std::invalid_argument("compare: " + key + " is given twice");
    }
    int n = static_cast<int>(values.size());
    if (n < MIN_COMPARE_PARTS || n > MAX_COMPARE_PARTS) {
        throw std::invalid_argument(
            "compare: " + key + " needs 2 or 3 values (one per part), got " + std::to_string(n));
    }
    if (!spec.empty() && n != spec.parts()) {
        throw std::invalid_argument("compare: " + key + " has " + std::to_string(n) +
                                    " values but " + spec.keys.front() + " has " +
                                    std::to_string(spec.parts()) + " (one per part)");
    }
    spec.keys.push_back(key);
    spec.values.push_back(std::move(values));
}

CompareSpec parseCompareSpec(std::string_view text) {
    CompareSpec spec;
    std::istringstream words{std::string(text)};
    for (std::string word; words >> word;) {
        size_t eq = word.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw std::invalid_argument("compare: '" + word +
                                        "' is not KEY=VALUE,VALUE (e.g. bias=none,constant,slope)");
        }
        std::vector<std::string> values;
        std::string rest = word.substr(eq + 1) + ",";
        for (size_t start = 0, comma; (comma = rest.find(',', start)) != std::string::npos;
             start = comma + 1) {
            values.push_back(rest.substr(start, comma - start));
            if (values.back().empty()) {
                throw std::invalid_argument("compare: an empty value in '" + word + "'");
            }
        }
        addCompareKey(spec, word.substr(0, eq), std::move(values));
    }
    if (spec.empty()) {
        throw std::invalid_argument("compare: no setting given (e.g. bias=none,constant,slope)");
    }
    return spec;
}

std::string compareSpecText(const CompareSpec& spec) {
    std::string out;
    for (size_t k = 0; k < spec.keys.size(); ++k) {
        out += (k ? " " : "") + spec.keys[k] + "=";
        for (size_t i = 0; i < spec.values[k].size(); ++i)
            out += (i ? "," : "") + spec.values[k][i];
    }
    return out;
}

LessonSettings comparePart(const LessonSettings& base, const CompareSpec& spec, int part) {
    LessonSettings s = base;
    bool kernelGiven = std::find(spec.keys.begin(), spec.keys.end(), "kernel") != spec.keys.end();
    for (size_t k = 0; k < spec.keys.size(); ++k) {
        const std::string& value = spec.values[k].at(static_cast<size_t>(part));
        // The parameter table's reader: the value in decimal, in its range, as given.
        if (std::optional<ParamProblem> problem =
                setParamFromText(s, *findParam(spec.keys[k]), value)) {
            throw std::invalid_argument("compare: " + problem->text());
        }
    }
    if (!kernelGiven) s.kernel = fitKernel(s.method, s.kernel);
    std::string label = comparePartLabel(spec, part);
    if (auto why = checkParams(s.ShadowSettings::pcfParams())) {
        throw std::invalid_argument("compare: " + label + ": " + why->text());
    }
    if (auto why = validateBias(static_cast<int>(s.bias), s.method)) {
        throw std::invalid_argument("compare: " + label + ": " + *why);
    }
    return s;
}

std::string comparePartLabel(const CompareSpec& spec, int part) {
    std::string out;
    for (size_t k = 0; k < spec.keys.size(); ++k) {
        out += (k ? ", " : "") + spec.keys[k] + " " + spec.values[k].at(static_cast<size_t>(part));
    }
    return out;
}

}  // namespace pcf
