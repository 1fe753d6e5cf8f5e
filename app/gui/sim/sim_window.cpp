#include "app/gui/sim/sim_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/runs/navigator_track_model.h"
#include "app/gui/runs/navigator_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "app/gui/sim/drive_keys.h"
#include "app/gui/sim/experiment_panel.h"
#include "app/gui/sim/signal_bars_view.h"
#include "app/gui/sim/status_picture_view.h"
#include "nav/navigator.h"
#include "run/builtin_scenes.h"
#include "run/run_csv.h"
#include "sim/simulator.h"
#include "workspace/workspace.h"

namespace tactile::gui {
namespace {

QString outcomeText(RunOutcome outcome) {
  const std::string_view name = runOutcomeName(outcome);
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

}  // namespace

SimWindow::SimWindow(const QString& dbPath, QWidget* parent) : QMainWindow(parent) {
  setObjectName(QStringLiteral("simWindow"));
  setAttribute(Qt::WA_DeleteOnClose, false);
  storage::OpenOptions options;
  options.mmapBytes = 0;
  const std::string path = dbPath.isEmpty() ? std::string(":memory:") : dbPath.toStdString();
  auto opened = workspace::Workspace::open(path, options);
  if (opened) {
    workspace_ = std::move(opened.value());
    dbPath_ = dbPath.isEmpty() ? QString() : QFileInfo(dbPath).absoluteFilePath();
  } else {
    dbStatus_ = opened.error();
  }
  session_ = new SimSession(this);
  session_->setWorkspace(workspace_.get());
  dataSession_ = new RunSession(this);
  dataSession_->setWorkspace(workspace_.get());
  buildUi();
  buildMenus();
  connect(session_, &SimSession::stepped, this, &SimWindow::updateState);
  connect(session_, &SimSession::pausedChanged, this, &SimWindow::updateControls);
  connect(session_, &SimSession::started, this, &SimWindow::updateControls);
  connect(session_, &SimSession::runEnded, this, [this](RunOutcome outcome) {
    updateControls();
    refreshDataPanel();
    showOutcome(outcome);
  });
  connect(session_, &SimSession::errorOccurred, this, &SimWindow::showError);
  dataTimer_ = new QTimer(this);
  dataTimer_->setInterval(250);
  connect(dataTimer_, &QTimer::timeout, this, [this] {
    if (dataPanelShown()) refreshDataPanel();
  });
  dataTimer_->start();
  if (!dbStatus_) showError(QString::fromStdString(dbStatus_.errorText()));
  updateControls();
  updateState();
  resize(1400, 900);
  keepWithinScreen(this);
}

SimWindow::~SimWindow() {
  // The session writes what it holds, and the views let go of the run, before the database
  // connection goes with workspace_.
  dataTimer_->stop();
  delete session_;
  session_ = nullptr;
  delete takeCentralWidget();
  delete dataSession_;
  dataSession_ = nullptr;
}

void SimWindow::buildUi() {
  setWindowTitle(tr("Tactile Simulator"));
  picture_ = new StatusPictureView(session_);
  picture_->setObjectName(QStringLiteral("statusPicture"));
  picture_->installEventFilter(this);
  bars_ = new SignalBarsView(session_);
  bars_->setObjectName(QStringLiteral("signalBars"));

  lightLabel_ = new QLabel;
  lightLabel_->setObjectName(QStringLiteral("collisionLight"));
  lightLabel_->setFixedSize(34, 34);
  commandLabel_ = new QLabel;
  commandLabel_->setObjectName(QStringLiteral("commandLabel"));
  QFont big = commandLabel_->font();
  big.setPointSizeF(big.pointSizeF() * 1.25);
  commandLabel_->setFont(big);
  stateLabel_ = new QLabel;
  stateLabel_->setObjectName(QStringLiteral("stateLabel"));
  stateLabel_->setWordWrap(true);
  stateLabel_->setTextFormat(Qt::PlainText);
  errorLabel_ = new QLabel;
  errorLabel_->setObjectName(QStringLiteral("simError"));
  errorLabel_->setStyleSheet(QStringLiteral("color: #b00000"));
  errorLabel_->setWordWrap(true);
  errorLabel_->hide();
  // How the last run ended, large: reaching the goal is the point of a run.
  outcomeLabel_ = new QLabel;
  outcomeLabel_->setObjectName(QStringLiteral("outcomeLabel"));
  QFont bold = outcomeLabel_->font();
  bold.setPointSizeF(bold.pointSizeF() * 1.5);
  bold.setBold(true);
  outcomeLabel_->setFont(bold);
  outcomeLabel_->setWordWrap(true);
  outcomeLabel_->hide();

  auto* lightRow = new QHBoxLayout;
  lightRow->addWidget(lightLabel_);
  lightRow->addWidget(commandLabel_, 1);

  modeBox_ = new QComboBox;
  modeBox_->setObjectName(QStringLiteral("modeBox"));
  modeBox_->addItem(tr("Practice"), static_cast<int>(SimMode::Practice));
  modeBox_->addItem(tr("Experiment"), static_cast<int>(SimMode::Experiment));
  modeBox_->addItem(tr("Autonomous"), static_cast<int>(SimMode::Autonomous));
  modelBox_ = new QComboBox;
  modelBox_->setObjectName(QStringLiteral("modelBox"));
  modelBox_->setFocusPolicy(Qt::ClickFocus);
  controlBox_ = new QComboBox;
  controlBox_->setObjectName(QStringLiteral("controlBox"));
  controlBox_->setFocusPolicy(Qt::ClickFocus);
  controlBox_->addItem(tr("Plan drive (map of touches)"), true);
  controlBox_->addItem(tr("Thesis strategies (wall following)"), false);
  controlBox_->setToolTip(
      tr("How a navigator with a model drives: by a plan on a map of what it touched (the "
         "default, as tactile navigate), or by the thesis's strategies (tactile navigate "
         "--wall-follow). The Bug2 bumper baseline ignores it."));
  sceneLabel_ = new QLabel;
  subjectEdit_ = new QLineEdit;
  subjectEdit_->setObjectName(QStringLiteral("subjectEdit"));
  subjectEdit_->setPlaceholderText(tr("needed in experiment mode"));
  subjectEdit_->setMaxLength(100);
  // An error about the missing name is stale once a name is typed.
  connect(subjectEdit_, &QLineEdit::textChanged, this, [this](const QString& text) {
    if (!text.trimmed().isEmpty() && errorLabel_->property("aboutSubject").toBool())
      errorLabel_->hide();
  });
  seedBox_ = new QSpinBox;
  seedBox_->setRange(0, 1000000);
  seedBox_->setSpecialValueText(tr("0: the scene's own"));
  seedBox_->setValue(1);
  limitBox_ = new QDoubleSpinBox;
  limitBox_->setRange(10, 7200);
  limitBox_->setDecimals(0);
  limitBox_->setValue(600);
  limitBox_->setSuffix(tr(" s"));
  rateBox_ = new QDoubleSpinBox;
  rateBox_->setObjectName(QStringLiteral("rateBox"));
  rateBox_->setRange(0, 1000);
  rateBox_->setDecimals(0);
  rateBox_->setValue(SimSession::kDefaultStepsPerSecond);
  rateBox_->setSpecialValueText(tr("as fast as possible"));
  rateBox_->setSuffix(tr(" steps/s"));
  for (QWidget* w : {static_cast<QWidget*>(modeBox_), static_cast<QWidget*>(seedBox_),
                     static_cast<QWidget*>(limitBox_), static_cast<QWidget*>(rateBox_)})
    w->setFocusPolicy(Qt::ClickFocus);
  connect(rateBox_, &QDoubleSpinBox::valueChanged, session_, &SimSession::setStepsPerSecond);
  connect(modeBox_, &QComboBox::currentIndexChanged, this, [this] {
    // Models stored since the window opened (e.g. trained in the workbench) come into the list.
    if (mode() == SimMode::Autonomous) reloadModels();
    updateControls();
  });
  connect(modelBox_, &QComboBox::currentIndexChanged, this, [this] { updateControls(); });

  auto* setupBox = new QGroupBox(tr("Run"));
  auto* form = new QFormLayout(setupBox);
  form->addRow(tr("Mode"), modeBox_);
  form->addRow(tr("Scene"), sceneLabel_);
  form->addRow(tr("Subject"), subjectEdit_);
  form->addRow(tr("Seed (start, goal)"), seedBox_);
  seedBox_->setObjectName(QStringLiteral("seedBox"));
  seedBox_->setToolTip(
      tr("Experiment mode: the seed of start and goal. Autonomous mode: the seed "
         "of the start, as in tactile navigate --seeds. 0: the scene's own start and goal "
         "(where the map benchmark starts)."));
  form->addRow(tr("Time limit"), limitBox_);
  form->addRow(tr("Step rate"), rateBox_);
  form->addRow(tr("Navigator model"), modelBox_);
  form->addRow(tr("Navigator drives by"), controlBox_);

  auto button = [](const QString& text, const char* name) {
    auto* b = new QPushButton(text);
    b->setObjectName(QLatin1String(name));
    b->setFocusPolicy(Qt::NoFocus);  // Space drives; it must never press a button
    return b;
  };
  startButton_ = button(tr("Start New Run"), "startButton");
  pauseButton_ = button(tr("Go"), "pauseButton");
  stepButton_ = button(tr("Step"), "stepButton");
  giveUpButton_ = button(tr("Give Up"), "giveUpButton");
  dataButton_ = button(tr("Data >>"), "dataButton");
  dataButton_->setCheckable(true);
  openButton_ = button(tr("Open in Workbench"), "openButton");
  connect(startButton_, &QPushButton::clicked, this, [this] { (void)startRun(); });
  connect(pauseButton_, &QPushButton::clicked, this, &SimWindow::togglePause);
  connect(stepButton_, &QPushButton::clicked, session_, &SimSession::stepOnce);
  connect(giveUpButton_, &QPushButton::clicked, this, &SimWindow::giveUp);
  connect(dataButton_, &QPushButton::toggled, this, &SimWindow::setDataPanelShown);
  connect(openButton_, &QPushButton::clicked, this, [this] {
    if (!session_->runName().isEmpty()) emit openRunRequested(session_->runName());
  });
  auto* buttons = new QGridLayout;
  buttons->addWidget(startButton_, 0, 0, 1, 2);
  buttons->addWidget(pauseButton_, 1, 0);
  buttons->addWidget(stepButton_, 1, 1);
  buttons->addWidget(giveUpButton_, 2, 0, 1, 2);
  buttons->addWidget(dataButton_, 3, 0);
  buttons->addWidget(openButton_, 3, 1);

  // The run's settings and buttons come first: nothing above them changes height, so a click
  // meant for Give Up never lands elsewhere when the state text below grows or shrinks.
  auto* side = new QWidget;
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->addWidget(setupBox);
  sideLayout->addLayout(buttons);
  sideLayout->addWidget(outcomeLabel_);
  sideLayout->addWidget(errorLabel_);
  // Autonomous mode only (it shows with the mode, not with the run's state): what the navigator
  // does, right under the buttons, where the person watching looks.
  experiment_ = new ExperimentPanel(session_);
  experimentBox_ = new QGroupBox(tr("Experiment panel"));
  auto* experimentLayout = new QVBoxLayout(experimentBox_);
  experimentLayout->addWidget(experiment_);
  sideLayout->addWidget(experimentBox_);
  sideLayout->addWidget(new QLabel(tr("Signal per group")));
  sideLayout->addWidget(bars_, 2);
  sideLayout->addLayout(lightRow);
  sideLayout->addWidget(stateLabel_);
  sideLayout->addStretch(1);
  // The column scrolls on a short screen instead of making the window taller than it.
  auto* sideScroll = new QScrollArea;
  sideScroll->setObjectName(QStringLiteral("simSideScroll"));
  sideScroll->setFrameShape(QFrame::NoFrame);
  sideScroll->setWidgetResizable(true);
  sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  sideScroll->setWidget(side);
  sideScroll->setMinimumWidth(460);

  auto* top = new QSplitter(Qt::Horizontal);
  top->addWidget(picture_);
  top->addWidget(sideScroll);
  top->setStretchFactor(0, 3);
  top->setStretchFactor(1, 2);

  timeline_ = new TimelineView(dataSession_, nullptr);
  timeline_->setObjectName(QStringLiteral("simTimeline"));
  dataPanel_ = new QWidget;
  auto* dataLayout = new QVBoxLayout(dataPanel_);
  dataLayout->setContentsMargins(0, 0, 0, 0);
  dataLayout->addWidget(new QLabel(tr("The run so far")));
  dataLayout->addWidget(timeline_, 1);
  // The navigator's strips under the timelines, for autonomous runs (their x_ columns).
  navTrack_ = new NavigatorTrackModel(dataSession_, this);
  navStrips_ = new NavigatorStripView(dataSession_, navTrack_, timeline_, dataPanel_);
  navStrips_->setFixedHeight(navStrips_->sizeHint().height());
  dataLayout->addWidget(navStrips_);
  dataPanel_->hide();

  splitter_ = new QSplitter(Qt::Vertical);
  splitter_->addWidget(top);
  splitter_->addWidget(dataPanel_);
  splitter_->setStretchFactor(0, 3);
  splitter_->setStretchFactor(1, 2);
  setCentralWidget(splitter_);
  sceneLabel_->setText(sceneSpec_);
  reloadModels();
}

namespace {
// The navigator box's entries: a stored model (Qt::UserRole: its name), the simulator's truth or
// the bumper baseline (Qt::UserRole: empty); kSourceRole tells which.
constexpr int kSourceRole = Qt::UserRole + 1;

int findSource(const QComboBox* box, nav::StatusSource source, const QString& model) {
  for (int i = 0; i < box->count(); ++i) {
    if (box->itemData(i, kSourceRole).toInt() == static_cast<int>(source) &&
        box->itemData(i).toString() == model)
      return i;
  }
  return -1;
}
}  // namespace

void SimWindow::reloadModels() {
  const QString current = modelBox_->currentData().toString();
  const nav::StatusSource currentSource = navigatorSource();
  modelBox_->clear();
  const auto add = [this](const QString& text, nav::StatusSource source, const QString& model) {
    modelBox_->addItem(text, model);
    modelBox_->setItemData(modelBox_->count() - 1, static_cast<int>(source), kSourceRole);
  };
  if (workspace_) {
    if (auto models = workspace_->models(); models.ok()) {
      for (const storage::ModelInfo& m : models.value()) {
        const QString name = QString::fromStdString(m.name);
        add(name, nav::StatusSource::Model, name);
      }
    }
  }
  add(tr("Simulator truth (the ceiling, no model)"), nav::StatusSource::Truth, QString());
  add(tr("Bug2 bumper (no model)"), nav::StatusSource::Bumper, QString());
  const int i = findSource(modelBox_, currentSource, current);
  if (i >= 0) modelBox_->setCurrentIndex(i);
}

void SimWindow::setNavigatorModel(const QString& model) {
  setNavigatorSource(model.isEmpty() ? nav::StatusSource::Bumper : nav::StatusSource::Model, model);
}

void SimWindow::setNavigatorSource(nav::StatusSource source, const QString& model) {
  reloadModels();
  const int i =
      findSource(modelBox_, source, source == nav::StatusSource::Model ? model : QString());
  if (i >= 0) modelBox_->setCurrentIndex(i);
}

nav::StatusSource SimWindow::navigatorSource() const {
  if (modelBox_->currentIndex() < 0) return nav::StatusSource::Bumper;
  return static_cast<nav::StatusSource>(modelBox_->currentData(kSourceRole).toInt());
}

QStringList SimWindow::navigatorModels() const {
  QStringList out;
  for (int i = 0; i < modelBox_->count(); ++i) {
    if (modelBox_->itemData(i, kSourceRole).toInt() != static_cast<int>(nav::StatusSource::Truth))
      out << modelBox_->itemData(i).toString();
  }
  return out;
}

Status SimWindow::makeNavigator(SimSetup& setup) {
  nav::NavigatorConfig config;
  const QString model = modelBox_->currentData().toString();
  config.source = navigatorSource();
  if (config.source == nav::StatusSource::Model) {
    if (!workspace_) return Error("no database is open");
    Result<analysis::ModelBundle> bundle = workspace_->loadModel(model.toStdString());
    if (!bundle) return bundle.error();
    config.source = nav::StatusSource::Model;
    config.models = std::make_shared<const analysis::ModelBundle>(std::move(bundle.value()));
    // A model without some groups leaves the navigator blind there: said before the run starts.
    QStringList missing;
    for (const GroupInfo& g : kSensorGroups)
      if (config.models->find(g.group) == nullptr)
        missing << QString::fromUtf8(g.shortName.data(),
                                     static_cast<qsizetype>(g.shortName.size()));
    if (!missing.isEmpty())
      navigatorWarning_ = tr("Model %1 has no model for %2: the navigator reads those groups as no "
                             "contact all run long.")
                              .arg(model, missing.join(QStringLiteral(", ")));
  }
  config.planDrive = controlBox_->currentData().toBool();
  Result<std::unique_ptr<nav::Navigator>> made = nav::Navigator::create(std::move(config));
  if (!made) return made.error();
  setup.driver = std::shared_ptr<sim::Driver>(std::move(made.value()));
  return Status::success();
}

void SimWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QMenu* scenes = file->addMenu(tr("Built-in &Scenes"));
  for (const std::string& name : builtinSceneNames()) {
    const QString spec = QString::fromStdString(name);
    scenes->addAction(spec, this, [this, spec] { setScene(spec); });
  }
  file->addAction(tr("Open Scene &File..."), this, &SimWindow::chooseSceneFile);
  file->addSeparator();
  file->addAction(tr("Open Run in &Workbench"), this, [this] {
    if (!session_->runName().isEmpty()) emit openRunRequested(session_->runName());
  });
  file->addAction(tr("Save Run as &CSV..."), this, &SimWindow::saveRunCsv);
  file->addSeparator();
  file->addAction(tr("&Close"), this, &QWidget::close);

