// Classifying a whole run with a model bundle: per group and step the predicted class, the
// per-class log-likelihoods and, optionally, a temporal decision (docs/analysis.md). Shared by
// `tactile classify` (run files and stored runs) and the workbench's prediction strip.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/model_file.h"
#include "analysis/temporal.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

enum class TemporalRule { None, Count, Sum, Hmm };
// "none", "count", "sum", "hmm".
std::optional<TemporalRule> parseTemporalRule(std::string_view name);
std::string_view temporalRuleName(TemporalRule rule);

struct ClassifyOptions {
  // The decision written as each step's class: nullopt = each model's default (online for a
  // model with transitions, else step). Ignored when `temporal` names one of the older rules.
  std::optional<DecisionMode> decision;
  // Also fill GroupClassification::online and ::offline (the workbench's strip shows both).
  bool allDecisions = false;
  TemporalRule temporal = TemporalRule::None;
  int count = 3;           // Count: consecutive steps required
  double threshold = 5.0;  // Sum: log-probability margin, nats
  int window = 0;          // Sum: sliding window in steps (0 = the whole contact)
  double stay = 0.9;       // Hmm: self-transition probability
};

// One group's classification of every step of a run.
struct GroupClassification {
  const GroupModel* model = nullptr;          // null: the bundle has no model for the group
  std::vector<std::uint8_t> noContactRule;    // 1 where every value is zero (NoContact by rule)
  std::vector<std::optional<int>> predicted;  // class index into model->classes; contact steps
  // A row of per-class log-likelihoods for each contact step (noContactRule 0), in step order:
  // contact steps x classes (StepLikelihoods' compact layout).
  Eigen::MatrixXd logLikelihoods;
  Decisions decided;         // the chosen decision (steps entries when a model exists)
  std::string decisionName;  // "step", "online", "offline", or the temporal rule's name
  Decisions online;          // with allDecisions: the forward filter's decisions
  Decisions offline;         // with allDecisions: forward-backward decisions

  // The class name at a step by the chosen decision: "NoContact" by rule, the decided class, or
  // "" where no model could say.
  std::string className(std::size_t step) const;
  // The per-step argmax (the decision without memory), same conventions.
  std::string stepClassName(std::size_t step) const;
  // The name of entry `step` of any decision list.
  std::string nameOf(const Decisions& decisions, std::size_t step) const;
};

struct RunClassification {
  std::size_t steps = 0;
  std::array<GroupClassification, kGroupCount> groups;  // in sensor-group order
};

// Evaluates the bundle's model of every group on the run's contact steps only (no-contact groups
// skip the model). The result points into `bundle`, which must outlive it.
RunClassification classifyRun(const RunData& run, const ModelBundle& bundle,
                              const ClassifyOptions& options = {});

}  // namespace tactile::analysis
