// A trained model's view of the open run, for the prediction strips: per group and step the
// predicted class and its confidence (the posterior probability of that class), where it
// disagrees with the current labels, and the holes (thesis 4.5) found along each side with their
// widths. Each group may use a different stored model. Classification runs off the GUI thread
// through the same core call as `tactile classify` (Workspace::classify), on a connection of its
// own.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/classify_run.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"
#include "storage/run_database.h"

namespace tactile::gui {

class LabelModel;

// One group's predictions over the run.
struct GroupPrediction {
  QString model;                  // stored model name ("" when the group has none)
  bool hasModel = false;          // the model has a classifier for this group
  std::vector<std::int8_t> cls;   // ContactClass per step, -1 where nothing was predicted
  std::vector<float> confidence;  // posterior probability of cls (1 for NoContact by rule)
  // The online (forward filter) and offline (forward-backward) decisions, as cls.
  std::vector<std::int8_t> online;
  std::vector<std::int8_t> offline;
  std::vector<std::uint8_t> disagrees;  // 1 where a label exists and differs from cls
  std::size_t disagreements = 0;

  std::optional<ContactClass> classAt(std::int64_t step) const;
};

// A hole found at one step along one side (analysis::kSides): the gap between two contact
// fragments and its width.
struct HoleMark {
  std::int64_t step = 0;
  int side = 0;  // index into analysis::kSides
  int sensorBefore = 0;
  int sensorAfter = 0;
  double widthUnits = 0.0;
};

// Posterior of every class (rows: steps) from log-likelihoods and log priors, in log space:
// log P(c | x) = l_c + log pi_c - logsumexp_k(l_k + log pi_k). Rows that are all -inf give -inf.
// Exposed for tests; shared by the strips and the confidence column of exports.
Eigen::MatrixXd logPosteriors(const Eigen::MatrixXd& logLikelihoods,
                              const Eigen::VectorXd& logPriors);

// All holes of a run, step by step, for every side.
std::vector<HoleMark> findHoles(const RunData& run);

class PredictionModel : public QObject {
  Q_OBJECT

 public:
  explicit PredictionModel(LabelModel* labels, QObject* parent = nullptr);
  ~PredictionModel() override;

  // Models per group (stored model names; empty: none for that group).
  using Choice = std::array<QString, kGroupCount>;
  static Choice sameForAll(const QString& model);

  // Classifies the run with the chosen models in the background; ready() or failed() follow. A
  // new call replaces a pending one's result.
  void compute(const QString& databasePath, const QString& runName, const Choice& models);
  // Forgets the predictions and the chosen models.
  void clear();
  void waitForFinished();

  bool isComputing() const { return computing_; }
  bool hasPredictions() const { return !runName_.isEmpty(); }
  const Choice& models() const { return models_; }
  const QString& runName() const { return runName_; }
  std::int64_t stepCount() const { return steps_; }
  const GroupPrediction& group(SensorGroup g) const {
    return groups_[static_cast<std::size_t>(groupIndex(g))];
  }
  const std::vector<HoleMark>& holes() const { return holes_; }
  // Holes at one step (sorted by step, so this is a range lookup).
  std::vector<HoleMark> holesAt(std::int64_t step) const;

  // The first step of the next (or previous) stretch of consecutive steps where the prediction
  // disagrees with the labels, in `group` or in any group; wraps around the run. From inside a
  // stretch, next skips the rest of it and previous goes to the stretch before it. nullopt when
  // nothing disagrees.
  std::optional<std::int64_t> nextDisagreement(std::int64_t from,
                                               std::optional<SensorGroup> group) const;
  std::optional<std::int64_t> previousDisagreement(std::int64_t from,
                                                   std::optional<SensorGroup> group) const;
  // The first step of the next stretch (wrapping around the run) where the model is unsure: some
  // group's predicted class has a posterior below `threshold`. From inside a stretch, skips the
  // rest of it. nullopt when the model is at least that sure everywhere.
  std::optional<std::int64_t> nextDoubt(std::int64_t from, double threshold) const;
  // The least sure group at a step (nullopt where every group is at least `threshold` sure).
  std::optional<SensorGroup> doubtfulGroup(std::int64_t step, double threshold) const;

 signals:
  void ready();
  void failed(const QString& message);
  // Disagreements changed (labels edited or predictions arrived).
  void changed();

 private:
  struct Result;
  void accept(std::shared_ptr<Result> result);
  void updateDisagreements();
  bool startsStretch(std::int64_t t, std::optional<SensorGroup> group) const;

  LabelModel* labels_;
  QFuture<void> future_;
  bool computing_ = false;
  std::uint64_t generation_ = 0;
  Choice models_;
  QString runName_;
  std::int64_t steps_ = 0;
  std::array<GroupPrediction, kGroupCount> groups_;
  std::vector<HoleMark> holes_;
};

}  // namespace tactile::gui
