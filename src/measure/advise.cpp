#include "measure/advise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>

namespace pcf {

const char* adviseBiasKey(BiasMode mode) {
    switch (mode) {
        case BiasMode::None:
            return "";
        case BiasMode::Normal:
            return "normal_offset";
        case BiasMode::Constant:
        case BiasMode::Slope:
        case BiasMode::ReceiverPlane:
        case BiasMode::Soft:
        case BiasMode::Interpolated:
            break;
    }
    return "constant_bias";
}

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

std::string adviseBiasName(const AdviseBias& bias) {
    std::string name(biasName(static_cast<int>(bias.mode)));
    if (bias.mode != BiasMode::None) name += " " + number(bias.amount);
    return name;
}

std::string adviseSettingName(const AdviseSetting& s) {
    std::string name(methodInfo(s.filter.method).name);
    if (s.filter.kernel > 0) name += " N=" + std::to_string(s.filter.kernel);
    if (s.filter.weights != PCF_WEIGHTS_BOX) {
        name += " " + std::string(weightsName(s.filter.weights));
        if (s.filter.weights == PCF_WEIGHTS_GAUSSIAN) name += " " + number(s.filter.sigma);
    }
    return name + " map " + std::to_string(s.mapSize) + " bias " + adviseBiasName(s.bias);
}

int adviseTexelReads(const AdviseFilter& f) {
    return fetchCounts(f.method, f.kernel > 0 ? f.kernel : 3).texels;
}

std::vector<AdviseSetting> adviseGrid(const AdviseSpace& space) {
    std::vector<AdviseSetting> grid;
    for (const AdviseFilter& f : space.filters) {
        for (int size : space.mapSizes) {
            for (const AdviseBias& b : space.biases) {
                if (validateBias(static_cast<int>(b.mode), f.method)) continue;
                grid.push_back({f, size, b});
            }
        }
    }
    return grid;
}

const char* adviseConstraintName(AdviseConstraint c) {
    switch (c) {
        case AdviseConstraint::Edge:
            return "edge";
        case AdviseConstraint::Acne:
            return "acne";
        case AdviseConstraint::Leak:
            return "leak";
        case AdviseConstraint::Shimmer:
            return "shimmer";
    }
    return "";
}

double AdviseMetrics::value(AdviseConstraint c) const {
    switch (c) {
        case AdviseConstraint::Edge:
            return edgeRmse;
        case AdviseConstraint::Acne:
            return acneShare;
        case AdviseConstraint::Leak:
            return leakTexels;
        case AdviseConstraint::Shimmer:
            return shimmerP99;
    }
    return 0.0;
}

std::optional<double> adviseLimit(const AdviseBudget& budget, AdviseConstraint c) {
    switch (c) {
        case AdviseConstraint::Edge:
            return budget.maxEdgeRmse;
        case AdviseConstraint::Acne:
            return budget.maxAcne;
        case AdviseConstraint::Leak:
            return budget.maxLeakTexels;
        case AdviseConstraint::Shimmer:
            return budget.maxShimmer;
    }
    return std::nullopt;
}

std::vector<AdviseConstraint> adviseBroken(const AdviseBudget& budget, const AdviseMetrics& m) {
    std::vector<AdviseConstraint> broken;
    for (AdviseConstraint c : ALL_ADVISE_CONSTRAINTS) {
        std::optional<double> limit = adviseLimit(budget, c);
        if (limit && !(m.value(c) <= *limit)) broken.push_back(c);
    }
    return broken;
}

bool adviseSpreadsOverlap(const AdviseMetrics& a, const AdviseMetrics& b) {
    return a.costMs - a.costIqr / 2 <= b.costMs + b.costIqr / 2 &&
           b.costMs - b.costIqr / 2 <= a.costMs + a.costIqr / 2;
}

namespace {

void checkSearchInput(const AdviseSpace& space, const AdviseBudget& budget) {
    if (space.filters.empty() || space.mapSizes.empty() || space.biases.empty()) {
        throw std::invalid_argument("advise: no filter, map size or bias to choose from");
    }
    if (!std::is_sorted(space.mapSizes.begin(), space.mapSizes.end()) ||
        std::adjacent_find(space.mapSizes.begin(), space.mapSizes.end()) != space.mapSizes.end()) {
        throw std::invalid_argument("advise: the map sizes must ascend");
    }
    for (AdviseConstraint c : ALL_ADVISE_CONSTRAINTS) {
        std::optional<double> limit = adviseLimit(budget, c);
        if (limit && !(*limit >= 0.0)) {
            throw std::invalid_argument(std::string("advise: the ") + adviseConstraintName(c) +
                                        " budget must be a number >= 0");
        }
    }
}

bool breaks(const AdviseCandidate& c, AdviseConstraint k) {
    return std::find(c.broken.begin(), c.broken.end(), k) != c.broken.end();
}

// The walk over the grid (advise.h's rules), measuring through the callback.
class AdviseSearch {
  public:
    AdviseSearch(const AdviseSpace& space, const AdviseBudget& budget, const AdviseMeasure& measure)
        : mSpace(space), mBudget(budget), mMeasure(measure) {}

