#include "analysis/report_svg.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include "analysis/report.h"  // htmlEscape

namespace tactile::analysis {

namespace {

constexpr double kWidth = 760.0;
constexpr double kHeight = 420.0;
constexpr double kLeft = 62.0;
constexpr double kRight = 230.0;  // legend
constexpr double kTop = 34.0;
constexpr double kBottom = 52.0;
constexpr std::size_t kLegendRows = 18;

// A qualitative palette (distinct on white, readable in grey print).
constexpr std::array<const char*, 10> kColours{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                               "#9467bd", "#8c564b", "#e377c2", "#17becf",
                                               "#7f7f7f", "#bcbd22"};

// Locale-independent number text with at most `decimals` decimals.
std::string num(double v, int decimals = 2) {
  if (!std::isfinite(v)) return "0";
  char buffer[64];
  const auto r =
      std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, decimals);
  std::string s(buffer, r.ptr);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0')
      s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

// A tick label: short general form (0.01, 0.1, 16, 1e-05).
std::string tickText(double v) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 3);
  return std::string(buffer, r.ptr);
}

struct Axis {
  // The y axis of every figure: percent, 0 at the bottom.
  static Axis percent() {
    Axis a;
    a.lo = 0.0;
    a.hi = 100.0;
    a.pixelLo = kHeight - kBottom;
    a.pixelHi = kTop;
    return a;
  }

  double lo = 0.0;
  double hi = 1.0;
  bool log = false;
  double pixelLo = 0.0;
  double pixelHi = 1.0;
  double map(double v) const {
    const double a = log ? std::log10(lo) : lo;
    const double b = log ? std::log10(hi) : hi;
    const double x = log ? std::log10(v) : v;
    const double t = b > a ? (x - a) / (b - a) : 0.5;
    return pixelLo + t * (pixelHi - pixelLo);
  }
};

// An x axis over the given values: logarithmic when all are positive (floors and orders are
// swept in geometric steps), linear when one is 0 or below; padded by a little on both sides.
Axis xAxisOver(const std::vector<double>& values) {
  Axis a;
  a.pixelLo = kLeft;
  a.pixelHi = kWidth - kRight;
  if (values.empty()) return a;
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  a.lo = *mn;
  a.hi = *mx;
  a.log = a.lo > 0.0;
  if (a.log) {
    a.lo /= 1.3;
    a.hi *= 1.3;
  } else {
    const double pad = a.hi > a.lo ? 0.05 * (a.hi - a.lo) : std::max(1.0, std::abs(a.lo) * 0.1);
    a.lo -= pad;
    a.hi += pad;
  }
  return a;
}

std::string header(const std::string& title) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(kWidth) +
         "\" height=\"" + num(kHeight) + "\" viewBox=\"0 0 " + num(kWidth) + " " + num(kHeight) +
         "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n<text x=\"" +
         num(kWidth / 2) + "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">" +
         htmlEscape(title) + "</text>\n";
}

// Frame, ticks, grid and axis titles. xTicks are drawn at the given values.
std::string frame(const Axis& x, const Axis& y, const std::vector<double>& xTicks,
                  const std::vector<double>& yTicks, const std::string& xTitle,
                  const std::string& yTitle) {
  std::string out;
  const double top = kTop;
  const double bottom = kHeight - kBottom;
  for (double v : yTicks) {
    const double py = y.map(v);
    out += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(py) + "\" x2=\"" + num(kWidth - kRight) +
           "\" y2=\"" + num(py) + "\" stroke=\"#e4e4e4\"/>\n";
    out += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(py + 4) + "\" text-anchor=\"end\">" +
           tickText(v) + "</text>\n";
  }
  for (double v : xTicks) {
    const double px = x.map(v);
    out += "<line x1=\"" + num(px) + "\" y1=\"" + num(bottom) + "\" x2=\"" + num(px) + "\" y2=\"" +
           num(bottom + 5) + "\" stroke=\"#444\"/>\n";
    out += "<text x=\"" + num(px) + "\" y=\"" + num(bottom + 17) + "\" text-anchor=\"middle\">" +
           tickText(v) + "</text>\n";
  }
  out += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(top) + "\" width=\"" +
         num(kWidth - kRight - kLeft) + "\" height=\"" + num(bottom - top) +
         "\" fill=\"none\" stroke=\"#444\"/>\n";
  out += "<text x=\"" + num((kLeft + kWidth - kRight) / 2) + "\" y=\"" + num(kHeight - 12) +
         "\" text-anchor=\"middle\">" + htmlEscape(xTitle) + "</text>\n";
  out += "<text transform=\"translate(16 " + num((top + bottom) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">" + htmlEscape(yTitle) + "</text>\n";
  return out;
}

// The mean line of the n-th series: colours cycle; the second cycle is dashed, and so on.
std::string seriesDash(std::size_t n) {
  return (n / kColours.size()) % 2 == 1 ? " stroke-dasharray=\"7 3\"" : "";
}

std::string legendEntry(std::size_t row, const std::string& colour, const std::string& text,
                        const std::string& dash = "") {
  const double lx = kWidth - kRight + 14;
  const double ly = kTop + 8 + 18.0 * static_cast<double>(row);
  return "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(lx + 18) + "\" y2=\"" +
         num(ly) + "\" stroke=\"" + colour + "\" stroke-width=\"2\"" + dash + "/>\n<circle cx=\"" +
         num(lx + 9) + "\" cy=\"" + num(ly) + "\" r=\"3\" fill=\"" + colour + "\"/>\n<text x=\"" +
         num(lx + 24) + "\" y=\"" + num(ly + 4) + "\">" + htmlEscape(text) + "</text>\n";
}

std::string emptyNote(const std::string& text) {
  return "<text x=\"" + num((kLeft + kWidth - kRight) / 2) + "\" y=\"" + num(kHeight / 2) +
         "\" text-anchor=\"middle\" fill=\"#777\">" + htmlEscape(text) + "</text>\n";
}

bool finite(double v) {
  return std::isfinite(v);
}

}  // namespace

