#include "analysis/report.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "analysis/report_svg.h"
#include "analysis/sweep_summary.h"
#include "analysis/training.h"
#include "base/file_text.h"

namespace tactile::analysis {

using nlohmann::json;

namespace {

// Numbers are written with std::to_chars, never printf: the workbench runs under the user's
// locale, whose decimal comma would break CSV and the figures.
std::string fixed(double v, int digits) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, digits);
  return std::string(buf, r.ptr);
}

std::string pct(std::optional<double> fraction) {
  return fraction ? fixed(100.0 * *fraction, 1) : std::string();
}

std::string csvEscape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

bool looksNumeric(const std::string& s) {
  return !s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' ||
                        s[0] == '.' || s.back() == '%');
}

std::string floorText(double f) {  // as "%g"
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, f, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

std::vector<std::string> cellKey(const SweepCell& c) {
  const bool trees = c.method == ClassifierMethod::Gbt;
  return {std::string(groupInfo(c.group).shortName), std::string(featureKindName(c.features)),
          std::string(classifierMethodName(c.method)),
          trees ? std::string() : std::string(covarianceFormName(c.form))};
}

// A cell's order and floor as the tables show them: empty for boosted trees, which have neither.
std::string orderText(const SweepCell& c) {
  return c.method == ClassifierMethod::Gbt ? std::string() : std::to_string(c.order);
}
std::string cellFloorText(const SweepCell& c) {
  return c.method == ClassifierMethod::Gbt ? std::string() : floorText(c.varianceFloor);
}

bool hasTrees(const SweepResult& sweep) {
  return std::any_of(sweep.cells.begin(), sweep.cells.end(), [](const SweepCellResult& r) {
    return r.cell.method == ClassifierMethod::Gbt;
  });
}

Table spreadTable(const SweepResult& sweep, SweptVariable variable) {
  const bool sweptIsFloor = variable == SweptVariable::Floor;
  Table t;
  t.title = sweptIsFloor ? "Correct rate against variance floor (thesis figure 4.13)"
                         : "Correct rate against model order (thesis figure 4.14)";
  t.header = {"group",
              "features",
              "method",
              "covariance",
              sweptIsFloor ? "order" : "floor",
              sweptIsFloor ? "floor" : "order",
              "seed",
              "mean_rate_%",
              "min_rate_%",
              "max_rate_%",
              "accuracy_%",
              "balanced_%"};
  for (const RateSeries& series : rateSeries(sweep, variable)) {
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      const SweepCell& c = sweep.cells[series.cells[i]].cell;
      std::vector<std::string> row = cellKey(c);
      const std::string order = std::to_string(c.order);
      const std::string floor = floorText(c.varianceFloor);
      row.push_back(sweptIsFloor ? order : floor);
      row.push_back(sweptIsFloor ? floor : order);
      row.push_back(std::to_string(c.seed));
      row.push_back(fixed(series.mean[i], 1));
      row.push_back(fixed(series.min[i], 1));
      row.push_back(fixed(series.max[i], 1));
      row.push_back(fixed(series.accuracy[i], 1));
      row.push_back(fixed(series.balancedAccuracy[i], 1));
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

}  // namespace

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<std::string> runNamesOf(const json& runs) {
  std::vector<std::string> out;
  if (!runs.is_array()) return out;
  for (const json& r : runs)
    if (r.is_object() && r.contains("name") && r["name"].is_string())
      out.push_back(r["name"].get<std::string>());
  return out;
}

std::optional<TableStyle> parseTableStyle(std::string_view name) {
  if (name == "text") return TableStyle::Text;
  if (name == "csv") return TableStyle::Csv;
  if (name == "md" || name == "markdown") return TableStyle::Markdown;
  if (name == "html") return TableStyle::Html;
  return std::nullopt;
}

namespace {

std::string markdownEscape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '|' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string Table::render(TableStyle style) const {
  std::ostringstream out;
  if (style == TableStyle::Markdown) {
    if (!title.empty()) out << "### " << markdownEscape(title) << "\n\n";
    auto line = [&out](const std::vector<std::string>& cells, std::size_t n) {
      out << "|";
      for (std::size_t i = 0; i < n; ++i)
        out << " " << (i < cells.size() ? markdownEscape(cells[i]) : std::string()) << " |";
      out << "\n";
    };
    line(header, header.size());
    out << "|";
    for (std::size_t i = 0; i < header.size(); ++i)
      out << (i == 0 ? "---|" : "---:|");
    out << "\n";
    for (const auto& r : rows)
      line(r, header.size());
    out << "\n";
    return out.str();
  }
  if (style == TableStyle::Html) {
    if (!title.empty()) out << "<h3>" << htmlEscape(title) << "</h3>\n";
    out << "<table>\n<tr>";
    for (const std::string& h : header)
      out << "<th>" << htmlEscape(h) << "</th>";
    out << "</tr>\n";
    for (const auto& r : rows) {
      out << "<tr>";
      for (std::size_t i = 0; i < header.size(); ++i)
        out << "<td>" << (i < r.size() ? htmlEscape(r[i]) : std::string()) << "</td>";
      out << "</tr>\n";
    }
    out << "</table>\n";
    return out.str();
  }
  if (style == TableStyle::Csv) {
    if (!title.empty()) out << "# " << title << "\n";
    auto line = [&out](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        out << (i ? "," : "") << csvEscape(cells[i]);
      out << "\n";
    };
    line(header);
    for (const auto& r : rows)
      line(r);
    return out.str();
  }
  std::vector<std::size_t> width(header.size(), 0);
  auto measure = [&width](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size() && i < width.size(); ++i) {
      width[i] = std::max(width[i], cells[i].size());
    }
  };
  measure(header);
  for (const auto& r : rows)
    measure(r);
  if (!title.empty()) out << title << "\n";
  // A column is numeric when every non-empty data cell looks like a number: right-aligned, header
  // included.
  std::vector<bool> numeric(width.size(), false);
  for (std::size_t i = 1; i < width.size(); ++i) {
    bool any = false, all = true;
    for (const auto& r : rows) {
      if (i >= r.size() || r[i].empty()) continue;
      any = true;
      all = all && looksNumeric(r[i]);
    }
    numeric[i] = any && all;
  }
  auto line = [&](const std::vector<std::string>& cells, bool /*isHeader*/) {
    for (std::size_t i = 0; i < width.size(); ++i) {
      const std::string cell = i < cells.size() ? cells[i] : std::string();
      const std::string pad(width[i] - cell.size(), ' ');
      if (i) out << "  ";
      out << (numeric[i] ? pad + cell : cell + (i + 1 < width.size() ? pad : ""));
    }
    out << "\n";
  };
  line(header, true);
  for (const auto& r : rows)
    line(r, false);
  return out.str();
}

Table confusionTable(const ConfusionMatrix& confusion, bool percent, const std::string& title) {
  Table t;
  t.title = title;
  const std::vector<ContactClass> classes = confusion.activeClasses();
  t.header.push_back(percent ? "true \\ predicted (%)" : "true \\ predicted");
  for (ContactClass c : classes)
    t.header.emplace_back(contactClassName(c));
  t.header.push_back(percent ? "samples" : "total");
  for (ContactClass truth : classes) {
    if (confusion.trueCount(truth) == 0) continue;  // only predicted, never true
    std::vector<std::string> row{std::string(contactClassName(truth))};
    for (ContactClass p : classes) {
      row.push_back(percent ? fixed(*confusion.percent(truth, p), 2)
                            : std::to_string(confusion.count(truth, p)));
    }
    row.push_back(std::to_string(confusion.trueCount(truth)));
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table oneVsRestRateTable(
    const std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>>& groups) {
  Table t;
  t.title =
      "Precision per class, one-vs-rest, % (of the steps predicted as a class, the share that are "
      "it)";
  // Columns for every class that has a classifier in some group, in ContactClass order.
  std::vector<ContactClass> classes;
  for (int c = 0; c < kContactClassCount; ++c) {
    for (const auto& g : groups) {
      if (std::any_of(g.second.begin(), g.second.end(), [c](const BinaryConfusion& b) {
            return static_cast<int>(b.positive) == c;
          })) {
        classes.push_back(static_cast<ContactClass>(c));
        break;
      }
    }
  }
  t.header.push_back("group");
  for (ContactClass c : classes) {
    t.header.emplace_back(contactClassName(c));
    t.header.push_back("No " + std::string(contactClassName(c)));
  }
  for (const auto& [group, binaries] : groups) {
    // Groups by their short names, as every other table names them.
    std::vector<std::string> row{std::string(groupInfo(group).shortName)};
    for (ContactClass c : classes) {
      auto it = std::find_if(binaries.begin(), binaries.end(),
                             [c](const BinaryConfusion& b) { return b.positive == c; });
      row.push_back(it == binaries.end() ? "" : pct(it->classRate()));
      row.push_back(it == binaries.end() ? "" : pct(it->restRate()));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table classRateTable(const std::vector<std::pair<std::string, Metrics>>& rows,
                     const std::string& title, std::size_t minTestSteps) {
  Table t;
  t.title = title;
  std::vector<ContactClass> classes;
  for (int c = 0; c < kContactClassCount; ++c) {
    for (const auto& r : rows) {
      if (r.second.recallOf(static_cast<ContactClass>(c))) {
        classes.push_back(static_cast<ContactClass>(c));
        break;
      }
    }
  }
  t.header.push_back("");
  for (ContactClass c : classes)
    t.header.emplace_back(contactClassName(c));
  t.header.insert(t.header.end(), {"accuracy", "balanced", "macro_f1"});
  for (const auto& [label, m] : rows) {
    std::vector<std::string> row{label};
    if (m.total == 0) {
      for (std::size_t i = 0; i < classes.size(); ++i)
        row.push_back("");
      row.insert(row.end(), {"no test data", "no test data", ""});
      t.rows.push_back(std::move(row));
      continue;
    }
    for (ContactClass c : classes) {
      const auto it = std::find_if(m.perClass.begin(), m.perClass.end(),
                                   [c](const ClassMetrics& k) { return k.label == c; });
      if (it == m.perClass.end() || it->support == 0) {
        row.emplace_back();
        continue;
      }
      // A rate on few steps says so in words: "50.0 (only 4 test steps)".
      std::string cell =
          it->support < minTestSteps
              ? pct(it->recall) + " (only " + std::to_string(it->support) + " test steps)"
              : pct(it->recall) + " (" + std::to_string(it->support) + ")";
      row.push_back(std::move(cell));
    }
    row.push_back(pct(m.accuracy) + " (" + std::to_string(m.total) + ")");
    row.push_back(pct(m.balancedAccuracy));
    row.push_back(fixed(m.macroF1, 3));
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table rateAgainstFloorTable(const SweepResult& sweep) {
  return spreadTable(sweep, SweptVariable::Floor);
}
Table rateAgainstOrderTable(const SweepResult& sweep) {
  return spreadTable(sweep, SweptVariable::Order);
}

// A cell's rate as the tables show it: empty for a cell without a model, "no test data" for one
// scored on no test rows (which is not a rate of 0, as the JSON's null says), else the figure.
std::string cellRate(const SweepCellResult& r, double value, int digits) {
  if (!r.ok) return "";
  if (r.confusion.total() == 0) return "no test data";
  return fixed(value, digits);
}

namespace {

// The best-cell tables: one row per cell of `cells`; the tree settings' column only when the
// sweep has trees.
Table bestTable(const SweepResult& sweep, const std::vector<std::size_t>& cells,
                const std::string& title) {
  const bool trees = hasTrees(sweep);
  Table t;
  t.title = title;
  t.header = {"group", "features", "method", "covariance", "order", "floor"};
  if (trees) t.header.push_back("trees");
  t.header.push_back("seed");
  if (trees) t.header.push_back("decision");
  for (const char* h : {"balanced_%", "accuracy_%", "macro_f1", "mean_loglik", "fit_s", "dropped"})
    t.header.push_back(h);
  for (const std::size_t i : cells) {
    const SweepCellResult* r = &sweep.cells[i];
    std::vector<std::string> row = cellKey(r->cell);
    row.push_back(orderText(r->cell));
    row.push_back(cellFloorText(r->cell));
    if (trees) row.push_back(treeSettingsText(r->cell));
    row.push_back(std::to_string(r->cell.seed));
    if (trees) row.push_back(std::string(decisionModeName(r->cell.decision)));
    row.push_back(cellRate(*r, 100.0 * r->metrics.balancedAccuracy, 1));
    row.push_back(cellRate(*r, 100.0 * r->metrics.accuracy, 1));
    row.push_back(cellRate(*r, r->metrics.macroF1, 3));
    row.push_back(r->meanLogLikelihood ? fixed(*r->meanLogLikelihood, 4) : "");
    row.push_back(fixed(r->fitSeconds, 3));
    row.push_back(std::to_string(r->droppedComponents));
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace

Table bestCellsTable(const SweepResult& sweep) {
  return bestTable(sweep, bestCells(sweep),
                   "Best cell per group (balanced accuracy on held-out rows)");
}

Table bestCellsByMethodTable(const SweepResult& sweep) {
  return bestTable(sweep, bestCellsByMethod(sweep),
                   "Best cell per group and method, side by side (balanced accuracy on held-out "
                   "rows)");
}

Table sweepCellsTable(const SweepResult& sweep) {
  Table t;
  t.title = "Sweep cells";
  const bool trees = hasTrees(sweep);
  t.header = {"cell",      "group",       "features",     "method",     "covariance",
              "order",     "floor",       "seed",         "ok",         "fit_s",
              "predict_s", "iterations",  "converged",    "accuracy_%", "balanced_%",
              "macro_f1",  "mean_loglik", "neg_inf_rows", "dropped",    "reason"};
  if (trees) t.header.insert(t.header.begin() + 7, "trees");
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    std::vector<std::string> row{std::to_string(i)};
    const std::vector<std::string> key = cellKey(r.cell);
    row.insert(row.end(), key.begin(), key.end());
    row.push_back(orderText(r.cell));
    row.push_back(cellFloorText(r.cell));
    if (trees) row.push_back(treeSettingsText(r.cell));
    row.push_back(std::to_string(r.cell.seed));
    row.push_back(r.ok ? "yes" : "no");
    row.push_back(fixed(r.fitSeconds, 4));
    row.push_back(fixed(r.predictSeconds, 4));
    row.push_back(std::to_string(r.iterations));
    row.push_back(r.converged ? "yes" : "no");
    row.push_back(cellRate(r, 100.0 * r.metrics.accuracy, 2));
    row.push_back(cellRate(r, 100.0 * r.metrics.balancedAccuracy, 2));
    row.push_back(cellRate(r, r.metrics.macroF1, 4));
    row.push_back(r.meanLogLikelihood ? fixed(*r.meanLogLikelihood, 4) : "");
    row.push_back(r.ok ? std::to_string(r.negInfRows) : "");
    row.push_back(r.ok ? std::to_string(r.droppedComponents) : "");
    row.push_back(r.reason);
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table contactPatternTable(const ContactPatternTable& patterns) {
  Table t;
  t.title = "Contact patterns of group " + std::string(groupInfo(patterns.group).shortName) +
            " (which of its sensors touch, in index order, 1 = contact)";
  std::vector<ContactClass> predicted;
  for (int c = 0; c < kContactClassCount; ++c) {
    for (const ContactPatternRow& r : patterns.rows) {
      if (r.predicted[static_cast<std::size_t>(c)] > 0) {
        predicted.push_back(static_cast<ContactClass>(c));
        break;
      }
    }
  }
  t.header = {"pattern", "true"};
  for (ContactClass c : predicted)
    t.header.push_back(std::string(contactClassName(c)) + "(predict)");
  t.header.insert(t.header.end(), {"total", "errors"});
  for (const ContactPatternRow& r : patterns.rows) {
    std::vector<std::string> row{r.pattern, std::string(contactClassName(r.truth))};
    for (ContactClass c : predicted) {
      row.push_back(std::to_string(r.predicted[static_cast<std::size_t>(c)]));
    }
    row.push_back(std::to_string(r.total()));
    row.push_back(std::to_string(r.errors()));
    t.rows.push_back(std::move(row));
  }
  return t;
}

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& i : items)
    out += (out.empty() ? "" : ", ") + i;
  return out;
}

template <typename T, typename Name>
std::string joinedNames(const std::vector<T>& items, Name name) {
  std::vector<std::string> out;
  for (const T& i : items)
    out.push_back(name(i));
  return joined(out);
}

Table configurationTable(const SweepResult& sweep, const json& configuration) {
  const SweepGrid& g = sweep.grid;
  Table t;
  t.title = "Configuration";
  t.header = {"setting", "value"};
  auto add = [&t](std::string key, std::string value) {
    t.rows.push_back({std::move(key), std::move(value)});
  };
  if (configuration.is_object()) {
    if (configuration.contains("label_set") && configuration["label_set"].is_string())
      add("label set", configuration["label_set"].get<std::string>());
    if (configuration.contains("train_runs"))
      add("training runs", joined(runNamesOf(configuration["train_runs"])));
    if (configuration.contains("test_runs"))
      add("test runs", joined(runNamesOf(configuration["test_runs"])));
    // A sweep over run files without test runs scores the last share of each training run.
    if (configuration.contains("holdout") && configuration["holdout"].is_number() &&
        configuration["holdout"].get<double>() > 0.0)
      add("held-out share of each training run", floorText(configuration["holdout"].get<double>()));
    if (configuration.contains("state") && configuration["state"].is_string())
      add("state", configuration["state"].get<std::string>());
    if (configuration.contains("program_version") && configuration["program_version"].is_string())
      add("program version", configuration["program_version"].get<std::string>());
  }
  std::vector<SensorGroup> groups = g.groups;
  if (groups.empty())
    for (const GroupInfo& info : kSensorGroups)
      groups.push_back(info.group);
  add("groups",
      joinedNames(groups, [](SensorGroup x) { return std::string(groupInfo(x).shortName); }));
  add("methods", joinedNames(g.methods, [](ClassifierMethod m) {
        return std::string(classifierMethodName(m));
      }));
  add("orders", joinedNames(g.orders, [](int o) { return std::to_string(o); }));
  add("covariance forms",
      joinedNames(g.forms, [](CovarianceForm f) { return std::string(covarianceFormName(f)); }));
  add("variance floors", joinedNames(g.varianceFloors, [](double f) { return floorText(f); }));
  if (std::find(g.methods.begin(), g.methods.end(), ClassifierMethod::Gbt) != g.methods.end()) {
    add("trees", joinedNames(g.treeCounts, [](int n) { return std::to_string(n); }));
    add("tree depths", joinedNames(g.depths, [](int d) { return std::to_string(d); }));
    add("learning rates", joinedNames(g.learningRates, [](double r) { return floorText(r); }));
    add("min child weights", joinedNames(g.minChildWeights, [](double w) { return floorText(w); }));
  }
  add("features",
      joinedNames(g.features, [](FeatureKind k) { return std::string(featureKindName(k)); }));
  add("seeds", joinedNames(g.seeds, [](std::uint64_t x) { return std::to_string(x); }));
  add("regularization", std::string(regularizationName(g.regularization)));
  add("initialisation", std::string(gmmInitName(g.init)));
  add("restarts", std::to_string(g.restarts));
  add("max iterations", std::to_string(g.maxIterations));
  add("tolerance", floorText(g.tolerance));
  add("priors", std::string(priorModeName(g.priors)));
  add("threads", std::to_string(sweep.threads));
  return t;
}

std::string cellName(const SweepCell& c) {
  if (c.method == ClassifierMethod::Gbt) {
    return "Group " + std::string(groupInfo(c.group).shortName) + ", gbt " + treeSettingsText(c) +
           (c.features != FeatureKind::Normal ? ", " + std::string(featureKindName(c.features))
                                              : std::string()) +
           ", seed " + std::to_string(c.seed) + ", " + std::string(decisionModeName(c.decision));
  }
  return "Group " + std::string(groupInfo(c.group).shortName) + ", " +
         std::string(classifierMethodName(c.method)) + " " +
         std::string(covarianceFormName(c.form)) + " order " + std::to_string(c.order) +
         " variance floor " + floorText(c.varianceFloor) +
         (c.features != FeatureKind::Normal ? ", " + std::string(featureKindName(c.features))
                                            : std::string()) +
         ", seed " + std::to_string(c.seed);
}

// A relative path as a Markdown link target: characters that end or break a link (space,
// parentheses, angle brackets, '%', '#', '?', control bytes) percent-encoded; other bytes (UTF-8
// names included) kept.
std::string linkTarget(const std::string& path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u == 0x7f ||
        std::string_view("()<>%#?[]\\\"").find(c) != std::string_view::npos) {
      out += '%';
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else {
      out += c;
    }
  }
  return out;
}

void heading(std::string& out, TableStyle style, const std::string& text) {
  if (style == TableStyle::Markdown) out += "## " + text + "\n\n";
  if (style == TableStyle::Html) out += "<h2>" + htmlEscape(text) + "</h2>\n";
  if (style == TableStyle::Text) out += "== " + text + " ==\n\n";
}

}  // namespace

std::vector<SweepFigure> sweepFigures(const SweepResult& sweep) {
  return {
      {"rate_floor.svg", "Correct rate against variance floor (thesis figure 4.13)",
       rateChartSvg(rateSeries(sweep, SweptVariable::Floor), SweptVariable::Floor,
                    "Correct rate against variance floor")},
      {"rate_order.svg", "Correct rate against model order (thesis figure 4.14)",
       rateChartSvg(rateSeries(sweep, SweptVariable::Order), SweptVariable::Order,
                    "Correct rate against model order")},
      {"time_error.svg", "Run time against error, Pareto front marked",
       timeErrorChartSvg(sweep, "Run time against error")},
  };
}

std::string sweepReport(const SweepResult& sweep, TableStyle style) {
  return sweepReport(sweep, style, SweepReportOptions{});
}

std::string sweepReport(const SweepResult& sweep, TableStyle style,
                        const SweepReportOptions& options) {
  std::string out;
  const std::string sep = style == TableStyle::Text ? "\n" : "";
  std::size_t ok = 0;
  for (const SweepCellResult& r : sweep.cells)
    ok += r.ok ? 1 : 0;
  const std::string headline = "Sweep: " + std::to_string(sweep.cells.size()) + " cells (" +
                               std::to_string(ok) + " fitted), " + std::to_string(sweep.threads) +
                               " threads, " + fixed(sweep.wallSeconds, 2) + " s" +
                               (sweep.cancelled ? ", CANCELLED" : "");
  if (style == TableStyle::Text) out += headline + "\n\n";
  if (style == TableStyle::Markdown) out += "# " + headline + "\n\n";
  if (style == TableStyle::Html) {
    out +=
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Sweep report</title>"
        "<style>body{font-family:sans-serif}table{border-collapse:collapse;margin-bottom:1em}"
        "td,th{border:1px solid #bbb;padding:2px 6px;text-align:right}th{background:#eee}"
        "</style></head><body>\n<h1>" +
        htmlEscape(headline) + "</h1>\n";
  }
  out += configurationTable(sweep, options.configuration).render(style) + sep;
  out += bestCellsTable(sweep).render(style) + sep;
  if (mixesMethods(sweep)) out += bestCellsByMethodTable(sweep).render(style) + sep;

  // Figures: inline in HTML, linked files in Markdown (when written beside it).
  if (style == TableStyle::Html ||
      (style == TableStyle::Markdown && !options.figureFolder.empty())) {
    heading(out, style, "Figures");
    for (const SweepFigure& f : sweepFigures(sweep)) {
      if (style == TableStyle::Html) {
        out += "<figure>" + f.svg + "<figcaption>" + htmlEscape(f.caption) +
               "</figcaption></figure>\n";
      } else {
        out += "![" + f.caption + "](" + linkTarget(options.figureFolder + "/" + f.file) + ")\n\n";
      }
    }
  }
  out += rateAgainstFloorTable(sweep).render(style) + sep;
  out += rateAgainstOrderTable(sweep).render(style) + sep;

  // Each group's best cell in detail: confusion in counts and percent, class rates, patterns.
  std::vector<const SweepCellResult*> best;
  for (const std::size_t i : bestCells(sweep))
    best.push_back(&sweep.cells[i]);
  heading(out, style, "Best cell of each group");
  std::vector<std::pair<std::string, Metrics>> rates;
  for (const SweepCellResult* r : best) {
    const std::string name = cellName(r->cell);
    rates.emplace_back(std::string(groupInfo(r->cell.group).shortName), r->metrics);
    // Nothing scored: the class-rate table below says "no test data"; no empty matrices.
    if (r->confusion.total() == 0) continue;
    out += confusionTable(r->confusion, false, name + ": confusion (counts)").render(style) + sep;
    out +=
        confusionTable(r->confusion, true, name + ": confusion (row percent)").render(style) + sep;
    if (!r->patterns.rows.empty()) out += contactPatternTable(r->patterns).render(style) + sep;
  }
  if (!rates.empty()) {
    out +=
        classRateTable(rates, "Correct rate per class of each group's best cell, %").render(style) +
        sep;
    std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>> oneVsRest;
    for (const SweepCellResult* r : best)
      oneVsRest.emplace_back(r->cell.group, binaryConfusions(r->confusion, r->classes));
    out += oneVsRestRateTable(oneVsRest).render(style) + sep;
  }
  out += sweepCellsTable(sweep).render(style) + sep;
  heading(out, style, "Confusion matrices of every cell");
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const SweepCellResult& r = sweep.cells[i];
    if (!r.ok || r.confusion.total() == 0) continue;  // "no test data" in the cell table
    out += confusionTable(r.confusion, false,
                          "Cell " + std::to_string(i) + ": " + cellName(r.cell) + " (counts)")
               .render(style) +
           sep;
  }
  if (style == TableStyle::Html) out += "</body></html>\n";
  return out;
}

Status writeSweepReport(const SweepResult& sweep, TableStyle style,
                        const std::filesystem::path& out, const json& configuration) {
  namespace fs = std::filesystem;
  SweepReportOptions options;
  options.configuration = configuration;
  const bool figureFiles = style == TableStyle::Markdown;
  const fs::path folder = out.parent_path() / (out.stem().string() + "_files");
  if (figureFiles) options.figureFolder = folder.filename().string();
  if (figureFiles) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) return Error(folder.string() + ": cannot create: " + ec.message());
    for (const SweepFigure& f : sweepFigures(sweep)) {
      if (Status s = writeFileAtomically(folder / f.file, f.svg); !s) return s;
    }
  }
  return writeFileAtomically(out, sweepReport(sweep, style, options));
}

namespace {

// A model's default decision, with the chain's emission weight when it is not 1 (the plain HMM):
// "online (evidence x 0.1)".
std::string decisionText(DecisionMode d, const TransitionModel& chain) {
  std::string out(decisionModeName(d));
  if (d != DecisionMode::Step && chain.emissionWeight != 1.0) {
    std::ostringstream w;
    w << chain.emissionWeight;
    out += " (evidence x " + w.str() + ")";
  }
  return out;
}

}  // namespace

std::string modelReport(const ModelBundle& bundle, TableStyle style, std::size_t minTestSteps) {
  const std::string sep = style == TableStyle::Text ? "\n" : "";
  std::string out;
  std::vector<std::pair<std::string, Metrics>> rateRows;
  std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>> ovr;
  std::string details;
  Table settings;
  settings.title = "Models";
  settings.header = {"group",   "features", "method",  "covariance", "order",   "floor",
                     "dropped", "classes",  "samples", "test",       "decision"};
  // Boosted trees have no covariance, order or floor: their settings get a column of their own,
  // shown when the bundle has trees.
  const bool anyTrees = std::any_of(bundle.models.begin(), bundle.models.end(),
                                    [](const GroupModel& m) { return m.classifier.trees(); });
  if (anyTrees) settings.header.insert(settings.header.begin() + 6, "trees");
  Table decisions;
  decisions.title = "Balanced accuracy by decision (%; test steps in brackets)";
  decisions.header = {"group", "evaluated on", "test", "step", "online", "offline"};
  Table scenes;
  scenes.title = "Held-out scenes (balanced accuracy %, by the default decision)";
  scenes.header = {"group", "scene", "test", "step", "online", "offline"};
  auto rate = [](const ConfusionMatrix& c) {
    return c.total() > 0 ? pct(computeMetrics(c).balancedAccuracy) : std::string("no test data");
  };
  for (const GroupModel& m : bundle.models) {
    const std::string groupName(groupInfo(m.group).shortName);
    const ModelEvaluation& e = m.evaluation;
    std::string classes;
    for (const std::string& c : m.classifier.classNames())
      classes += (classes.empty() ? "" : " ") + c;
    // The order asked for (components dropped for lack of mass are in "dropped"); models without
    // their settings show the most components any class kept.
    int order = 0;
    for (int c = 0; c < m.classifier.classCount() && m.classifier.trees() == nullptr; ++c)
      order = std::max(order, static_cast<int>(m.classifier.model(c).weights().size()));
    if (m.classifier.method() == ClassifierMethod::Gmm && !e.fit.empty())
      order = std::max(order, m.provenance.classifier.gmm.components);
    std::string dropped;  // components dropped for lack of mass: the mixtures' figure
    if (!e.fit.empty() && m.classifier.trees() == nullptr) {
      int sum = 0;
      for (const ClassFitRecord& f : e.fit)
        sum += f.droppedComponents;
      dropped = std::to_string(sum);
    }
    const DecisionMode d = m.transitions.empty() ? DecisionMode::Step : m.decision;
    const bool isTrees = m.classifier.trees() != nullptr;
    std::vector<std::string> row = {
        groupName,
        std::string(featureKindName(m.features)),
        std::string(classifierMethodName(m.classifier.method())),
        isTrees ? "" : std::string(covarianceFormName(m.covariance)),
        isTrees ? "" : std::to_string(order),
        isTrees ? "" : floorText(m.varianceFloor),
        dropped,
        classes,
        std::to_string(e.samplesTrain > 0 ? e.samplesTrain : m.provenance.samples),
        e.scored() ? std::to_string(e.samplesTest()) : "no test data",
        decisionText(d, m.transitions)};
    if (anyTrees)
      row.insert(row.begin() + 6,
                 isTrees ? describeGbtSettings(m.provenance.classifier.gbt) : std::string());
    settings.rows.push_back(std::move(row));
    decisions.rows.push_back({groupName, e.evaluatedOn, std::to_string(e.samplesTest()),
                              rate(e.confusion(DecisionMode::Step)),
                              rate(e.confusion(DecisionMode::Online)),
                              rate(e.confusion(DecisionMode::Offline))});
    for (const SceneScore& sc : e.scenes) {
      scenes.rows.push_back({groupName, sc.scene, std::to_string(sc.byDecision[0].total()),
                             rate(sc.byDecision[decisionIndex(DecisionMode::Step)]),
                             rate(sc.byDecision[decisionIndex(DecisionMode::Online)]),
                             rate(sc.byDecision[decisionIndex(DecisionMode::Offline)])});
    }
    if (!e.scenes.empty()) {
      auto mean = [&](DecisionMode mode) {
        const std::optional<double> v = meanSceneBalancedAccuracy(e.scenes, mode);
        return v ? pct(*v) : std::string("no test data");
      };
      scenes.rows.push_back({groupName, "mean over scenes", "", mean(DecisionMode::Step),
                             mean(DecisionMode::Online), mean(DecisionMode::Offline)});
    }
    const ConfusionMatrix& confusion = e.confusion(d);
    rateRows.emplace_back(
        std::string(groupInfo(m.group).longName) + " (" + std::string(decisionModeName(d)) + ")",
        computeMetrics(confusion));
    if (!e.scored()) continue;
    const std::string on = e.evaluatedOn.empty() ? "evaluation data" : e.evaluatedOn;
    const std::string what = " on " + on + ", " + std::string(decisionModeName(d)) + " decision";
    details +=
        confusionTable(confusion, false, "Group " + groupName + ": confusion" + what + " (counts)")
            .render(style) +
        sep;
    details += confusionTable(confusion, true,
                              "Group " + groupName + ": confusion" + what + " (row percent)")
                   .render(style) +
               sep;
    if (!e.patterns.rows.empty()) details += contactPatternTable(e.patterns).render(style) + sep;
    if (!e.oneVsRest.empty()) ovr.emplace_back(m.group, e.oneVsRest);
  }
  out += settings.render(style) + sep;
  out += decisions.render(style) + sep;
  if (!scenes.rows.empty()) out += scenes.render(style) + sep;
  if (!rateRows.empty()) {
    out += classRateTable(rateRows,
                          "Correct rate per class, % (test steps in brackets; fewer than " +
                              std::to_string(minTestSteps) + " marked \"only\")",
                          minTestSteps)
               .render(style) +
           sep;
  }
  if (!ovr.empty()) out += oneVsRestRateTable(ovr).render(style) + sep;
  out += details;
  return out;
}

}  // namespace tactile::analysis
