#include "app/gui/main_window.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMap>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressDialog>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTextEdit>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/plot_style.h"
#include "app/gui/common/progress_bridge.h"
#include "app/gui/common/settings_keys.h"
#include "app/gui/common/shortcuts.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/labels/history_view.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/labels/label_panel_view.h"
#include "app/gui/learning/model_picker_dialog.h"
#include "app/gui/learning/prediction_model.h"
#include "app/gui/learning/sweep_results_window.h"
#include "app/gui/learning/sweep_worker.h"
#include "app/gui/learning/training_dialog.h"
#include "app/gui/preferences_dialog.h"
#include "app/gui/runs/import_worker.h"
#include "app/gui/runs/mcap_dialogs.h"
#include "app/gui/runs/navigator_track_model.h"
#include "app/gui/runs/navigator_view.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_list_model.h"
#include "app/gui/runs/run_list_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/step_controls_view.h"
#include "app/gui/runs/timeline_view.h"
#include "app/gui/sim/sim_window.h"
#include "app/gui/user_guide_window.h"
#include "sim/scene_source.h"
#include "workspace/run_mcap.h"
#include "workspace/workspace.h"

namespace tactile::gui {

namespace keys = settings_keys;

namespace {

constexpr int kPageCacheKiB = 16 * 1024;

constexpr int kSaveDelayMs = 400;  // quiet time before changed settings are written

// A field the user types text into: it keeps every key while it has the focus.
bool isTextField(const QObject* o) {
  if (qobject_cast<const QLineEdit*>(o) != nullptr ||
      qobject_cast<const QAbstractSpinBox*>(o) != nullptr ||
      qobject_cast<const QTextEdit*>(o) != nullptr ||
      qobject_cast<const QPlainTextEdit*>(o) != nullptr)
    return true;
  const auto* combo = qobject_cast<const QComboBox*>(o);
  return combo != nullptr && combo->isEditable();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      session_(new RunSession(this)),
      labels_(new LabelModel(this)),
      runModel_(new RunListModel(this)) {
  setObjectName(QStringLiteral("MainWindow"));
  setAcceptDrops(true);
  setDockNestingEnabled(true);
  createViews();
  createActions();
  resize(1400, 900);
  restoreSettings();
  applyPreferences();
  updateTitle();
  updateStatus();
  // The timelines take the keyboard focus, not the first text field of the docks: the step and
  // class keys work at once.
  timeline_->setFocusPolicy(Qt::StrongFocus);
  timeline_->setFocus(Qt::OtherFocusReason);
  qApp->installEventFilter(this);

  saveTimer_ = new QTimer(this);
  saveTimer_->setSingleShot(true);
  saveTimer_->setInterval(kSaveDelayMs);
  connect(saveTimer_, &QTimer::timeout, this, [this] { saveSettings(); });
  connect(session_, &RunSession::currentStepChanged, this, &MainWindow::scheduleSave);
  connect(timeline_, &TimelineView::visibleRangeChanged, this, &MainWindow::scheduleSave);
  connect(route_, &RouteView::viewSettingsChanged, this, &MainWindow::scheduleSave);
  connect(labelPanel_, &LabelPanelView::settingsChanged, this, &MainWindow::scheduleSave);
  connect(steps_, &StepControlsView::speedChanged, this, &MainWindow::scheduleSave);
  connect(runList_, &RunListView::filterChanged, this, &MainWindow::scheduleSave);

  connect(session_, &RunSession::errorOccurred, this, &MainWindow::showError);
  connect(labels_, &LabelModel::errorOccurred, this, &MainWindow::showError);
  connect(labelPanel_, &LabelPanelView::errorOccurred, this, &MainWindow::showError);
  connect(labelPanel_, &LabelPanelView::statusMessage, this, &MainWindow::showMessage);
  connect(labels_, &LabelModel::changedElsewhere, this, [this](const QString& lines) {
    showMessage(tr("Labels changed by others: %1").arg(QString(lines).replace('\n', "; ")));
  });
  connect(labels_, &LabelModel::connectionLost, this, &MainWindow::serverLost);
  connect(runList_, &RunListView::assignmentRequested, this, &MainWindow::changeAssignment);
  reconnectTimer_ = new QTimer(this);
  reconnectTimer_->setInterval(3000);
  connect(reconnectTimer_, &QTimer::timeout, this, [this] {
    if (openDatabase(dbPath_).ok()) {
      reconnectTimer_->stop();
      showMessage(tr("Reconnected to %1").arg(dbPath_));
    }
  });
  connect(session_, &RunSession::currentStepChanged, this, &MainWindow::updateStatus);
  connect(session_, &RunSession::selectionChanged, this, &MainWindow::updateStatus);
  connect(session_, &RunSession::runOpened, this, [this] {
    updateTitle();
    updateStatus();
  });
  connect(labels_, &LabelModel::labelSetChanged, this, [this] {
    updateStatus();
    if (workspace_) saveSettings();
    (void)runModel_->reloadCoverage(workspace_.get(), labels_->setId());
  });
  connect(labels_->undoStack(), &QUndoStack::indexChanged, this,
          [this] { (void)runModel_->reloadCoverage(workspace_.get(), labels_->setId()); });
  connect(runList_, &RunListView::runChosen, this, [this](const QString& name) {
    if (name.toStdString() != session_->info().name || !session_->isOpen()) {
      Status s = openRun(name);
      if (!s) showError(QString::fromStdString(s.errorText()));
    }
  });
}

MainWindow::~MainWindow() {
  qApp->removeEventFilter(this);
  // Views hold pointers into the workspace through the session and the label model.
  session_->setWorkspace(nullptr);
  labels_->setWorkspace(nullptr);
}

void MainWindow::createViews() {
  timeline_ = new TimelineView(session_, labels_, this);
  // The timelines, with the navigator's strips under them for runs of `tactile navigate`.
  auto* navTrack = new NavigatorTrackModel(session_, this);
  auto* centre = new QWidget(this);
  auto* column = new QVBoxLayout(centre);
  column->setContentsMargins(0, 0, 0, 0);
  column->setSpacing(0);
  column->addWidget(timeline_, 1);
  column->addWidget(new NavigatorStripView(session_, navTrack, timeline_, centre));
  setCentralWidget(centre);

  auto dock = [this](const QString& title, const QString& name, QWidget* content,
                     Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(content);
    addDockWidget(area, d);
    return d;
  };
  runList_ = new RunListView(runModel_, this);
  route_ = new RouteView(session_, labels_, this);
  predictions_ = new PredictionModel(labels_, this);
  timeline_->setPredictions(predictions_);
  route_->setPredictions(predictions_);
  connect(predictions_, &PredictionModel::failed, this,
          [this](const QString& message) { showError(tr("Predictions: %1").arg(message)); });
  connect(predictions_, &PredictionModel::ready, this, [this] {
    std::size_t n = 0;
    bool labelled = false;
    for (const GroupInfo& g : kSensorGroups) {
      n += predictions_->group(g.group).disagreements;
      labelled = labelled || !labels_->segments(g.group).empty();
    }
    // Nothing to disagree with is not agreement.
    if (!labelled) {
      showMessage(
          tr("Predictions shown; this run has no labels in the set yet (Ctrl+L labels "
             "the steps in view from the model)"));
      return;
    }
    showMessage(tr("Predictions shown: %n step(s) disagree with the labels (N: next)", nullptr,
                   static_cast<int>(n)));
  });
  labelPanel_ = new LabelPanelView(session_, labels_, this);
  QDockWidget* runs =
      dock(tr("Runs"), QStringLiteral("runsDock"), runList_, Qt::LeftDockWidgetArea);
  QDockWidget* route =
      dock(tr("Route"), QStringLiteral("routeDock"), route_, Qt::LeftDockWidgetArea);
  // The panels of forms scroll on a short screen rather than making the window taller than it.
  auto scrolling = [this](QWidget* content, const QString& name) {
    auto* area = new QScrollArea(this);
    area->setObjectName(name);
    area->setFrameShape(QFrame::NoFrame);
    area->setWidgetResizable(true);
    area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    area->setWidget(content);
    // As wide as the panel needs, with room for the vertical scroll bar.
    area->setMinimumWidth(content->minimumSizeHint().width() +
                          area->verticalScrollBar()->sizeHint().width());
    return area;
  };
  QDockWidget* labels =
      dock(tr("Labels"), QStringLiteral("labelsDock"),
           scrolling(labelPanel_, QStringLiteral("labelsScroll")), Qt::RightDockWidgetArea);
  QDockWidget* navigator = dock(tr("Navigator"), QStringLiteral("navigatorDock"),
                                scrolling(new NavigatorPanelView(session_, navTrack, this),
                                          QStringLiteral("navigatorScroll")),
                                Qt::RightDockWidgetArea);
  QDockWidget* history = dock(tr("History"), QStringLiteral("historyDock"),
                              new HistoryView(session_, labels_, this), Qt::RightDockWidgetArea);
  tabifyDockWidget(labels, navigator);
  tabifyDockWidget(labels, history);
  labels->raise();
  splitDockWidget(runs, route, Qt::Vertical);
  resizeDocks({runs, route}, {260, 560}, Qt::Vertical);
  resizeDocks({runs, labels}, {500, 300}, Qt::Horizontal);

  steps_ = new StepControlsView(session_, this);
  QToolBar* bar = addToolBar(tr("Steps"));
  bar->setObjectName(QStringLiteral("stepToolBar"));
  bar->addWidget(steps_);

  stepLabel_ = new QLabel(this);
  setLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(stepLabel_);
  statusBar()->addPermanentWidget(setLabel_);
}

void MainWindow::bindShortcut(QAction* action, const QString& id) {
  const ShortcutEntry entry = shortcutEntry(id);
  Q_ASSERT(!entry.keys.isEmpty());
  action->setObjectName(id);
  action->setShortcuts(entry.keys);
  for (const QKeySequence& k : entry.keys)
    actionOfKey_.insert(k, action);
  if (entry.global) {
    action->setAutoRepeat(true);
    globalKeys_ << entry.keys;
  }
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
    return QMainWindow::eventFilter(watched, event);
  auto* widget = qobject_cast<QWidget*>(watched);
  if (widget == nullptr || widget->window() != this)
    return QMainWindow::eventFilter(watched, event);
  auto* key = static_cast<QKeyEvent*>(event);
  const bool escape = key->key() == Qt::Key_Escape && key->modifiers() == Qt::NoModifier;
  if (isTextField(widget)) {
    // Escape leaves the field (back to the timelines) instead of clearing the selection.
    if (!escape) return QMainWindow::eventFilter(watched, event);
    if (event->type() == QEvent::ShortcutOverride) {
      event->accept();
    } else {
      timeline_->setFocus(Qt::ShortcutFocusReason);
    }
    return true;
  }
  // Any other focused widget (a table, a slider, a button) would take the arrow or digit keys for
  // itself: the window's step, class and undo shortcuts come first.
  const QKeySequence pressed(key->keyCombination());
  if (event->type() == QEvent::ShortcutOverride && globalKeys_.contains(pressed)) {
    event->ignore();
    return true;
  }
  // A bound key that reaches a widget as a plain key press found no shortcut: the window is not
  // the active one (a session without a window manager), so Qt matched none. The key still does
  // what the table says.
  if (event->type() == QEvent::KeyPress && !isActiveWindow()) {
    if (QAction* action = actionOfKey_.value(pressed); action != nullptr && action->isEnabled()) {
      action->trigger();
      return true;
    }
  }
  return QMainWindow::eventFilter(watched, event);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  // Nothing is being typed yet: a text field that got the focus by default gives it back.
  if (QWidget* f = focusWidget(); f == nullptr || isTextField(f))
    timeline_->setFocus(Qt::OtherFocusReason);
}

void MainWindow::scheduleSave() {
  if (saveTimer_ != nullptr) saveTimer_->start();
}

void MainWindow::applyPreferences() {
  QSettings settings;
  const QString annotator = settings.value(keys::kAnnotator).toString().trimmed();
  labels_->setAnnotator(annotator.toStdString());
  if (runList_ != nullptr) runList_->setAnnotator(annotator);
  timeline_->setRowHeight(
      settings.value(keys::kTimelineRowHeight, PreferencesDialog::kDefaultRowHeight).toInt());
}

void MainWindow::showUserGuide() {
  auto* window = findChild<UserGuideWindow*>();
  if (window == nullptr) window = new UserGuideWindow(this);
  window->show();
  window->raise();
  window->activateWindow();
}

void MainWindow::showKeyboardShortcuts() {
  auto* dialog = findChild<QDialog*>(QStringLiteral("shortcutsDialog"));
  if (dialog == nullptr) {
    dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("shortcutsDialog"));
    dialog->setWindowTitle(tr("Keyboard Shortcuts"));
    auto* text = new QTextBrowser(dialog);
    text->setObjectName(QStringLiteral("shortcutsText"));
    text->setHtml(shortcutTableHtml());
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(text);
    layout->addWidget(buttons);
    dialog->resize(560, 640);
  }
  dialog->show();
  dialog->raise();
  dialog->activateWindow();
}

void MainWindow::showPreferences() {
  auto* dialog = findChild<PreferencesDialog*>();
  if (dialog == nullptr) {
    dialog = new PreferencesDialog(this);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
      dialog->save();
      applyPreferences();
      showMessage(tr("Preferences saved"));
    });
  }
  dialog->load();
  dialog->show();
  dialog->raise();
  dialog->activateWindow();
}

