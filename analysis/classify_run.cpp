#include "analysis/classify_run.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "analysis/features.h"
#include "analysis/gaussian_mixture.h"
#include "analysis/gmm_kernels.h"

namespace tactile::analysis {

namespace {
// Steps of the run that classifyRun walks through with every group before moving on (their sensor
// values, 88 doubles a step, stay in cache between the groups).
constexpr std::size_t kClassifySliceSteps = 512;
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

namespace {

// One group's evaluation while classifyRun walks the run: contact rows gather, their features
// computed straight into a column-major block of kDensityBlockRows rows, which is evaluated when
// full (and at the end). Buffers are sized once; nothing is allocated per step.
struct GroupPass {
  GroupClassification* out = nullptr;
  SensorGroup group = SensorGroup::Front;
  FeatureKind kind = FeatureKind::Normal;
  int dims = 0;
  int classes = 0;
  int contactSteps = 0;   // steps of the current contact before this one (capped)
  Eigen::MatrixXd block;  // kDensityBlockRows x dims, column-major
  std::vector<std::size_t> blockSteps;
  std::vector<double> row;
  Eigen::MatrixXd ll;  // kDensityBlockRows x classes
  GaussianMixture::BlockScratch scratch;
  Eigen::MatrixXd treeScores;  // a block's scaled likelihoods from trees
  // The contact steps' log-likelihoods so far, a row of `classes` values per step, in step order.
  std::vector<double> rows;

  void evaluate() {
    const Eigen::Index rows = static_cast<Eigen::Index>(blockSteps.size());
    if (rows == 0) return;
    const ClassModelSet& classifier = out->model->classifier;
    if (const GbtModel* trees = classifier.trees()) {
      trees->logScaledLikelihoods(block.topRows(rows), treeScores);
      ll.topRows(rows) = treeScores;
    } else {
      for (int c = 0; c < classes; ++c)
        classifier.model(c).blockLogDensities(block.data(), kDensityBlockRows, rows,
                                              ll.col(c).data(), scratch);
    }
    const Eigen::VectorXd& logPriors = classifier.logPriors();
    for (Eigen::Index i = 0; i < rows; ++i) {
      const auto t = static_cast<Eigen::Index>(blockSteps[static_cast<std::size_t>(i)]);
      // The argmax of ClassModelSet::predictFromLogLikelihoods: strict, so ties keep the lowest
      // index and NaN never wins.
      int best = 0;
      double bestScore = -std::numeric_limits<double>::infinity();
      for (int c = 0; c < classes; ++c) {
        const double v = ll(i, c);
        this->rows.push_back(v);
        const double score = v + logPriors(c);
        if (score > bestScore) {
          bestScore = score;
          best = c;
        }
      }
      out->predicted[static_cast<std::size_t>(t)] = best;
    }
    blockSteps.clear();
  }
};

}  // namespace

RunClassification classifyRun(const RunData& run, const ModelBundle& bundle,
                              const ClassifyOptions& options) {
  RunClassification out;
  const std::size_t steps = run.stepCount();
  out.steps = steps;
  std::vector<GroupPass> passes;
  for (const GroupInfo& info : kSensorGroups) {
    GroupClassification& go = out.groups[static_cast<std::size_t>(groupIndex(info.group))];
    go.model = bundle.find(info.group);
    go.noContactRule.resize(steps);
    go.predicted.assign(steps, std::nullopt);
    GroupPass p;
    p.out = &go;
    p.group = info.group;
    if (go.model != nullptr) {
      p.kind = go.model->features;
      p.dims = featureDimension(info.group, p.kind);
      p.classes = go.model->classifier.classCount();
      p.block.resize(kDensityBlockRows, p.dims);
      p.blockSteps.reserve(static_cast<std::size_t>(kDensityBlockRows));
      p.row.resize(static_cast<std::size_t>(p.dims));
      p.ll.resize(kDensityBlockRows, p.classes);
    }
    passes.push_back(std::move(p));
  }
  // The run in slices of steps, every group over each slice in turn: a slice's sensor values are
  // read from memory once for all groups (the context features and touch flags of one group read
  // the values of others). Each row's log-likelihoods depend neither on the slicing nor on the
  // blocks (the density is evaluated row by row).
  const double dt = stepSecondsOf(run);
  for (std::size_t s0 = 0; s0 < steps; s0 += kClassifySliceSteps) {
    const std::size_t s1 = std::min(steps, s0 + kClassifySliceSteps);
    for (GroupPass& p : passes) {
      std::vector<std::uint8_t>& zero = p.out->noContactRule;
      const bool modelled = p.out->model != nullptr;
      for (std::size_t t = s0; t < s1; ++t) {
        const double* values = run.stepSensors(t);
        const bool isZero = groupIsZero(values, p.group);
        zero[t] = isZero ? 1 : 0;
        if (isZero) {
          p.contactSteps = 0;
          continue;
        }
        if (modelled) {
          // The context of stepContextOf, kept as the walk goes (contact steps counted here
          // instead of back from every step).
          StepContext context;
          if (usesMotion(p.kind)) {
            // The motion kinds look back over up to kMotionLagCap steps' commands.
            context = stepContextOf(run, t, p.group, p.kind, dt);
          } else {
            context.values = values;
            context.laggedValues = t >= static_cast<std::size_t>(kContextLag)
                                       ? run.stepSensors(t - static_cast<std::size_t>(kContextLag))
                                       : nullptr;
            context.v = t < run.v.size() ? run.v[t] : 0.0;
            context.omega = t < run.omega.size() ? run.omega[t] : 0.0;
            context.contactSteps = p.contactSteps;
          }
          groupFeatures(context, p.group, p.kind, p.row.data());
          const Eigen::Index i = static_cast<Eigen::Index>(p.blockSteps.size());
          double* to = p.block.data() + i;
          for (int d = 0; d < p.dims; ++d)
            to[d * kDensityBlockRows] = p.row[static_cast<std::size_t>(d)];
          p.blockSteps.push_back(t);
          if (p.blockSteps.size() == static_cast<std::size_t>(kDensityBlockRows)) p.evaluate();
        }
        if (p.contactSteps < kContextCap) ++p.contactSteps;
      }
    }
  }
  for (GroupPass& p : passes) {
    if (p.out->model == nullptr) continue;
    p.evaluate();
    const auto contactRows =
        p.classes > 0 ? static_cast<Eigen::Index>(p.rows.size()) / p.classes : 0;
    p.out->logLikelihoods =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            p.rows.data(), contactRows, p.classes);
    std::vector<double>().swap(p.rows);
  }

  for (const GroupInfo& info : kSensorGroups) {
    GroupClassification& go = out.groups[static_cast<std::size_t>(groupIndex(info.group))];
    if (go.model == nullptr) continue;
    const int classes = go.model->classifier.classCount();
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
