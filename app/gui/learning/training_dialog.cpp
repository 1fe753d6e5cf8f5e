#include "app/gui/learning/training_dialog.h"

#include <QCheckBox>
#include <QClipboard>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableView>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

#include "app/gui/common/duration_text.h"
#include "app/gui/common/settings_keys.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/learning/sweep_cells_model.h"
#include "app/gui/learning/sweep_worker.h"

namespace tactile::gui {

namespace {

constexpr int kTrainColumn = 2;
constexpr int kTestColumn = 3;

Error failure(std::string message) {
  return Error(std::move(message));
}

QString qs(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// "1, 2, 4" or "1 2 4": the items, or what is wrong.
Result<std::vector<double>> parseNumbers(const QString& text, const QString& what) {
  std::vector<double> out;
  const QStringList items =
      text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
  for (const QString& item : items) {
    bool ok = false;
    const double v = item.toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
      return failure(what.toStdString() + ": '" + item.toStdString() + "' is not a number");
    }
    out.push_back(v);
  }
  if (out.empty()) return failure(what.toStdString() + ": give at least one value");
  return out;
}

}  // namespace

TrainingDialog::TrainingDialog(workspace::Workspace& workspace, QString databasePath,
                               QWidget* parent)
    : QDialog(parent), workspace_(workspace), databasePath_(std::move(databasePath)) {
  setWindowTitle(tr("Train and sweep"));
  worker_ = new SweepWorker(this);
  cells_ = new SweepCellsModel(this);
  buildUi();
  connect(worker_, &SweepWorker::progressed, this, &TrainingDialog::onProgress);
  connect(worker_, &SweepWorker::cellFinished, this,
          [this](const analysis::SweepCellResult& cell) { cells_->addCell(cell); });
  connect(worker_, &SweepWorker::finished, this, &TrainingDialog::onFinished);
  reload();
  restoreForm();
}

TrainingDialog::~TrainingDialog() = default;

void TrainingDialog::buildUi() {
  auto* settings = new QWidget;
  form_ = settings;
  auto* form = new QFormLayout(settings);

  labelSet_ = new QComboBox;
  labelSet_->setObjectName(QStringLiteral("labelSet"));
  connect(labelSet_, &QComboBox::currentTextChanged, this, [this] {
    fillRuns();
    refreshRows();
  });
  form->addRow(tr("Label set:"), labelSet_);

  runs_ = new QTableWidget(0, 4);
  runs_->setObjectName(QStringLiteral("runs"));
  runs_->setHorizontalHeaderLabels({tr("Run"), tr("Steps"), tr("Train"), tr("Test")});
  runs_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  runs_->verticalHeader()->hide();
  runs_->setSelectionMode(QAbstractItemView::NoSelection);
  runs_->setMinimumHeight(140);
  // A run is a training run or a test run, never both.
  connect(runs_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (item->checkState() != Qt::Checked) return;
    const int other = item->column() == kTrainColumn ? kTestColumn : kTrainColumn;
    if (item->column() != kTrainColumn && item->column() != kTestColumn) return;
    if (QTableWidgetItem* o = runs_->item(item->row(), other); o && o->checkState() == Qt::Checked)
      o->setCheckState(Qt::Unchecked);
  });
  form->addRow(tr("Runs:"), runs_);