void MainWindow::createActions() {
  // Every key comes from the one shortcut table (common/shortcuts.h) that Help lists.
  // ---- File ----
  QMenu* file = menuBar()->addMenu(tr("&File"));
  bindShortcut(file->addAction(tr("&Open Database..."), this, [this] { chooseDatabase(false); }),
               QStringLiteral("openDatabase"));
  file->addAction(tr("&New Database..."), this, [this] { chooseDatabase(true); });
  QAction* openServer = file->addAction(tr("Open &Server..."), this, &MainWindow::chooseServer);
  openServer->setObjectName(QStringLiteral("openServerAction"));
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  file->addSeparator();
  bindShortcut(file->addAction(tr("&Import Runs..."), this, &MainWindow::chooseRunFiles),
               QStringLiteral("importRuns"));
  QAction* importMcapAction =
      file->addAction(tr("Import &MCAP..."), this, &MainWindow::chooseMcapToImport);
  importMcapAction->setObjectName(QStringLiteral("importMcapAction"));
  file->addAction(tr("Export &Labels..."), labelPanel_, &LabelPanelView::exportLabels);
  QMenu* exportRun = file->addMenu(tr("Export &Run"));
  exportRun->setObjectName(QStringLiteral("exportRunMenu"));
  QAction* exportMcap = exportRun->addAction(tr("&MCAP..."), this, &MainWindow::chooseMcapExport);
  exportMcap->setObjectName(QStringLiteral("exportMcapAction"));
  file->addSeparator();
  bindShortcut(file->addAction(tr("New &Simulation..."), this, [this] { openSimulator(); }),
               QStringLiteral("newSimulation"));
  file->addSeparator();
  QAction* prefs = file->addAction(tr("&Preferences..."), this, &MainWindow::showPreferences);
  prefs->setMenuRole(QAction::PreferencesRole);
  bindShortcut(prefs, QStringLiteral("preferences"));
  file->addSeparator();
  bindShortcut(file->addAction(tr("&Quit"), this, &QWidget::close), QStringLiteral("quit"));
  rebuildRecentMenu();

  // ---- Edit ----
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = labels_->undoStack()->createUndoAction(this, tr("&Undo"));
  bindShortcut(undo, QStringLiteral("undo"));
  QAction* redo = labels_->undoStack()->createRedoAction(this, tr("&Redo"));
  bindShortcut(redo, QStringLiteral("redo"));
  // Undo and redo say what they did (the stack's own action runs first; the command undone is
  // then the one to redo, and the other way round).
  connect(undo, &QAction::triggered, this, [this] {
    if (const QString what = labels_->undoStack()->redoText(); !what.isEmpty())
      showMessage(tr("Undone: %1").arg(what));
  });
  connect(redo, &QAction::triggered, this, [this] {
    if (const QString what = labels_->undoStack()->undoText(); !what.isEmpty())
      showMessage(tr("Redone: %1").arg(what));
  });
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  for (int i = 0; i < kContactClassCount; ++i) {
    const auto cls = static_cast<ContactClass>(i);
    QAction* a = edit->addAction(tr("Label as %1").arg(className(cls)), labelPanel_,
                                 [this, cls] { labelPanel_->applyClass(cls); });
    bindShortcut(a, QStringLiteral("labelAs%1").arg(i + 1));
  }
  bindShortcut(edit->addAction(tr("&Delete Segment"), labelPanel_, &LabelPanelView::deleteAtCursor),
               QStringLiteral("deleteSegment"));
  bindShortcut(edit->addAction(tr("Move Segment Start Left"), this,
                               [this] { labelPanel_->nudgeEdge(false, -1); }),
               QStringLiteral("moveStartLeft"));
  bindShortcut(edit->addAction(tr("Move Segment Start Right"), this,
                               [this] { labelPanel_->nudgeEdge(false, 1); }),
               QStringLiteral("moveStartRight"));
  bindShortcut(edit->addAction(tr("Move Segment End Left"), this,
                               [this] { labelPanel_->nudgeEdge(true, -1); }),
               QStringLiteral("moveEndLeft"));
  bindShortcut(edit->addAction(tr("Move Segment End Right"), this,
                               [this] { labelPanel_->nudgeEdge(true, 1); }),
               QStringLiteral("moveEndRight"));
  bindShortcut(edit->addAction(tr("Clear Selection"), session_, &RunSession::clearSelection),
               QStringLiteral("clearSelection"));

  // ---- Go: stepping is exact, one key press is one step whatever the run's length ----
  QMenu* go = menuBar()->addMenu(tr("&Go"));
  struct StepKey {
    QString text;
    QString id;
    std::int64_t delta;
  };
  const StepKey stepKeys[] = {
      {tr("Next Step"), QStringLiteral("nextStep"), 1},
      {tr("Previous Step"), QStringLiteral("previousStep"), -1},
      {tr("Forward 10 Steps"), QStringLiteral("forward10"), 10},
      {tr("Back 10 Steps"), QStringLiteral("back10"), -10},
      {tr("Forward 100 Steps"), QStringLiteral("forward100"), 100},
      {tr("Back 100 Steps"), QStringLiteral("back100"), -100},
  };
  for (const StepKey& k : stepKeys)
    bindShortcut(go->addAction(k.text, this, [this, d = k.delta] { stepBy(d); }), k.id);
  bindShortcut(go->addAction(tr("Forward One Screen"), this, [this] { stepByScreen(1); }),
               QStringLiteral("forwardScreen"));
  bindShortcut(go->addAction(tr("Back One Screen"), this, [this] { stepByScreen(-1); }),
               QStringLiteral("backScreen"));
  bindShortcut(go->addAction(tr("First Step"), this, [this] { session_->setCurrentStep(0); }),
               QStringLiteral("firstStep"));
  bindShortcut(go->addAction(tr("Last Step"), this,
                             [this] { session_->setCurrentStep(session_->stepCount()); }),
               QStringLiteral("lastStep"));
  bindShortcut(go->addAction(tr("Play / Pause"), steps_, &StepControlsView::togglePlaying),
               QStringLiteral("playPause"));

  // ---- View ----
  viewMenu_ = menuBar()->addMenu(tr("&View"));
  for (QDockWidget* d : findChildren<QDockWidget*>())
    viewMenu_->addAction(d->toggleViewAction());
  viewMenu_->addSeparator();
  bindShortcut(viewMenu_->addAction(tr("Robot Close-up / Whole Scene"), this,
                                    [this] { route_->setWholeScene(!route_->wholeScene()); }),
               QStringLiteral("closeUp"));
  QAction* byLabel = viewMenu_->addAction(tr("Colour Route by Label"));
  byLabel->setCheckable(true);
  connect(byLabel, &QAction::toggled, this, [this](bool on) {
    route_->setColourMode(on ? RouteView::ColourMode::Label : RouteView::ColourMode::Time);
  });
  connect(route_, &RouteView::viewSettingsChanged, this, [this, byLabel] {
    byLabel->setChecked(route_->colourMode() == RouteView::ColourMode::Label);
  });
  viewMenu_->addSeparator();
  auto* channels = new QActionGroup(this);
  const std::pair<QString, TimelineView::Channel> channelItems[] = {
      {tr("Heatmap: Normal"), TimelineView::Channel::Normal},
      {tr("Heatmap: Shear"), TimelineView::Channel::Shear},
      {tr("Heatmap: Magnitude"), TimelineView::Channel::Magnitude},
  };
  for (const auto& [text, channel] : channelItems) {
    QAction* a =
        viewMenu_->addAction(text, this, [this, c = channel] { timeline_->setChannel(c); });
    a->setCheckable(true);
    a->setChecked(timeline_->channel() == channel);
    channels->addAction(a);
  }
  bindShortcut(
      viewMenu_->addAction(tr("Zoom to Whole Run"), timeline_, &TimelineView::showWholeRun),
      QStringLiteral("zoomWholeRun"));

  // ---- Learn ----
  QMenu* learn = menuBar()->addMenu(tr("&Learn"));
  bindShortcut(learn->addAction(tr("&Train and Sweep..."), this, &MainWindow::showTrainingDialog),
               QStringLiteral("trainAndSweep"));
  learn->addAction(tr("Open &Sweep Results..."), this, &MainWindow::chooseSweep);
  learn->addSeparator();
  bindShortcut(
      learn->addAction(tr("Show &Predictions..."), this, &MainWindow::choosePredictionModels),
      QStringLiteral("showPredictions"));
  learn->addAction(tr("&Hide Predictions"), this, [this] { predictions_->clear(); });
  bindShortcut(
      learn->addAction(tr("&Next Disagreement"), this, [this] { jumpToDisagreement(true); }),
      QStringLiteral("nextDisagreement"));
  bindShortcut(
      learn->addAction(tr("Pre&vious Disagreement"), this, [this] { jumpToDisagreement(false); }),
      QStringLiteral("previousDisagreement"));
  bindShortcut(learn->addAction(tr("Next &Doubt"), this, &MainWindow::jumpToDoubt),
               QStringLiteral("nextDoubt"));
  bindShortcut(learn->addAction(tr("&Label from Model"), this, &MainWindow::labelFromModel),
               QStringLiteral("labelFromModel"));
  learn->addSeparator();
  learn->addAction(tr("&Export Model..."), this, &MainWindow::chooseModelToExport);
  learn->addAction(tr("&Import Model..."), this, &MainWindow::chooseModelToImport);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  bindShortcut(help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showKeyboardShortcuts),
               QStringLiteral("keyboardShortcuts"));
  help->addAction(tr("&User Guide"), this, &MainWindow::showUserGuide);
  help->addSeparator();
  help->addAction(tr("&About Tactile Workbench"), this, &MainWindow::showAbout);
}

