#include "lesson/lesson_words.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "kernel/trace_explain.h"
#include "lesson/lesson_claims.h"

namespace pcf {

namespace {

// A piece of a step's text as the rules read it.
struct Word {
    enum Kind { Text, Number, Placeholder, Punct, Skipped } kind = Text;
    std::string text;  // lower case for Text; a placeholder's name ("visibility")
    std::size_t at = 0;
    bool quoted = false;  // inside "double quotes"
};

bool wordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
           (static_cast<unsigned char>(c) >= 0x80);
}

bool isNumber(std::string_view s) {
    std::size_t digits = 0, dots = 0;
    for (char c : s) {
        if (std::isdigit(static_cast<unsigned char>(c))) {
            ++digits;
        } else if (c == '.') {
            ++dots;
        } else {
            return false;
        }
    }
    return digits > 0 && dots <= 1 && s.front() != '.' && s.back() != '.';
}

// A run of word characters: a number, or a word (a trailing full stop is punctuation).
void addRun(std::vector<Word>& out, std::string_view run, std::size_t at, bool quoted) {
    std::string_view core = run;
    while (!core.empty() && core.back() == '.') core.remove_suffix(1);
    if (!core.empty()) {
        Word w{isNumber(core) ? Word::Number : Word::Text, std::string(core), at, quoted};
        if (w.kind == Word::Text) {
            for (char& c : w.text)
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
        out.push_back(std::move(w));
    }
    if (core.size() < run.size()) out.push_back({Word::Punct, ".", at + core.size(), quoted});
}

// The text as words, numbers, placeholders and punctuation; code spans are one Skipped word, a
// preformatted line's start and a paragraph gap a full stop.
std::vector<Word> wordsOf(std::string_view text) {
    std::vector<Word> out;
    bool quoted = false;
    bool lineStart = true;
    for (std::size_t i = 0; i < text.size();) {
        char c = text[i];
        if (lineStart && (text.substr(i, 2) == "  " || c == '\t' || c == '\n')) {
            out.push_back({Word::Punct, ".", i, false});  // a table row or a gap ends a sentence
            quoted = false;
        }
        lineStart = c == '\n';
        std::size_t close = std::string_view::npos;
        if (c == '{' && text.substr(i, 2) != "{{" &&
            (close = text.find('}', i)) != std::string_view::npos) {
            std::string_view inside = text.substr(i + 1, close - i - 1);
            inside = inside.substr(0, std::min(inside.find('*'), inside.find(':')));
            out.push_back({Word::Placeholder, std::string(inside), i, quoted});
            i = close + 1;
        } else if (c == '`' && (close = text.find('`', i + 1)) != std::string_view::npos &&
                   text.substr(i, close - i).find('\n') == std::string_view::npos) {
            out.push_back({Word::Skipped, "", i, quoted});
            i = close + 1;
        } else if (c == '"') {
            quoted = !quoted;
            out.push_back({Word::Punct, "\"", i, quoted});
            ++i;
        } else if (wordChar(c)) {
            std::size_t end = i;
            while (end < text.size() && wordChar(text[end])) ++end;
            addRun(out, text.substr(i, end - i), i, quoted);
            i = end;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else {
            std::size_t n = (c == '<' || c == '>') && text.substr(i + 1, 1) == "=" ? 2 : 1;
            out.push_back({Word::Punct, std::string(text.substr(i, n)), i, quoted});
            i += n;
        }
    }
    return out;
}

bool endsClause(const Word& w) {
    return w.kind == Word::Punct &&
           (w.text == "." || w.text == "," || w.text == ";" || w.text == ":" || w.text == "?" ||
            w.text == "!" || w.text == "\"");
}

bool isOperator(const Word& w) {
    static const char* ops[] = {"+", "-", "*", "/", "^", "<", ">", "<=", ">=", "x", "×", "%"};
    if (w.kind != Word::Punct && !(w.kind == Word::Text && w.text == "x")) return false;
    return std::any_of(std::begin(ops), std::end(ops), [&](const char* o) { return w.text == o; });
}

double value(const Word& w) { return std::strtod(w.text.c_str(), nullptr); }

int decimals(const Word& w) {
    std::size_t dot = w.text.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(w.text.size() - dot - 1);
}

// Whether a typed number is q: to its own last digit when it has three decimals or more (the
// placeholder rounded), else as the placeholder prints it (four decimals).
bool typedAs(const Word& w, double q) {
    double v = value(w);
    int d = decimals(w);
    if (d >= 3) return std::fabs(q - v) <= 0.5 * std::pow(10.0, -d) + 1e-9;
    return std::fabs(q - v) < 5e-5;
}

struct Quantity {
    std::string name;  // the placeholder, "visibility", "tap[2].depth"
    double value = 0.0;
};

// The step's quantities a decimal may be typed for, and its counts.
std::vector<Quantity> quantities(const Trace& tr, const StepContext& ctx, bool counts) {
    static const char* decimalNames[] = {
        "visibility", "1-visibility", "ref",    "z",          "depth_bias", "uv.x",     "uv.y",
        "texel.x",    "texel.y",      "frac.x", "frac.y",     "1-frac.x",   "1-frac.y", "g.x",
        "g.y",        "tent.s",       "tent.t", "in_texel.x", "in_texel.y"};
    static const char* countNames[] = {"lit_count", "shadowed_count", "taps",    "texels",
                                       "distinct",  "fetches",        "hw_taps", "gathers"};
    std::vector<Quantity> out;
    auto add = [&](const std::string& name) {
        if (std::optional<double> v = placeholderNumber(name, tr, ctx)) out.push_back({name, *v});
    };
    if (counts) {
        for (const char* n : countNames) add(n);
        return out;
    }
    for (const char* n : decimalNames) add(n);
    for (std::size_t k = 0; k < tr.taps.size(); ++k) {
        for (const char* f : {"depth", "ref", "weight"}) {
            add("tap[" + std::to_string(k) + "]." + f);
        }
    }
    return out;
}

// The words the rules read, with what they know of the step.
struct Reader {
    const std::vector<Word>& w;
    const Trace& tr;
    const StepContext& ctx;
    std::vector<WordProblem>& out;
    std::vector<bool> used = std::vector<bool>(w.size(), false);  // numbers a rule has read

    bool is(std::size_t k, Word::Kind kind, std::string_view text = {}) const {
        return k < w.size() && w[k].kind == kind && (text.empty() || w[k].text == text);
    }
    bool word(std::size_t k, std::string_view text) const { return is(k, Word::Text, text); }
    void refuse(std::size_t k, std::string problem) {
        out.push_back({w[k].at, std::move(problem)});
    }

    // A formula's constant: next to an operator.
    bool besideOperator(std::size_t k) const {
        return (k > 0 && isOperator(w[k - 1])) || (k + 1 < w.size() && isOperator(w[k + 1]));
    }
    // ... or the result of arithmetic on typed numbers ("1 - 0.2 = 0.8").
    bool operand(std::size_t k) const {
        if (besideOperator(k)) return true;
        if (k == 0 || !is(k - 1, Word::Punct, "=")) return false;
        for (std::size_t j = k - 1; j-- > 0 && !endsClause(w[j]);) {
            if (w[j].kind == Word::Placeholder) return false;
        }
        return true;
    }
    // One of a list of three or more numbers: "0, 0.25, 0.5, 0.75 or 1".
    bool inList(std::size_t k) const {
        auto joiner = [&](std::size_t j) {
            return is(j, Word::Punct, ",") || word(j, "or") || word(j, "and");
        };
        int count = 1;
        for (std::size_t j = k; j >= 2 && joiner(j - 1) && is(j - 2, Word::Number); j -= 2) ++count;
        for (std::size_t j = k; joiner(j + 1) && is(j + 2, Word::Number); j += 2) ++count;
        return count >= 3;
    }

    void labelled(std::size_t k);
    void typedDecimal(std::size_t k);
    void countPhrase(std::size_t k);
    void stateWord(std::size_t k);
    std::optional<std::pair<std::string, std::size_t>> stateAt(std::size_t k) const;
    std::size_t visibilityAt(std::size_t k) const;
};

// "visibility 1", "ref = 0.5", "fx of 0.25": the number after a quantity's name.
void Reader::labelled(std::size_t k) {
    static const std::pair<const char*, const char*> names[] = {{"visibility", "visibility"},
                                                                {"ref", "ref"},
                                                                {"z", "z"},
                                                                {"fx", "frac.x"},
                                                                {"fy", "frac.y"},
                                                                {"depth", ""}};
    for (auto [label, placeholder] : names) {
        if (!word(k, label)) continue;
        std::size_t n = k + 1;
        if (is(n, Word::Punct, "=") || is(n, Word::Punct, ":") || word(n, "is") || word(n, "of"))
            ++n;
        if (!is(n, Word::Number) || w[n].quoted || besideOperator(n)) return;
        used[n] = true;
        std::string typed = w[k].text + " " + w[n].text;
        if (std::string_view(placeholder).empty()) {
            for (std::size_t t = 0; t < tr.taps.size(); ++t) {
                if (!typedAs(w[n], tr.taps[t].depth)) continue;
                return refuse(k, "\"" + typed + "\" types read " + std::to_string(t) +
                                     "'s depth: write {tap[" + std::to_string(t) + "].depth}");
            }
            return;
        }
        std::optional<double> q = placeholderNumber(placeholder, tr, ctx);
        if (!q) return;
        std::string use = "{" + std::string(placeholder) + "}";
        if (typedAs(w[n], *q)) {
            return refuse(k, "\"" + typed + "\" types the step's " + label + ": write " + use +
                                 " (a typed number does not follow the keys)");
        }
        return refuse(k, "\"" + typed + "\" is false here: the step's " + label + " is " +
                             formatNumber(static_cast<float>(*q)) + " (write " + use + ")");
    }
}

// A decimal equal to one of the step's quantities.
void Reader::typedDecimal(std::size_t k) {
    if (decimals(w[k]) == 0 || w[k].quoted || used[k] || operand(k) || inList(k)) return;
    std::vector<std::string> names;
    for (const Quantity& q : quantities(tr, ctx, false)) {
        if (typedAs(w[k], q.value)) names.push_back("{" + q.name + "}");
    }
    if (names.empty()) return;
    if (names.size() == 1) {
        return refuse(k, w[k].text + " is the step's " + names[0] + " typed: write " + names[0] +
                             " (a typed number does not follow the keys)");
    }
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    refuse(k, w[k].text + " is a number of the step typed (" + list +
                  "): write the placeholder it stands for (a typed number does not follow the "
                  "keys)");
}

// "3 of the 4 reads": a typed count of the step.
void Reader::countPhrase(std::size_t k) {
    if (!word(k, "of") || k == 0) return;
    std::size_t m = word(k + 1, "the") ? k + 2 : k + 1;
    bool before = is(k - 1, Word::Number) && decimals(w[k - 1]) == 0 && !w[k - 1].quoted;
    bool after = is(m, Word::Number) && decimals(w[m]) == 0 && !w[m].quoted;
    bool phrase = (before || is(k - 1, Word::Placeholder)) && (after || is(m, Word::Placeholder));
    if (!phrase) return;
    std::vector<Quantity> counts = quantities(tr, ctx, true);
    auto check = [&](std::size_t at, bool part) {
        used[at] = true;
        for (const Quantity& q : counts) {
            bool partName = q.name == "lit_count" || q.name == "shadowed_count";
            if (partName != part || value(w[at]) != q.value) continue;
            return refuse(at, "\"" + w[at].text + "\" in \"" +
                                  (part ? w[at].text + " of" : "of " + w[at].text) +
                                  "\" is the step's {" + q.name + "} typed: write {" + q.name +
                                  "}");
        }
    };
    if (before) check(k - 1, true);
    if (after) check(m, false);
}

// A state phrase at w[k] ("fully lit", "in shadow", "half in shadow", "in the penumbra"): the
// claim it states (lit, shadowed, penumbra) and the words after it; nullopt when none.
std::optional<std::pair<std::string, std::size_t>> Reader::stateAt(std::size_t k) const {
    std::size_t at = k;
    while (word(at, "still") || word(at, "now") || word(at, "then") || word(at, "also")) ++at;
    std::string qualifier;
    if (word(at, "fully") || word(at, "entirely") || word(at, "half") || word(at, "partly") ||
        word(at, "partially")) {
        qualifier = w[at++].text;
    }
    bool partial = qualifier == "half" || qualifier == "partly" || qualifier == "partially";
    if (word(at, "lit")) return std::pair{std::string(partial ? "penumbra" : "lit"), at + 1};
    if (word(at, "shadowed"))
        return std::pair{std::string(partial ? "penumbra" : "shadowed"), at + 1};
    if (word(at, "dark") && !qualifier.empty() && !partial)
        return std::pair{std::string("shadowed"), at + 1};
    if (word(at, "in") && word(at + 1, "shadow"))
        return std::pair{std::string(partial ? "penumbra" : "shadowed"), at + 2};
    if (word(at, "in") && word(at + 1, "full") && word(at + 2, "shadow"))
        return std::pair{std::string("shadowed"), at + 3};
    if (word(at, "in") && word(at + 1, "the") && word(at + 2, "penumbra"))
        return std::pair{std::string("penumbra"), at + 3};
    if (word(at, "in") && word(at + 1, "penumbra"))
        return std::pair{std::string("penumbra"), at + 2};
    return std::nullopt;
}

// Where the point's visibility is named from w[k]: "visibility {visibility}", "visibility =
// 0.6", "{visibility}"; the index after it, or 0 when none is.
std::size_t Reader::visibilityAt(std::size_t k) const {
    if (is(k, Word::Placeholder, "visibility")) return k + 1;
    if (!word(k, "visibility")) return 0;
    std::size_t n = k + 1;
    if (is(n, Word::Punct, "=") || word(n, "is") || word(n, "of")) ++n;
    return is(n, Word::Number) || is(n, Word::Placeholder, "visibility") ? n + 1 : 0;
}

// A state word about the point, checked as its claim.
void Reader::stateWord(std::size_t k) {
    std::optional<std::pair<std::string, std::size_t>> state;
    std::size_t from = k;
    // "the point is lit", "this pixel stays in shadow", "it is lit".
    bool verb = word(k, "is") || word(k, "stays") || word(k, "lies") || word(k, "sits") ||
                word(k, "remains") || word(k, "was");
    bool subject =
        k > 0 && (word(k - 1, "it") ||
                  ((word(k - 1, "point") || word(k - 1, "pixel")) && k > 1 &&
                   (word(k - 2, "the") || word(k - 2, "this") || word(k - 2, "ringed"))));
    if (verb && subject) {
        state = stateAt(k + 1);
        if (state) from = k + 1;
    }
    // "visibility {visibility}: in shadow".
    if (!state) {
        std::size_t after = visibilityAt(k);
        if (after > 0 && (is(after, Word::Punct, ":") || is(after, Word::Punct, ","))) {
            state = stateAt(after + 1);
            if (state) from = after + 1;
        }
    }
    // "fully lit, visibility 1": the state opens its clause ("3 of 4 are lit: ..." is about the
    // reads).
    if (!state && (k == 0 || endsClause(w[k - 1]))) {
        std::optional<std::pair<std::string, std::size_t>> s = stateAt(k);
        if (s && (is(s->second, Word::Punct, ",") || is(s->second, Word::Punct, ":")) &&
            visibilityAt(s->second + 1) > 0) {
            state = s;
        }
    }
    if (!state || w[from].quoted) return;
    auto holds = [&](const std::string& name) {
        StepClaim claim{name, 0, parseClaim(name)};
        return claimHolds(claim, tr, ctx, ClaimWorld{});
    };
    if (holds(state->first)) return;
    std::string truth = holds("lit") ? "lit" : holds("shadowed") ? "shadowed" : "penumbra";
    std::string said;
    for (std::size_t j = from; j < state->second; ++j)
        said += (said.empty() ? "" : " ") + w[j].text;
    refuse(from, "\"" + said + "\" is false here: the point's visibility is " +
                     formatNumber(static_cast<float>(tr.visibility)) + ", " +
                     (truth == "penumbra" ? "in the penumbra" : truth) +
                     " (write {visibility}, and list the claim \"" + truth + "\" to check it)");
}

}  // namespace

std::vector<WordProblem> typedWordProblems(std::string_view text, const Trace& trace,
                                           const StepContext& ctx) {
    std::vector<Word> words = wordsOf(text);
    std::vector<WordProblem> out;
    Reader r{words, trace, ctx, out};
    for (std::size_t k = 0; k < words.size(); ++k) {
        if (words[k].quoted) continue;
        r.labelled(k);
        r.countPhrase(k);
        r.stateWord(k);
    }
    // What no rule above read: decimals typed for a quantity.
    for (std::size_t k = 0; k < words.size(); ++k) {
        if (words[k].kind == Word::Number) r.typedDecimal(k);
    }
    // One problem a place ("visibility {visibility}: in shadow" is read from both words).
    std::stable_sort(out.begin(), out.end(), [](const WordProblem& a, const WordProblem& b) {
        return a.offset < b.offset;
    });
    out.erase(std::unique(
                  out.begin(), out.end(),
                  [](const WordProblem& a, const WordProblem& b) { return a.offset == b.offset; }),
              out.end());
    return out;
}

}  // namespace pcf