  split_ = new QComboBox;
  split_->setObjectName(QStringLiteral("split"));
  // Each split under the name `tactile train --split` and `tactile sweep --split` give it.
  const auto splitItem = [this](workspace::SplitMode mode, const QString& what) {
    const std::string_view name = workspace::splitModeName(mode);
    split_->addItem(QStringLiteral("%1 - %2").arg(
                        QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())), what),
                    static_cast<int>(mode));
  };
  splitItem(workspace::SplitMode::ByRun, tr("score on the test runs"));
  splitItem(workspace::SplitMode::ByScene,
            tr("leave one scene out: each scene scored by models trained without it"));
  splitItem(workspace::SplitMode::LeaveOneRunOut,
            tr("leave one run out (Train model only; a sweep cannot)"));
  // The default of the command line and of the core's requests.
  split_->setCurrentIndex(split_->findData(static_cast<int>(workspace::TrainRequest{}.split)));
  split_->setToolTip(
      tr("by-run: the runs marked Test are scored (the command line's default); by-scene: each "
         "scene's runs (marked for training) are scored by models trained without that scene, no "
         "test runs; leave-one-run-out: each run scored by a model trained on the others (Train "
         "model only)"));
  form->addRow(tr("Split:"), split_);

  auto* groupRow = new QHBoxLayout;
  for (const GroupInfo& g : kSensorGroups) {
    auto* box = new QCheckBox(qs(g.shortName));
    box->setProperty("key", QStringLiteral("group:") + qs(g.shortName));
    box->setToolTip(qs(g.longName));
    box->setChecked(true);
    groups_.push_back(box);
    groupRow->addWidget(box);
  }
  groupRow->addStretch();
  form->addRow(tr("Groups:"), groupRow);

  auto* methodRow = new QHBoxLayout;
  gaussian_ = new QCheckBox(tr("Gaussian"));
  gmm_ = new QCheckBox(tr("GMM"));
  gmm_->setChecked(true);
  gbt_ = new QCheckBox(tr("Boosted trees"));
  gbt_->setObjectName(QStringLiteral("methodGbt"));
  gbt_->setToolTip(
      tr("Gradient-boosted trees (XGBoost) under the same class chain: the online "
         "and offline decisions use their class posteriors divided by the priors"));
  methodRow->addWidget(gaussian_);
  methodRow->addWidget(gmm_);
  methodRow->addWidget(gbt_);
  methodRow->addStretch();
  form->addRow(tr("Methods:"), methodRow);

  // The trees' own settings, swept like orders and floors (shown when boosted trees are ticked).
  auto treeEdit = [](const QString& name, const QString& text, const QString& tip) {
    auto* e = new QLineEdit(text);
    e->setObjectName(name);
    e->setToolTip(tip);
    e->setMaximumWidth(110);
    return e;
  };
  trees_ = treeEdit(QStringLiteral("trees"), QStringLiteral("100"),
                    tr("Boosting rounds (trees per class), comma-separated"));
  depths_ = treeEdit(QStringLiteral("depths"), QStringLiteral("6"),
                     tr("Largest tree depths, comma-separated"));
  learningRates_ = treeEdit(QStringLiteral("learningRates"), QStringLiteral("0.1"),
                            tr("Learning rates (shrinkage of each round), comma-separated"));
  minChildWeights_ = treeEdit(QStringLiteral("minChildWeights"), QStringLiteral("1"),
                              tr("Least summed weight in a leaf, comma-separated"));
  auto* treeLayout = new QHBoxLayout;
  treeLayout->setContentsMargins(0, 0, 0, 0);
  for (const auto& [label, edit] :
       {std::pair{tr("rounds"), trees_}, std::pair{tr("depth"), depths_},
        std::pair{tr("rate"), learningRates_}, std::pair{tr("min weight"), minChildWeights_}}) {
    treeLayout->addWidget(new QLabel(label));
    treeLayout->addWidget(edit);
  }
  treeLayout->addStretch();
  treeRow_ = new QWidget;
  treeRow_->setLayout(treeLayout);
  form->addRow(tr("Trees:"), treeRow_);
  const auto showTrees = [this, form] { form->setRowVisible(treeRow_, gbt_->isChecked()); };
  connect(gbt_, &QCheckBox::toggled, this, showTrees);
  showTrees();

  orders_ = new QLineEdit(QStringLiteral("1, 2, 4, 8, 16"));
  orders_->setObjectName(QStringLiteral("orders"));
  orders_->setToolTip(tr("Model orders (components per class), comma-separated"));
  form->addRow(tr("Orders:"), orders_);

  auto* formRow = new QHBoxLayout;
  for (analysis::CovarianceForm f : analysis::kAllCovarianceForms) {
    auto* box = new QCheckBox(qs(analysis::covarianceFormName(f)));
    box->setProperty("key", QStringLiteral("form:") + qs(analysis::covarianceFormName(f)));
    box->setChecked(f == analysis::CovarianceForm::NodalDiag ||
                    f == analysis::CovarianceForm::NodalFull);
    forms_.push_back(box);
    formRow->addWidget(box);
  }
  formRow->addStretch();
  form->addRow(tr("Covariance:"), formRow);

  floors_ = new QLineEdit(QStringLiteral("0.01, 0.03, 0.1"));
  floors_->setObjectName(QStringLiteral("floors"));
  floors_->setToolTip(tr("Variance floors, comma-separated"));
  form->addRow(tr("Variance floors:"), floors_);

  // Two columns: the longer kinds' names ("normal+shear+touch+motion+neighbours") four to a row
  // made the settings wider than the dialog, and the runs' Train and Test columns scrolled out of
  // sight.
  auto* featureRow = new QGridLayout;
  constexpr int kFeatureColumns = 2;
  int featureIndex = 0;
  for (analysis::FeatureKind k : analysis::kFeatureKinds) {
    auto* box = new QCheckBox(qs(analysis::featureKindName(k)));
    box->setProperty("key", QStringLiteral("features:") + qs(analysis::featureKindName(k)));
    box->setChecked(k == analysis::FeatureKind::Normal);
    features_.push_back(box);
    featureRow->addWidget(box, featureIndex / kFeatureColumns, featureIndex % kFeatureColumns);
    ++featureIndex;
  }
  featureRow->setColumnStretch(kFeatureColumns, 1);
  form->addRow(tr("Features:"), featureRow);

  seeds_ = new QLineEdit(QStringLiteral("1"));
  seeds_->setObjectName(QStringLiteral("seeds"));
  form->addRow(tr("Seeds:"), seeds_);

  auto* decisionRow = new QHBoxLayout;
  for (analysis::DecisionMode m : analysis::kDecisionModes) {
    auto* box = new QCheckBox(qs(analysis::decisionModeName(m)));
    box->setProperty("key", QStringLiteral("decision:") + qs(analysis::decisionModeName(m)));
    box->setObjectName(QStringLiteral("decision-") + qs(analysis::decisionModeName(m)));
    box->setChecked(m == analysis::DecisionMode::Step);
    decisions_.push_back(box);
    decisionRow->addWidget(box);
  }
  decisionRow->addStretch();
  auto* decisionHelp = new QWidget;
  decisionHelp->setLayout(decisionRow);
  decisionHelp->setToolTip(
      tr("Decision modes: step = each step alone; online = HMM forward filter over the contact "
         "(causal, what a navigator may use); offline = forward-backward over the whole contact. "
         "A sweep scores every ticked mode (cells differing only here share one fit); Train model "
         "always scores all three and its models decide online by default"));
  form->addRow(tr("Decisions:"), decisionHelp);

  name_ = new QLineEdit;
  name_->setPlaceholderText(tr("automatic"));
  form->addRow(tr("Name:"), name_);

  threads_ = new QSpinBox;
  threads_->setObjectName(QStringLiteral("threads"));
  threads_->setRange(0, 256);
  threads_->setSpecialValueText(tr("all cores"));
  form->addRow(tr("Threads:"), threads_);

  groupDefaults_ = new QCheckBox(tr("each group's default settings"));
  groupDefaults_->setObjectName(QStringLiteral("groupDefaults"));
  groupDefaults_->setChecked(true);
  groupDefaults_->setToolTip(
      tr("Train model uses each group's default family with its settings (order, covariance and "
         "floor, or rounds and depth), features and evidence weight, as tactile train does; "
         "unticked, the first value of every list above"));
  form->addRow(tr("Train model with:"), groupDefaults_);

  emissionWeight_ = new QDoubleSpinBox;
  emissionWeight_->setObjectName(QStringLiteral("emissionWeight"));
  emissionWeight_->setRange(0.0, 10.0);
  emissionWeight_->setSingleStep(0.05);
  emissionWeight_->setDecimals(2);
  emissionWeight_->setSpecialValueText(tr("each group's default"));
  emissionWeight_->setToolTip(
      tr("Train model: the weight of each step's evidence in the online and offline decisions "
         "(1 is the plain HMM; smaller lets the class chain outweigh single steps, larger lets "
         "a few steps outweigh the chain), as tactile train --emission-weight. Sweeps always use "
         "each group's default for the method"));
  form->addRow(tr("Evidence weight:"), emissionWeight_);

  plan_ = new QLabel;
  plan_->setObjectName(QStringLiteral("plan"));
  plan_->setWordWrap(true);
  form->addRow(tr("Plan:"), plan_);
  unscorable_ = new QLabel;
  unscorable_->setObjectName(QStringLiteral("unscorable"));
  unscorable_->setWordWrap(true);
  unscorable_->setStyleSheet(QStringLiteral("color: #8a4b00"));
  leaveOut_ = new QPushButton(tr("Leave Them Out"));
  leaveOut_->setObjectName(QStringLiteral("leaveOut"));
  leaveOut_->setToolTip(tr("Untick the groups the test runs cannot score"));
  connect(leaveOut_, &QPushButton::clicked, this, [this] {
    for (SensorGroup group : std::vector<SensorGroup>(unscorableGroups_))
      groups_[static_cast<std::size_t>(groupIndex(group))]->setChecked(false);
  });
  auto* unscorableRow = new QHBoxLayout;
  unscorableRow->addWidget(unscorable_, 1);
  unscorableRow->addWidget(leaveOut_);
  unscorable_->hide();
  leaveOut_->hide();
  form->addRow(QString(), unscorableRow);
  // The plan follows every edit, and an error shown for a bad form goes once it is fixed.
  for (QLineEdit* e : {orders_, floors_, seeds_, trees_, depths_, learningRates_, minChildWeights_})
    connect(e, &QLineEdit::textChanged, this, &TrainingDialog::refreshPlan);
  for (const std::vector<QCheckBox*>* list : {&groups_, &forms_, &features_})
    for (QCheckBox* box : *list)
      connect(box, &QCheckBox::toggled, this, &TrainingDialog::refreshPlan);
  for (QCheckBox* box : {gaussian_, gmm_, gbt_})
    connect(box, &QCheckBox::toggled, this, &TrainingDialog::refreshPlan);
  connect(threads_, &QSpinBox::valueChanged, this, &TrainingDialog::refreshPlan);
  connect(runs_, &QTableWidget::itemChanged, this, &TrainingDialog::refreshRows);
  connect(split_, &QComboBox::currentIndexChanged, this, &TrainingDialog::refreshPlan);

  sweepButton_ = new QPushButton(tr("Run sweep"));
  sweepButton_->setObjectName(QStringLiteral("runSweep"));
  sweepButton_->setDefault(true);
  planButton_ = new QPushButton(tr("Plan for workers"));
  planButton_->setObjectName(QStringLiteral("planForWorkers"));
  planButton_->setToolTip(
      tr("Store the sweep with every cell pending, to be filled by tactile sweep work processes "
         "on any machine that reaches the database, or by a Slurm job array"));
  trainButton_ = new QPushButton(tr("Train model"));
  trainButton_->setObjectName(QStringLiteral("trainModel"));
  trainButton_->setToolTip(tr("Train one model per group and store it in the database"));
  cancelButton_ = new QPushButton(tr("Cancel"));
  cancelButton_->setObjectName(QStringLiteral("cancel"));
  cancelButton_->setEnabled(false);
  auto* close = new QPushButton(tr("Close"));
  connect(sweepButton_, &QPushButton::clicked, this, &TrainingDialog::startSweep);
  connect(planButton_, &QPushButton::clicked, this, &TrainingDialog::planForWorkers);
  connect(trainButton_, &QPushButton::clicked, this, &TrainingDialog::startTrain);
  connect(cancelButton_, &QPushButton::clicked, this, &TrainingDialog::cancel);
  connect(close, &QPushButton::clicked, this, &QDialog::close);

  progress_ = new QProgressBar;
  progress_->setRange(0, 1);
  progress_->setValue(0);
  status_ = new QLabel(tr("Choose the runs and the grid, then run a sweep or train a model."));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  sorted_ = new QSortFilterProxyModel(this);
  sorted_->setSourceModel(cells_);
  sorted_->setSortRole(Qt::UserRole);
  cellsView_ = new QTableView;
  cellsView_->setObjectName(QStringLiteral("cells"));
  cellsView_->setModel(sorted_);
  cellsView_->setSortingEnabled(true);
  cellsView_->sortByColumn(SweepCellsModel::BalancedAccuracy, Qt::DescendingOrder);
  for (const auto& [column, shown] :
       SweepCellsModel::settingsColumns({analysis::ClassifierMethod::Gmm}))
    cellsView_->setColumnHidden(column, !shown);
  cellsView_->setSelectionBehavior(QAbstractItemView::SelectRows);
  cellsView_->verticalHeader()->hide();
  cellsView_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  cellsView_->horizontalHeader()->setStretchLastSection(true);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(sweepButton_);
  buttons->addWidget(planButton_);
  buttons->addWidget(trainButton_);
  buttons->addWidget(cancelButton_);
  buttons->addStretch();
  buttons->addWidget(close);

  auto* results = new QWidget;
  auto* resultsLayout = new QVBoxLayout(results);
  resultsLayout->setContentsMargins(0, 0, 0, 0);
  resultsLayout->addWidget(progress_);
  resultsLayout->addWidget(status_);
  commands_ = new QPlainTextEdit;
  commands_->setObjectName(QStringLiteral("workerCommands"));
  commands_->setReadOnly(true);
  commands_->setLineWrapMode(QPlainTextEdit::NoWrap);
  commands_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  commands_->setFixedHeight(commands_->fontMetrics().lineSpacing() * 5 + 12);
  copyCommands_ = new QPushButton(tr("Copy Commands"));
  copyCommands_->setObjectName(QStringLiteral("copyCommands"));
  connect(copyCommands_, &QPushButton::clicked, this,
          [this] { QGuiApplication::clipboard()->setText(commands_->toPlainText()); });
  auto* commandsRow = new QHBoxLayout;
  commandsRow->addWidget(commands_, 1);
  commandsRow->addWidget(copyCommands_, 0, Qt::AlignTop);
  resultsLayout->addLayout(commandsRow);
  commands_->hide();
  copyCommands_->hide();
  trainResult_ = new QTableWidget(0, 6);
  trainResult_->setObjectName(QStringLiteral("trainResult"));
  trainResult_->setHorizontalHeaderLabels({tr("Group"), tr("Balanced accuracy %"), tr("Accuracy %"),
                                           tr("Training samples"), tr("Test samples"),
                                           tr("Fit s")});
  trainResult_->verticalHeader()->hide();
  trainResult_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  trainResult_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  trainResult_->horizontalHeader()->setStretchLastSection(true);
  resultStack_ = new QStackedWidget;
  resultStack_->addWidget(cellsView_);
  resultStack_->addWidget(trainResult_);
  resultsLayout->addWidget(resultStack_, 1);

  // The results need the room of all eight groups' rows (a header, eight rows, the progress
  // and status lines); the settings scroll in what is left.
  const int rowHeight = trainResult_->verticalHeader()->defaultSectionSize();
  const int resultsHeight = progress_->sizeHint().height() + 2 * status_->sizeHint().height() +
                            trainResult_->horizontalHeader()->sizeHint().height() +
                            (kGroupCount + 1) * rowHeight + 24;
  results->setMinimumHeight(resultsHeight);
  auto* settingsScroll = new QScrollArea;
  settingsScroll->setObjectName(QStringLiteral("settingsScroll"));
  settingsScroll->setFrameShape(QFrame::NoFrame);
  settingsScroll->setWidgetResizable(true);
  settingsScroll->setWidget(settings);
  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(settingsScroll);
  splitter->addWidget(results);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 1);
  splitter->setChildrenCollapsible(false);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(splitter, 1);
  layout->addLayout(buttons);
  resize(900, 900);
  keepWithinScreen(this);
  const int settingsHeight = std::max(150, height() - resultsHeight - 80);
  splitter->setSizes({settingsHeight, resultsHeight});
}