Status MainWindow::openDatabase(const QString& path, bool create) {
  storage::OpenOptions options;
  options.mode = create ? storage::OpenMode::Create : storage::OpenMode::ReadWrite;
  // The views read a run's track once and then small windows and summaries; a large page cache or
  // a memory-mapped file would only hold the whole steps table after the first open (hundreds of
  // MB of resident memory on a long run).
  options.cacheKiB = kPageCacheKiB;
  options.mmapBytes = 0;
  auto opened = workspace::Workspace::open(path.toStdString(), options);
  if (!opened) return opened.error();
  saveSettings();  // the old database's last run and step
  // Until the new database's run and set are restored, what the models pass through on the way
  // (no set, step 0) must not overwrite what is remembered.
  switching_ = true;
  // The learning windows work on the old database's connection.
  delete training_;
  training_ = nullptr;
  delete results_;
  results_ = nullptr;
  predictions_->waitForFinished();
  predictions_->clear();  // the models chosen belong to the old database
  session_->setWorkspace(nullptr);
  labels_->setWorkspace(nullptr);
  workspace_ = std::move(opened.value());
  dbPath_ =
      storage::isServerAddress(path.toStdString()) ? path : QFileInfo(path).absoluteFilePath();
  reconnectTimer_->stop();
  session_->setWorkspace(workspace_.get());
  labels_->setWorkspace(workspace_.get());
  rememberDatabase(dbPath_);

  QSettings settings;
  settings.beginGroup(QStringLiteral("databases/") + QString(dbPath_).replace('/', '|'));
  const QString lastSet = settings.value(keys::kLastLabelSet).toString();
  const QString lastRun = settings.value(keys::kLastRun).toString();
  const qint64 lastStep = settings.value(QStringLiteral("lastStep"), 0).toLongLong();
  settings.endGroup();

  if (!lastSet.isEmpty() && labels_->openSet(lastSet.toStdString()).ok()) {
  } else if (auto sets = workspace_->labelStore().list(); sets && !sets->empty()) {
    (void)labels_->openSet(sets->front().name);
  }
  Status listed = runModel_->reload(workspace_.get(), labels_->setId());
  if (!listed) showError(QString::fromStdString(listed.errorText()));
  if (!lastRun.isEmpty() && openRun(lastRun).ok()) {
    session_->setCurrentStep(lastStep);
  } else if (runModel_->rowCount() > 0) {
    (void)openRun(QString::fromStdString(runModel_->run(0).name));
  }
  switching_ = false;
  saveSettings();
  updateTitle();
  applyRights();
  showMessage(tr("Opened %1").arg(dbPath_));
  return Status::success();
}