std::string rateChartSvg(const std::vector<RateSeries>& series, SweptVariable variable,
                         const std::string& title) {
  std::vector<double> xs;
  for (const RateSeries& s : series)
    for (double v : s.x)
      if (finite(v)) xs.push_back(v);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  const Axis x = xAxisOver(xs);
  const Axis y = Axis::percent();
  std::string out = header(title);
  out += frame(x, y, xs, {0, 20, 40, 60, 80, 100},
               variable == SweptVariable::Floor ? "Variance floor" : "Model order",
               "Correct rate per class (%)");
  if (xs.empty()) out += emptyNote("no cell with a model");
  std::size_t drawn = 0;
  for (const RateSeries& s : series) {
    const std::string colour = kColours[drawn % kColours.size()];
    std::string line;
    std::string bandUpper;
    std::string bandLower;
    std::vector<std::string> lowerPoints;  // the band's lower edge, walked back
    std::string dots;
    const std::size_t n = std::min({s.x.size(), s.mean.size(), s.min.size(), s.max.size()});
    for (std::size_t i = 0; i < n; ++i) {
      if (!finite(s.x[i]) || !finite(s.mean[i]) || !finite(s.min[i]) || !finite(s.max[i]) ||
          (x.log && s.x[i] <= 0.0))
        continue;
      const std::string px = num(x.map(s.x[i]));
      line += (line.empty() ? "" : " ") + px + "," + num(y.map(s.mean[i]));
      bandUpper += (bandUpper.empty() ? "" : " ") + px + "," + num(y.map(s.max[i]));
      bandLower += (bandLower.empty() ? "" : " ") + px + "," + num(y.map(s.min[i]));
      lowerPoints.push_back(px + "," + num(y.map(s.min[i])));
      dots += "<g><title>" + htmlEscape(s.label) + ": " + tickText(s.x[i]) + " mean " +
              num(s.mean[i], 1) + " %, min " + num(s.min[i], 1) + " %, max " + num(s.max[i], 1) +
              " %</title><circle cx=\"" + px + "\" cy=\"" + num(y.map(s.mean[i])) +
              "\" r=\"3\" fill=\"" + colour + "\"/></g>\n";
    }
    if (line.empty()) continue;
    // min..max over the classes as a pale band edged by thin dashed lines around the mean.
    std::string band = bandUpper;
    for (auto it = lowerPoints.rbegin(); it != lowerPoints.rend(); ++it)
      band += " " + *it;
    out += "<polygon points=\"" + band + "\" fill=\"" + colour +
           "\" fill-opacity=\"0.10\" stroke=\"none\"/>\n";
    for (const std::string* bound : {&bandUpper, &bandLower}) {
      out += "<polyline points=\"" + *bound + "\" fill=\"none\" stroke=\"" + colour +
             "\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"/>\n";
    }
    out += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" + colour +
           "\" stroke-width=\"2\"" + seriesDash(drawn) + "/>\n" + dots;
    if (drawn < kLegendRows) out += legendEntry(drawn, colour, s.label, seriesDash(drawn));
    ++drawn;
  }
  if (drawn > kLegendRows) {
    out += legendEntry(kLegendRows, "#ffffff",
                       "+ " + std::to_string(drawn - kLegendRows) + " more series");
  }
  out += "</svg>\n";
  return out;
}

