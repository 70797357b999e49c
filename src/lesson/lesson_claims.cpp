#include "lesson/lesson_claims.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace pcf {

// A claim's token: a member of ParsedClaim (lesson.h holds claims), so outside the anonymous
// namespace.
struct ClaimToken {
    enum Kind { Number, Name, Op } kind = Number;
    double number = 0.0;
    std::string name;  // the inside of a {placeholder}
    char op = 0;       // + - * / ( )
};

namespace {

using Token = ClaimToken;

std::string trim(std::string_view s) {
    size_t a = s.find_first_not_of(" \t");
    if (a == std::string_view::npos) return "";
    size_t b = s.find_last_not_of(" \t");
    return std::string(s.substr(a, b - a + 1));
}

std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    for (size_t i = 0; i < s.size();) {
        char c = s[i];
        if (c == ' ' || c == '\t') {
            ++i;
        } else if (c == '{') {
            size_t close = s.find('}', i);
            if (close == std::string_view::npos) throw std::invalid_argument("a { with no }");
            std::string name(s.substr(i + 1, close - i - 1));
            if (std::optional<std::string> problem = numberPlaceholderProblem(name)) {
                throw std::invalid_argument(*problem);
            }
            out.push_back({Token::Name, 0.0, name, 0});
            i = close + 1;
        } else if (std::string_view("+-*/()").find(c) != std::string_view::npos) {
            out.push_back({Token::Op, 0.0, {}, c});
            ++i;
        } else {
            double v = 0.0;
            auto [end, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
            if (ec != std::errc() || end == s.data() + i) {
                throw std::invalid_argument("unexpected '" + std::string(s.substr(i)) +
                                            "' (write placeholders in braces: {visibility})");
            }
            // from_chars reads "inf" and "nan" too: nothing compares with them as a claim means.
            if (!std::isfinite(v)) {
                throw std::invalid_argument("'" + std::string(s.substr(i, end - (s.data() + i))) +
                                            "' is not a finite number");
            }
            out.push_back({Token::Number, v, {}, 0});
            i = static_cast<size_t>(end - s.data());
        }
    }
    if (out.empty()) throw std::invalid_argument("an empty side");
    return out;
}

using Lookup = std::function<std::optional<double>(const std::string&)>;

// Recursive descent: expr = term (+|- term)*, term = factor (*|/ factor)*,
// factor = number | {name} | ( expr ) | - factor. A value nullopt (an index past the trace's
// reads) makes the whole nullopt. Each ( and unary - nests one level deeper on the stack: past
// MAX_CLAIM_NESTING the claim is refused (a claim nested 60,000 deep overflowed the stack; a
// sanitized build's frames are larger and overflowed at about 5,000).
class Evaluator {
  public:
    Evaluator(const std::vector<Token>& t, Lookup lookup) : mT(t), mLookup(std::move(lookup)) {}
    std::optional<double> run() {
        std::optional<double> v = expr();
        if (mAt != mT.size()) throw std::invalid_argument("unexpected tokens after an expression");
        return v;
    }

  private:
    bool isOp(char op) const {
        return mAt < mT.size() && mT[mAt].kind == Token::Op && mT[mAt].op == op;
    }
    std::optional<double> expr() {
        std::optional<double> v = term();
        while (isOp('+') || isOp('-')) {
            char op = mT[mAt++].op;
            std::optional<double> r = term();
            if (v && r) v = op == '+' ? *v + *r : *v - *r;
            if (!r) v.reset();
        }
        return v;
    }
    std::optional<double> term() {
        std::optional<double> v = factor();
        while (isOp('*') || isOp('/')) {
            char op = mT[mAt++].op;
            std::optional<double> r = factor();
            if (v && r) v = op == '*' ? *v * *r : *v / *r;
            if (!r) v.reset();
        }
        return v;
    }
    std::optional<double> factor() {
        if (mAt >= mT.size()) throw std::invalid_argument("an expression ends too early");
        const Token& t = mT[mAt++];
        if (t.kind == Token::Number) return t.number;
        if (t.kind == Token::Name) return mLookup(t.name);
        if (t.op != '-' && t.op != '(') {
            throw std::invalid_argument(std::string("unexpected '") + t.op + "'");
        }
        if (++mDepth > MAX_CLAIM_NESTING) {
            throw std::invalid_argument("nested deeper than " + std::to_string(MAX_CLAIM_NESTING) +
                                        " levels of ( and unary -");
        }
        std::optional<double> v;
        if (t.op == '-') {
            v = factor();
            if (v) v = -*v;
        } else {
            v = expr();
            if (!isOp(')')) throw std::invalid_argument("a ( with no )");
            ++mAt;
        }
        --mDepth;
        return v;
    }