Status MainWindow::openRun(const QString& name) {
  Status s = session_->open(name.toStdString());
  if (!s) return s;
  labels_->setRun(session_->info().id, session_->info().name, session_->stepCount());
  runList_->selectRun(session_->info().name);
  // The chosen models follow the user from run to run.
  if (predictionsWanted()) predictions_->compute(dbPath_, name, predictions_->models());
  timeline_->showWholeRun();
  lastError_.clear();
  // Remembered at once, so a crash or a killed session still comes back to this run.
  saveSettings();
  return Status::success();
}

void MainWindow::importRuns(const QStringList& files) {
  if (!workspace_) return showError(tr("Open or create a database before importing runs."));
  if (files.isEmpty()) return;
  auto* bridge = new ProgressBridge(this);
  // The range is set by the first progress report: folders are expanded on the worker thread.
  auto* dialog = new QProgressDialog(tr("Importing runs..."), tr("Cancel"), 0, 0, this);
  dialog->setObjectName(QStringLiteral("importProgress"));
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(0);
  dialog->setValue(0);
  connect(bridge, &ProgressBridge::progressed, dialog, [dialog](qint64 done, qint64 total) {
    if (total > 0 && dialog->maximum() != total) {
      dialog->setMaximum(static_cast<int>(total));
      dialog->setLabelText(tr("Importing %n run file(s)...", nullptr, static_cast<int>(total)));
    }
    dialog->setValue(static_cast<int>(done));
  });
  connect(dialog, &QProgressDialog::canceled, bridge, &ProgressBridge::cancel);
  auto* watcher = new QFutureWatcher<ImportSummary>(this);
  connect(watcher, &QFutureWatcher<ImportSummary>::finished, this, [this, watcher, bridge, dialog] {
    const ImportSummary result = watcher->result();
    dialog->reset();
    dialog->deleteLater();
    watcher->deleteLater();
    bridge->deleteLater();
    if (!result.error.isEmpty()) return showError(result.error);
    Status listed = runModel_->reload(workspace_.get(), labels_->setId());
    if (!listed) showError(QString::fromStdString(listed.errorText()));
    QString text = tr("Imported %n run(s)", nullptr, result.imported());
    if (bridge->cancelled()) text += tr("; cancelled");
    QStringList problems = result.problems();
    problems << result.warnings;
    if (!problems.isEmpty()) {
      showError(text +
                tr("; %n file(s) not imported: ", nullptr, static_cast<int>(problems.size())) +
                problems.join(QStringLiteral("; ")));
    } else {
      showMessage(text);
    }
  });
  watcher->setFuture(startImport(dbPath_, files, bridge));
}

void MainWindow::stepBy(std::int64_t delta) {
  session_->setCurrentStep(session_->currentStep() + delta);
}

void MainWindow::stepByScreen(int direction) {
  const StepRange visible = timeline_->visibleRange();
  const std::int64_t page = std::max<std::int64_t>(1, visible.size());
  timeline_->setVisibleRange({visible.first + direction * page, visible.last + direction * page});
  session_->setCurrentStep(session_->currentStep() + direction * page);
}