void TrainingDialog::rememberForm() const {
  namespace keys = settings_keys;
  QSettings settings;
  settings.setValue(keys::kTrainingLabelSet, labelSet_->currentText());
  settings.setValue(keys::kTrainingOrders, orders_->text());
  settings.setValue(keys::kTrainingFloors, floors_->text());
  settings.setValue(keys::kTrainingTrees, trees_->text());
  settings.setValue(keys::kTrainingDepths, depths_->text());
  settings.setValue(keys::kTrainingLearningRates, learningRates_->text());
  settings.setValue(keys::kTrainingMinChildWeights, minChildWeights_->text());
  settings.setValue(keys::kTrainingSeeds, seeds_->text());
  settings.setValue(keys::kTrainingSplit, split_->currentData());
  QStringList ticked;
  for (const std::vector<QCheckBox*>* list : {&groups_, &forms_, &features_, &decisions_})
    for (const QCheckBox* box : *list)
      if (box->isChecked()) ticked << box->property("key").toString();
  if (gaussian_->isChecked()) ticked << QStringLiteral("method:gaussian");
  if (gmm_->isChecked()) ticked << QStringLiteral("method:gmm");
  if (gbt_->isChecked()) ticked << QStringLiteral("method:gbt");
  settings.setValue(keys::kTrainingTicked, ticked);
}

