// The sweep figures in the workbench, from the same data as the report's: correct rate against
// variance floor and against model order (thesis figures 4.13 and 4.14: per series the mean rate
// over classes with min..max as error bars, log x axis) and run time against error with the
// Pareto front (analysis::rateSeries and analysis::paretoFront). Each exports PNG and PDF;
// clicking a point of the time-against-error plot selects that cell.
#pragma once

#include <QWidget>

#include <map>
#include <optional>
#include <vector>

#include "analysis/report.h"
#include "analysis/sweep.h"

class QCustomPlot;
class QCPAbstractPlottable;
class QMouseEvent;

namespace tactile::gui {

class SweepPlot : public QWidget {
  Q_OBJECT

 public:
  explicit SweepPlot(QWidget* parent = nullptr);

  void showRates(const std::vector<analysis::RateSeries>& series, analysis::SweptVariable variable);
  // Every successful cell (of `group`, or all), one colour per group; the front of the shown cells.
  void showTimeError(const analysis::SweepResult& sweep, std::optional<SensorGroup> group);

  QCustomPlot* plot() const { return plot_; }
  int seriesCount() const { return seriesCount_; }  // rate series, or groups of points
  int frontCount() const { return frontCount_; }    // Pareto front points
  int pointCount() const { return pointCount_; }    // points drawn

  bool exportPng(const QString& path);
  bool exportPdf(const QString& path);

 signals:
  void cellClicked(int cellIndex);

 private:
  void clear();
  void onPlottableClick(QCPAbstractPlottable* plottable, int dataIndex, QMouseEvent* event);

  QCustomPlot* plot_ = nullptr;
  int seriesCount_ = 0;
  int frontCount_ = 0;
  int pointCount_ = 0;
  // Points of each time-against-error graph, by data index: the cell they stand for.
  std::map<const QCPAbstractPlottable*, std::vector<int>> cellsOf_;
};

}  // namespace tactile::gui
