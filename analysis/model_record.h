// What a trained model records about itself: where it came from (provenance) and how it scored
// (evaluation). Typed here; their JSON ("trained_on", "metrics" of a model file) is read and
// written by model_file.cpp only, so a model trained from run files and one trained from a
// database carry the same shape (docs/file-formats.md#model-file).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/metrics.h"
#include "analysis/temporal.h"
#include "run/contact_class.h"

namespace tactile::analysis {

// A run a model was trained or scored on: a run file's path or a stored run's name, its step
// count, checksum (stored runs; empty for run files) and scene (its `scene` metadata).
struct RunReference {
  std::string name;
  std::int64_t steps = 0;
  std::string checksum;
  std::string scene;
  bool operator==(const RunReference&) const = default;
};

struct ModelProvenance {
  std::string labelSet;  // the stored label set (database form); empty for run files
  std::string labels;    // run files: the label file, or "truth columns"; empty for a database
  std::vector<RunReference> trainRuns;
  std::vector<RunReference> testRuns;
  std::string split;  // by-run, leave-one-run-out, by-scene, holdout, training-data
  double holdout = 0.0;
  std::string programVersion;
  std::string importedFrom;  // the file a stored model was imported from
  // The settings the group was trained with (features and decision live in the model itself).
  ClassifierOptions classifier;
  std::size_t samples = 0;  // training rows
  std::array<std::size_t, kContactClassCount> classCounts{};
  std::size_t zeroRows = 0;
  std::vector<ContactClass> unmodelled;  // classes present with too few rows to model
};

// Per modelled class: how its fit went.
struct ClassFitRecord {
  int iterations = 0;
  bool converged = false;
  double trainMeanLogLikelihood = 0.0;
  int droppedComponents = 0;
};

inline constexpr std::size_t kDecisionModeCount = 3;
inline std::size_t decisionIndex(DecisionMode mode) {
  return static_cast<std::size_t>(mode);
}

// One held-out scene's score (by-scene split).
struct SceneScore {
  std::string scene;
  std::array<ConfusionMatrix, kDecisionModeCount> byDecision;  // step, online, offline
};

struct ModelEvaluation {
  std::string evaluatedOn;  // e.g. "test runs", "leave-one-scene-out", "training runs"
  std::size_t samplesTrain = 0;
  double fitSeconds = 0.0;
  double predictSeconds = 0.0;
  std::vector<std::string> warnings;
  std::vector<ClassFitRecord> fit;  // parallel to the model's classes (may be empty)
  // Confusion of each decision mode on the test rows (rows: truth, columns: decision). All empty
  // when nothing was scored: then every rate is "no test data", never 0.
  std::array<ConfusionMatrix, kDecisionModeCount> byDecision;
  std::optional<double> meanLogLikelihood;
  std::size_t negInfRows = 0;
  std::size_t zeroRows = 0;
  ContactPatternTable patterns;
  std::vector<BinaryConfusion> oneVsRest;
  std::vector<SceneScore> scenes;  // by-scene split: each held-out scene

  std::size_t samplesTest() const { return byDecision[0].total(); }
  bool scored() const { return samplesTest() > 0; }
  const ConfusionMatrix& confusion(DecisionMode mode) const {
    return byDecision[decisionIndex(mode)];
  }
  // Balanced accuracy of a decision mode; nullopt without test rows.
  std::optional<double> balancedAccuracy(DecisionMode mode) const;
  std::optional<double> accuracy(DecisionMode mode) const;
};

// The mean over held-out scenes of a decision mode's balanced accuracy (scenes without test rows
// left out); nullopt when no scene has any.
std::optional<double> meanSceneBalancedAccuracy(const std::vector<SceneScore>& scenes,
                                                DecisionMode mode);

}  // namespace tactile::analysis