void TrainingDialog::restoreForm() {
  namespace keys = settings_keys;
  const QSettings settings;
  if (settings.contains(keys::kTrainingOrders))
    orders_->setText(settings.value(keys::kTrainingOrders).toString());
  if (settings.contains(keys::kTrainingFloors))
    floors_->setText(settings.value(keys::kTrainingFloors).toString());
  if (settings.contains(keys::kTrainingSeeds))
    seeds_->setText(settings.value(keys::kTrainingSeeds).toString());
  for (const auto& [key, edit] :
       {std::pair{keys::kTrainingTrees, trees_}, std::pair{keys::kTrainingDepths, depths_},
        std::pair{keys::kTrainingLearningRates, learningRates_},
        std::pair{keys::kTrainingMinChildWeights, minChildWeights_}}) {
    if (settings.contains(key)) edit->setText(settings.value(key).toString());
  }
  if (settings.contains(keys::kTrainingSplit)) {
    const int i = split_->findData(settings.value(keys::kTrainingSplit));
    if (i >= 0) split_->setCurrentIndex(i);
  }
  if (settings.contains(keys::kTrainingTicked)) {
    const QStringList ticked = settings.value(keys::kTrainingTicked).toStringList();
    for (const std::vector<QCheckBox*>* list : {&groups_, &forms_, &features_, &decisions_})
      for (QCheckBox* box : *list)
        box->setChecked(ticked.contains(box->property("key").toString()));
    gaussian_->setChecked(ticked.contains(QStringLiteral("method:gaussian")));
    gmm_->setChecked(ticked.contains(QStringLiteral("method:gmm")));
    gbt_->setChecked(ticked.contains(QStringLiteral("method:gbt")));
  }
  if (settings.contains(keys::kTrainingLabelSet))
    setLabelSet(settings.value(keys::kTrainingLabelSet).toString());
}

void TrainingDialog::done(int result) {
  rememberForm();
  QDialog::done(result);
}

void TrainingDialog::closeEvent(QCloseEvent* event) {
  rememberForm();
  QDialog::closeEvent(event);
}

void TrainingDialog::reload() {
  const QString current = labelSet_->currentText();
  const QSignalBlocker block(labelSet_);
  labelSet_->clear();
  auto sets = workspace_.labelSets();
  if (sets) {
    for (const storage::LabelSetCatalogEntry& e : sets.value())
      labelSet_->addItem(QString::fromStdString(e.set.name));
  }
  const int keep = labelSet_->findText(current);
  if (keep >= 0) labelSet_->setCurrentIndex(keep);
  fillRuns();
  trainRows_ = {};
  testRows_ = {};
  refreshTiming();
  refreshRows();
}

