// The report's figures as standalone SVG 1.1 text, with no drawing library: correct rate against
// variance floor and against model order (thesis figures 4.13 and 4.14: per series the mean rate
// over classes as a line, min..max as a band) and run time against error with the Pareto front.
// Numbers are written locale-independently; no NaN or infinity is ever written (such points are
// left out).
#pragma once

#include <string>
#include <vector>

#include "analysis/report.h"
#include "analysis/sweep.h"

namespace tactile::analysis {

// Rate against the swept variable (log x axis when every x is positive): the mean as a solid
// line, min and max dashed. Empty series are left
// out; with none the chart says so.
std::string rateChartSvg(const std::vector<RateSeries>& series, SweptVariable variable,
                         const std::string& title);

// Fit + predict seconds (log x) against error percent (100 - balanced accuracy) of every
// successful cell, one colour per group; the Pareto front (paretoFront) joined and ringed.
std::string timeErrorChartSvg(const SweepResult& sweep, const std::string& title);

}  // namespace tactile::analysis
