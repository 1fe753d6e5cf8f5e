// Reports (docs/analysis.md#reports-reporth) as text tables or CSV: confusion matrices in counts
// and percent, per-class correct rates as in thesis table 4.19, rate against floor and against
// order (mean, min, max over classes) as in figures 4.13 and 4.14, and the contact-pattern error
// table of thesis table 4.39.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/metrics.h"
#include "analysis/sweep.h"

namespace tactile::analysis {

enum class TableStyle { Text, Csv, Markdown, Html };
// "text", "csv", "md", "html".
std::optional<TableStyle> parseTableStyle(std::string_view name);

// A small table: header and rows of cells, rendered as aligned text (numbers right-aligned), CSV,
// a Markdown pipe table or an HTML table (cells escaped).
struct Table {
  std::string title;  // printed above a text table; CSV: a "# title" line
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string render(TableStyle style) const;
};

// Confusion matrix, rows = true class, columns = predicted class; counts or row percent.
Table confusionTable(const ConfusionMatrix& confusion, bool percent, const std::string& title);

// Thesis table 4.19: per group, for each class c the one-vs-rest correct rates "c" and "No c"
// (correct identifications over all predictions of that label); empty cells where a class has
// no classifier in that group.
Table oneVsRestRateTable(
    const std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>>& groups);

// Multi-class per-class correct rate (recall, percent) per row label, as in thesis table 4.31.
Table classRateTable(const std::vector<std::pair<std::string, Metrics>>& rows,
                     const std::string& title);

// Figures 4.13 / 4.14 as tables. One row per successful sweep cell, grouped into series that
// hold everything but the swept variable fixed; values are the mean, min and max over the
// cell's classes of the per-class rate (recall, percent), plus accuracy and balanced accuracy.
Table rateAgainstFloorTable(const SweepResult& sweep);
Table rateAgainstOrderTable(const SweepResult& sweep);

// The best cell per group by balanced accuracy (ties: fewer components, then faster fit).
Table bestCellsTable(const SweepResult& sweep);

// Every cell: settings, fit / predict time, iterations, converged, metrics, held-out loglik.
Table sweepCellsTable(const SweepResult& sweep);

// Thesis table 4.39: per on/off pattern and true class, the counts of predicted classes.
Table contactPatternTable(const ContactPatternTable& patterns);

// Whole reports, as printed by `tactile report`.
std::string sweepReport(const SweepResult& sweep, TableStyle style);
// A model file's (or bundle's) stored evaluation ("metrics" of each model, as written by
// `tactile train`): confusion in counts and percent, rates, contact patterns, one-vs-rest table.
std::string modelReport(const nlohmann::json& modelOrBundle, TableStyle style);

}  // namespace tactile::analysis