void TrainingDialog::refreshTiming() {
  // Calibrates the cost model on every stored cell (newest sweeps first, at most 2000 cells): the
  // median of seconds per unit, so that one grid's estimate holds for another's.
  secondsPerUnit_ = -1;
  timedCells_ = 0;
  std::vector<double> rates;
  if (auto sweeps = workspace_.sweeps(); sweeps && !sweeps->empty()) {
    for (auto it = sweeps->rbegin(); it != sweeps->rend() && rates.size() < 2000; ++it) {
      auto stored = workspace_.loadSweep(it->id);
      if (!stored) continue;
      for (const analysis::SweepCellResult& c : stored->cells) {
        const double seconds = c.fitSeconds + c.predictSeconds;
        if (!c.ok || !std::isfinite(seconds) || c.trainRows == 0) continue;
        rates.push_back(seconds / analysis::sweepCellUnits(c.cell, c.trainRows, c.testRows));
      }
    }
  }
  if (!rates.empty()) {
    std::nth_element(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2),
                     rates.end());
    secondsPerUnit_ = rates[rates.size() / 2];
    timedCells_ = static_cast<int>(rates.size());
  }
  refreshPlan();
}

void TrainingDialog::refreshRows() {
  trainRows_ = {};
  testRows_ = {};
  const std::string set = labelSet_->currentText().toStdString();
  if (!set.empty()) {
    if (auto t = workspace_.labelledContactSteps(set, runsWithRole(RunRole::Train)))
      trainRows_ = t.value();
    if (auto t = workspace_.labelledContactSteps(set, runsWithRole(RunRole::Test)))
      testRows_ = t.value();
  }
  refreshPlan();
}

void TrainingDialog::refreshPlan() {
  auto g = grid();
  if (!g) {
    plan_->setText(QStringLiteral("<span style=\"color:#b00020\">%1</span>")
                       .arg(QString::fromStdString(g.errorText()).toHtmlEscaped()));
    return;
  }
  const std::vector<analysis::SweepCell> planned = analysis::expandGrid(g.value());
  const auto cells = static_cast<qint64>(planned.size());
  QString text = tr("%n cell(s)", nullptr, static_cast<int>(cells));
  const bool byRun = static_cast<workspace::SplitMode>(split_->currentData().toInt()) ==
                     workspace::SplitMode::ByRun;
  plannedSeconds_ = -1;
  if (secondsPerUnit_ >= 0) {
    // Each cell's own cost (its group's rows, its order and covariance form), spread over the
    // threads.
    double units = 0;
    for (const analysis::SweepCell& cell : planned) {
      const auto gi = static_cast<std::size_t>(groupIndex(cell.group));
      units += analysis::sweepCellUnits(cell, trainRows_[gi], byRun ? testRows_[gi] : 0);
    }
    const int threads = threads_->value() > 0 ? threads_->value() : QThread::idealThreadCount();
    const double seconds =
        secondsPerUnit_ * units / std::max(1, std::min<int>(threads, static_cast<int>(cells)));
    plannedSeconds_ = seconds;
    text += tr(", about %1 on %n thread(s) (each cell's rows, order and covariance form, timed "
               "by %2 stored cells)",
               nullptr, threads)
                .arg(durationText(seconds))
                .arg(timedCells_);
  } else {
    text +=
        tr("; the time left shows once the first cells finish (no sweep is stored yet to "
           "estimate from)");
  }
  plan_->setText(text);
  // The groups the chosen test runs cannot score: said before the sweep starts.
  unscorableGroups_.clear();
  QStringList none, few;
  if (byRun && !runsWithRole(RunRole::Test).empty()) {
    for (SensorGroup group : g->groups) {
      const std::size_t rows = testRows_[static_cast<std::size_t>(groupIndex(group))];
      if (rows >= analysis::kMinTestSteps) continue;
      unscorableGroups_.push_back(group);
      (rows == 0 ? none : few) << qs(groupInfo(group).shortName);
    }
  }
  QStringList parts;
  if (!none.isEmpty())
    parts << tr("the test runs hold no labelled contact steps of %1")
                 .arg(none.join(QStringLiteral(", ")));
  if (!few.isEmpty())
    parts << tr("too few (under %1) of %2")
                 .arg(analysis::kMinTestSteps)
                 .arg(few.join(QStringLiteral(", ")));
  unscorable_->setText(parts.isEmpty() ? QString()
                                       : tr("Cannot be scored: %1. Their cells would be fitted "
                                            "but read \"no test data\".")
                                             .arg(parts.join(QStringLiteral("; "))));
  unscorable_->setVisible(!parts.isEmpty());
  leaveOut_->setVisible(!parts.isEmpty());
  // A validation error in the status goes once the form is valid again.
  if (statusIsError_ && !worker_->isRunning() && sweepRequest()) {
    statusIsError_ = false;
    status_->setText(tr("Ready."));
  }
}

bool TrainingDialog::formEditable() const {
  return form_->isEnabled();
}

void TrainingDialog::setLabelSet(const QString& name) {
  const int i = labelSet_->findText(name);
  if (i >= 0) labelSet_->setCurrentIndex(i);
}

void TrainingDialog::fillRuns() {
  const QSignalBlocker block(runs_);
  runs_->setRowCount(0);
  auto sets = workspace_.labelSets();
  auto runs = workspace_.runs();
  if (!sets || !runs) return;
  std::vector<std::string> labelled;
  for (const storage::LabelSetCatalogEntry& e : sets.value())
    if (QString::fromStdString(e.set.name) == labelSet_->currentText()) labelled = e.runs;
  // The same default hold-out as `tactile train`: every fourth run by name is a test run.
  const workspace::RunSplit split = workspace::holdOutEveryFourth(labelled);
  for (const storage::RunCatalogEntry& r : runs.value()) {
    if (std::find(labelled.begin(), labelled.end(), r.run.name) == labelled.end()) continue;
    const int row = runs_->rowCount();
    runs_->insertRow(row);
    auto* name = new QTableWidgetItem(QString::fromStdString(r.run.name));
    name->setFlags(Qt::ItemIsEnabled);
    auto* steps = new QTableWidgetItem(QString::number(r.run.stepCount));
    steps->setFlags(Qt::ItemIsEnabled);
    steps->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    const bool test =
        std::find(split.test.begin(), split.test.end(), r.run.name) != split.test.end();
    auto* train = new QTableWidgetItem;
    train->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    train->setCheckState(test ? Qt::Unchecked : Qt::Checked);
    auto* testItem = new QTableWidgetItem;
    testItem->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    testItem->setCheckState(test ? Qt::Checked : Qt::Unchecked);
    runs_->setItem(row, 0, name);
    runs_->setItem(row, 1, steps);
    runs_->setItem(row, kTrainColumn, train);
    runs_->setItem(row, kTestColumn, testItem);
  }
  runs_->resizeColumnToContents(1);
}

