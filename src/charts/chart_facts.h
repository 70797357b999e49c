// chart_facts.h: the statements a lesson step makes about its chart's data ("chart: FACT" claims,
// lesson/lesson_claims.h), read from the CSV the chart draws, so that `lesson check` verifies
// them as it verifies the words about a lookup. One table (chart_facts.cpp): each fact's words,
// the charts it applies to, and its test. Orders of dots ("A faster than B") are not facts here:
// lesson_claims.h parses those itself.
//
//   measured on NAME                          any chart: GL_RENDERER contains NAME (bench.csv's
//                                             gl_renderer, stability.csv's setup row)
//   measured against the KIND truth           a bench chart: every row's truth (bench.csv's
//                                             truth column) is KIND, hard or area
//   X is the most accurate                    a bench chart: the dot X names (a label or its
//   X is the least accurate                   first word, one dot) is strictly below (above)
//                                             every other on the chart's accuracy axis (edge
//                                             RMSE; near the contacts on a #contact chart)
//   the front is A, B                         a bench chart: its Pareto front of the medians (the
//                                             ringed dots, fastest first) is exactly A, B (dot
//                                             labels, "gather3 1024")
//   M: acne falls as the bias grows           #tradeoff: method M's acne over the onset at the
//                                             smallest bias, under it at the largest
//   M: leak grows with the bias               #tradeoff: M's leak under the onset at the smallest
//                                             bias, over it (some contact scene) at the largest
//   M: a good bias lies between acne and leak #tradeoff: M has good biases (stability_figures.h:
//                                             TradeoffSeries::good), acne over the onset below
//                                             them and leak over it above them
//   L: over the onset at every elevation      #acne: line L's false-shadow rate is at or over the
//                                             onset (1 %) at every elevation swept
//   L: crosses the onset above E degrees      #acne: as the sun sets, the first elevation where L
//   L: crosses the onset below E degrees      reaches the onset is above (below) E; a line that
//                                             never reaches it is below every E
//   L: rises over the onset and falls back    #acne: L starts under the onset at the highest sun,
//                                             reaches it, and ends under it at the lowest
//   L: leak falls under 0.001 from K V        #bleed: at the chart's gap, the first value of
//                                             setting K on line L ("vsm 5x5") whose leak (99th
//                                             percentile) is under 0.001 is V ("lbr 0.3")
//   at lambda L, cascade K reads the fewest   #cascades: at split lambda L, cascade K's texels
//     texels per pixel (or the most)          per screen pixel (the median its line draws) is
//                                             strictly below (above) every other cascade's there
//   at lambda L, cascade K holds no receiver  #cascades: K's line has no point at L (no receiver
//                                             on screen reads it)
//   the cascades spread less at lambda A than #cascades: the most over the fewest texels per
//     at lambda B                             pixel over the cascades with receivers is smaller
//                                             at A than at B
//
//   the choice is X                           an advise chart (step_chart.h: DIR/advise.csv):
//   the runner-up is X                        the setting advise chose (the cheapest other one
//                                             that meets the budget; "none": no other does) is
//                                             X, named as advise names it ("hw2x2 map 512 bias
//                                             none")
//   X meets the budget                        X breaks none of the budget's bounds
//   X breaks the C budget(s)                  the bounds X breaks are exactly C ("edge",
//                                             "edge and shimmer", "edge, acne and leak")
//   the C budget binds / budgets bind         what rules out the cheaper settings
//                                             (advise.h: adviseBinds) is exactly C
//   X reads N texels                          advise.csv's texel reads per lookup of X
//   the search measured M of G settings       advise.csv's settings and advise.json's grid
//   N settings meet the budget                how many measured settings meet every bound
//   the budget is edge E, acne A, ...         advise.json's bounds, each one set, in that order
//   the timer cannot order X and Y            the choice's timing tie is exactly X and Y
//   X costs more than Y                       X's cost median is above Y's, spreads apart
//
// M is the chart's panel title ("pcf-gather 5x5", "nearest"); L a panel's title, a space and the
// line's bias mode ("pcf-gather 5x5 normal").
#pragma once

#include <string>

namespace pcf {

struct ChartFactAnswer {
    bool holds = false;
    std::string why;  // the numbers that decided it ("acne 0.3% at bias 0.0005")
};

// Whether `fact` holds on `chart` ("PATH" or "PATH#contact" for a bench.csv, "PATH#NAME" for a
// stability chart, as step_chart.h reads them). Throws std::invalid_argument naming the facts the
// chart knows when none matches, InputError for the file.
ChartFactAnswer chartFactHolds(const std::string& chart, const std::string& fact);

// Throws std::invalid_argument as chartFactHolds does when no fact of the table matches `fact`
// for that kind of chart (the file is not read): a lesson is refused at load for it.
void checkChartFactKnown(const std::string& chart, const std::string& fact);

}  // namespace pcf
