// The sweep figures in the workbench, from the same data as the report's: correct rate against
// variance floor and against model order (thesis figures 4.13 and 4.14: per series the mean rate
// over classes with min..max as error bars, log x axis) and run time against error with the
// Pareto front (analysis::rateSeries and analysis::paretoFront). Each exports PNG and PDF; clicking
// a point selects that cell, and the selected cell is ringed.
#pragma once

#include <QWidget>

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "analysis/sweep.h"
#include "analysis/sweep_summary.h"

class QCustomPlot;
class QCPAbstractPlottable;
class QCPGraph;
class QCPItemText;
class QCPItemTracer;
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
  // The ring drawn there (visible only with a marked cell; never clipped at the axes).
  QCPItemTracer* markRing() const { return ring_; }
  // Shown over an empty figure (no cells with a model), else empty.
  QString emptyMessage() const;

  // The values of the point within a few pixels of `pos` (this widget's coordinates), else empty.
  QString tipAt(QPoint pos) const;
  // Back to the whole figure after a zoom or pan (also a double click).
  void resetView();

  bool exportPng(const QString& path);
  bool exportPdf(const QString& path);

 signals:
  void cellClicked(int cellIndex);

 private:
  void clear();
  void finish(const QString& emptyText);
  void onPlottableClick(QCPAbstractPlottable* plottable, int dataIndex, QMouseEvent* event);
  QString pointTip(QPointF plotPos) const;

  QCustomPlot* plot_ = nullptr;
  QCPGraph* front_ = nullptr;
  QCPGraph* mark_ = nullptr;
  QCPItemText* empty_ = nullptr;
  QCPItemTracer* ring_ = nullptr;
  int seriesCount_ = 0;
  int frontCount_ = 0;
  int pointCount_ = 0;
  int marked_ = -1;
  std::pair<double, double> homeX_{0, 1};  // the axis ranges the figure was drawn with
  std::pair<double, double> homeY_{0, 1};
  // Points of each graph, by data index: the cell they stand for.
  std::map<const QCPAbstractPlottable*, std::vector<int>> cellsOf_;
  // The value each point stands for on the x axis (points at one swept value are drawn a little
  // apart; a hover reports the value, not where the point was drawn).
  std::map<const QCPAbstractPlottable*, std::vector<double>> xOf_;
  bool timeAxis_ = false;  // the x axis holds seconds (shown in ms below 1 s)
  // Where each drawn cell's point is (plot coordinates).
  std::map<int, QPointF> pointOf_;
};

}  // namespace tactile::gui