    const std::vector<Token>& mT;
    Lookup mLookup;
    size_t mAt = 0;
    int mDepth = 0;  // ( and unary - open around the current token
};

// The first comparison operator outside braces: its position and spelling.
std::pair<size_t, std::string> findComparison(std::string_view s) {
    int depth = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '{') ++depth;
        if (c == '}') --depth;
        if (depth > 0) continue;
        if (c == '<' || c == '>' || c == '!') {
            bool eq = i + 1 < s.size() && s[i + 1] == '=';
            if (c == '!' && !eq) continue;
            return {i, std::string(s.substr(i, eq ? 2 : 1))};
        }
        if (c == '=' || c == '~') return {i, std::string(1, c)};
    }
    return {std::string_view::npos, ""};
}

std::string numberText(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

}  // namespace

class ParsedClaim {
  public:
    enum Kind {
        Lit,
        Shadowed,
        Penumbra,
        FailingNearer,
        OnGround,
        Bits,
        Flickers,
        Steady,
        Compare,
        Chart,
        ChartFact
    };
    Kind kind = Compare;
    std::vector<ClaimToken> lhs, rhs;
    std::string op;
    double tolerance = 0.0;
    std::string chartA, chartB, metric;  // chart: a's metric < b's
    std::string fact;                    // chart: any other statement (ClaimWorld::chartFact)
    std::string bits;                    // bits: every read's bit, in read order
};

namespace {

// "chart: A faster than B" and the like (Chart), or any other fact about the chart (ChartFact);
// `rest` is what follows "chart:".
void parseChartClaim(ParsedClaim& c, const std::string& rest) {
    // "A faster than B": A's time is less; "slower": B's is; accuracy reads the RMSE.
    static const std::tuple<std::string_view, std::string_view, bool> ORDERS[] = {
        {" faster than ", "time", false},
        {" slower than ", "time", true},
        {" more accurate than ", "rmse", false},
        {" less accurate than ", "rmse", true}};
    for (const auto& [words, metric, swap] : ORDERS) {
        size_t at = rest.find(words);
        if (at == std::string::npos) continue;
        std::string a = trim(std::string_view(rest).substr(0, at));
        std::string b = trim(std::string_view(rest).substr(at + words.size()));
        if (a.empty() || b.empty()) break;
        c.kind = ParsedClaim::Chart;
        c.chartA = swap ? b : a;
        c.chartB = swap ? a : b;
        c.metric = metric;
        return;
    }
    // Anything else is a fact the chart's own table knows (charts/chart_facts.h), or
    // `lesson check` says which it knows.
    if (rest.empty()) throw std::invalid_argument("'chart:' says nothing about the chart");
    c.kind = ParsedClaim::ChartFact;
    c.fact = rest;
}

}  // namespace

std::shared_ptr<const ParsedClaim> parseClaim(std::string_view text) {
    auto c = std::make_shared<ParsedClaim>();
    std::string t = trim(text);
    if (t == "lit") c->kind = ParsedClaim::Lit;
    if (t == "shadowed") c->kind = ParsedClaim::Shadowed;
    if (t == "penumbra") c->kind = ParsedClaim::Penumbra;
    if (t == "failing taps nearer") c->kind = ParsedClaim::FailingNearer;
    if (t == "on the ground") c->kind = ParsedClaim::OnGround;
    if (t == "flickers") c->kind = ParsedClaim::Flickers;
    if (t == "steady") c->kind = ParsedClaim::Steady;
    if (t.rfind("bits ", 0) == 0) {
        c->kind = ParsedClaim::Bits;
        c->bits = trim(std::string_view(t).substr(5));
        if (c->bits.empty() || c->bits.find_first_not_of("01") != std::string::npos) {
            throw std::invalid_argument("bits takes the reads' bits in read order: bits 1010");
        }
    }
    if (c->kind != ParsedClaim::Compare) return c;
    if (t.rfind("chart:", 0) == 0) {
        parseChartClaim(*c, trim(std::string_view(t).substr(6)));
        return c;
    }
    auto [at, op] = findComparison(t);
    if (at == std::string_view::npos) {
        throw std::invalid_argument(
            "no comparison (=, !=, <, <=, >, >=, ~) and not a keyword (lit, shadowed, penumbra, "
            "failing taps nearer, on the ground, flickers, steady, chart: ...)");
    }
    c->op = op;
    std::string_view rhs = std::string_view(t).substr(at + op.size());
    if (op == "~") {
        size_t pm = rhs.find("+-");
        if (pm == std::string_view::npos) {
            throw std::invalid_argument("a near (~) needs its tolerance: a ~ b +- 0.001");
        }
        std::string tol = trim(rhs.substr(pm + 2));
        double v = 0.0;
        auto [end, ec] = std::from_chars(tol.data(), tol.data() + tol.size(), v);
        if (ec != std::errc() || end != tol.data() + tol.size() || !(v >= 0.0) ||
            !std::isfinite(v)) {
            throw std::invalid_argument("the tolerance after +- must be a finite number >= 0");
        }
        c->tolerance = v;
        rhs = rhs.substr(0, pm);
    }
    c->lhs = tokenize(std::string_view(t).substr(0, at));
    c->rhs = tokenize(rhs);
    // Both sides must parse as expressions: evaluate them once with every value 1.
    Lookup ones = [](const std::string&) { return std::optional<double>(1.0); };
    Evaluator(c->lhs, ones).run();
    Evaluator(c->rhs, ones).run();
    return c;
}