void MainWindow::chooseDatabase(bool create) {
  const QString path =
      create ? QFileDialog::getSaveFileName(this, tr("New database"),
                                            startPath(QStringLiteral("databases")),
                                            tr("Tactile databases (*.db);;All files (*)"))
             : QFileDialog::getOpenFileName(this, tr("Open database"),
                                            startPath(QStringLiteral("databases")),
                                            tr("Tactile databases (*.db *.sqlite);;All files (*)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("databases"), path);
  Status s = openDatabase(path, create);
  if (!s) showOpenError(QString::fromStdString(s.errorText()));
}

namespace {

// An address as the workbench may keep it: without a password (one in the address is moved to
// the process's PGPASSWORD, which libpq reads and nothing saves).
QString addressWithoutPassword(const QString& address) {
  const std::string shown = storage::shownAddress(address.toStdString());
  if (shown.find("***") == std::string::npos) return address;
  QString plain = QString::fromStdString(shown);
  // The password itself, for PGPASSWORD: what "***" stands for.
  const qsizetype at = plain.indexOf(QStringLiteral("***"));
  const QString after = plain.mid(at + 3);
  const qsizetype end = address.size() - after.size();
  qputenv("PGPASSWORD", address.mid(at, end - at).toUtf8());
  plain.remove(QRegularExpression(QStringLiteral(":\\*\\*\\*(?=@)")));
  plain.remove(QRegularExpression(QStringLiteral("[?&]?password=\\*\\*\\*")));
  plain.remove(QRegularExpression(QStringLiteral("\\bpassword=\\*\\*\\* ?")));
  return plain;
}

bool needsPassword(const QString& error) {
  return error.contains(QStringLiteral("no password supplied")) ||
         error.contains(QStringLiteral("password authentication failed"));
}

}  // namespace

void MainWindow::chooseServer() {
  QSettings settings;
  const QStringList recent = settings.value(keys::kRecentServers).toStringList();
  bool ok = false;
  const QString given = QInputDialog::getItem(
      this, tr("Open Server"),
      tr("PostgreSQL address, e.g. postgresql://anna@lab-server/tactile\n(the password is asked "
         "when the server wants one, or comes from ~/.pgpass)"),
      recent, 0, true, &ok);
  if (!ok || given.trimmed().isEmpty()) return;
  const QString address = addressWithoutPassword(given.trimmed());
  if (!storage::isServerAddress(address.toStdString())) {
    showOpenError(tr("%1 is not a server address (postgresql://USER@HOST/DATABASE)").arg(address));
    return;
  }
  Status s = openDatabase(address);
  if (!s && needsPassword(QString::fromStdString(s.errorText()))) {
    const QString password =
        QInputDialog::getText(this, tr("Password"), tr("Password for %1:").arg(address),
                              QLineEdit::Password, QString(), &ok);
    if (!ok) return;
    qputenv("PGPASSWORD", password.toUtf8());  // this process only; never saved
    s = openDatabase(address);
  }
  if (!s) {
    showOpenError(QString::fromStdString(s.errorText()));
    return;
  }
  QStringList servers = recent;
  servers.removeAll(address);
  servers.prepend(address);
  while (servers.size() > keys::kMaxRecentDatabases)
    servers.removeLast();
  settings.setValue(keys::kRecentServers, servers);
}

void MainWindow::changeAssignment(const QString& run, const QString& action) {
  if (!workspace_) return;
  const std::string me = labels_->annotator();
  std::string who = me;
  storage::AssignmentState state = storage::AssignmentState::Todo;
  if (action == QStringLiteral("assign")) {
    bool ok = false;
    who = QInputDialog::getText(this, tr("Assign Run"), tr("Annotator to assign %1 to:").arg(run),
                                QLineEdit::Normal, QString(), &ok)
              .trimmed()
              .toStdString();
    if (!ok || who.empty()) return;
  } else {
    if (me.empty()) {
      showError(tr("Set your annotator name in Preferences first."));
      return;
    }
    state = *storage::parseAssignmentState(action.toStdString());
  }
  const std::string set = labels_->hasSet() ? labels_->setName() : std::string();
  const Status s =
      workspace_->labelStore().assign({run.toStdString()}, std::nullopt, who,
                                      action == QStringLiteral("assign") ? set : "", state, me);
  if (!s) {
    showError(QString::fromStdString(s.errorText()));
    return;
  }
  (void)runModel_->reloadAssignments(workspace_.get());
  showMessage(tr("%1 assigned to %2: %3")
                  .arg(run, QString::fromStdString(who), RunListModel::stateText(state)));
}

void MainWindow::applyRights() {
  const storage::RunDatabase::Rights rights =
      workspace_ ? workspace_->rights() : storage::RunDatabase::Rights{};
  // The server refuses what a role may not do; these only spare the user the attempt.
  for (const char* name : {"importRuns", "importMcapAction", "newSimulation"}) {
    if (auto* action = findChild<QAction*>(QLatin1String(name))) {
      action->setEnabled(rights.manageRuns);
    }
  }
  for (const char* name : {"trainAndSweep"}) {
    if (auto* action = findChild<QAction*>(QLatin1String(name))) {
      action->setEnabled(rights.keepModels);
    }
  }
  labelPanel_->setEnabled(rights.editLabels);
  if (workspace_ && (!rights.manageRuns || !rights.keepModels || !rights.editLabels)) {
    showMessage(tr("Your role on this database: %1")
                    .arg(rights.manageRuns   ? tr("admin")
                         : rights.keepModels ? tr("researcher")
                         : rights.editLabels ? tr("annotator")
                                             : tr("read only")));
  }
}

void MainWindow::jumpToDoubt() {
  if (!predictions_->hasPredictions())
    return showError(tr("No predictions shown: Learn > Show Predictions"));
  const double threshold =
      QSettings().value(keys::kDoubtThreshold, keys::kDefaultDoubtThreshold).toDouble();
  const std::optional<std::int64_t> at =
      predictions_->nextDoubt(session_->currentStep(), threshold);
  if (!at) {
    return showMessage(
        tr("The model is at least %1 % sure everywhere").arg(100.0 * threshold, 0, 'f', 0));
  }
  session_->setCurrentStep(*at);
  if (const auto group = predictions_->doubtfulGroup(*at, threshold)) {
    session_->setSelectedGroup(*group);
    const GroupPrediction& p = predictions_->group(*group);
    const auto said = p.classAt(*at);
    const std::string_view name = groupInfo(*group).shortName;
    showMessage(tr("Step %1, group %2: the model is unsure (%3 % %4)")
                    .arg(*at)
                    .arg(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())))
                    .arg(100.0 * p.confidence[static_cast<std::size_t>(*at)], 0, 'f', 0)
                    .arg(said ? className(*said) : QString()));
  }
  const StepRange visible = timeline_->visibleRange();
  if (*at < visible.first || *at > visible.last) {
    const std::int64_t half = std::max<std::int64_t>(1, visible.size() / 2);
    timeline_->setVisibleRange({*at - half, *at + half});
  }
}

void MainWindow::labelFromModel() {
  if (!session_->isOpen() || !labels_->hasSet()) {
    showError(tr("Open a run and a label set first."));
    return;
  }
  if (!predictions_->hasPredictions()) {
    showError(
        tr("Show a model's predictions first (Learn > Show Predictions): their model's "
           "decisions are what Label from Model writes."));
    return;
  }
  std::array<std::string, kGroupCount> models;
  for (std::size_t g = 0; g < models.size(); ++g)
    models[g] = predictions_->models()[g].toStdString();
  // The selection, else the steps in view.
  std::int64_t first = timeline_->visibleRange().first;
  std::int64_t last = timeline_->visibleRange().last;
  if (const auto sel = session_->selection()) {
    first = sel->first;
    last = sel->last;
  }
  const std::vector<SensorGroup> groups = labelPanel_->groupsFor(first, last);
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const Status s = labels_->labelFromModels(models, groups, first, last);
  QApplication::restoreOverrideCursor();
  if (!s) {
    showError(QString::fromStdString(s.errorText()));
    return;
  }
  showMessage(tr("Steps %1-%2 labelled from the model (Undo takes it back)").arg(first).arg(last));
}

void MainWindow::serverLost(const QString& message) {
  // What to expect first: the server's own words are long and the status bar cuts them.
  showError(tr("Lost the connection to the database; trying again every 3 seconds, and edits are "
               "not stored meanwhile (%1)")
                .arg(message));
  reconnectTimer_->start();
}

