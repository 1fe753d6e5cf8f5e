#include "analysis/model_record.h"

namespace tactile::analysis {

std::optional<double> ModelEvaluation::balancedAccuracy(DecisionMode mode) const {
  const ConfusionMatrix& c = confusion(mode);
  if (c.total() == 0) return std::nullopt;
  return computeMetrics(c).balancedAccuracy;
}

std::optional<double> ModelEvaluation::accuracy(DecisionMode mode) const {
  const ConfusionMatrix& c = confusion(mode);
  if (c.total() == 0) return std::nullopt;
  return computeMetrics(c).accuracy;
}

std::optional<double> meanSceneBalancedAccuracy(const std::vector<SceneScore>& scenes,
                                                DecisionMode mode) {
  double sum = 0.0;
  int n = 0;
  for (const SceneScore& s : scenes) {
    const ConfusionMatrix& c = s.byDecision[decisionIndex(mode)];
    if (c.total() == 0) continue;
    sum += computeMetrics(c).balancedAccuracy;
    ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

}  // namespace tactile::analysis