  QMenu* run = menuBar()->addMenu(tr("&Run"));
  run->addAction(tr("Start &New Run"), this, [this] { (void)startRun(); });
  run->addAction(tr("&Go / Pause (P)"), this, &SimWindow::togglePause);
  run->addAction(tr("&Step (N)"), session_, &SimSession::stepOnce);
  run->addAction(tr("&Give Up"), this, &SimWindow::giveUp);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("Robot Close-up / Whole Scene (M)"), this, [this] { picture_->toggle(); });
  view->addAction(tr("&Data Panel"), this, [this] { setDataPanelShown(!dataPanelShown()); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Briefing: Bug1 and Bug2"), this, &SimWindow::showBriefing);
  help->addAction(tr("&Keys"), this, &SimWindow::showKeys);
}

void SimWindow::setMode(SimMode mode) {
  const int i = modeBox_->findData(static_cast<int>(mode));
  if (i >= 0) modeBox_->setCurrentIndex(i);
}

SimMode SimWindow::mode() const {
  return static_cast<SimMode>(modeBox_->currentData().toInt());
}

void SimWindow::setScene(const QString& spec) {
  sceneSpec_ = spec;
  sceneLabel_->setText(spec);
  statusBar()->showMessage(tr("Scene %1: press Start New Run").arg(spec));
}

void SimWindow::setSubject(const QString& subject) {
  subjectEdit_->setText(subject);
}

void SimWindow::setSeed(int seed) {
  seedBox_->setValue(seed);
}

void SimWindow::setTimeLimitSeconds(double seconds) {
  limitBox_->setValue(seconds);
}

void SimWindow::setStepsPerSecond(double rate) {
  rateBox_->setValue(rate);
  session_->setStepsPerSecond(rate);
}

Status SimWindow::startRun() {
  SimSetup setup;
  setup.mode = mode();
  setup.scene = sceneSpec_;
  setup.subject = subjectEdit_->text();
  setup.seed = static_cast<std::uint64_t>(seedBox_->value());
  setup.timeLimitSeconds = limitBox_->value();
  navigatorWarning_.clear();
  if (setup.mode == SimMode::Autonomous) {
    if (Status made = makeNavigator(setup); !made) {
      showError(QString::fromStdString(made.errorText()));
      return made;
    }
  }
  Status started = session_->start(setup);
  if (!started) {
    showError(QString::fromStdString(started.errorText()));
    errorLabel_->setProperty(
        "aboutSubject", setup.mode == SimMode::Experiment && setup.subject.trimmed().isEmpty());
    return started;
  }
  errorLabel_->hide();
  outcomeLabel_->hide();
  if (!navigatorWarning_.isEmpty()) {
    errorLabel_->setText(navigatorWarning_);
    errorLabel_->setProperty("aboutSubject", false);
    errorLabel_->show();
  }
  session_->setStepsPerSecond(rateBox_->value());
  shownSteps_ = 0;
  shownFinished_ = false;
  picture_->setFocus();
  const QString name = session_->runName().isEmpty() ? tr("(not stored)") : session_->runName();
  if (setup.mode == SimMode::Autonomous) {
    // The person watches: the whole scene, the route so far, the experiment panel.
    picture_->setWholeScene(true);
    statusBar()->showMessage(
        tr("Run %1 ready: Play (P) lets the navigator drive, Step (N) takes one step").arg(name));
  } else {
    statusBar()->showMessage(
        tr("Run %1 ready: drive with the arrow keys and W, A, S, D (Help > Keys)").arg(name));
  }
  return Status::success();
}

Status SimWindow::replayCommands(const QString& runFile) {
  RunCsvResult read = readRunCsv(runFile.toStdString());
  if (!read) {
    showError(QString::fromStdString(read.errorText()));
    return read.error();
  }
  Status started = startRun();
  if (!started) return started;
  std::vector<sim::Command> commands;
  commands.reserve(read->stepCount());
  for (std::size_t k = 0; k < read->stepCount(); ++k)
    commands.push_back({read->v[k], read->omega[k]});
  session_->setCommandScript(std::move(commands));
  session_->setPaused(false);
  return Status::success();
}

void SimWindow::giveUp() {
  if (!session_->isStarted() || session_->hasEnded()) return;
  session_->giveUp();
}

void SimWindow::togglePause() {
  session_->setPaused(!session_->isPaused());
}

bool SimWindow::handleKey(int key) {
  const SimKey* k = simKeyFor(key);
  if (k == nullptr) return false;
  if (isDriveAction(k->action)) {
    if (!session_->isStarted() || session_->hasEnded()) return true;
    if (session_->mode() == SimMode::Autonomous) return true;  // the navigator drives
    // The first drive key of a waiting run starts the clock.
    if (session_->isPaused()) session_->setPaused(false);
    session_->setCommand(applyDriveAction(k->action, session_->command()));
    updateState();
    return true;
  }
  switch (k->action) {
    case SimKeyAction::ToggleView:
      if (!picture_->toggle() && !session_->mayShowScene())
        statusBar()->showMessage(tr("The scene stays hidden in experiment mode"), 3000);
      break;
    case SimKeyAction::ToggleTouchMap:
      picture_->setShowTouchMap(!picture_->showTouchMap());
      statusBar()->showMessage(picture_->showTouchMap()
                                   ? tr("The navigator's touch map and plan are drawn (T: off)")
                                   : tr("The navigator's touch map and plan are hidden (T: on)"),
                               3000);
      break;
    case SimKeyAction::TogglePause:
      togglePause();
      break;
    case SimKeyAction::StepOnce:
      if (session_->isPaused()) session_->stepOnce();
      break;
    default:
      break;
  }
  return true;
}

void SimWindow::keyPressEvent(QKeyEvent* event) {
  if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) {
    QMainWindow::keyPressEvent(event);
    return;
  }
  if (!handleKey(event->key())) QMainWindow::keyPressEvent(event);
}

bool SimWindow::eventFilter(QObject* watched, QEvent* event) {
  if (watched == picture_ && event->type() == QEvent::KeyPress) {
    auto* key = static_cast<QKeyEvent*>(event);
    if (!(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) &&
        handleKey(key->key()))
      return true;
  }
  return QMainWindow::eventFilter(watched, event);
}

void SimWindow::closeEvent(QCloseEvent* event) {
  // A run still going when the window closes is kept as given up: the person left it.
  if (session_->isStarted() && !session_->hasEnded() && session_->stepCount() > 0)
    session_->giveUp();
  QMainWindow::closeEvent(event);
}

SimWindow::Light SimWindow::light() const {
  const sim::Simulator* sim = session_->simulator();
  if (sim == nullptr || session_->stepCount() == 0) return Light::Idle;
  return sim->blocked() ? Light::Blocked : Light::Moving;
}

QString SimWindow::commandText() const {
  const sim::Command& c = session_->command();
  return tr("v %1 units/s   \u03c9 %2 rad/s").arg(c.v, 0, 'f', 0).arg(c.omega, 0, 'f', 2);
}

QString SimWindow::stateText() const {
  return stateLabel_->text();
}

void SimWindow::updateState() {
  const Light l = light();
  const QString colour = l == Light::Blocked  ? QStringLiteral("#d62020")
                         : l == Light::Moving ? QStringLiteral("#20a040")
                                              : QStringLiteral("#b0b0b0");
  lightLabel_->setStyleSheet(
      QStringLiteral("background: %1; border-radius: 17px; border: 1px solid #555").arg(colour));
  lightLabel_->setToolTip(l == Light::Blocked  ? tr("Blocked: the last step was stopped")
                          : l == Light::Moving ? tr("Moving freely")
                                               : tr("No step yet"));
  commandLabel_->setText(commandText());
  QString state;
  if (!session_->isStarted()) {
    state = tr("No run yet.");
  } else {
    state = tr("%1 mode, scene %2, step %3 (%4 s)")
                .arg(simModeTitle(session_->mode()), session_->setup().scene)
                .arg(session_->stepCount())
                .arg(session_->elapsedSeconds(), 0, 'f', 1);
    if (const auto left = session_->timeLeftSeconds())
      state += tr(", %1 s left").arg(*left, 0, 'f', 0);
    if (!session_->runName().isEmpty())
      state +=
          tr("\nrun %1, %2 steps stored").arg(session_->runName()).arg(session_->storedSteps());
    else
      state += tr("\nnot stored (no database)");
    if (const auto outcome = session_->outcome())
      state += tr("\noutcome: %1").arg(outcomeText(*outcome));
    else if (session_->isPaused() && session_->mode() == SimMode::Autonomous)
      state += tr("\npaused: Play (P) lets the navigator drive, Step (N) takes one step");
    else if (session_->isPaused())
      state += tr("\npaused: a drive key or Go starts the clock");
  }
  stateLabel_->setText(state);
}

void SimWindow::updateControls() {
  const bool running = session_->isStarted() && !session_->hasEnded();
  pauseButton_->setText(session_->isPaused() ? tr("Go") : tr("Pause"));
  pauseButton_->setEnabled(running);
  stepButton_->setEnabled(running);
  giveUpButton_->setEnabled(running);
  openButton_->setEnabled(!session_->runName().isEmpty() && !dbPath_.isEmpty());
  const bool experiment = mode() == SimMode::Experiment;
  const bool autonomous = mode() == SimMode::Autonomous;
  seedBox_->setEnabled(experiment || autonomous);
  limitBox_->setEnabled(experiment || autonomous);
  modelBox_->setEnabled(autonomous);
  controlBox_->setEnabled(autonomous && navigatorSource() != nav::StatusSource::Bumper);
  experimentBox_->setVisible(autonomous);
  if (session_->mode() == SimMode::Autonomous && session_->isStarted())
    pauseButton_->setText(session_->isPaused() ? tr("Play") : tr("Pause"));
  // The status bar says what is going on now (the ended run's message stays until the next).
  if (running) {
    const QString name = session_->runName().isEmpty() ? tr("(not stored)") : session_->runName();
    if (session_->mode() == SimMode::Autonomous)
      statusBar()->showMessage(
          session_->isPaused()
              ? tr("Run %1 paused: Play (P) lets the navigator drive, Step (N) takes one step")
                    .arg(name)
              : tr("Run %1: the navigator drives; Pause (P) stops it").arg(name));
    else
      statusBar()->showMessage(
          session_->isPaused()
              ? tr("Run %1 ready: drive with the arrow keys and W, A, S, D (Help > Keys)").arg(name)
              : tr("Run %1: driving, the clock runs; Give Up ends the run").arg(name));
  }
  updateState();
}

void SimWindow::showOutcome(RunOutcome outcome) {
  const QString text = outcome == RunOutcome::Success
                           ? tr("Goal reached: run %1 succeeded in %2 s")
                                 .arg(session_->runName())
                                 .arg(session_->elapsedSeconds(), 0, 'f', 1)
                           : tr("Run %1 ended: %2").arg(session_->runName(), outcomeText(outcome));
  outcomeLabel_->setStyleSheet(outcome == RunOutcome::Success ? QStringLiteral("color: #006d2c")
                                                              : QStringLiteral("color: #7a4a00"));
  outcomeLabel_->setText(text);
  outcomeLabel_->show();
  statusBar()->showMessage(text);
}

bool SimWindow::dataPanelShown() const {
  return dataPanel_->isVisibleTo(this);
}

void SimWindow::setDataPanelShown(bool shown) {
  dataPanel_->setVisible(shown);
  if (dataButton_->isChecked() != shown) dataButton_->setChecked(shown);
  dataButton_->setText(shown ? tr("Data <<") : tr("Data >>"));
  if (shown) {
    shownSteps_ = 0;
    refreshDataPanel();
  }
}

void SimWindow::refreshDataPanel() {
  const QString name = session_->runName();
  const std::size_t stored = session_->storedSteps();
  if (name.isEmpty() || stored == 0) return;
  const bool finished = session_->hasEnded();
  if (stored == shownSteps_ && finished == shownFinished_ &&
      dataSession_->info().name == name.toStdString())
    return;
  if (!dataSession_->open(name.toStdString())) return;
  shownSteps_ = stored;
  shownFinished_ = finished;
  timeline_->showWholeRun();
  dataSession_->setCurrentStep(dataSession_->stepCount() - 1);
}

void SimWindow::chooseSceneFile() {
  const QString file =
      QFileDialog::getOpenFileName(this, tr("Open Scene"), startPath(QStringLiteral("scenes")),
                                   tr("Scenes (*.json);;All files (*)"));
  rememberPath(QStringLiteral("scenes"), file);
  if (!file.isEmpty()) setScene(file);
}

void SimWindow::saveRunCsv() {
  const RunData* run = session_->run();
  if (run == nullptr || run->stepCount() == 0) return showError(tr("No steps recorded yet."));
  const QString file = QFileDialog::getSaveFileName(
      this, tr("Save Run"), startPath(QStringLiteral("runs")), tr("Run files (*.csv)"));
  if (file.isEmpty()) return;
  rememberPath(QStringLiteral("runs"), file);
  Status written = writeRunCsv(*run, file.toStdString());
  if (!written) showError(QString::fromStdString(written.errorText()));
}

void SimWindow::showBriefing() {
  QMessageBox box(this);
  box.setObjectName(QStringLiteral("briefing"));
  box.setWindowTitle(tr("Briefing: Bug1 and Bug2"));
  box.setTextFormat(Qt::RichText);
  box.setText(tr(
      "<p>You drive the robot by touch: the close-up shows only the robot, which domes touch "
      "something, where it heads (blue) and where the goal lies (red), with the distance. Two "
      "classic strategies for a point robot that feels its way may help:</p>"
      "<p><b>Bug1</b><br>1. Head for the goal.<br>2. When you hit an obstacle, go all the way "
      "round it, keeping contact, and remember the point where you were closest to the goal."
      "<br>3. Go back to that point, leave the obstacle there and head for the goal again.</p>"
      "<p><b>Bug2</b><br>1. Head for the goal along the straight line from the start to the goal "
      "(the S-G line).<br>2. When an obstacle is in the way, follow its edge until you meet the "
      "S-G line again, closer to the goal than where you hit it.<br>3. Leave the obstacle there "
      "and go on along the line.</p>"
      "<p>The robot is not a point: it is 140 long and 80 wide, it turns about its rear axle, "
      "and it loses contact easily when it follows an edge carelessly.</p>"));
  box.exec();
}

void SimWindow::showKeys() {
  QString text = QStringLiteral("<table>");
  for (const SimKey& k : simKeys()) {
    text += QStringLiteral("<tr><td><b>%1</b>&nbsp;&nbsp;</td><td>%2</td></tr>")
                .arg(QString::fromLatin1(k.keyText), simKeyDescription(k).toHtmlEscaped());
  }
  text += QStringLiteral("</table>");
  QMessageBox box(this);
  box.setObjectName(QStringLiteral("keysHelp"));
  box.setWindowTitle(tr("Simulator Keys"));
  box.setTextFormat(Qt::RichText);
  box.setText(text);
  box.exec();
}

void SimWindow::showError(const QString& message) {
  errorLabel_->setText(message);
  errorLabel_->show();
  statusBar()->showMessage(message, 8000);
}

}  // namespace tactile::gui