void MainWindow::chooseRunFiles() {
  const QStringList files =
      QFileDialog::getOpenFileNames(this, tr("Import runs"), startPath(QStringLiteral("runs")),
                                    tr("Run files (*.csv);;All files (*)"));
  if (!files.isEmpty()) rememberPath(QStringLiteral("runs"), files.front());
  importRuns(files);
}

namespace {

QStringList localPaths(const QMimeData* mime) {
  QStringList paths;
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile()) paths << url.toLocalFile();
  return paths;
}

}  // namespace

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const DroppedPaths dropped = sortDroppedPaths(localPaths(event->mimeData()));
  if (!dropped.databases.isEmpty() || !dropped.runInputs.isEmpty() || !dropped.mcapFiles.isEmpty())
    event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const DroppedPaths dropped = sortDroppedPaths(localPaths(event->mimeData()));
  if (!dropped.mcapFiles.isEmpty()) {
    event->acceptProposedAction();
    if (dropped.mcapFiles.size() > 1 || !dropped.databases.isEmpty() ||
        !dropped.runInputs.isEmpty()) {
      return showError(tr("Drop one MCAP file at a time, on its own."));
    }
    return importMcapFile(dropped.mcapFiles.front());
  }
  if (dropped.databases.isEmpty() && dropped.runInputs.isEmpty()) {
    if (!dropped.ignored.isEmpty())
      showError(tr("Not a run file, folder or database: %1").arg(dropped.ignored.join(", ")));
    return;
  }
  event->acceptProposedAction();
  // A database dropped with run files opens first; the runs go into it.
  if (dropped.databases.size() > 1)
    return showError(tr("Drop one database at a time (%n dropped).", nullptr,
                        static_cast<int>(dropped.databases.size())));
  if (!dropped.databases.isEmpty()) {
    Status s = openDatabase(dropped.databases.front());
    if (!s) return showOpenError(QString::fromStdString(s.errorText()));
  }
  if (!dropped.runInputs.isEmpty()) importRuns(dropped.runInputs);
}

// ---- MCAP ------------------------------------------------------------------------------------

void MainWindow::showMcapError(const QString& title, const QString& message) {
  showError(message);
  auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("mcapError"));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

void MainWindow::chooseMcapExport() {
  if (!workspace_ || !session_->isOpen()) return showError(tr("Open a run first"));
  QStringList sets;
  if (auto catalog = workspace_->labelSets()) {
    for (const storage::LabelSetCatalogEntry& e : catalog.value())
      sets << QString::fromStdString(e.set.name);
  }
  QStringList models;
  if (auto stored = workspace_->models()) {
    for (const storage::ModelInfo& m : stored.value())
      models << QString::fromStdString(m.name);
  }
  const QString run = QString::fromStdString(session_->info().name);
  const QString folder = QFileInfo(dbPath_).absolutePath();
  const QStringList checked{QString::fromStdString(labels_->setName())};
  McapExportDialog dialog(run, sets, checked, models, folder + QLatin1Char('/') + run + ".mcap",
                          this);
  if (dialog.exec() != QDialog::Accepted) return;
  exportRunMcap(dialog.path(), dialog.labelSets(), dialog.model());
}

void MainWindow::exportRunMcap(const QString& path, const QStringList& labelSets,
                               const QString& model) {
  if (!workspace_ || !session_->isOpen()) return showError(tr("Open a run first"));
  if (mcapBusy_) return showError(tr("An MCAP export or import is already running"));
  workspace::McapExportRequest request;
  request.run = session_->info().name;
  for (const QString& set : labelSets)
    request.labelSets.push_back(set.toStdString());
  request.model = model.toStdString();
  request.out = path.toStdString();
  const std::int64_t steps = session_->stepCount();
  auto* bridge = new ProgressBridge(this);
  request.progress = bridge->callback();
  auto* dialog =
      new QProgressDialog(tr("Exporting '%1' to %2...")
                              .arg(QString::fromStdString(request.run), QFileInfo(path).fileName()),
                          tr("Cancel"), 0, 1000, this);
  dialog->setObjectName(QStringLiteral("mcapExportProgress"));
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(800);  // a short export shows no dialog
  connect(bridge, &ProgressBridge::progressed, dialog, [dialog](qint64 done, qint64 total) {
    if (total > 0) dialog->setValue(static_cast<int>(1000 * done / total));
  });
  connect(dialog, &QProgressDialog::canceled, bridge, &ProgressBridge::cancel);
  mcapBusy_ = true;
  const QString db = dbPath_;
  auto* watcher = new QFutureWatcher<QString>(this);
  connect(watcher, &QFutureWatcher<QString>::finished, this,
          [this, watcher, bridge, dialog, path, steps] {
            const QString error = watcher->result();
            dialog->reset();
            dialog->deleteLater();
            watcher->deleteLater();
            bridge->deleteLater();
            mcapBusy_ = false;
            if (bridge->cancelled()) return showMessage(tr("MCAP export cancelled"));
            if (!error.isEmpty()) return showMcapError(tr("Export Run as MCAP"), error);
            lastError_.clear();
            showMessage(
                tr("Run written to %1 (%n step(s))", nullptr, static_cast<int>(steps)).arg(path));
          });
  // The worker has its own connection to the database (the window keeps using its own).
  watcher->setFuture(QtConcurrent::run([db, request]() -> QString {
    storage::OpenOptions open;
    open.mode = storage::OpenMode::ReadOnly;
    auto ws = workspace::Workspace::open(db.toStdString(), open);
    if (!ws) return QString::fromStdString(ws.errorText());
    auto report = workspace::exportRunMcap(*ws.value(), request);
    if (!report) return QString::fromStdString(report.errorText());
    return QString();
  }));
}

void MainWindow::chooseMcapToImport() {
  if (!workspace_) return showError(tr("Open or create a database before importing runs."));
  const QString file =
      QFileDialog::getOpenFileName(this, tr("Import MCAP"), startPath(QStringLiteral("mcap")),
                                   tr("MCAP files (*.mcap);;All files (*)"));
  rememberPath(QStringLiteral("mcap"), file);
  if (!file.isEmpty()) importMcapFile(file);
}

void MainWindow::importMcapFile(const QString& path) {
  if (!workspace_) return showError(tr("Open or create a database before importing runs."));
  if (workspace::isRunMcapFile(path.toStdString())) return importMcap(path, {}, {});
  // A bag: its channels as `tactile mcap info` lists them, for the mapping.
  auto scanned = mcap::scanFile(path.toStdString());
  if (!scanned)
    return showMcapError(tr("Import MCAP"), QString::fromStdString(scanned.errorText()));
  auto* dialog = new McapMappingDialog(scanned.value(), path, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this,
          [this, dialog, path] { importMcap(path, dialog->mappingJson(), dialog->runName()); });
  dialog->open();
}