std::vector<std::string> claimPlaceholders(const StepClaim& claim) {
    std::vector<std::string> names;
    if (!claim.parsed || claim.parsed->kind != ParsedClaim::Compare) return names;
    for (const auto* side : {&claim.parsed->lhs, &claim.parsed->rhs}) {
        for (const ClaimToken& t : *side) {
            if (t.kind == ClaimToken::Name) names.push_back(t.name);
        }
    }
    return names;
}

std::string chartFactOf(const StepClaim& claim) {
    return claim.parsed && claim.parsed->kind == ParsedClaim::ChartFact ? claim.parsed->fact : "";
}

bool isChartClaim(const StepClaim& claim) {
    return claim.parsed && (claim.parsed->kind == ParsedClaim::Chart ||
                            claim.parsed->kind == ParsedClaim::ChartFact);
}

bool isMotionClaim(const StepClaim& claim) {
    return claim.parsed && (claim.parsed->kind == ParsedClaim::Flickers ||
                            claim.parsed->kind == ParsedClaim::Steady);
}

namespace {

// A placeholder as a class would say it ("in_texel.y": "where the point lies across its texel
// in v"), for the placeholders claims compare most; "" for the others.
std::string placeholderInWords(const std::string& name) {
    static const std::pair<std::string_view, std::string_view> NOUNS[] = {
        {"visibility", "the visibility"},
        {"shadow", "the shadow, 1 - visibility"},
        {"light_angle", "the light's angle from the surface's normal"},
        {"in_texel.x", "where the point lies across its texel in u"},
        {"in_texel.y", "where the point lies across its texel in v"},
        {"frac.x", "the sub-texel position in u"},
        {"frac.y", "the sub-texel position in v"},
        {"lit_count", "the number of reads that pass"},
        {"shadowed_count", "the number of reads that fail"},
        {"ref", "the depth compared, ref"},
        {"depth_bias", "the bias, z - ref"},
    };
    for (const auto& [key, noun] : NOUNS) {
        if (name == key) return std::string(noun);
    }
    // part[K].visibility, tap[K].margin, tap[K].depth: the K-th, counted from 1.
    size_t open = name.find('['), close = name.find(']');
    if (open == std::string::npos || close == std::string::npos || close < open) return "";
    std::string base = name.substr(0, open), field = name.substr(close + 1);
    int k = std::atoi(name.substr(open + 1, close - open - 1).c_str()) + 1;
    if (base == "part" && field == ".visibility") {
        return "the visibility of part " + std::to_string(k) + " of the split view";
    }
    if (base == "tap" && field == ".margin") return "read " + std::to_string(k) + "'s depth - ref";
    if (base == "tap" && field == ".depth") return "read " + std::to_string(k) + "'s stored depth";
    return "";
}

// "{light_angle} > 60" as "the light's angle from the surface's normal is above 60"; "" for an
// expression that is not one named placeholder against one number.
std::string comparisonInWords(const ParsedClaim& c) {
    if (c.lhs.size() != 1 || c.rhs.size() != 1 || c.lhs[0].kind != ClaimToken::Name ||
        c.rhs[0].kind != ClaimToken::Number) {
        return "";
    }
    std::string noun = placeholderInWords(c.lhs[0].name);
    if (noun.empty()) return "";
    std::string value = numberText(c.rhs[0].number);
    if (c.op == "~") return noun + " is within " + numberText(c.tolerance) + " of " + value;
    static const std::pair<std::string_view, std::string_view> OPS[] = {
        {"=", "exactly"},  {"!=", "not"},  {"<", "below"},
        {"<=", "at most"}, {">", "above"}, {">=", "at least"}};
    for (const auto& [op, words] : OPS) {
        if (c.op == op) return noun + " is " + std::string(words) + " " + value;
    }
    return "";
}

}  // namespace