void TrainingDialog::setRunRole(const QString& run, RunRole role) {
  for (int row = 0; row < runs_->rowCount(); ++row) {
    if (runs_->item(row, 0)->text() != run) continue;
    runs_->item(row, kTrainColumn)
        ->setCheckState(role == RunRole::Train ? Qt::Checked : Qt::Unchecked);
    runs_->item(row, kTestColumn)
        ->setCheckState(role == RunRole::Test ? Qt::Checked : Qt::Unchecked);
  }
}

void TrainingDialog::setGrid(const QString& orders, const QString& floors, const QString& seeds) {
  orders_->setText(orders);
  floors_->setText(floors);
  seeds_->setText(seeds);
}

void TrainingDialog::setGroupsChecked(const std::vector<SensorGroup>& groups) {
  for (std::size_t i = 0; i < groups_.size(); ++i)
    groups_[i]->setChecked(std::find(groups.begin(), groups.end(), kSensorGroups[i].group) !=
                           groups.end());
}

void TrainingDialog::setFormsChecked(const std::vector<analysis::CovarianceForm>& forms) {
  for (std::size_t i = 0; i < forms_.size(); ++i)
    forms_[i]->setChecked(std::find(forms.begin(), forms.end(), analysis::kAllCovarianceForms[i]) !=
                          forms.end());
}

std::vector<std::string> TrainingDialog::runsWithRole(RunRole role) const {
  std::vector<std::string> out;
  const int column = role == RunRole::Train ? kTrainColumn : kTestColumn;
  for (int row = 0; row < runs_->rowCount(); ++row)
    if (runs_->item(row, column)->checkState() == Qt::Checked)
      out.push_back(runs_->item(row, 0)->text().toStdString());
  return out;
}

Result<analysis::SweepGrid> TrainingDialog::grid() const {
  analysis::SweepGrid g;
  g.groups.clear();
  for (std::size_t i = 0; i < groups_.size(); ++i)
    if (groups_[i]->isChecked()) g.groups.push_back(kSensorGroups[i].group);
  if (g.groups.empty()) return failure("choose at least one group");
  g.methods.clear();
  if (gaussian_->isChecked()) g.methods.push_back(analysis::ClassifierMethod::Gaussian);
  if (gmm_->isChecked()) g.methods.push_back(analysis::ClassifierMethod::Gmm);
  if (gbt_->isChecked()) g.methods.push_back(analysis::ClassifierMethod::Gbt);
  if (g.methods.empty()) return failure("choose at least one method");
  if (gbt_->isChecked()) {
    const auto wholeNumbers = [](QLineEdit* edit, const QString& what,
                                 std::vector<int>& out) -> Status {
      auto values = parseNumbers(edit->text(), what);
      if (!values) return values.error();
      out.clear();
      for (double v : values.value()) {
        if (v != std::floor(v) || std::abs(v) > 1.0e9)
          return Status::failure(what.toStdString() + ": " + QString::number(v).toStdString() +
                                 " is not a whole number");
        out.push_back(static_cast<int>(v));
      }
      return Status::success();
    };
    if (Status ok = wholeNumbers(trees_, tr("Trees"), g.treeCounts); !ok) return ok.error();
    if (Status ok = wholeNumbers(depths_, tr("Depths"), g.depths); !ok) return ok.error();
    auto rates = parseNumbers(learningRates_->text(), tr("Learning rates"));
    if (!rates) return rates.error();
    g.learningRates = rates.value();
    auto weights = parseNumbers(minChildWeights_->text(), tr("Min child weights"));
    if (!weights) return weights.error();
    g.minChildWeights = weights.value();
  }
  auto orders = parseNumbers(orders_->text(), tr("Orders"));
  if (!orders) return orders.error();
  g.orders.clear();
  for (double o : orders.value()) {
    // The range is the one grid check's (below), in the words every front end gives.
    if (o != std::floor(o) || std::abs(o) > 1.0e9) {
      return failure("Orders: " + QString::number(o).toStdString() + " is not a whole number");
    }
    g.orders.push_back(static_cast<int>(o));
  }
  g.forms.clear();
  for (std::size_t i = 0; i < forms_.size(); ++i)
    if (forms_[i]->isChecked()) g.forms.push_back(analysis::kAllCovarianceForms[i]);
  if (g.forms.empty() && gmm_->isChecked()) return failure("choose at least one covariance form");
  if (g.forms.empty()) g.forms.push_back(analysis::CovarianceForm::NodalFull);
  auto floors = parseNumbers(floors_->text(), tr("Variance floors"));
  if (!floors) return floors.error();
  g.varianceFloors = floors.value();
  g.features.clear();
  for (std::size_t i = 0; i < features_.size(); ++i)
    if (features_[i]->isChecked()) g.features.push_back(analysis::kFeatureKinds[i]);
  if (g.features.empty()) return failure("choose at least one feature kind");
  auto seeds = parseNumbers(seeds_->text(), tr("Seeds"));
  if (!seeds) return seeds.error();
  g.decisions.clear();
  for (std::size_t i = 0; i < decisions_.size(); ++i)
    if (decisions_[i]->isChecked()) g.decisions.push_back(analysis::kDecisionModes[i]);
  if (g.decisions.empty()) return failure("choose at least one decision mode");
  g.seeds.clear();
  for (double s : seeds.value()) {
    if (s < 0 || s != std::floor(s) || s > 9.0e15) {
      return failure("Seeds: " + QString::number(s).toStdString() +
                     " is not a whole number of at least 0");
    }
    g.seeds.push_back(static_cast<std::uint64_t>(s));
  }
  if (Status ok = analysis::checkSweepGrid(g); !ok) return ok.error();
  return g;
}

