#include "analysis/sweep_summary.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace tactile::analysis {

namespace {

std::string floorText(double f) {  // as "%g", whatever the locale
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, f, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

// Mean, min, max over the classes of a cell of the per-class rate (recall), percent.
struct RateSpread {
  double mean = 0.0, min = 0.0, max = 0.0;
  bool any = false;
};
RateSpread spreadOf(const Metrics& m) {
  RateSpread s;
  int n = 0;
  for (const ClassMetrics& c : m.perClass) {
    if (!c.recall) continue;
    const double r = 100.0 * *c.recall;
    if (n == 0) {
      s.min = s.max = r;
    } else {
      s.min = std::min(s.min, r);
      s.max = std::max(s.max, r);
    }
    s.mean += r;
    ++n;
  }
  if (n > 0) {
    s.mean /= n;
    s.any = true;
  }
  return s;
}

}  // namespace

std::vector<RateSeries> rateSeries(const SweepResult& sweep, SweptVariable variable) {
  const bool sweptIsFloor = variable == SweptVariable::Floor;
  // Series key: (group, features, method, form, fixed value, seed), in that order.
  using Key = std::tuple<int, int, int, int, double, std::uint64_t>;
  std::map<Key, std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    if (!r.ok || !spreadOf(r.metrics).any || r.cell.method == ClassifierMethod::Gbt) continue;
    const SweepCell& c = r.cell;
    members[Key{groupIndex(c.group), static_cast<int>(c.features), static_cast<int>(c.method),
                static_cast<int>(c.form),
                sweptIsFloor ? static_cast<double>(c.order) : c.varianceFloor, c.seed}]
        .push_back(i);
  }
  std::vector<RateSeries> out;
  for (auto& [key, cells] : members) {
    auto swept = [&](std::size_t i) {
      const SweepCell& c = sweep.cells[i].cell;
      return sweptIsFloor ? c.varianceFloor : static_cast<double>(c.order);
    };
    std::stable_sort(cells.begin(), cells.end(),
                     [&](std::size_t a, std::size_t b) { return swept(a) < swept(b); });
    const SweepCell& first = sweep.cells[cells.front()].cell;
    RateSeries s;
    s.group = first.group;
    s.features = first.features;
    s.method = first.method;
    s.form = first.form;
    s.fixedValue = std::get<4>(key);
    s.seed = first.seed;
    s.label =
        std::string(groupInfo(first.group).shortName) + " " +
        std::string(classifierMethodName(first.method)) +
        (first.method == ClassifierMethod::Gmm ? " " + std::string(covarianceFormName(first.form))
                                               : std::string()) +
        (first.features != FeatureKind::Normal ? " " + std::string(featureKindName(first.features))
                                               : std::string()) +
        (sweptIsFloor ? " order " + std::to_string(first.order)
                      : " floor " + floorText(first.varianceFloor));
    if (sweep.grid.seeds.size() > 1) s.label += " seed " + std::to_string(first.seed);
    for (std::size_t i : cells) {
      const SweepCellResult& r = sweep.cells[i];
      const RateSpread spread = spreadOf(r.metrics);
      s.x.push_back(swept(i));
      s.mean.push_back(spread.mean);
      s.min.push_back(spread.min);
      s.max.push_back(spread.max);
      s.accuracy.push_back(100.0 * r.metrics.accuracy);
      s.balancedAccuracy.push_back(100.0 * r.metrics.balancedAccuracy);
      s.cells.push_back(i);
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::size_t> paretoFront(const SweepResult& sweep, std::optional<SensorGroup> group) {
  // Error is 1 - balanced accuracy: compared through the balanced accuracy itself (higher is less
  // error), so that no rounding of a subtraction can make two different cells look equal.
  struct Point {
    std::size_t index;
    double seconds;
    double balanced;
  };
  std::vector<Point> points;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    // A cell scored on no test rows has no error to weigh.
    if (!r.ok || r.confusion.total() == 0 || (group && r.cell.group != *group)) continue;
    const double seconds = r.fitSeconds + r.predictSeconds;
    if (!std::isfinite(seconds) || !std::isfinite(r.metrics.balancedAccuracy)) continue;
    points.push_back({i, seconds, r.metrics.balancedAccuracy});
  }
  std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return a.seconds != b.seconds ? a.seconds < b.seconds : a.balanced > b.balanced;
  });
  // Walking by time, a point is on the front when its error is below every faster point's, or
  // equals that of the point that set the best error with the same time.
  std::vector<std::size_t> front;
  double bestBalanced = -std::numeric_limits<double>::infinity();
  double bestSeconds = -1.0;
  for (const Point& p : points) {
    if (p.balanced > bestBalanced) {
      bestBalanced = p.balanced;
      bestSeconds = p.seconds;
      front.push_back(p.index);
    } else if (p.balanced == bestBalanced && p.seconds == bestSeconds) {
      front.push_back(p.index);
    }
  }
  return front;
}

bool betterCell(const SweepCellResult& a, const SweepCellResult& b, std::size_t minTestSteps) {
  const std::optional<double> ra = balancedAccuracyOver(a.metrics, minTestSteps);
  const std::optional<double> rb = balancedAccuracyOver(b.metrics, minTestSteps);
  if (ra.has_value() != rb.has_value()) return ra.has_value();
  if (ra && *ra != *rb) return *ra > *rb;
  // Neither has a class with enough test steps: nothing better to go by than all of them.
  if (!ra && a.metrics.balancedAccuracy != b.metrics.balancedAccuracy)
    return a.metrics.balancedAccuracy > b.metrics.balancedAccuracy;
  if (a.cell.order != b.cell.order) return a.cell.order < b.cell.order;
  return a.fitSeconds < b.fitSeconds;
}

std::vector<std::size_t> bestCells(const SweepResult& sweep, std::size_t minTestSteps) {
  std::map<int, std::size_t> best;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    if (!r.ok) continue;
    const auto [it, inserted] = best.try_emplace(groupIndex(r.cell.group), i);
    if (!inserted && betterCell(r, sweep.cells[it->second], minTestSteps)) it->second = i;
  }
  std::vector<std::size_t> out;
  for (const auto& [g, i] : best)
    out.push_back(i);
  return out;
}

std::vector<std::size_t> bestCellsByMethod(const SweepResult& sweep, std::size_t minTestSteps) {
  std::map<std::pair<int, int>, std::size_t> best;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    if (!r.ok) continue;
    const auto [it, inserted] =
        best.try_emplace(std::pair{groupIndex(r.cell.group), static_cast<int>(r.cell.method)}, i);
    if (!inserted && betterCell(r, sweep.cells[it->second], minTestSteps)) it->second = i;
  }
  std::vector<std::size_t> out;
  for (const auto& [key, i] : best)
    out.push_back(i);
  return out;
}

bool mixesMethods(const SweepResult& sweep) {
  for (const SweepCellResult& r : sweep.cells)
    if (r.cell.method != sweep.cells.front().cell.method) return true;
  return false;
}

std::string treeSettingsText(const SweepCell& cell) {
  if (cell.method != ClassifierMethod::Gbt) return {};
  return std::to_string(cell.trees) + " trees, depth " + std::to_string(cell.depth) + ", rate " +
         floorText(cell.learningRate) + ", min child weight " + floorText(cell.minChildWeight);
}

}  // namespace tactile::analysis
