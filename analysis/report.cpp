#include "analysis/report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

#include "analysis/training.h"

namespace tactile::analysis {

using nlohmann::json;

namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
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

std::string floorText(double f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", f);
  return buf;
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

std::vector<std::string> cellKey(const SweepCell& c) {
  return {std::string(groupInfo(c.group).shortName), std::string(featureKindName(c.features)),
          std::string(classifierMethodName(c.method)), std::string(covarianceFormName(c.form))};
}

// Cells sorted by (group, features, method, form, fixed variable, swept variable, seed).
Table spreadTable(const SweepResult& sweep, bool sweptIsFloor) {
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
  std::vector<const SweepCellResult*> cells;
  for (const SweepCellResult& r : sweep.cells) {
    if (r.ok) cells.push_back(&r);
  }
  auto key = [sweptIsFloor](const SweepCellResult* r) {
    const SweepCell& c = r->cell;
    const double fixedVar = sweptIsFloor ? c.order : c.varianceFloor;
    const double swept = sweptIsFloor ? c.varianceFloor : c.order;
    return std::make_tuple(groupIndex(c.group), static_cast<int>(c.features),
                           static_cast<int>(c.method), static_cast<int>(c.form), fixedVar, swept,
                           c.seed);
  };
  std::stable_sort(
      cells.begin(), cells.end(),
      [&](const SweepCellResult* a, const SweepCellResult* b) { return key(a) < key(b); });
  for (const SweepCellResult* r : cells) {
    const RateSpread s = spreadOf(r->metrics);
    std::vector<std::string> row = cellKey(r->cell);
    const std::string order = std::to_string(r->cell.order);
    const std::string floor = floorText(r->cell.varianceFloor);
    row.push_back(sweptIsFloor ? order : floor);
    row.push_back(sweptIsFloor ? floor : order);
    row.push_back(std::to_string(r->cell.seed));
    row.push_back(s.any ? fixed(s.mean, 1) : "");
    row.push_back(s.any ? fixed(s.min, 1) : "");
    row.push_back(s.any ? fixed(s.max, 1) : "");
    row.push_back(fixed(100.0 * r->metrics.accuracy, 1));
    row.push_back(fixed(100.0 * r->metrics.balancedAccuracy, 1));
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace

std::optional<TableStyle> parseTableStyle(std::string_view name) {
  if (name == "text") return TableStyle::Text;
  if (name == "csv") return TableStyle::Csv;
  if (name == "md" || name == "markdown") return TableStyle::Markdown;
  if (name == "html") return TableStyle::Html;
  return std::nullopt;
}

namespace {

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
  t.title = "One-vs-rest correct rates, % (thesis table 4.19)";
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
    std::vector<std::string> row{std::string(groupInfo(group).longName)};
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
                     const std::string& title) {
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
    for (ContactClass c : classes)
      row.push_back(pct(m.recallOf(c)));
    row.push_back(pct(m.accuracy));
    row.push_back(pct(m.balancedAccuracy));
    row.push_back(fixed(m.macroF1, 3));
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table rateAgainstFloorTable(const SweepResult& sweep) {
  return spreadTable(sweep, true);
}
Table rateAgainstOrderTable(const SweepResult& sweep) {
  return spreadTable(sweep, false);
}

Table bestCellsTable(const SweepResult& sweep) {
  Table t;
  t.title = "Best cell per group (balanced accuracy on held-out rows)";
  t.header = {"group",      "features",   "method",   "covariance",  "order", "floor",  "seed",
              "balanced_%", "accuracy_%", "macro_f1", "mean_loglik", "fit_s", "dropped"};
  std::map<int, const SweepCellResult*> best;
  for (const SweepCellResult& r : sweep.cells) {
    if (!r.ok) continue;
    const int g = groupIndex(r.cell.group);
    const SweepCellResult*& b = best[g];
    auto better = [](const SweepCellResult& a, const SweepCellResult& c) {
      if (a.metrics.balancedAccuracy != c.metrics.balancedAccuracy) {
        return a.metrics.balancedAccuracy > c.metrics.balancedAccuracy;
      }
      if (a.cell.order != c.cell.order) return a.cell.order < c.cell.order;
      return a.fitSeconds < c.fitSeconds;
    };
    if (b == nullptr || better(r, *b)) b = &r;
  }
  for (const auto& [g, r] : best) {
    std::vector<std::string> row = cellKey(r->cell);
    row.push_back(std::to_string(r->cell.order));
    row.push_back(floorText(r->cell.varianceFloor));
    row.push_back(std::to_string(r->cell.seed));
    row.push_back(fixed(100.0 * r->metrics.balancedAccuracy, 1));
    row.push_back(fixed(100.0 * r->metrics.accuracy, 1));
    row.push_back(fixed(r->metrics.macroF1, 3));
    row.push_back(r->meanLogLikelihood ? fixed(*r->meanLogLikelihood, 4) : "");
    row.push_back(fixed(r->fitSeconds, 3));
    row.push_back(std::to_string(r->droppedComponents));
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table sweepCellsTable(const SweepResult& sweep) {
  Table t;
  t.title = "Sweep cells";
  t.header = {"group",       "features",     "method",     "covariance", "order",
              "floor",       "seed",         "ok",         "fit_s",      "predict_s",
              "iterations",  "converged",    "accuracy_%", "balanced_%", "macro_f1",
              "mean_loglik", "neg_inf_rows", "dropped",    "reason"};
  for (const SweepCellResult& r : sweep.cells) {
    std::vector<std::string> row = cellKey(r.cell);
    row.push_back(std::to_string(r.cell.order));
    row.push_back(floorText(r.cell.varianceFloor));
    row.push_back(std::to_string(r.cell.seed));
    row.push_back(r.ok ? "yes" : "no");
    row.push_back(fixed(r.fitSeconds, 4));
    row.push_back(fixed(r.predictSeconds, 4));
    row.push_back(std::to_string(r.iterations));
    row.push_back(r.converged ? "yes" : "no");
    row.push_back(r.ok ? fixed(100.0 * r.metrics.accuracy, 2) : "");
    row.push_back(r.ok ? fixed(100.0 * r.metrics.balancedAccuracy, 2) : "");
    row.push_back(r.ok ? fixed(r.metrics.macroF1, 4) : "");
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
            " (thesis table 4.39; sensors in index order, 1 = contact)";
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

std::string sweepReport(const SweepResult& sweep, TableStyle style) {
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
        "<style>table{border-collapse:collapse;margin-bottom:1em}td,th{border:1px solid "
        "#bbb;padding:2px 6px;text-align:right}th{background:#eee}</style></head><body>\n<h1>" +
        htmlEscape(headline) + "</h1>\n";
  }
  out += bestCellsTable(sweep).render(style) + sep;
  out += rateAgainstFloorTable(sweep).render(style) + sep;
  out += rateAgainstOrderTable(sweep).render(style) + sep;
  // Confusion matrices of each group's best cell.
  std::map<int, const SweepCellResult*> best;
  for (const SweepCellResult& r : sweep.cells) {
    if (!r.ok) continue;
    const SweepCellResult*& b = best[groupIndex(r.cell.group)];
    if (b == nullptr || r.metrics.balancedAccuracy > b->metrics.balancedAccuracy) b = &r;
  }
  for (const auto& [g, r] : best) {
    const std::string name = "Group " + std::string(groupInfo(r->cell.group).shortName) + ", " +
                             std::string(classifierMethodName(r->cell.method)) + " " +
                             std::string(covarianceFormName(r->cell.form)) + " order " +
                             std::to_string(r->cell.order) + " variance floor " +
                             floorText(r->cell.varianceFloor);
    out += confusionTable(r->confusion, false, name + ": confusion (counts)").render(style) + sep;
    out +=
        confusionTable(r->confusion, true, name + ": confusion (row percent)").render(style) + sep;
  }
  out += sweepCellsTable(sweep).render(style);
  if (style == TableStyle::Html) out += "</body></html>\n";
  return out;
}

std::string modelReport(const json& value, TableStyle style) {
  std::vector<json> models;
  if (value.value("format", "") == "tactile-model-bundle" && value.contains("models")) {
    for (const json& m : value["models"])
      models.push_back(m);
  } else {
    models.push_back(value);
  }
  const std::string sep = style == TableStyle::Text ? "\n" : "";
  std::string out;
  std::vector<std::pair<std::string, Metrics>> rateRows;
  std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>> ovr;
  std::string details;
  Table settings;
  settings.title = "Models";
  settings.header = {"group",   "features", "method",     "covariance",
                     "order",   "floor",    "dropped",    "regularization",
                     "classes", "samples",  "accuracy_%", "balanced_%"};
  for (const json& m : models) {
    const std::string groupName = m.value("group", "?");
    const auto group = parseSensorGroup(groupName);
    const json metrics = m.value("metrics", json::object());
    const json eval = metrics.value("evaluation", json::object());
    std::string classes;
    for (const json& c : m.value("classes", json::array())) {
      classes += (classes.empty() ? "" : " ") + c.get<std::string>();
    }
    int order = 0;
    if (m.contains("components") && m["components"].is_object() && !m["components"].empty()) {
      order = static_cast<int>(m["components"].begin()->value("weights", json::array()).size());
    }
    ConfusionMatrix confusion;
    const bool haveConfusion =
        eval.contains("confusion") && confusionFromJson(eval["confusion"], confusion);
    const Metrics met = computeMetrics(confusion);
    // Components removed for lack of mass, summed over the classes (train writes them per class).
    std::string dropped;
    if (metrics.contains("dropped_components") && metrics["dropped_components"].is_object()) {
      long sum = 0;
      for (const auto& [name, count] : metrics["dropped_components"].items())
        if (count.is_number_integer()) sum += count.get<long>();
      dropped = std::to_string(sum);
    }
    settings.rows.push_back(
        {groupName, m.value("features", ""), m.value("method", ""), m.value("covariance", ""),
         std::to_string(order), floorText(m.value("variance_floor", 0.0)), dropped,
         m.value("regularization", ""), classes, haveConfusion ? std::to_string(met.total) : "",
         haveConfusion ? pct(met.accuracy) : "", haveConfusion ? pct(met.balancedAccuracy) : ""});
    if (!haveConfusion || !group) continue;
    const std::string on = metrics.value("evaluated_on", "evaluation data");
    rateRows.emplace_back(groupInfo(*group).longName, met);
    details += confusionTable(confusion, false,
                              "Group " + groupName + ": confusion on " + on + " (counts)")
                   .render(style) +
               sep;
    details += confusionTable(confusion, true,
                              "Group " + groupName + ": confusion on " + on + " (row percent)")
                   .render(style) +
               sep;
    if (eval.contains("contact_patterns")) {
      ContactPatternTable patterns;
      patterns.group = *group;
      for (const json& r : eval["contact_patterns"]) {
        const auto truth = parseContactClass(r.value("truth", ""));
        if (!truth) continue;
        ContactPatternRow row{r.value("pattern", ""), *truth, {}};
        for (auto it = r["predicted"].begin(); it != r["predicted"].end(); ++it) {
          if (const auto p = parseContactClass(it.key())) {
            row.predicted[static_cast<std::size_t>(*p)] = it.value().get<std::size_t>();
          }
        }
        patterns.rows.push_back(row);
      }
      details += contactPatternTable(patterns).render(style) + sep;
    }
    if (eval.contains("one_vs_rest")) {
      std::vector<BinaryConfusion> bins;
      for (const json& b : eval["one_vs_rest"]) {
        const auto c = parseContactClass(b.value("class", ""));
        if (!c) continue;
        bins.push_back({*c, b.value("tp", std::size_t{0}), b.value("fp", std::size_t{0}),
                        b.value("fn", std::size_t{0}), b.value("tn", std::size_t{0})});
      }
      ovr.emplace_back(*group, std::move(bins));
    }
  }
  out += settings.render(style) + sep;
  if (!rateRows.empty()) {
    out += classRateTable(rateRows, "Per-class correct rate (recall, %)").render(style) + sep;
  }
  if (!ovr.empty()) out += oneVsRestRateTable(ovr).render(style) + sep;
  out += details;
  return out;
}

}  // namespace tactile::analysis
