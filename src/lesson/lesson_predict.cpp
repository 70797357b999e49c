#include "lesson/lesson_predict.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace pcf {

namespace {

std::string trimmed(std::string_view s) {
    size_t a = s.find_first_not_of(" \t");
    if (a == std::string_view::npos) return "";
    size_t b = s.find_last_not_of(" \t");
    return std::string(s.substr(a, b - a + 1));
}

// A whole number, a decimal or a fraction "a/b" filling all of `s`; nullopt otherwise.
std::optional<double> parseTypedNumber(std::string_view s) {
    std::string t = trimmed(s);
    if (t.empty()) return std::nullopt;
    size_t slash = t.find('/');
    auto whole = [](const std::string& x) -> std::optional<double> {
        if (x.empty()) return std::nullopt;
        char* end = nullptr;
        double v = std::strtod(x.c_str(), &end);
        if (end != x.c_str() + x.size() || !std::isfinite(v)) return std::nullopt;
        return v;
    };
    if (slash == std::string::npos) return whole(t);
    std::optional<double> a = whole(trimmed(t.substr(0, slash)));
    std::optional<double> b = whole(trimmed(t.substr(slash + 1)));
    if (!a || !b || *b == 0.0) return std::nullopt;
    return *a / *b;
}

}  // namespace

std::string canonicalPlaceholder(std::string_view inside) {
    std::string name(inside.substr(0, inside.find_first_of("*:")));
    size_t open = name.find('[');
    size_t close = name.find(']');
    if (open == std::string::npos || close == std::string::npos || close < open) return name;
    bool pair = name.substr(open, close - open).find(',') != std::string::npos;
    return name.substr(0, open) + (pair ? "[I,J]" : "[K]") + name.substr(close + 1);
}

std::vector<std::string> placeholdersIn(std::string_view text) {
    std::vector<std::string> out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '{') continue;
        if (i + 1 < text.size() && text[i + 1] == '{') {
            ++i;
            continue;
        }
        size_t close = text.find('}', i + 1);
        if (close == std::string_view::npos) break;
        out.push_back(canonicalPlaceholder(text.substr(i + 1, close - i - 1)));
        i = close;
    }
    return out;
}

std::string predictAnswerName(const StepPredict& p) {
    std::string_view a = p.answer;
    if (a.size() < 3) return "";
    return canonicalPlaceholder(a.substr(1, a.size() - 2));
}

std::optional<std::string> predictProblem(const StepPredict& p, bool toleranceGiven, int taps,
                                          int fetches, int parts) {
    std::string_view a = p.answer;
    bool one = a.size() >= 3 && a.front() == '{' && a.back() == '}' &&
               a.substr(1, a.size() - 2).find_first_of("{}") == std::string_view::npos;
    if (!one) {
        return "answer must be one placeholder, e.g. \"{visibility}\" (the answer comes from "
               "the trace), got \"" +
               p.answer + "\"";
    }
    if (auto why = numberPlaceholderProblem(a.substr(1, a.size() - 2))) {
        return "answer " + p.answer + ": " + *why;
    }
    std::vector<std::pair<std::string, std::string>> texts{{"ask", p.ask}, {"answer", p.answer}};
    for (size_t k = 0; k < p.choices.size(); ++k) {
        texts.emplace_back("choice " + std::string(1, choiceLetter(k)), p.choices[k]);
    }
    for (const auto& [what, text] : texts) {
        if (auto problem = checkPlaceholders(text, taps, fetches, parts)) {
            return what + ": " + problem->problem;
        }
    }
    if (p.choices.size() == 1 || p.choices.size() > MAX_PREDICT_CHOICES) {
        return "choices must be 2 to " + std::to_string(MAX_PREDICT_CHOICES) + ", got " +
               std::to_string(p.choices.size());
    }
    if (!p.choices.empty() && toleranceGiven) {
        return "a multiple choice takes no tolerance (a typed answer names a choice)";
    }
    if (p.choices.empty() && !toleranceGiven) {
        return "a number answer needs a tolerance: how far off a typed answer may be "
               "(tolerance = 0 for an exact count)";
    }
    if (!std::isfinite(p.tolerance) || p.tolerance < 0.0) {
        return "tolerance must be a number >= 0";
    }
    return std::nullopt;
}

FilledPredict fillPredict(const StepPredict& p, const Trace& trace, const StepContext& ctx) {
    FilledPredict f;
    f.ask = fillText(p.ask, trace, ctx);
    f.answer = fillText(p.answer, trace, ctx);
    std::string_view a = p.answer;
    f.value = placeholderNumber(a.substr(1, a.size() - 2), trace, ctx);
    for (const std::string& c : p.choices) {
        f.choices.push_back(fillText(c, trace, ctx));
        if (f.choices.back() == f.answer) {
            f.choice = f.choice < 0 ? static_cast<int>(f.choices.size()) - 1 : -2;
        }
    }
    if (f.choice < -1) f.choice = -1;  // several: no one choice (predictChoiceProblem says so)
    return f;
}

std::optional<std::string> predictChoiceProblem(const StepPredict& p, const FilledPredict& f) {
    if (p.choices.empty()) return std::nullopt;
    int matches = 0;
    for (const std::string& c : f.choices) matches += c == f.answer;
    if (matches == 1) return std::nullopt;
    std::string listed;
    for (const std::string& c : f.choices) listed += (listed.empty() ? "" : ", ") + c;
    return "the answer " + p.answer + " = " + f.answer + " is " +
           (matches == 0 ? "none" : std::to_string(matches)) + " of the choices (" + listed + ")";
}

PredictVerdict judgePrediction(const StepPredict& p, const FilledPredict& f,
                               std::string_view typed) {
    PredictVerdict v;
    std::string t = trimmed(typed);
    if (t.empty()) return v;
    if (!f.choices.empty()) {
        int picked = -1;
        if (t.size() == 1 && std::isalpha(static_cast<unsigned char>(t[0]))) {
            int k = std::toupper(static_cast<unsigned char>(t[0])) - 'A';
            if (k >= 0 && k < static_cast<int>(f.choices.size())) picked = k;
        }
        std::optional<double> number = parseTypedNumber(t);
        for (size_t k = 0; k < f.choices.size() && picked < 0; ++k) {
            std::optional<double> c = parseTypedNumber(f.choices[k]);
            if (f.choices[k] == t || (number && c && *number == *c)) picked = static_cast<int>(k);
        }
        v.understood = picked >= 0;
        v.right = v.understood && picked == f.choice;
        return v;
    }
    std::optional<double> number = parseTypedNumber(t);
    v.understood = number.has_value() && f.value.has_value();
    // A hair of slack: "0.8" for 0.8000001 is right at tolerance 0.
    v.right = v.understood && std::abs(*number - *f.value) <= p.tolerance + 1e-6;
    return v;
}

std::string answerLine(const StepPredict& p, const FilledPredict& f, std::string_view typed) {
    std::string line = "Answer: ";
    if (f.choice >= 0) {
        line += std::string(1, choiceLetter(static_cast<size_t>(f.choice))) + ", " + f.answer + ".";
    } else if (p.choices.empty() && p.tolerance > 0.0) {
        line += f.answer + " (within " + formatNumber(static_cast<float>(p.tolerance)) +
                " counts as right).";
    } else {
        line += f.answer + ".";
    }
    std::string t = trimmed(typed);
    if (t.empty()) return line;
    PredictVerdict v = judgePrediction(p, f, t);
    line += " You said " + t + ": " +
            (!v.understood ? "not an answer here"
             : v.right     ? "right"
                           : "not this time") +
            ".";
    return line;
}

}  // namespace pcf
