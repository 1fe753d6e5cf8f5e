#include "app/gui/learning/sweep_results_window.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>

#include <utility>

#include "analysis/model_file.h"
#include "analysis/report.h"
#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/learning/sweep_results_view.h"
#include "app/gui/learning/sweep_worker.h"
#include "base/text_rules.h"
#include "workspace/workspace.h"

namespace tactile::gui {

SweepResultsWindow::SweepResultsWindow(workspace::Workspace& workspace, QString databasePath,
                                       QWidget* parent)
    : QMainWindow(parent), workspace_(workspace), databasePath_(std::move(databasePath)) {
  setAttribute(Qt::WA_DeleteOnClose, false);
  view_ = new SweepResultsView;
  setCentralWidget(view_);
  worker_ = new SweepWorker(this);
  connect(worker_, &SweepWorker::finished, this, &SweepResultsWindow::onModelTrained);

  QToolBar* bar = addToolBar(tr("Sweep"));
  bar->setObjectName(QStringLiteral("sweepToolBar"));
  bar->addAction(tr("Export Report..."), this, &SweepResultsWindow::chooseReportFile);
  bar->addAction(tr("Store Model of Cell"), this, [this] {
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Store Model"),
                                               tr("Name (empty: %1):").arg(automaticModelName()),
                                               QLineEdit::Normal, QString(), &ok);
    if (!ok) return;
    const std::string typed = name.trimmed().toStdString();
    if (const Status valid = checkName(typed, "model name"); !typed.empty() && !valid) {
      QMessageBox::warning(this, tr("Store Model"), QString::fromStdString(valid.errorText()));
      return;
    }
    trainSelectedCell(name.trimmed());
  });
  bar->addAction(tr("Export Model of Cell..."), this, &SweepResultsWindow::chooseModelFile);
  bar->addSeparator();
  QAction* close = bar->addAction(tr("Close"), this, &QWidget::close);
  close->setObjectName(QStringLiteral("closeResults"));
  // Ctrl+W on every platform, beside whatever the platform's Close is.
  QList<QKeySequence> closeKeys{QKeySequence(Qt::CTRL | Qt::Key_W)};
  for (const QKeySequence& k : QKeySequence::keyBindings(QKeySequence::Close))
    if (!closeKeys.contains(k)) closeKeys << k;
  close->setShortcuts(closeKeys);
  close->setShortcutContext(Qt::WindowShortcut);
  close->setToolTip(
      tr("Close this window (%1)").arg(close->shortcut().toString(QKeySequence::NativeText)));
  resize(1400, 900);
  keepWithinScreen(this);
}

QString SweepResultsWindow::automaticModelName() const {
  const int cell = view_->selectedCell();
  if (cell < 0 || static_cast<std::size_t>(cell) >= sweep_.cells.size()) return tr("automatic");
  const std::string_view group =
      groupInfo(sweep_.cells[static_cast<std::size_t>(cell)].cell.group).shortName;
  return QStringLiteral("sweep%1-%2-cell%3")
      .arg(sweepId_)
      .arg(QString::fromUtf8(group.data(), static_cast<qsizetype>(group.size())))
      .arg(cell);
}

SweepResultsWindow::~SweepResultsWindow() = default;

Status SweepResultsWindow::showSweep(std::int64_t sweepId) {
  auto info = workspace_.sweepStore().info(sweepId);
  if (!info) return info.error();
  auto sweep = workspace_.loadSweep(sweepId);
  if (!sweep) return sweep.error();
  if (sweepId != sweepId_) storedModels_.clear();
  sweepId_ = sweepId;
  sweep_ = std::move(sweep.value());
  try {
    configuration_ = nlohmann::json::parse(info->configurationJson);
  } catch (const nlohmann::json::exception&) {
    configuration_ = nlohmann::json::object();
  }
  view_->setSweep(sweepId, sweep_);
  const std::string state = configuration_.value("state", std::string());
  setWindowTitle(tr("Sweep %1: %2 (%3)")
                     .arg(sweepId)
                     .arg(QString::fromStdString(info->name), QString::fromStdString(state)));
  return {};
}

