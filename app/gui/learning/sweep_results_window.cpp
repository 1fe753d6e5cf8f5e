#include "app/gui/learning/sweep_results_window.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <utility>

#include "analysis/model_file.h"
#include "analysis/report.h"
#include "app/gui/common/duration_text.h"
#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/learning/sweep_results_view.h"
#include "app/gui/learning/sweep_worker.h"
#include "base/text_rules.h"
#include "run/json_text.h"
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
  status_ = new QLabel;
  status_->setObjectName(QStringLiteral("sweepStatus"));
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  statusBar()->addPermanentWidget(status_, 1);
  poll_ = new QTimer(this);
  poll_->setInterval(1000);
  connect(poll_, &QTimer::timeout, this, &SweepResultsWindow::refreshStatus);
  resize(1400, 900);
  keepWithinScreen(this);
}

namespace {

// A cell's settings as its key (two results of one cell never both show).
std::string cellKey(const analysis::SweepCell& cell) {
  return dumpJson(analysis::sweepCellSettingsToJson(cell));
}

}  // namespace

bool SweepResultsWindow::following() const {
  return poll_->isActive();
}

void SweepResultsWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (sweepId_ != 0) refreshStatus();
}

void SweepResultsWindow::hideEvent(QHideEvent* event) {
  QMainWindow::hideEvent(event);
  poll_->stop();  // a closed window follows nothing; showing it again looks again
}

void SweepResultsWindow::updateTitle(const std::string& name, const std::string& state) {
  setWindowTitle(tr("Sweep %1: %2 (%3)")
                     .arg(sweepId_)
                     .arg(QString::fromStdString(name), QString::fromStdString(state)));
}

void SweepResultsWindow::showCell(const analysis::SweepCellResult& cell) {
  if (!shownCells_.insert(cellKey(cell.cell)).second) return;
  sweep_.cells.push_back(cell);
  view_->addCell(cell);
}

void SweepResultsWindow::refreshStatus() {
  if (sweepId_ == 0) return;
  auto status = workspace_.sweepStatus(sweepId_);
  if (!status) {
    poll_->stop();
    status_->setText(tr("The sweep's status cannot be read: %1")
                         .arg(QString::fromStdString(status.errorText())));
    return;
  }
  const workspace::SweepStatus& s = status.value();
  if (s.done > sweep_.cells.size()) {
    // Cells stored since the last look, by any worker: the shown ones stay as they are.
    auto stored = workspace_.loadSweep(sweepId_);
    if (stored) {
      for (const analysis::SweepCellResult& cell : stored->cells)
        showCell(cell);
    }
  }
  if (s.state != shownState_) {
    shownState_ = s.state;
    updateTitle(s.name, s.state);
  }
  if (!s.planned) {
    status_->setText(tr("%n cell(s)", nullptr, static_cast<int>(s.cells)));
    poll_->stop();
    return;
  }
  QString text = tr("%1 of %2 cells done, %3 running, %4 pending, %5 failed")
                     .arg(s.done)
                     .arg(s.cells)
                     .arg(s.running)
                     .arg(s.pending)
                     .arg(s.failed);
  const bool open = s.pending + s.running > 0;
  if (open && s.secondsLeft) {
    text += tr("; about %1 left").arg(durationText(*s.secondsLeft));
  } else if (open && s.running == 0) {
    text += tr("; waiting for workers (tactile sweep work)");
  }
  QStringList failures;
  for (const storage::SweepClaim& c : s.failedClaims)
    failures << tr("job %1 on %2: %3")
                    .arg(c.job)
                    .arg(QString::fromStdString(c.worker), QString::fromStdString(c.error));
  status_->setText(text);
  status_->setToolTip(failures.join(QLatin1Char('\n')));
  if (open && !poll_->isActive()) poll_->start();
  if (!open) poll_->stop();
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
  shownCells_.clear();
  for (const analysis::SweepCellResult& cell : sweep_.cells)
    shownCells_.insert(cellKey(cell.cell));
  shownState_ = configuration_.value("state", std::string());
  updateTitle(info->name, shownState_);
  refreshStatus();
  return {};
}

void SweepResultsWindow::addCell(std::int64_t sweepId, const analysis::SweepCellResult& cell) {
  if (sweepId != sweepId_) return;
  showCell(cell);
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