std::string timeErrorChartSvg(const SweepResult& sweep, const std::string& title) {
  constexpr double kMinSeconds = 1e-6;
  std::vector<double> seconds;
  for (const SweepCellResult& r : sweep.cells) {
    const double s = r.fitSeconds + r.predictSeconds;
    if (r.ok && r.confusion.total() > 0 && finite(s) && finite(r.metrics.balancedAccuracy))
      seconds.push_back(std::max(s, kMinSeconds));
  }
  Axis x;
  x.pixelLo = kLeft;
  x.pixelHi = kWidth - kRight;
  x.log = true;
  std::vector<double> ticks;
  if (!seconds.empty()) {
    const auto [mn, mx] = std::minmax_element(seconds.begin(), seconds.end());
    x.lo = std::pow(10.0, std::floor(std::log10(*mn)));
    x.hi = std::pow(10.0, std::ceil(std::log10(*mx)));
    if (x.hi <= x.lo) x.hi = x.lo * 10.0;
    for (double t = x.lo; t <= x.hi * 1.0001; t *= 10.0)
      ticks.push_back(t);
  } else {
    x.lo = 1e-3;
    x.hi = 1.0;
  }
  const Axis y = Axis::percent();
  std::string out = header(title);
  out += frame(x, y, ticks, {0, 20, 40, 60, 80, 100}, "Fit + predict time (s)",
               "Error: 100 - balanced accuracy (%)");
  if (seconds.empty()) out += emptyNote("no cell with a model");
  std::map<int, std::string> colourOf;
  for (const SweepCellResult& r : sweep.cells) {
    if (!r.ok) continue;
    const int g = groupIndex(r.cell.group);
    if (colourOf.count(g) == 0) colourOf[g] = kColours[colourOf.size() % kColours.size()];
  }
  auto point = [&](const SweepCellResult& r) {
    return std::make_pair(x.map(std::max(r.fitSeconds + r.predictSeconds, kMinSeconds)),
                          y.map(100.0 - 100.0 * r.metrics.balancedAccuracy));
  };
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    if (!r.ok || r.confusion.total() == 0 || !finite(r.fitSeconds + r.predictSeconds) ||
        !finite(r.metrics.balancedAccuracy))
      continue;
    const auto [px, py] = point(r);
    const SweepCell& c = r.cell;
    const std::string settings = c.method == ClassifierMethod::Gbt
                                     ? treeSettingsText(c)
                                     : std::string(covarianceFormName(c.form)) + " order " +
                                           std::to_string(c.order) + " floor " +
                                           tickText(c.varianceFloor);
    const std::string colour = colourOf[groupIndex(c.group)];
    // Boosted trees as squares, the mixtures as dots: the families apart at a glance.
    const std::string marker = c.method == ClassifierMethod::Gbt
                                   ? "<rect x=\"" + num(px - 3.0) + "\" y=\"" + num(py - 3.0) +
                                         "\" width=\"6\" height=\"6\" fill=\"" + colour + "\"/>"
                                   : "<circle cx=\"" + num(px) + "\" cy=\"" + num(py) +
                                         "\" r=\"3\" fill=\"" + colour + "\"/>";
    out += "<g><title>cell " + std::to_string(i) + ": " +
           std::string(groupInfo(c.group).shortName) + " " +
           std::string(classifierMethodName(c.method)) + " " + settings + "</title>" + marker +
           "</g>\n";
  }
  // Each group's own front (cells of different groups are no alternatives to each other), in the
  // group's colour, as a staircase: from each front cell right to the next one's time, then down.
  std::size_t ringed = 0;
  std::map<int, std::size_t> frontSize;
  for (const auto& [g, colour] : colourOf) {
    const std::vector<std::size_t> front =
        paretoFront(sweep, kSensorGroups[static_cast<std::size_t>(g)].group);
    frontSize[g] = front.size();
    std::string steps;
    for (std::size_t k = 0; k < front.size(); ++k) {
      const auto [px, py] = point(sweep.cells[front[k]]);
      if (k > 0) steps += " " + num(px) + "," + num(point(sweep.cells[front[k - 1]]).second);
      steps += (steps.empty() ? "" : " ") + num(px) + "," + num(py);
      out += "<circle cx=\"" + num(px) + "\" cy=\"" + num(py) +
             "\" r=\"6\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.2\"/>\n";
      ++ringed;
    }
    if (!steps.empty()) {
      out += "<polyline points=\"" + steps + "\" fill=\"none\" stroke=\"" + colour +
             "\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\"/>\n";
    }
  }
  std::size_t row = 0;
  for (const auto& [g, colour] : colourOf) {
    if (row >= kLegendRows) break;
    out +=
        legendEntry(row++, colour,
                    "group " + std::string(kSensorGroups[static_cast<std::size_t>(g)].shortName) +
                        " (front: " + std::to_string(frontSize[g]) + ")");
  }
  if (ringed > 0 && row < kLegendRows) {
    out += legendEntry(row++, "#000000",
                       "ringed: the group's Pareto front (" + std::to_string(ringed) + ")");
  }
  const auto isTrees = [](const SweepCellResult& r) {
    return r.cell.method == ClassifierMethod::Gbt;
  };
  const bool anyTrees = std::any_of(sweep.cells.begin(), sweep.cells.end(), isTrees);
  const bool anyMixtures = !std::all_of(sweep.cells.begin(), sweep.cells.end(), isTrees);
  if (anyTrees && anyMixtures && row < kLegendRows)
    out += legendEntry(row, "#000000", "squares: boosted trees; dots: Gaussian mixtures");
  out += "</svg>\n";
  return out;
}

}  // namespace tactile::analysis