    std::vector<AdviseCandidate> run() {
        std::vector<AdviseFilter> families = mSpace.filters;
        std::stable_sort(families.begin(), families.end(), [](const auto& a, const auto& b) {
            return adviseTexelReads(a) < adviseTexelReads(b);
        });
        for (const AdviseFilter& f : families) {
            if (!skipped(f)) walkFamily(f);
        }
        return std::move(mMeasured);
    }

  private:
    const AdviseSpace& mSpace;
    const AdviseBudget& mBudget;
    const AdviseMeasure& mMeasure;
    std::vector<AdviseCandidate> mMeasured;
    std::optional<AdviseCandidate> mBest;  // the cheapest median that met the budget so far
    // Per (method, weights, sigma): the smallest N whose first size already cost too much.
    std::map<std::tuple<int, int, float>, int> mTooCostly;

    static std::tuple<int, int, float> methodKey(const AdviseFilter& f) {
        return {f.method, f.weights, f.sigma};
    }

    bool skipped(const AdviseFilter& f) const {
        auto it = mTooCostly.find(methodKey(f));
        return it != mTooCostly.end() && f.kernel > it->second;
    }

    // It cannot beat the best so far, nor can the same filter at a larger map (which costs no
    // less): its whole spread lies above the best one's, or the two overlap and it reads more
    // texels (the tie rule picks fewer reads).
    bool costlier(const AdviseCandidate& c) const {
        if (!mBest) return false;
        const AdviseMetrics& m = c.metrics;
        const AdviseMetrics& best = mBest->metrics;
        if (m.costMs - m.costIqr / 2 > best.costMs + best.costIqr / 2) return true;
        return adviseSpreadsOverlap(m, best) && c.texelReads > mBest->texelReads;
    }

    const AdviseCandidate& measureOne(const AdviseSetting& s) {
        AdviseCandidate c;
        c.setting = s;
        c.metrics = mMeasure(s);
        c.texelReads = adviseTexelReads(s.filter);
        c.broken = adviseBroken(mBudget, c.metrics);
        if (c.feasible() && (!mBest || c.metrics.costMs < mBest->metrics.costMs)) mBest = c;
        mMeasured.push_back(c);
        return mMeasured.back();
    }

    // The biases at one size from `start`: the index of the last one measured, or -1 when none
    // can combine with the method.
    int walkBiases(const AdviseFilter& f, int size, int start) {
        int last = -1;
        for (int b = start; b < static_cast<int>(mSpace.biases.size()); ++b) {
            const AdviseBias& bias = mSpace.biases[static_cast<size_t>(b)];
            if (validateBias(static_cast<int>(bias.mode), f.method)) continue;
            last = b;
            const AdviseCandidate& c = measureOne({f, size, bias});
            bool onlyAcne = c.broken.size() == 1 && c.broken[0] == AdviseConstraint::Acne;
            if (!onlyAcne || costlier(c)) break;
        }
        return last;
    }

    // Whether a failed setting at the next size could meet the budget: every measure that
    // broke it fell from the size before (the first size always goes on).
    static bool improving(const AdviseCandidate& now, const AdviseCandidate* before) {
        if (before == nullptr) return true;
        for (AdviseConstraint k : now.broken) {
            if (!(now.metrics.value(k) < before->metrics.value(k))) return false;
        }
        return true;
    }