Result<workspace::SweepRequest> TrainingDialog::sweepRequest() const {
  if (labelSet_->currentText().isEmpty()) return failure("the database has no label set");
  workspace::SweepRequest request;
  request.labelSet = labelSet_->currentText().toStdString();
  request.trainRuns = runsWithRole(RunRole::Train);
  request.split = static_cast<workspace::SplitMode>(split_->currentData().toInt());
  if (request.split == workspace::SplitMode::LeaveOneRunOut) {
    return failure("a sweep scores on test runs or leaves one scene out; choose one of those");
  }
  if (request.split == workspace::SplitMode::ByRun) request.testRuns = runsWithRole(RunRole::Test);
  if (request.trainRuns.empty()) return failure("mark at least one run for training");
  if (request.split == workspace::SplitMode::ByRun && request.testRuns.empty())
    return failure("a sweep scores on test runs: mark at least one");
  auto g = grid();
  if (!g) return g.error();
  request.grid = std::move(g.value());
  request.name = name_->text().trimmed().toStdString();
  request.threads = threads_->value();
  // The one check of a sweep request, as `tactile sweep` makes it.
  if (Status ok = workspace::checkSweepRequest(request); !ok) return ok.error();
  return request;
}

Result<workspace::TrainRequest> TrainingDialog::trainRequest() const {
  if (labelSet_->currentText().isEmpty()) return failure("the database has no label set");
  auto g = grid();
  if (!g) return g.error();
  workspace::TrainRequest request;
  request.labelSet = labelSet_->currentText().toStdString();
  request.split = static_cast<workspace::SplitMode>(split_->currentData().toInt());
  request.trainRuns = runsWithRole(RunRole::Train);
  if (request.split == workspace::SplitMode::ByRun) request.testRuns = runsWithRole(RunRole::Test);
  if (request.trainRuns.empty()) return failure("mark at least one run for training");
  request.groups = g->groups;
  if (groupDefaults_->isChecked()) {
    request.settings = analysis::defaultGroupSettings();
  } else {
    analysis::SweepCell first;
    first.method = g->methods.back();  // the last ticked: GMM over Gaussian, trees over both
    first.order = g->orders.front();
    first.trees = g->treeCounts.front();
    first.depth = g->depths.front();
    first.learningRate = g->learningRates.front();
    first.minChildWeight = g->minChildWeights.front();
    first.form = g->forms.front();
    first.varianceFloor = g->varianceFloors.front();
    first.features = g->features.front();
    first.seed = g->seeds.front();
    analysis::TrainSettings settings;
    settings.features = first.features;
    settings.classifier = analysis::cellClassifierOptions(g.value(), first);
    settings.classifier.oneVsRest = true;
    request.settings = analysis::GroupSettings::same(settings);
    // The chain weighs the evidence as the sweep scored these settings: each group's default for
    // the method.
    for (const GroupInfo& info : kSensorGroups) {
      request.settings.of(info.group).emissionWeight =
          analysis::defaultEmissionWeight(info.group, first.method);
    }
  }
  if (emissionWeight_->value() > 0.0) {
    for (analysis::TrainSettings& s : request.settings.byGroup)
      s.emissionWeight = emissionWeight_->value();
  }
  for (analysis::TrainSettings& s : request.settings.byGroup) {
    s.classifier.threads = threads_->value();
    s.classifier.gmm.threads = threads_->value();
  }
  request.modelName = name_->text().trimmed().toStdString();
  return request;
}

void TrainingDialog::setBusy(bool busy) {
  sweepButton_->setEnabled(!busy);
  planButton_->setEnabled(!busy);
  trainButton_->setEnabled(!busy);
  cancelButton_->setEnabled(busy);
  // The whole form is locked while a job runs: what is shown is what runs.
  form_->setEnabled(!busy);
}

void TrainingDialog::showError(const QString& message) {
  statusIsError_ = true;
  status_->setText(
      QStringLiteral("<span style=\"color:#b00020\">%1</span>").arg(message.toHtmlEscaped()));
}

void TrainingDialog::startSweep() {
  rememberForm();
  auto request = sweepRequest();
  if (!request) {
    showError(QString::fromStdString(request.errorText()));
    return;
  }
  const std::size_t total = analysis::expandGrid(request->grid).size();
  cells_->clear();
  for (const auto& [column, shown] : SweepCellsModel::settingsColumns(request->grid.methods))
    cellsView_->setColumnHidden(column, !shown);
  statusIsError_ = false;
  resultStack_->setCurrentWidget(cellsView_);
  if (!worker_->startSweep(databasePath_, request.value())) return;
  setBusy(true);
  progress_->setRange(0, static_cast<int>(total));
  progress_->setValue(0);
  status_->setText(tr("Sweep of %n cell(s) started.", nullptr, static_cast<int>(total)));
}

void TrainingDialog::startTrain() {
  rememberForm();
  auto request = trainRequest();
  if (!request) {
    showError(QString::fromStdString(request.errorText()));
    return;
  }
  // Trained and scored first, stored after: a group that scored 0 or had no test data is worth a
  // question before the model goes into the database.
  pendingTrain_ = request.value();
  pendingTrain_.store = false;
  if (!worker_->startTrain(databasePath_, pendingTrain_)) return;
  statusIsError_ = false;
  trainResult_->setRowCount(0);
  resultStack_->setCurrentWidget(trainResult_);
  setBusy(true);
  progress_->setRange(0, 0);
  status_->setText(tr("Training started."));
}

void TrainingDialog::planForWorkers() {
  auto request = sweepRequest();
  if (!request) {
    showError(QString::fromStdString(request.errorText()));
    return;
  }
  auto planned = workspace_.planSweep(request.value());
  if (!planned) {
    showError(tr("The sweep was not planned: %1").arg(QString::fromStdString(planned.errorText())));
    return;
  }
  statusIsError_ = false;
  const std::string db = databasePath_.toStdString();
  commands_->setPlainText(
      tr("# One worker; start as many as you like, on any machine that reaches the database:") +
      QLatin1Char('\n') +
      QString::fromStdString(workspace::sweepWorkCommand(db, planned->sweepId)) +
      QLatin1Char('\n') + tr("# Or 4 workers as a Slurm job array:") + QLatin1Char('\n') +
      QString::fromStdString(workspace::sweepSubmitCommand(db, planned->sweepId, 4)));
  commands_->show();
  copyCommands_->show();
  status_->setText(tr("Sweep %1 planned: %n cell(s), all pending, for the workers below.", nullptr,
                      static_cast<int>(planned->cells))
                       .arg(planned->sweepId));
  emit sweepPlanned(planned->sweepId);
  // The results window that opens for the sweep must not hide the commands still to be copied.
  raise();
  activateWindow();
}

