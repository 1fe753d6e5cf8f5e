// The report's figures as standalone SVG 1.1 text, with no drawing library: correct rate against
// variance floor and against model order (thesis figures 4.13 and 4.14: per series the mean rate
// over classes as a line, min..max as a band) and run time against error with the Pareto front.
// Numbers are written locale-independently; no NaN or infinity is ever written (such points are
// left out).
#pragma once

#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "analysis/sweep_summary.h"

namespace tactile::analysis {

// Rate against the swept variable (log x axis when every x is positive, linear otherwise; a tick
// at each swept value): per series the mean as a solid line with dots, the min..max band pale and
// edged by dashed lines, a legend entry by label. Series without a finite point are left out;
// with none the chart says so. Points are read up to the shortest of x, mean, min and max.
std::string rateChartSvg(const std::vector<RateSeries>& series, SweptVariable variable,
                         const std::string& title);

// Fit + predict seconds (log x, decades) against error percent (100 - balanced accuracy) of every
// successful cell scored on test rows, one colour per group; each group's own Pareto front
// (paretoFront of that group: cells of different groups are no alternatives to each other) ringed
// and joined as a staircase in the group's colour. Cells with a non-finite time are left out.
std::string timeErrorChartSvg(const SweepResult& sweep, const std::string& title);

}  // namespace tactile::analysis