std::string claimInWords(const StepClaim& claim) {
    if (!claim.parsed) return "";
    switch (claim.parsed->kind) {
        case ParsedClaim::Lit:
            return "the point is fully lit";
        case ParsedClaim::Shadowed:
            return "the point is fully shadowed";
        case ParsedClaim::Penumbra:
            return "the point is in penumbra, partly lit";
        case ParsedClaim::FailingNearer:
            return "every read that fails stores a depth nearer the light than the point";
        case ParsedClaim::OnGround:
            return "the point lies on the ground";
        case ParsedClaim::Bits:
            return "the reads' comparison bits are " + claim.parsed->bits;
        case ParsedClaim::Flickers:
            return "the point's visibility jumps between frames of the step's own sweep";
        case ParsedClaim::Steady:
            return "the point's visibility stays the same over every frame of the step's own "
                   "sweep";
        case ParsedClaim::Chart:
        case ParsedClaim::ChartFact:
            return "";
        case ParsedClaim::Compare:
            break;
    }
    return comparisonInWords(*claim.parsed);
}

namespace {

bool litHolds(const Trace& t) {
    // Every read that counts passes (the weights' float sum may round to 0.99999994).
    for (const TapRecord& tap : t.taps) {
        if (tap.weight > 0.0f && tap.lit < 0.5f) return false;
    }
    return t.visibility > 0.99999f;
}

bool failingNearer(const Trace& t, std::string* why) {
    for (size_t k = 0; k < t.taps.size(); ++k) {
        const TapRecord& tap = t.taps[k];
        if (tap.lit < 0.5f && !(tap.depth < tap.ref)) {
            if (why)
                *why = "read " + std::to_string(k) +
                       " fails with depth - ref = " + numberText(tap.depth - tap.ref);
            return false;
        }
    }
    return true;
}

// The curve's largest change between two consecutive frames, in `most`; `why` gets it and where,
// with `rule` (what the claim asks of it), or the frame whose point is on no receiver (false).
bool largestChange(const std::vector<float>& curve, const std::string& rule, float& most,
                   std::string* why) {
    most = 0.0f;
    size_t at = 0;
    for (size_t k = 0; k < curve.size(); ++k) {
        if (curve[k] < 0.0f) {
            if (why) *why = "frame " + std::to_string(k) + ": the point is on no receiver";
            return false;
        }
        if (k == 0) continue;
        float change = std::fabs(curve[k] - curve[k - 1]);
        if (change > most) {
            most = change;
            at = k;
        }
    }
    if (why) {
        *why =
            "largest change between two frames " + numberText(most) +
            (most > 0.0f ? " (frame " + std::to_string(at - 1) + " to " + std::to_string(at) + ")"
                         : std::string()) +
            " over " + std::to_string(curve.size()) + " frames; " + rule;
    }
    return true;
}

// Whether the curve jumps by FLICKER_JUMP or more between two consecutive frames.
bool curveFlickers(const std::vector<float>& curve, std::string* why) {
    float most = 0.0f;
    std::string rule = "flicker is a jump of " + numberText(FLICKER_JUMP) + " or more";
    return largestChange(curve, rule, most, why) && most >= FLICKER_JUMP;
}

// Whether the curve changes by less than STEADY_CHANGE between every two consecutive frames.
bool curveSteady(const std::vector<float>& curve, std::string* why) {
    float most = 0.0f;
    std::string rule = "steady is a change under 1/512 every frame";
    return largestChange(curve, rule, most, why) && most < STEADY_CHANGE;
}

bool compare(double a, const std::string& op, double b, double tolerance) {
    if (op == "=") return a == b;
    if (op == "!=") return a != b;
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    if (op == ">=") return a >= b;
    return std::fabs(a - b) <= tolerance;
}

// Every claim says what decided it when the caller asks (`why` not null).
void tellWhy(std::string* why, std::string s) {
    if (why) *why = std::move(s);
}

// bits: every read's comparison bit, in read order, against the claim's string.
bool bitsHold(const ParsedClaim& c, const Trace& trace, std::string* why) {
    std::string got;
    for (const TapRecord& tap : trace.taps) got += tap.lit >= 0.5f ? '1' : '0';
    tellWhy(why, "bits " + got);
    return got == c.bits;
}

// flickers, steady: decided on the step's flicker curve, which the world computes (held without
// one).
bool flickerClaimHolds(const ClaimWorld& world, bool steady, std::string* why) {
    if (!world.flickerCurve) return true;
    std::variant<std::vector<float>, std::string> curve = world.flickerCurve();
    if (auto* problem = std::get_if<std::string>(&curve)) {
        tellWhy(why, *problem);
        return false;
    }
    const std::vector<float>& values = std::get<std::vector<float>>(curve);
    return steady ? curveSteady(values, why) : curveFlickers(values, why);
}

// chart: A faster (more accurate) than B, read off the step's chart by the world (held without
// one).
bool chartOrderHolds(const ParsedClaim& c, const ClaimWorld& world, std::string* why) {
    if (!world.chartLess) return true;
    std::variant<bool, std::string> r = world.chartLess(c.chartA, c.chartB, c.metric);
    if (auto* problem = std::get_if<std::string>(&r)) {
        tellWhy(why, *problem);
        return false;
    }
    tellWhy(why, c.chartA + "'s " + c.metric + " is not less than " + c.chartB + "'s");
    return std::get<bool>(r);
}

// chart: any other fact, decided by the world (held without one).
bool chartFactClaimHolds(const ParsedClaim& c, const ClaimWorld& world, std::string* why) {
    if (!world.chartFact) return true;
    std::string factWhy;
    bool holds = world.chartFact(c.fact, &factWhy);
    tellWhy(why, factWhy);
    return holds;
}

// A comparison of two expressions over the step's placeholders; false where a placeholder has
// no value (an index past the trace's reads).
bool comparisonHolds(const ParsedClaim& c, const Trace& trace, const StepContext& ctx,
                     std::string* why) {
    Lookup values = [&](const std::string& name) { return placeholderNumber(name, trace, ctx); };
    std::optional<double> a = Evaluator(c.lhs, values).run();
    std::optional<double> b = Evaluator(c.rhs, values).run();
    if (!a || !b) {
        tellWhy(why, "a placeholder has no value here (an index past the trace's reads)");
        return false;
    }
    bool holds = compare(*a, c.op, *b, c.tolerance);
    std::string got = numberText(*a) + " " + c.op + " " + numberText(*b);
    if (c.op == "~") got += " +- " + numberText(c.tolerance);
    tellWhy(why, (holds ? "" : "not ") + got);
    return holds;
}

}  // namespace