void TrainingDialog::cancel() {
  if (!worker_->isRunning()) return;
  worker_->cancel();
  cancelButton_->setEnabled(false);
  status_->setText(tr("Cancelling: running fits stop after their current iteration..."));
}

void TrainingDialog::onProgress(qint64 done, qint64 total, double secondsLeft) {
  if (total <= 0) return;
  if (progress_->maximum() != static_cast<int>(total))
    progress_->setRange(0, static_cast<int>(total));
  progress_->setValue(static_cast<int>(std::min(done, total)));
  if (!cancelButton_->isEnabled()) return;  // cancelling
  status_->setText(
      secondsLeft >= 0
          ? tr("%1 of %2 done, about %3 left").arg(done).arg(total).arg(durationText(secondsLeft))
          : tr("%1 of %2 done").arg(done).arg(total));
}

void TrainingDialog::onFinished(const LearningJobResult& finished) {
  LearningJobResult result = finished;  // a training is stored here (when asked) and renamed
  setBusy(false);
  if (progress_->maximum() == 0) progress_->setRange(0, 1);
  if (result.kind == LearningJobResult::Kind::Sweep) {
    if (!result.error.isEmpty()) {
      showError(tr("The sweep failed: %1").arg(result.error));
    } else if (result.cancelled) {
      status_->setText(tr("Sweep %1 cancelled after %2 s; its %n finished cell(s) are stored.",
                          nullptr, static_cast<int>(result.cells))
                           .arg(result.sweepId)
                           .arg(result.seconds, 0, 'f', 1));
    } else {
      progress_->setValue(progress_->maximum());
      status_->setText(
          tr("Sweep %1 finished: %n cell(s) in %2 s.", nullptr, static_cast<int>(result.cells))
              .arg(result.sweepId)
              .arg(result.seconds, 0, 'f', 1));
    }
    if (result.sweepId > 0 && result.cells > 0) {
      refreshTiming();  // the new sweep's cell times make the next estimate
      emit sweepStored(result.sweepId);
    }
  } else {
    if (result.ok && result.unstored) {
      QStringList doubtful;
      for (const workspace::GroupTrainReport& g : result.groups) {
        if (!g.doubtful()) continue;
        doubtful << (g.balancedAccuracy
                         ? tr("%1 scored 0 on %2 test steps")
                               .arg(qs(groupInfo(g.group).shortName))
                               .arg(g.samplesTest)
                         : tr("%1 had no test data").arg(qs(groupInfo(g.group).shortName)));
      }
      bool store = true;
      if (!doubtful.isEmpty()) {
        const QString text =
            tr("%1. Store the model anyway?").arg(doubtful.join(QStringLiteral("; ")));
        store = askToStore_
                    ? askToStore_(text)
                    : QMessageBox::question(this, tr("Store the model?"), text) == QMessageBox::Yes;
      }
      if (!store) {
        setBusy(false);
        progress_->setRange(0, 1);
        status_->setText(
            tr("The model was not stored (%1).").arg(doubtful.join(QStringLiteral("; "))));
        emit jobFinished();
        return;
      }
      auto saved = workspace_.storeTrained(std::move(*result.unstored), pendingTrain_);
      if (!saved) {
        result.ok = false;
        result.error = QString::fromStdString(saved.errorText());
      } else {
        result.modelName = QString::fromStdString(saved->modelName);
      }
    }
    if (result.ok) {
      QStringList lines;
      for (const workspace::GroupTrainReport& g : result.groups) {
        const QString name = qs(groupInfo(g.group).shortName);
        lines << (!g.trained
                      ? tr("%1: skipped (%2)").arg(name, QString::fromStdString(g.skippedBecause))
                  : g.balancedAccuracy ? tr("%1: balanced accuracy %2 % (%3 test steps)")
                                             .arg(name)
                                             .arg(100.0 * *g.balancedAccuracy, 0, 'f', 1)
                                             .arg(g.samplesTest)
                                       : tr("%1: no test data").arg(name));
      }
      progress_->setRange(0, 1);
      progress_->setValue(1);
      status_->setText(tr("Model '%1' stored (%2 s). %3")
                           .arg(result.modelName)
                           .arg(result.seconds, 0, 'f', 1)
                           .arg(lines.join(QStringLiteral("; "))));
      showTrainResult(result);
      emit modelTrained(result.modelName);
    } else if (result.cancelled) {
      progress_->setRange(0, 1);
      status_->setText(tr("Training cancelled; nothing was stored."));
    } else {
      progress_->setRange(0, 1);
      showError(tr("Training failed: %1").arg(result.error));
    }
  }
  emit jobFinished();
}

void TrainingDialog::showTrainResult(const LearningJobResult& result) {
  trainResult_->setRowCount(0);
  auto cell = [](const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
  };
  for (const workspace::GroupTrainReport& g : result.groups) {
    const int row = trainResult_->rowCount();
    trainResult_->insertRow(row);
    trainResult_->setItem(row, 0, new QTableWidgetItem(qs(groupInfo(g.group).shortName)));
    if (!g.trained) {
      trainResult_->setItem(
          row, 1,
          new QTableWidgetItem(tr("skipped: %1").arg(QString::fromStdString(g.skippedBecause))));
      continue;
    }
    // A group without test rows has no score: "no test data", never 0.
    auto percent = [](const std::optional<double>& rate) {
      return rate ? QString::number(100.0 * *rate, 'f', 1) : tr("no test data");
    };
    trainResult_->setItem(row, 1, cell(percent(g.balancedAccuracy)));
    trainResult_->setItem(row, 2, cell(percent(g.accuracy)));
    trainResult_->setItem(row, 3, cell(QString::number(g.samplesTrain)));
    trainResult_->setItem(row, 4, cell(QString::number(g.samplesTest)));
    trainResult_->setItem(row, 5, cell(QString::number(g.fitSeconds, 'f', 2)));
  }
  resultStack_->setCurrentWidget(trainResult_);
}

}  // namespace tactile::gui