void MainWindow::importMcap(const QString& path, const std::string& mappingJson,
                            const QString& name) {
  if (!workspace_) return showError(tr("Open or create a database before importing runs."));
  if (mcapBusy_) return showError(tr("An MCAP export or import is already running"));
  workspace::McapImportRequest request;
  request.file = path.toStdString();
  if (!mappingJson.empty()) request.mappingText = mappingJson;
  request.name = name.toStdString();
  request.sceneResolver = sim::proceduralSceneJson;
  auto* dialog = new QProgressDialog(tr("Importing %1...").arg(QFileInfo(path).fileName()),
                                     QString(), 0, 0, this);
  dialog->setObjectName(QStringLiteral("mcapImportProgress"));
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(800);
  mcapBusy_ = true;
  const QString db = dbPath_;
  auto* watcher = new QFutureWatcher<storage::ImportOutcome>(this);
  connect(
      watcher, &QFutureWatcher<storage::ImportOutcome>::finished, this, [this, watcher, dialog] {
        const storage::ImportOutcome outcome = watcher->result();
        dialog->reset();
        dialog->deleteLater();
        watcher->deleteLater();
        mcapBusy_ = false;
        if (outcome.status == storage::ImportStatus::Failed)
          return showMcapError(tr("Import MCAP"), QString::fromStdString(outcome.message));
        Status listed = runModel_->reload(workspace_.get(), labels_->setId());
        if (!listed) showError(QString::fromStdString(listed.errorText()));
        lastError_.clear();
        if (outcome.status == storage::ImportStatus::Skipped)
          return showMessage(QString::fromStdString(outcome.message));
        showMessage(tr("Imported run '%1' (%n step(s))", nullptr, static_cast<int>(outcome.steps))
                        .arg(QString::fromStdString(outcome.runName)));
      });
  watcher->setFuture(QtConcurrent::run([db, request]() {
    storage::OpenOptions open;
    open.mode = storage::OpenMode::ReadWrite;
    auto database = storage::RunDatabase::open(db.toStdString(), open);
    if (!database) {
      storage::ImportOutcome failed;
      failed.status = storage::ImportStatus::Failed;
      failed.message = database.errorText();
      return failed;
    }
    return workspace::importMcap(database.value()->runs(), request);
  }));
}