void SweepResultsWindow::addCell(std::int64_t sweepId, const analysis::SweepCellResult& cell) {
  if (sweepId != sweepId_) return;
  sweep_.cells.push_back(cell);
  view_->addCell(cell);
}

Status SweepResultsWindow::exportReport(const QString& path) {
  if (sweepId_ == 0) return Error("no sweep is shown");
  const QString suffix = QFileInfo(path).suffix().toLower();
  const analysis::TableStyle style = suffix == QLatin1String("md") ? analysis::TableStyle::Markdown
                                     : suffix == QLatin1String("csv") ? analysis::TableStyle::Csv
                                     : suffix == QLatin1String("txt") ? analysis::TableStyle::Text
                                                                      : analysis::TableStyle::Html;
  return analysis::writeSweepReport(sweep_, style, path.toStdString(), configuration_);
}

void SweepResultsWindow::chooseReportFile() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Report"),
      startPath(QStringLiteral("reports"), QStringLiteral("sweep-%1.html").arg(sweepId_)),
      tr("HTML report (*.html);;Markdown report (*.md);;CSV tables (*.csv);;Text (*.txt)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("reports"), path);
  if (Status s = exportReport(path); !s) {
    QMessageBox::warning(this, tr("Export Report"), QString::fromStdString(s.errorText()));
    return;
  }
  statusBar()->showMessage(tr("Report written to %1").arg(path), 8000);
}

bool SweepResultsWindow::trainSelectedCell(const QString& name, const QString& file) {
  const int cell = view_->selectedCell();
  if (cell < 0 || static_cast<std::size_t>(cell) >= sweep_.cells.size()) {
    statusBar()->showMessage(tr("Select a cell first."), 5000);
    return false;
  }
  if (!sweep_.cells[static_cast<std::size_t>(cell)].ok) {
    statusBar()->showMessage(
        tr("That cell has no model: %1")
            .arg(QString::fromStdString(sweep_.cells[static_cast<std::size_t>(cell)].reason)),
        8000);
    return false;
  }
  pendingModelFile_ = file;
  // Export exports: a model for a file is not stored (and so never becomes a default model).
  if (!worker_->startCellModel(databasePath_, sweepId_, static_cast<std::size_t>(cell), name,
                               file.isEmpty()))
    return false;
  statusBar()->showMessage(tr("Training the cell's model..."));
  return true;
}

void SweepResultsWindow::chooseModelFile() {
  const QString name = automaticModelName();
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Model"), startPath(QStringLiteral("models"), name + QStringLiteral(".json")),
      tr("Model files (*.json)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("models"), path);
  trainSelectedCell(QString(), path);
}

void SweepResultsWindow::onModelTrained(const LearningJobResult& result) {
  if (!result.ok) {
    const QString why = result.cancelled ? tr("cancelled") : result.error;
    QMessageBox::warning(this, tr("Model of Cell"), tr("No model was stored: %1").arg(why));
    return;
  }
  if (!pendingModelFile_.isEmpty()) {
    const QString file = std::exchange(pendingModelFile_, QString());
    const Status written = result.unstored ? analysis::writeModelBundleFile(file.toStdString(),
                                                                            result.unstored->bundle)
                                           : Status(Error("the cell's model was not handed back"));
    if (!written) {
      QMessageBox::warning(this, tr("Export Model"), QString::fromStdString(written.errorText()));
      return;
    }
    statusBar()->showMessage(tr("Model written to %1 (not stored in the database).").arg(file),
                             10000);
    return;
  }
  storedModels_ << result.modelName;
  view_->setStoredModels(storedModels_);
  statusBar()->showMessage(tr("Model '%1' stored.").arg(result.modelName), 10000);
  emit modelStored(result.modelName);
}

}  // namespace tactile::gui
