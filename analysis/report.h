// Reports (docs/analysis.md#reports-reporth) as text tables or CSV: confusion matrices in counts
// and percent, per-class correct rates as in thesis table 4.19, rate against floor and against
// order (mean, min, max over classes) as in figures 4.13 and 4.14, and the contact-pattern error
// table of thesis table 4.39.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/metrics.h"
#include "analysis/model_file.h"
#include "analysis/sweep.h"
#include "analysis/sweep_summary.h"
#include "base/error.h"

namespace tactile::analysis {

enum class TableStyle { Text, Csv, Markdown, Html };
// "text", "csv", "md", "html".
std::optional<TableStyle> parseTableStyle(std::string_view name);

// Text escaped for HTML and SVG (& < > ").
std::string htmlEscape(const std::string& text);
// The names in a stored configuration's run list ([{"name": ...}, ...]; other entries skipped).
std::vector<std::string> runNamesOf(const nlohmann::json& runs);

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

// Thesis table 4.19: per group (short name), for each class c the one-vs-rest correct rates "c"
// and "No c", which are precisions (correct identifications over all predictions of that label);
// empty cells where a class has no classifier in that group.
Table oneVsRestRateTable(
    const std::vector<std::pair<SensorGroup, std::vector<BinaryConfusion>>>& groups);

// Multi-class per-class correct rate (recall, percent) per row label, as in thesis table 4.31,
// each with its test-step count beside it ("93.1 (412)"); a class with fewer than minTestSteps
// test steps says so ("50.0 (only 4 test steps)"). A row without test steps reads "no test
// data".
Table classRateTable(const std::vector<std::pair<std::string, Metrics>>& rows,
                     const std::string& title, std::size_t minTestSteps = kMinTestSteps);

// Figures 4.13 / 4.14 as tables (rateSeries, one row per point). One row per successful sweep cell,
// grouped into series that hold everything but the swept variable fixed; values are the mean, min
// and max over the cell's classes of the per-class rate (recall, percent), plus accuracy and
// balanced accuracy.
Table rateAgainstFloorTable(const SweepResult& sweep);
Table rateAgainstOrderTable(const SweepResult& sweep);

// The best cell per group (bestCells): settings and metrics.
Table bestCellsTable(const SweepResult& sweep);
// Each (group, method)'s best cell (bestCellsByMethod): the families side by side.
Table bestCellsByMethodTable(const SweepResult& sweep);

// Every cell: settings, fit / predict time, iterations, converged, metrics, held-out loglik.
Table sweepCellsTable(const SweepResult& sweep);

// Thesis table 4.39: per on/off pattern and true class, the counts of predicted classes.
Table contactPatternTable(const ContactPatternTable& patterns);

// Whole reports, as printed by `tactile report`: the headline, the configuration (the grid and,
// from the stored sweep's configuration JSON, label set, runs and state), the best cell per group,
// the figures (HTML: inline SVG; Markdown: links into `figureFolder` when set), rate against
// floor and order, each group's best cell in detail (confusion in counts and percent, contact
// patterns, per-class rates), every cell, and every fitted cell's confusion matrix.
struct SweepReportOptions {
  nlohmann::json configuration = nlohmann::json::object();
  std::string figureFolder;  // Markdown: folder (relative to the report) holding the figures
};
std::string sweepReport(const SweepResult& sweep, TableStyle style);
std::string sweepReport(const SweepResult& sweep, TableStyle style,
                        const SweepReportOptions& options);

// The report's figures (report_svg.h): file name, caption and SVG text.
struct SweepFigure {
  std::string file;
  std::string caption;
  std::string svg;
};
std::vector<SweepFigure> sweepFigures(const SweepResult& sweep);

// Writes the report to `out`; Markdown also writes its figures as SVG files into the folder
// "<stem>_files" beside it. Every file is written under a temporary name and renamed into place.
// The CLI's `report` and the workbench's Export Report call this.
Status writeSweepReport(const SweepResult& sweep, TableStyle style,
                        const std::filesystem::path& out,
                        const nlohmann::json& configuration = nlohmann::json::object());
// A model bundle's stored evaluation (of models trained from run files or a database alike):
// settings, test counts and balanced accuracy per decision mode, held-out scenes, confusion in
// counts and percent, per-class rates with counts and "only N test steps" marks, contact patterns,
// one-vs-rest table. A group without test rows says "no test data".
std::string modelReport(const ModelBundle& bundle, TableStyle style,
                        std::size_t minTestSteps = kMinTestSteps);

}  // namespace tactile::analysis
