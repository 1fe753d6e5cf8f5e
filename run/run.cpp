#include "run/run.h"

#include <array>

#include "base/text_parse.h"

namespace tactile {
namespace {
constexpr std::array<std::string_view, 5> kOutcomeNames{"unknown", "success", "gave-up", "timeout",
                                                        "unreachable"};
}  // namespace

std::string_view runOutcomeName(RunOutcome outcome) {
  return kOutcomeNames[static_cast<std::size_t>(outcome)];
}

std::optional<RunOutcome> parseRunOutcome(std::string_view name) {
  for (std::size_t i = 0; i < kOutcomeNames.size(); ++i) {
    if (kOutcomeNames[i] == name) return static_cast<RunOutcome>(i);
  }
  return std::nullopt;
}

RunData RunData::clone() const {
  RunData copy;
  copy.metadata = metadata;
  copy.x = x;
  copy.y = y;
  copy.theta = theta;
  copy.v = v;
  copy.omega = omega;
  copy.blocked = blocked;
  copy.sensors = sensors;
  copy.truth = truth;
  copy.extraColumns = extraColumns;
  copy.extraValues = extraValues;
  return copy;
}

const std::string* RunData::meta(std::string_view key) const {
  for (const auto& [k, v] : metadata) {
    if (k == key) return &v;
  }
  return nullptr;
}

void RunData::setMeta(std::string_view key, std::string value) {
  for (auto& [k, v] : metadata) {
    if (k == key) {
      v = std::move(value);
      return;
    }
  }
  metadata.emplace_back(std::string(key), std::move(value));
}

std::optional<double> RunData::dtSeconds() const {
  const std::string* text = meta("dt");
  double value = 0.0;
  if (text == nullptr || !parseFiniteDouble(*text, value)) return std::nullopt;
  return value;
}

std::optional<Pose2d> RunData::start() const {
  const std::string* text = meta("start");
  std::vector<double> values;
  if (text == nullptr || !parseDoubleList(*text, 3, values)) return std::nullopt;
  return Pose2d{values[0], values[1], values[2]};
}

std::optional<std::pair<double, double>> RunData::goal() const {
  const std::string* text = meta("goal");
  std::vector<double> values;
  if (text == nullptr || !parseDoubleList(*text, 2, values)) return std::nullopt;
  return std::pair{values[0], values[1]};
}

RunOutcome RunData::outcome() const {
  const std::string* text = meta("outcome");
  if (text == nullptr) return RunOutcome::Unknown;
  return parseRunOutcome(*text).value_or(RunOutcome::Unknown);
}

void RunData::reserve(std::size_t steps, bool withTruth) {
  for (auto* column : {&x, &y, &theta, &v, &omega})
    column->reserve(steps);
  blocked.reserve(steps);
  sensors.reserve(steps * kValuesPerStep);
  if (withTruth) truth.reserve(steps * kGroupCount);
}

void RunData::appendStep(double px, double py, double ptheta, double pv, double pomega,
                         bool isBlocked, const double* stepValues, const ContactClass* stepTruth) {
  x.push_back(px);
  y.push_back(py);
  theta.push_back(ptheta);
  v.push_back(pv);
  omega.push_back(pomega);
  blocked.push_back(isBlocked ? 1 : 0);
  sensors.insert(sensors.end(), stepValues, stepValues + kValuesPerStep);
  if (stepTruth != nullptr) truth.insert(truth.end(), stepTruth, stepTruth + kGroupCount);
}

bool operator==(const RunData& a, const RunData& b) {
  return a.metadata == b.metadata && a.x == b.x && a.y == b.y && a.theta == b.theta && a.v == b.v &&
         a.omega == b.omega && a.blocked == b.blocked && a.sensors == b.sensors &&
         a.truth == b.truth && a.extraColumns == b.extraColumns && a.extraValues == b.extraValues;
}

}  // namespace tactile
