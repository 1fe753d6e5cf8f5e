// The summary of a sweep that the report, its figures and the workbench's plots share: rate
// series against the swept variable (thesis figures 4.13 and 4.14), the run time against error
// Pareto front, and the one rule that picks each group's best cell.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/metrics.h"
#include "analysis/sweep.h"

namespace tactile::analysis {

// Figures 4.13 / 4.14 as data: one series per fixed setting (group, features, method, form, the
// other of order / floor, seed) with a point per value of the swept variable, ascending. Cells of
// boosted trees, which have neither order nor floor, are in none. Each
// point is one successful cell with per-class rates (recall, percent): their mean, min and max
// over the cell's classes, and the cell's accuracy and balanced accuracy (percent).
enum class SweptVariable { Floor, Order };
struct RateSeries {
  SensorGroup group = SensorGroup::Front;
  FeatureKind features = FeatureKind::Normal;
  ClassifierMethod method = ClassifierMethod::Gmm;
  CovarianceForm form = CovarianceForm::NodalDiag;
  double fixedValue = 0.0;  // the order (floor swept) or the floor (order swept)
  std::uint64_t seed = 1;
  std::string label;      // e.g. "F gmm nodal-diag order 4" or "R gaussian floor 0.1"
  std::vector<double> x;  // swept values
  std::vector<double> mean, min, max, accuracy, balancedAccuracy;
  std::vector<std::size_t> cells;  // index into SweepResult::cells of each point
};
std::vector<RateSeries> rateSeries(const SweepResult& sweep, SweptVariable variable);

// Run time against error: the successful cells scored on test rows (of one group, or all) that
// no other one beats, that is, none has both fit + predict seconds and error (1 - balanced
// accuracy) at most as large and one of them smaller. Indices into sweep.cells, by ascending time
// (cells equal in both are all kept, in cell order). Cells with a non-finite time or balanced
// accuracy are left out.
std::vector<std::size_t> paretoFront(const SweepResult& sweep,
                                     std::optional<SensorGroup> group = std::nullopt);

// The better of two successful cells: higher balanced accuracy, then fewer components (order),
// then a faster fit. The report, the CLI and the workbench pick best cells with this one rule.
// Balanced accuracy counts only classes with at least minTestSteps test steps ("too few" classes
// never decide); a cell with no such class loses to any cell that has one (when neither has one,
// balanced accuracy over all classes decides).
bool betterCell(const SweepCellResult& a, const SweepCellResult& b,
                std::size_t minTestSteps = kMinTestSteps);
// Index into sweep.cells of each group's best successful cell (betterCell; the first of equals),
// in group order; groups without one are left out.
std::vector<std::size_t> bestCells(const SweepResult& sweep,
                                   std::size_t minTestSteps = kMinTestSteps);
// The same for each (group, method) pair: the families side by side. In group order, then
// method order (gaussian, gmm, gbt).
std::vector<std::size_t> bestCellsByMethod(const SweepResult& sweep,
                                           std::size_t minTestSteps = kMinTestSteps);
// The sweep has cells of more than one method.
bool mixesMethods(const SweepResult& sweep);
// A Gbt cell's tree settings as text ("100 trees, depth 6, rate 0.1, min child weight 1"); empty
// for the other methods.
std::string treeSettingsText(const SweepCell& cell);

}  // namespace tactile::analysis
