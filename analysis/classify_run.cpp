#include "analysis/classify_run.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "analysis/features.h"

namespace tactile::analysis {

namespace {
// Contact rows evaluated at once by classifyRun.
constexpr Eigen::Index kClassifyChunkRows = 4096;
constexpr std::array<std::pair<TemporalRule, std::string_view>, 4> kRuleNames{{
    {TemporalRule::None, "none"},
    {TemporalRule::Count, "count"},
    {TemporalRule::Sum, "sum"},
    {TemporalRule::Hmm, "hmm"},
}};
}  // namespace

std::optional<TemporalRule> parseTemporalRule(std::string_view name) {
  for (const auto& [rule, text] : kRuleNames)
    if (text == name) return rule;
  return std::nullopt;
}

std::string_view temporalRuleName(TemporalRule rule) {
  for (const auto& [value, text] : kRuleNames)
    if (value == rule) return text;
  return "?";
}

std::string GroupClassification::nameOf(const Decisions& decisions, std::size_t step) const {
  if (noContactRule[step]) return "NoContact";
  if (model == nullptr || step >= decisions.size() || !decisions[step]) return "";
  return model->classifier.classNames()[static_cast<std::size_t>(*decisions[step])];
}

std::string GroupClassification::className(std::size_t step) const {
  return nameOf(decided, step);
}

std::string GroupClassification::stepClassName(std::size_t step) const {
  return nameOf(predicted, step);
}

RunClassification classifyRun(const RunData& run, const ModelBundle& bundle,
                              const ClassifyOptions& options) {
  RunClassification out;
  const std::size_t steps = run.stepCount();
  out.steps = steps;
  for (const GroupInfo& info : kSensorGroups) {
    GroupClassification& go = out.groups[static_cast<std::size_t>(groupIndex(info.group))];
    go.model = bundle.find(info.group);
    go.noContactRule.resize(steps);
    for (std::size_t t = 0; t < steps; ++t)
      go.noContactRule[t] = groupIsZero(run, t, info.group) ? 1 : 0;
    go.predicted.assign(steps, std::nullopt);
    if (go.model == nullptr) continue;
    const FeatureKind kind = go.model->features;
    std::vector<Eigen::Index> contactRows;
    for (std::size_t t = 0; t < steps; ++t) {
      if (!go.noContactRule[t]) contactRows.push_back(static_cast<Eigen::Index>(t));
    }
    const int classes = go.model->classifier.classCount();
    go.logLikelihoods = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(steps), classes,
                                                  -std::numeric_limits<double>::infinity());
    // The contact rows in chunks, their features computed straight into the chunk: the
    // evaluation's buffers stay a few MB whatever the run's length (a whole 1,000,000-step run at
    // once, with a feature row for every step, spent more time faulting in and clearing fresh
    // memory than evaluating densities). Each row's log-likelihoods do not depend on the chunking.
    const Eigen::Index contact = static_cast<Eigen::Index>(contactRows.size());
    const int dims = featureDimension(info.group, kind);
    std::vector<double> row(static_cast<std::size_t>(dims));
    Eigen::MatrixXd x;
    Eigen::MatrixXd ll;
    for (Eigen::Index start = 0; start < contact; start += kClassifyChunkRows) {
      const Eigen::Index rows = std::min(kClassifyChunkRows, contact - start);
      x.resize(rows, dims);
      for (Eigen::Index i = 0; i < rows; ++i) {
        groupFeatures(run,
                      static_cast<std::size_t>(contactRows[static_cast<std::size_t>(start + i)]),
                      info.group, kind, row.data());
        for (int d = 0; d < dims; ++d)
          x(i, d) = row[static_cast<std::size_t>(d)];
      }
      go.model->classifier.logLikelihoods(x, ll);
      const std::vector<int> pred = go.model->classifier.predictFromLogLikelihoods(ll);
      for (Eigen::Index c = 0; c < classes; ++c) {
        const double* from = ll.col(c).data();
        double* to = go.logLikelihoods.col(c).data();
        for (Eigen::Index i = 0; i < rows; ++i)
          to[contactRows[static_cast<std::size_t>(start + i)]] = from[i];
      }
      for (Eigen::Index i = 0; i < rows; ++i)
        go.predicted[static_cast<std::size_t>(contactRows[static_cast<std::size_t>(start + i)])] =
            pred[static_cast<std::size_t>(i)];
    }
    // The likelihoods lend themselves to the deciders and come back below (no copy).
    StepLikelihoods sl{std::move(go.logLikelihoods), {}, go.model->classifier.logPriors()};
    sl.observed.resize(steps);
    for (std::size_t t = 0; t < steps; ++t)
      sl.observed[t] = go.noContactRule[t] ? 0 : 1;
    const TransitionModel& chain = go.model->transitions;
    switch (options.temporal) {
      case TemporalRule::Count:
        go.decided = consecutiveCountDecisions(sl, options.count);
        break;
      case TemporalRule::Sum:
        go.decided = summedLogProbabilityDecisions(sl, options.threshold, options.window);
        break;
      case TemporalRule::Hmm:
        go.decided = hmmForwardFilter(sl, options.stay).decisions;
        break;
      case TemporalRule::None: {
        DecisionMode mode = options.decision.value_or(go.model->decision);
        if (chain.empty() || chain.classCount() != classes) mode = DecisionMode::Step;
        go.decisionName = decisionModeName(mode);
        if (mode == DecisionMode::Step) {
          go.decided = go.predicted;
        } else {
          go.decided = decide(sl, chain, mode);
        }
        break;
      }
    }
    if (options.temporal != TemporalRule::None) {
      go.decisionName = temporalRuleName(options.temporal);
    }
    if (options.allDecisions) {
      go.online = decide(sl, chain, DecisionMode::Online);
      go.offline = decide(sl, chain, DecisionMode::Offline);
    }
    go.logLikelihoods = std::move(sl.logLik);
  }
  return out;
}

}  // namespace tactile::analysis