void MainWindow::showOpenError(const QString& message) {
  showError(message);
  auto* box =
      new QMessageBox(QMessageBox::Warning, tr("Open database"), message, QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("openError"));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

void MainWindow::showError(const QString& message) {
  lastError_ = message;
  statusBar()->showMessage(tr("Error: %1").arg(message), 15000);
}

void MainWindow::showMessage(const QString& message) {
  statusBar()->showMessage(message, 8000);
}

void MainWindow::updateTitle() {
  QString title = tr("Tactile Workbench");
  if (!dbPath_.isEmpty()) {
    const bool server = storage::isServerAddress(dbPath_.toStdString());
    title = (server ? dbPath_ : QFileInfo(dbPath_).fileName()) + QStringLiteral(" - ") + title;
  }
  if (session_->isOpen())
    title = QString::fromStdString(session_->info().name) + QStringLiteral(" - ") + title;
  setWindowTitle(title);
}

void MainWindow::updateStatus() {
  if (session_->isOpen()) {
    QString text = tr("Step %1 of %2 steps")
                       .arg(QLocale().toString(static_cast<qlonglong>(session_->currentStep())),
                            QLocale().toString(static_cast<qlonglong>(session_->stepCount())));
    if (const auto sel = session_->selection())
      text += tr("  |  selected %1-%2").arg(sel->first).arg(sel->last);
    stepLabel_->setText(text);
  } else {
    stepLabel_->setText(workspace_ ? tr("No run open") : tr("No database open"));
  }
  setLabel_->setText(labels_->hasSet()
                         ? tr("Label set: %1").arg(QString::fromStdString(labels_->setName()))
                         : tr("No label set"));
}

void MainWindow::rememberDatabase(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value(keys::kRecentDatabases).toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > keys::kMaxRecentDatabases)
    recent.removeLast();
  settings.setValue(keys::kRecentDatabases, recent);
  settings.setValue(keys::kLastDatabase, path);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = QSettings().value(keys::kRecentDatabases).toStringList();
  for (const QString& path : recent) {
    recentMenu_->addAction(path, this, [this, path] {
      Status s = openDatabase(path);
      if (!s) showOpenError(QString::fromStdString(s.errorText()));
    });
  }
  recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::showAbout() {
  QMessageBox::about(this, tr("About Tactile Workbench"),
                     tr("Tactile Workbench %1\nResearch workbench for tactile-based mobile-robot "
                        "navigation.")
                         .arg(QApplication::applicationVersion()));
}

void MainWindow::restoreSettings() {
  QSettings settings;
  restoreGeometryWithinScreen(this, settings.value(keys::kGeometry).toByteArray());
  restoreState(settings.value(keys::kWindowState).toByteArray());
  timeline_->restoreSettings(settings);
  route_->restoreSettings(settings);
  labelPanel_->restoreSettings(settings);
  steps_->setSpeed(settings.value(keys::kPlaySpeed, steps_->speed()).toInt());
  runList_->setFilterText(settings.value(keys::kRunFilter).toString());
}

void MainWindow::saveSettings() const {
  QSettings settings;
  settings.setValue(keys::kGeometry, saveGeometry());
  settings.setValue(keys::kWindowState, saveState());
  timeline_->saveSettings(settings);
  route_->saveSettings(settings);
  labelPanel_->saveSettings(settings);
  settings.setValue(keys::kPlaySpeed, steps_->speed());
  settings.setValue(keys::kRunFilter, runList_->filterText());
  if (!dbPath_.isEmpty() && !switching_) {
    settings.beginGroup(QStringLiteral("databases/") + QString(dbPath_).replace('/', '|'));
    settings.setValue(keys::kLastLabelSet, QString::fromStdString(labels_->setName()));
    if (session_->isOpen()) {
      settings.setValue(keys::kLastRun, QString::fromStdString(session_->info().name));
      settings.setValue(QStringLiteral("lastStep"), static_cast<qint64>(session_->currentStep()));
    }
    settings.endGroup();
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  saveSettings();
  if (training_ != nullptr && training_->worker()->isRunning()) {
    const auto answer = QMessageBox::question(this, tr("Quit"),
                                              tr("A sweep or training is running. Cancel it and "
                                                 "quit? Finished sweep cells stay stored."));
    if (answer != QMessageBox::Yes) {
      event->ignore();
      return;
    }
  }
  if (results_ != nullptr) results_->close();
  event->accept();
}

TrainingDialog* MainWindow::trainingDialog() {
  if (!workspace_) return nullptr;
  if (training_ == nullptr) {
    training_ = new TrainingDialog(*workspace_, dbPath_, this);
    for (auto signal : {&TrainingDialog::sweepStored, &TrainingDialog::sweepPlanned}) {
      connect(training_, signal, this, [this](qint64 id) {
        if (Status s = openSweep(id); !s) showError(QString::fromStdString(s.errorText()));
      });
    }
    connect(training_, &TrainingDialog::modelTrained, this,
            [this](const QString& name) { showMessage(tr("Model '%1' stored").arg(name)); });
  }
  return training_;
}

void MainWindow::showTrainingDialog() {
  const bool fresh = training_ == nullptr;
  TrainingDialog* dialog = trainingDialog();
  if (dialog == nullptr) {
    showError(tr("Open a database first"));
    return;
  }
  if (!dialog->worker()->isRunning()) {
    dialog->reload();
    // The labels dock's set is only the first choice: a set chosen in the dialog stays, as its
    // grid does.
    if (fresh && !labels_->setName().empty())
      dialog->setLabelSet(QString::fromStdString(labels_->setName()));
  }
  dialog->show();
  dialog->raise();
  dialog->activateWindow();
}

Status MainWindow::openSweep(qint64 sweepId) {
  if (!workspace_) return Error("no database is open");
  if (results_ == nullptr) {
    results_ = new SweepResultsWindow(*workspace_, dbPath_, this);
    results_->setWindowFlag(Qt::Window);
    connect(results_, &SweepResultsWindow::modelStored, this,
            [this](const QString& name) { showMessage(tr("Model '%1' stored").arg(name)); });
  }
  if (Status s = results_->showSweep(sweepId); !s) return s;
  results_->show();
  results_->raise();
  return Status::success();
}

void MainWindow::chooseSweep() {
  if (!workspace_) return showError(tr("Open a database first"));
  auto sweeps = workspace_->sweeps();
  if (!sweeps) return showError(QString::fromStdString(sweeps.errorText()));
  if (sweeps->empty())
    return showError(tr("The database has no sweep yet: Learn > Train and Sweep"));
  QStringList items;
  for (auto it = sweeps->rbegin(); it != sweeps->rend(); ++it)
    items << tr("%1: %2 (%3 cells, %4)")
                 .arg(it->id)
                 .arg(QString::fromStdString(it->name))
                 .arg(it->cellCount)
                 .arg(QString::fromStdString(it->createdAt));
  bool ok = false;
  const QString item =
      QInputDialog::getItem(this, tr("Open Sweep Results"), tr("Sweep:"), items, 0, false, &ok);
  if (!ok) return;
  const qint64 id = item.section(QLatin1Char(':'), 0, 0).toLongLong();
  if (Status s = openSweep(id); !s) showError(QString::fromStdString(s.errorText()));
}

void MainWindow::chooseModelToExport() {
  if (!workspace_) return showError(tr("Open a database first"));
  auto models = workspace_->models();
  if (!models) return showError(QString::fromStdString(models.errorText()));
  if (models->empty()) return showError(tr("The database has no model yet"));
  QStringList names;
  for (const storage::ModelInfo& m : models.value())
    names << QString::fromStdString(m.name);
  bool ok = false;
  const QString name =
      QInputDialog::getItem(this, tr("Export Model"), tr("Model:"), names, 0, false, &ok);
  if (!ok) return;
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Model"), startPath(QStringLiteral("models"), name + QStringLiteral(".json")),
      tr("Model files (*.json)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("models"), path);
  if (Status s = workspace_->exportModel(name.toStdString(), path.toStdString()); !s)
    return showError(QString::fromStdString(s.errorText()));
  showMessage(tr("Model '%1' written to %2").arg(name, path));
}

bool MainWindow::predictionsWanted() const {
  for (const QString& m : predictions_->models())
    if (!m.isEmpty()) return true;
  return false;
}

Status MainWindow::showPredictions(const QString& model) {
  PredictionModel::Choice choice = PredictionModel::sameForAll(model);
  return showPredictions(choice);
}

Status MainWindow::showPredictions(const PredictionModel::Choice& models) {
  if (!workspace_) return Error("no database is open");
  if (!session_->isOpen()) return Error("no run is open");
  for (const QString& m : models) {
    if (m.isEmpty()) continue;
    if (auto info = workspace_->modelStore().info(m.toStdString()); !info) return info.error();
  }
  predictions_->compute(dbPath_, QString::fromStdString(session_->info().name), models);
  return Status::success();
}

void MainWindow::waitForPredictions() {
  predictions_->waitForFinished();
}

void MainWindow::choosePredictionModels() {
  if (!workspace_ || !session_->isOpen()) return showError(tr("Open a run first"));
  auto models = workspace_->models();
  if (!models) return showError(QString::fromStdString(models.errorText()));
  if (models->empty())
    return showError(tr("The database has no model yet: Learn > Train and Sweep"));
  QStringList names;
  QMap<QString, QStringList> coverage;
  for (const storage::ModelInfo& m : models.value()) {
    const QString name = QString::fromStdString(m.name);
    names << name;
    // The stored metrics hold one entry per group the model covers.
    try {
      const nlohmann::json metrics = nlohmann::json::parse(m.metricsJson);
      for (const GroupInfo& g : kSensorGroups)
        if (metrics.is_object() && metrics.contains(std::string(g.shortName)))
          coverage[name] << QString::fromUtf8(g.shortName.data(),
                                              static_cast<qsizetype>(g.shortName.size()));
    } catch (const nlohmann::json::exception&) {
      // Unreadable metrics: the name alone.
    }
  }
  ModelPickerDialog picker(names, predictions_->models(), this);
  picker.setCoverage(coverage);
  if (picker.exec() != QDialog::Accepted) return;
  if (Status s = showPredictions(picker.choice()); !s)
    showError(QString::fromStdString(s.errorText()));
}

void MainWindow::jumpToDisagreement(bool forward) {
  if (!predictions_->hasPredictions())
    return showError(tr("No predictions shown: Learn > Show Predictions"));
  const std::int64_t from = session_->currentStep();
  const std::optional<std::int64_t> at =
      forward ? predictions_->nextDisagreement(from, std::nullopt)
              : predictions_->previousDisagreement(from, std::nullopt);
  if (!at) return showMessage(tr("The model agrees with the labels everywhere"));
  session_->setCurrentStep(*at);
  // The first group that disagrees there becomes the selected one, and the timeline shows it.
  for (const GroupInfo& g : kSensorGroups) {
    const GroupPrediction& p = predictions_->group(g.group);
    if (*at >= static_cast<std::int64_t>(p.disagrees.size()) ||
        !p.disagrees[static_cast<std::size_t>(*at)])
      continue;
    session_->setSelectedGroup(g.group);
    const auto said = p.classAt(*at);
    const auto label = labels_->classAt(g.group, *at);
    showMessage(
        tr("Step %1, group %2: the model says %3 (%4 %), the label %5")
            .arg(*at)
            .arg(QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size())))
            .arg(said ? className(*said) : QString())
            .arg(100.0 * p.confidence[static_cast<std::size_t>(*at)], 0, 'f', 0)
            .arg(label ? className(*label) : QString()));
    break;
  }
  const StepRange visible = timeline_->visibleRange();
  if (*at < visible.first || *at > visible.last) {
    const std::int64_t half = visible.size() / 2;
    timeline_->setVisibleRange({*at - half, *at - half + visible.size() - 1});
  }
}

void MainWindow::chooseModelToImport() {
  if (!workspace_) return showError(tr("Open a database first"));
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Import Model"), startPath(QStringLiteral("models")), tr("Model files (*.json)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("models"), path);
  bool ok = false;
  const QString name =
      QInputDialog::getText(this, tr("Import Model"), tr("Store as:"), QLineEdit::Normal,
                            QFileInfo(path).completeBaseName(), &ok);
  if (!ok) return;
  auto stored = workspace_->importModel(path.toStdString(), name.trimmed().toStdString());
  if (!stored) return showError(QString::fromStdString(stored.errorText()));
  showMessage(tr("Model '%1' stored from %2").arg(QString::fromStdString(stored.value()), path));
}

}  // namespace tactile::gui

namespace tactile::gui {

SimWindow* MainWindow::openSimulator(const QString& scene) {
  // One simulator window on the open database (or an in-memory one without a database); it
  // has its own connection, so it lives on if this window opens another database.
  auto* window = new SimWindow(dbPath_, this);  // a window of its own, deleted with this one
  window->setAttribute(Qt::WA_DeleteOnClose);
  if (!scene.isEmpty()) window->setScene(scene);
  connect(window, &SimWindow::openRunRequested, this, [this](const QString& name) {
    if (workspace_) (void)runModel_->reload(workspace_.get(), labels_->setId());
    const Status opened = openRun(name);
    if (!opened) showError(QString::fromStdString(opened.errorText()));
    show();
    raise();
    activateWindow();
  });
  window->show();
  return window;
}

}  // namespace tactile::gui