    void walkFamily(const AdviseFilter& f) {
        int start = 0;
        std::optional<AdviseCandidate> before;
        for (size_t i = 0; i < mSpace.mapSizes.size(); ++i) {
            int last = walkBiases(f, mSpace.mapSizes[i], start);
            if (last < 0) return;  // no bias of the space combines with the method
            AdviseCandidate c = mMeasured.back();
            if (costlier(c)) {  // met the budget or not, it cannot win, nor can larger N
                if (i == 0) {
                    auto [it, fresh] = mTooCostly.emplace(methodKey(f), f.kernel);
                    if (!fresh) it->second = std::min(it->second, f.kernel);
                }
                return;
            }
            if (c.feasible()) return;
            if (!improving(c, before ? &*before : nullptr)) return;
            start = breaks(c, AdviseConstraint::Leak) ? 0 : last;
            before = c;
        }
    }
};

// How far a candidate is from the budget: the constraints it breaks, then the largest ratio of
// a broken measure to its bound.
std::pair<size_t, double> distanceToBudget(const AdviseCandidate& c, const AdviseBudget& budget) {
    double worst = 0.0;
    for (AdviseConstraint k : c.broken) {
        double limit = adviseLimit(budget, k).value_or(0.0);
        worst = std::max(worst, c.metrics.value(k) / std::max(limit, 1e-12));
    }
    return {c.broken.size(), worst};
}

}  // namespace

void chooseAdvice(AdviseResult& result, const AdviseBudget& budget) {
    const std::vector<AdviseCandidate>& m = result.measured;
    std::vector<size_t> feasible;
    for (size_t k = 0; k < m.size(); ++k) {
        if (m[k].feasible()) feasible.push_back(k);
    }
    if (feasible.empty()) {
        for (size_t k = 0; k < m.size(); ++k) {
            if (!result.closest ||
                distanceToBudget(m[k], budget) < distanceToBudget(m[*result.closest], budget)) {
                result.closest = k;
            }
        }
        return;
    }
    auto byMedian = [&](size_t a, size_t b) { return m[a].metrics.costMs < m[b].metrics.costMs; };
    std::stable_sort(feasible.begin(), feasible.end(), byMedian);
    std::vector<size_t> tied;
    for (size_t k : feasible) {
        if (adviseSpreadsOverlap(m[k].metrics, m[feasible[0]].metrics)) tied.push_back(k);
    }
    size_t choice = *std::min_element(tied.begin(), tied.end(), [&](size_t a, size_t b) {
        if (m[a].texelReads != m[b].texelReads) return m[a].texelReads < m[b].texelReads;
        return byMedian(a, b);
    });
    result.choice = choice;
    for (size_t k : feasible) {
        if (k != choice) {
            result.runnerUp = k;
            break;
        }
    }
    if (tied.size() > 1) result.tied = tied;
}

namespace {

// The feasible candidates' costs from one round-robin timing of them all.
void retimeFeasible(std::vector<AdviseCandidate>& measured, const AdviseRetime& retime) {
    std::vector<size_t> feasible;
    std::vector<AdviseSetting> settings;
    for (size_t k = 0; k < measured.size(); ++k) {
        if (!measured[k].feasible()) continue;
        feasible.push_back(k);
        settings.push_back(measured[k].setting);
    }
    if (feasible.size() < 2) return;
    std::vector<AdviseCost> costs = retime(settings);
    if (costs.size() != feasible.size()) {
        throw std::logic_error("advise: the retiming gave a cost per setting asked");
    }
    for (size_t i = 0; i < feasible.size(); ++i) {
        AdviseCandidate& c = measured[feasible[i]];
        c.metrics.costMs = costs[i].ms;
        c.metrics.costIqr = costs[i].iqr;
        c.retimed = true;
    }
}

}  // namespace

AdviseResult searchAdvice(const AdviseSpace& space, const AdviseBudget& budget,
                          const AdviseMeasure& measure, const AdviseRetime& retime) {
    checkSearchInput(space, budget);
    AdviseResult result;
    result.gridSize = adviseGrid(space).size();
    result.measured = AdviseSearch(space, budget, measure).run();
    if (retime) retimeFeasible(result.measured, retime);
    chooseAdvice(result, budget);
    return result;
}

std::string adviseBreakText(const AdviseCandidate& c, AdviseConstraint k,
                            const AdviseBudget& budget) {
    double v = c.metrics.value(k);
    std::string limit = number(adviseLimit(budget, k).value_or(0.0));
    char text[128];
    switch (k) {
        case AdviseConstraint::Edge:
            std::snprintf(text, sizeof text, "has an edge RMSE of %.3g (budget %s)", v,
                          limit.c_str());
            break;
        case AdviseConstraint::Acne:
            std::snprintf(text, sizeof text, "darkens %.3g%% of the clean lit pixels (budget %s%%)",
                          100.0 * v, number(100.0 * adviseLimit(budget, k).value_or(0.0)).c_str());
            break;
        case AdviseConstraint::Leak:
            std::snprintf(text, sizeof text, "leaks %.2g texels (budget %s)", v, limit.c_str());
            break;
        case AdviseConstraint::Shimmer:
            std::snprintf(text, sizeof text, "shimmers with a p99 jump of %.2g (budget %s)", v,
                          limit.c_str());
            break;
    }
    return text;
}

namespace {

// The same filter and bias one map size down, measured: what the choice's map size is for.
const AdviseCandidate* smallerMap(const AdviseResult& r, const AdviseCandidate& choice) {
    const AdviseCandidate* found = nullptr;
    for (const AdviseCandidate& c : r.measured) {
        if (c.setting.filter == choice.setting.filter &&
            c.setting.mapSize < choice.setting.mapSize &&
            (!found || c.setting.mapSize > found->setting.mapSize ||
             (c.setting.mapSize == found->setting.mapSize &&
              c.setting.bias == choice.setting.bias))) {
            found = &c;
        }
    }
    return found;
}

// The cheapest measured setting below the choice's cost that broke the budget.
const AdviseCandidate* cheaperFailure(const AdviseResult& r, const AdviseCandidate& choice) {
    const AdviseCandidate* found = nullptr;
    for (const AdviseCandidate& c : r.measured) {
        if (!c.feasible() && c.metrics.costMs < choice.metrics.costMs &&
            (!found || c.metrics.costMs < found->metrics.costMs)) {
            found = &c;
        }
    }
    return found;
}

}  // namespace

std::string adviseBinding(const AdviseResult& result, const AdviseBudget& budget) {
    if (!result.choice) return "";
    const AdviseCandidate& choice = result.measured[*result.choice];
    if (const AdviseCandidate* below = smallerMap(result, choice); below && !below->feasible()) {
        std::string budgets, breaks;
        for (size_t k = 0; k < below->broken.size(); ++k) {
            const char* joint = k == 0 ? "" : k + 1 == below->broken.size() ? " and " : ", ";
            budgets += joint + std::string(adviseConstraintName(below->broken[k]));
            breaks += joint + adviseBreakText(*below, below->broken[k], budget);
        }
        return "map " + std::to_string(choice.setting.mapSize) + " is needed for the " + budgets +
               (below->broken.size() > 1 ? " budgets; " : " budget; ") +
               std::to_string(below->setting.mapSize) + " " + breaks;
    }
    if (const AdviseCandidate* cheaper = cheaperFailure(result, choice)) {
        AdviseConstraint k = cheaper->broken.front();
        return std::string("the ") + adviseConstraintName(k) + " budget rules out the cheaper " +
               adviseSettingName(cheaper->setting) + ", which " +
               adviseBreakText(*cheaper, k, budget);
    }
    return "nothing binds: the cheapest setting measured meets every budget";
}

std::string adviseTieNote(const AdviseResult& result) {
    if (result.tied.size() < 2 || !result.choice) return "";
    std::string names;
    for (size_t k : result.tied) {
        if (k == *result.choice) continue;
        if (!names.empty()) names += ", ";
        names += adviseSettingName(result.measured[k].setting);
    }
    const AdviseCandidate& choice = result.measured[*result.choice];
    bool fewest = std::all_of(result.tied.begin(), result.tied.end(), [&](size_t k) {
        return k == *result.choice || result.measured[k].texelReads > choice.texelReads;
    });
    std::string why = fewest ? "so the one with the fewest texel reads (" +
                                   std::to_string(choice.texelReads) + ") is chosen"
                             : "and none reads fewer texels than the chosen one (" +
                                   std::to_string(choice.texelReads) +
                                   "), so its lower median decides";
    return "the timer cannot order " + adviseSettingName(choice.setting) + " and " + names +
           " (their cost spreads overlap), " + why;
}

}  // namespace pcf
