#include "app/gui/learning/prediction_model.h"

#include <QCoreApplication>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "analysis/hole_detection.h"
#include "analysis/temporal.h"
#include "app/gui/labels/label_model.h"
#include "workspace/workspace.h"

namespace tactile::gui {

std::optional<ContactClass> GroupPrediction::classAt(std::int64_t step) const {
  if (step < 0 || step >= static_cast<std::int64_t>(cls.size())) return std::nullopt;
  const std::int8_t c = cls[static_cast<std::size_t>(step)];
  if (c < 0) return std::nullopt;
  return static_cast<ContactClass>(c);
}

Eigen::MatrixXd logPosteriors(const Eigen::MatrixXd& logLikelihoods,
                              const Eigen::VectorXd& logPriors) {
  Eigen::MatrixXd out(logLikelihoods.rows(), logLikelihoods.cols());
  const double ninf = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd row(logLikelihoods.cols());
  for (Eigen::Index t = 0; t < logLikelihoods.rows(); ++t) {
    for (Eigen::Index c = 0; c < logLikelihoods.cols(); ++c)
      row[c] = logLikelihoods(t, c) + (logPriors.size() == row.size() ? logPriors[c] : 0.0);
    const double norm = analysis::logSumExp(row);
    for (Eigen::Index c = 0; c < row.size(); ++c)
      out(t, c) = std::isfinite(norm) && row[c] != ninf ? row[c] - norm : ninf;
  }
  return out;
}

std::vector<HoleMark> findHoles(const RunData& run) {
  std::vector<HoleMark> out;
  const auto placements = domePlacements();
  for (std::size_t step = 0; step < run.stepCount(); ++step) {
    const std::array<bool, kSensorCount> contact = analysis::sensorContacts(run, step);
    for (std::size_t side = 0; side < analysis::kSides.size(); ++side) {
      const analysis::SideRange& s = analysis::kSides[side];
      const analysis::HoleScan scan =
          analysis::scanSide(contact, s.firstSensor, s.count, placements);
      for (const analysis::Hole& h : scan.holes)
        out.push_back({static_cast<std::int64_t>(step), static_cast<int>(side), h.lastSensorBefore,
                       h.firstSensorAfter, h.widthUnits});
    }
  }
  return out;
}

// What the worker hands back.
struct PredictionModel::Result {
  std::uint64_t generation = 0;
  QString runName;
  QString error;
  std::int64_t steps = 0;
  std::array<GroupPrediction, kGroupCount> groups;
  std::vector<HoleMark> holes;
};

namespace {

void fillGroup(const analysis::GroupClassification& g, std::size_t steps, GroupPrediction& out) {
  out.cls.assign(steps, -1);
  out.confidence.assign(steps, 0.0f);
  out.online.assign(steps, -1);
  out.offline.assign(steps, -1);
  out.hasModel = g.model != nullptr;
  for (std::size_t t = 0; t < steps; ++t) {
    if (t < g.noContactRule.size() && g.noContactRule[t]) {
      out.cls[t] = static_cast<std::int8_t>(ContactClass::NoContact);
      out.online[t] = out.offline[t] = out.cls[t];
      out.confidence[t] = 1.0f;
    }
  }
  if (g.model == nullptr) return;
  for (const auto& [from, to] :
       {std::pair{&g.online, &out.online}, std::pair{&g.offline, &out.offline}}) {
    for (std::size_t t = 0; t < steps && t < from->size(); ++t) {
      if ((*from)[t])
        (*to)[t] =
            static_cast<std::int8_t>(g.model->classes[static_cast<std::size_t>(*(*from)[t])]);
    }
  }
  // A row of likelihoods per contact step, in step order.
  const Eigen::MatrixXd post = logPosteriors(g.logLikelihoods, g.model->classifier.logPriors());
  Eigen::Index row = 0;
  for (std::size_t t = 0; t < steps && t < g.predicted.size(); ++t) {
    if (t < g.noContactRule.size() && g.noContactRule[t]) continue;
    const Eigen::Index here = row++;
    if (!g.predicted[t]) continue;
    const int c = *g.predicted[t];
    out.cls[t] = static_cast<std::int8_t>(g.model->classes[static_cast<std::size_t>(c)]);
    const double p = here < post.rows() ? std::exp(post(here, c)) : 0.0;
    out.confidence[t] = std::isfinite(p) ? static_cast<float>(std::clamp(p, 0.0, 1.0)) : 0.0f;
  }
}

}  // namespace

PredictionModel::PredictionModel(LabelModel* labels, QObject* parent)
    : QObject(parent), labels_(labels) {
  if (labels_ != nullptr) {
    connect(labels_, &LabelModel::labelsChanged, this, &PredictionModel::updateDisagreements);
    connect(labels_, &LabelModel::labelSetChanged, this, &PredictionModel::updateDisagreements);
  }
}

PredictionModel::~PredictionModel() {
  future_.waitForFinished();
}

PredictionModel::Choice PredictionModel::sameForAll(const QString& model) {
  Choice c;
  c.fill(model);
  return c;
}

void PredictionModel::compute(const QString& databasePath, const QString& runName,
                              const Choice& models) {
  future_.waitForFinished();  // one job at a time; a classification takes a moment
  const std::uint64_t generation = ++generation_;
  computing_ = true;
  models_ = models;
  future_ = QtConcurrent::run([this, databasePath, runName, models, generation] {
    auto result = std::make_shared<Result>();
    result->generation = generation;
    result->runName = runName;
    storage::OpenOptions options;
    options.mode = storage::OpenMode::ReadOnly;
    auto ws = workspace::Workspace::open(databasePath.toStdString(), options);
    if (!ws) {
      result->error = QString::fromStdString(ws.errorText());
    } else {
      // Each distinct model classifies the run once, for every group that chose it.
      std::map<QString, std::vector<int>> groupsOf;
      for (int g = 0; g < kGroupCount; ++g)
        if (!models[static_cast<std::size_t>(g)].isEmpty())
          groupsOf[models[static_cast<std::size_t>(g)]].push_back(g);
      bool haveRun = false;
      RunData run;
      for (const auto& [model, groups] : groupsOf) {
        analysis::ClassifyOptions options;
        options.allDecisions = true;  // the strip shows the online and offline decisions too
        auto classified = ws.value()->classify(model.toStdString(), runName.toStdString(), options);
        if (!classified) {
          result->error = QString::fromStdString(classified.errorText());
          break;
        }
        const std::size_t steps = classified->result.steps;
        result->steps = static_cast<std::int64_t>(steps);
        for (int g : groups) {
          GroupPrediction& p = result->groups[static_cast<std::size_t>(g)];
          p.model = model;
          fillGroup(classified->result.groups[static_cast<std::size_t>(g)], steps, p);
        }
        if (!haveRun) {
          run = std::move(classified->run);
          haveRun = true;
        }
      }
      if (result->error.isEmpty() && !haveRun) {
        auto loaded = ws.value()->loadRun(runName.toStdString());
        if (loaded) {
          run = std::move(loaded.value());
          haveRun = true;
          result->steps = static_cast<std::int64_t>(run.stepCount());
        } else {
          result->error = QString::fromStdString(loaded.errorText());
        }
      }
      if (result->error.isEmpty() && haveRun) result->holes = findHoles(run);
    }
    QMetaObject::invokeMethod(
        this, [this, result] { accept(result); }, Qt::QueuedConnection);
  });
}

void PredictionModel::waitForFinished() {
  future_.waitForFinished();
  // Deliver the queued result now (tests, screenshots).
  QCoreApplication::sendPostedEvents(this);
}

void PredictionModel::accept(std::shared_ptr<Result> result) {
  if (result->generation != generation_) return;  // a newer request replaced it
  computing_ = false;
  if (!result->error.isEmpty()) {
    clear();
    emit failed(result->error);
    return;
  }
  runName_ = result->runName;
  steps_ = result->steps;
  groups_ = std::move(result->groups);
  holes_ = std::move(result->holes);
  updateDisagreements();
  emit ready();
}

void PredictionModel::clear() {
  ++generation_;
  computing_ = false;
  models_ = Choice{};
  runName_.clear();
  steps_ = 0;
  for (GroupPrediction& g : groups_)
    g = GroupPrediction{};
  holes_.clear();
  emit changed();
}

void PredictionModel::updateDisagreements() {
  if (runName_.isEmpty()) return;
  for (const GroupInfo& info : kSensorGroups) {
    GroupPrediction& p = groups_[static_cast<std::size_t>(groupIndex(info.group))];
    p.disagrees.assign(p.cls.size(), 0);
    p.disagreements = 0;
    if (labels_ == nullptr || !labels_->hasSet()) continue;
    for (const storage::LabelSegment& s : labels_->segments(info.group)) {
      const std::int64_t last =
          std::min<std::int64_t>(s.lastStep, static_cast<std::int64_t>(p.cls.size()) - 1);
      for (std::int64_t t = std::max<std::int64_t>(0, s.firstStep); t <= last; ++t) {
        const std::int8_t c = p.cls[static_cast<std::size_t>(t)];
        if (c >= 0 && c != static_cast<std::int8_t>(s.cls)) {
          p.disagrees[static_cast<std::size_t>(t)] = 1;
          ++p.disagreements;
        }
      }
    }
  }
  emit changed();
}

std::vector<HoleMark> PredictionModel::holesAt(std::int64_t step) const {
  auto lo = std::lower_bound(holes_.begin(), holes_.end(), step,
                             [](const HoleMark& h, std::int64_t s) { return h.step < s; });
  std::vector<HoleMark> out;
  for (; lo != holes_.end() && lo->step == step; ++lo)
    out.push_back(*lo);
  return out;
}

namespace {

bool disagreesAt(const std::array<GroupPrediction, kGroupCount>& groups, std::int64_t t,
                 std::optional<SensorGroup> group) {
  for (const GroupInfo& info : kSensorGroups) {
    if (group && info.group != *group) continue;
    const GroupPrediction& p = groups[static_cast<std::size_t>(groupIndex(info.group))];
    if (t < static_cast<std::int64_t>(p.disagrees.size()) &&
        p.disagrees[static_cast<std::size_t>(t)])
      return true;
  }
  return false;
}

}  // namespace

// A stretch is a maximal run of consecutive disagreeing steps; it starts at t when t disagrees
// and t - 1 does not (or t is the first step).
bool PredictionModel::startsStretch(std::int64_t t, std::optional<SensorGroup> group) const {
  return disagreesAt(groups_, t, group) && (t == 0 || !disagreesAt(groups_, t - 1, group));
}

std::optional<std::int64_t> PredictionModel::nextDisagreement(
    std::int64_t from, std::optional<SensorGroup> group) const {
  if (steps_ <= 0) return std::nullopt;
  for (std::int64_t k = 1; k <= steps_; ++k) {
    const std::int64_t t = ((from + k) % steps_ + steps_) % steps_;
    if (startsStretch(t, group)) return t;
  }
  return std::nullopt;
}

std::optional<std::int64_t> PredictionModel::previousDisagreement(
    std::int64_t from, std::optional<SensorGroup> group) const {
  if (steps_ <= 0) return std::nullopt;
  // From inside a stretch (past its first step), the previous one is the stretch before it, as N
  // from inside a stretch skips the rest of it.
  from = std::clamp<std::int64_t>(from, 0, steps_ - 1);
  while (from > 0 && disagreesAt(groups_, from, group) && disagreesAt(groups_, from - 1, group))
    --from;
  for (std::int64_t k = 1; k <= steps_; ++k) {
    const std::int64_t t = ((from - k) % steps_ + steps_) % steps_;
    if (startsStretch(t, group)) return t;
  }
  return std::nullopt;
}

std::optional<SensorGroup> PredictionModel::doubtfulGroup(std::int64_t step,
                                                          double threshold) const {
  std::optional<SensorGroup> least;
  float lowest = static_cast<float>(threshold);
  for (const GroupInfo& info : kSensorGroups) {
    const GroupPrediction& p = groups_[static_cast<std::size_t>(groupIndex(info.group))];
    if (step < 0 || step >= static_cast<std::int64_t>(p.cls.size())) continue;
    const auto k = static_cast<std::size_t>(step);
    if (p.cls[k] < 0 || k >= p.confidence.size()) continue;
    if (p.confidence[k] < lowest) {
      lowest = p.confidence[k];
      least = info.group;
    }
  }
  return least;
}

std::optional<std::int64_t> PredictionModel::nextDoubt(std::int64_t from, double threshold) const {
  if (steps_ <= 0) return std::nullopt;
  auto doubt = [&](std::int64_t t) { return doubtfulGroup(t, threshold).has_value(); };
  for (std::int64_t k = 1; k <= steps_; ++k) {
    const std::int64_t t = ((from + k) % steps_ + steps_) % steps_;
    if (doubt(t) && (t == 0 || !doubt(t - 1))) return t;
  }
  return std::nullopt;
}

}  // namespace tactile::gui