bool claimHolds(const StepClaim& claim, const Trace& trace, const StepContext& ctx,
                const ClaimWorld& world, std::string* why) {
    const ParsedClaim& c = *claim.parsed;
    switch (c.kind) {
        case ParsedClaim::Lit:
            tellWhy(why, "visibility " + numberText(trace.visibility));
            return litHolds(trace);
        case ParsedClaim::Shadowed:
            tellWhy(why, "visibility " + numberText(trace.visibility));
            return trace.visibility == 0.0f;
        case ParsedClaim::Penumbra:
            tellWhy(why, "visibility " + numberText(trace.visibility));
            return trace.visibility > 0.0f && trace.visibility < 1.0f;
        case ParsedClaim::FailingNearer:
            return failingNearer(trace, why);
        case ParsedClaim::Bits:
            return bitsHold(c, trace, why);
        case ParsedClaim::OnGround:
            tellWhy(why, "the point is not on a plane");
            return world.onPlane;
        case ParsedClaim::Flickers:
            return flickerClaimHolds(world, false, why);
        case ParsedClaim::Steady:
            return flickerClaimHolds(world, true, why);
        case ParsedClaim::Chart:
            return chartOrderHolds(c, world, why);
        case ParsedClaim::ChartFact:
            return chartFactClaimHolds(c, world, why);
        case ParsedClaim::Compare:
            break;
    }
    return comparisonHolds(c, trace, ctx, why);
}

}  // namespace pcf
