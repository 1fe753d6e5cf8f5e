// The sweep figures in the workbench, from the same data as the report's: correct rate against
// variance floor and against model order (thesis figures 4.13 and 4.14: per series the mean rate
// over classes with min..max as error bars, log x axis) and run time against error with the
// Pareto front (analysis::rateSeries and analysis::paretoFront). Each exports PNG and PDF; clicking
// a point selects that cell, and the selected cell is ringed.
#pragma once

#include <QWidget>

#include <map>
#include <optional>
#include <vector>

#include "analysis/report.h"
#include "analysis/sweep.h"

class QCustomPlot;
class QCPAbstractPlottable;
class QCPGraph;
class QCPItemText;
class QMouseEvent;

namespace tactile::gui {

class SweepPlot : public QWidget {
  Q_OBJECT

 public:
  explicit SweepPlot(QWidget* parent = nullptr);

  // Rate series as analysis::rateSeries returns them. `cellOf` maps each series' cell indices
  // (RateSeries::cells) to the cell indices clicks report and markCell takes (empty: the same).
  void showRates(const std::vector<analysis::RateSeries>& series, analysis::SweptVariable variable,
                 const std::vector<int>& cellOf = {});
  // Every successful cell (of `group`, or all), one colour per group; the front of the shown cells.
  void showTimeError(const analysis::SweepResult& sweep, std::optional<SensorGroup> group);
  // Rings the point of that cell (-1 or a cell not drawn: no ring).
  void markCell(int cellIndex);

  QCustomPlot* plot() const { return plot_; }
  int seriesCount() const { return seriesCount_; }  // rate series, or groups of points
  int frontCount() const { return frontCount_; }    // Pareto front points
  int pointCount() const { return pointCount_; }    // points drawn (front and ring not counted)
  // The graph joining the Pareto front (time against error), else null.
  QCPGraph* frontGraph() const { return front_; }
  // The ring around the marked cell: empty when none is marked.
  QCPGraph* markGraph() const { return mark_; }
  // Shown over an empty figure (no cells with a model), else empty.
  QString emptyMessage() const;

  bool exportPng(const QString& path);
  bool exportPdf(const QString& path);

 signals:
  void cellClicked(int cellIndex);

 private:
  void clear();
  void finish(const QString& emptyText);
  void onPlottableClick(QCPAbstractPlottable* plottable, int dataIndex, QMouseEvent* event);

  QCustomPlot* plot_ = nullptr;
  QCPGraph* front_ = nullptr;
  QCPGraph* mark_ = nullptr;
  QCPItemText* empty_ = nullptr;
  int seriesCount_ = 0;
  int frontCount_ = 0;
  int pointCount_ = 0;
  int marked_ = -1;
  // Points of each graph, by data index: the cell they stand for.
  std::map<const QCPAbstractPlottable*, std::vector<int>> cellsOf_;
  // Where each drawn cell's point is (plot coordinates).
  std::map<int, QPointF> pointOf_;
};

}  // namespace tactile::gui
