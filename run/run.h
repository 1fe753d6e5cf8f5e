// One recorded run in memory: per-step pose, command, blocked flag, 88 sensor values and optional
// ground truth, stored column-wise so long runs stay compact and fast to scan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile {

inline constexpr std::string_view kRunFormat = "tactile-run 1";

// Unreachable: the driver found no way to the goal (wall-follow: it walked all round the obstacle
// in its way).
enum class RunOutcome : std::uint8_t { Unknown, Success, GaveUp, Timeout, Unreachable };
std::string_view runOutcomeName(RunOutcome outcome);  // "success", "gave-up", "unreachable", ...
std::optional<RunOutcome> parseRunOutcome(std::string_view name);

struct Pose2d {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  // radians
};

// Move-only: a run can hold millions of values, and an accidental copy is a bug. Use clone().
class RunData {
 public:
  RunData() = default;
  RunData(RunData&&) noexcept = default;
  RunData& operator=(RunData&&) noexcept = default;
  RunData(const RunData&) = delete;
  RunData& operator=(const RunData&) = delete;
  RunData clone() const;

  // Metadata lines in file order, `format` included when present. Known keys (format, scene,
  // subject, dt, start, goal, outcome) are validated on read; unknown keys are kept as attributes.
  std::vector<std::pair<std::string, std::string>> metadata;

  std::vector<double> x, y, theta, v, omega;
  std::vector<std::uint8_t> blocked;
  // stepCount() * kValuesPerStep values: n0, s0, n1, s1, ..., n43, s43 for each step.
  std::vector<double> sensors;
  // Empty, or stepCount() * kGroupCount classes in group order.
  std::vector<ContactClass> truth;
  // `x_`-prefixed columns, kept as text: stepCount() * extraColumns.size() values, row-major.
  std::vector<std::string> extraColumns;
  std::vector<std::string> extraValues;

  std::size_t stepCount() const { return x.size(); }
  bool hasTruth() const { return !truth.empty(); }

  double normal(std::size_t step, int sensor) const {
    return sensors[step * kValuesPerStep + normalOffset(sensor)];
  }
  double shear(std::size_t step, int sensor) const {
    return sensors[step * kValuesPerStep + shearOffset(sensor)];
  }
  const double* stepSensors(std::size_t step) const {
    return sensors.data() + step * kValuesPerStep;
  }
  ContactClass truthAt(std::size_t step, SensorGroup g) const {
    return truth[step * kGroupCount + groupIndex(g)];
  }

  // Metadata access. Typed getters return nullopt when the key is absent (values were validated
  // by the reader; for hand-built runs an unparsable value also gives nullopt).
  const std::string* meta(std::string_view key) const;
  void setMeta(std::string_view key, std::string value);  // replaces or appends
  std::optional<double> dtSeconds() const;
  std::optional<Pose2d> start() const;
  std::optional<std::pair<double, double>> goal() const;
  RunOutcome outcome() const;

  // Reserves and appends one step (sensors: kValuesPerStep values; truth: kGroupCount or null).
  void reserve(std::size_t steps, bool withTruth);
  void appendStep(double px, double py, double ptheta, double pv, double pomega, bool isBlocked,
                  const double* stepValues, const ContactClass* stepTruth);
};

bool operator==(const RunData& a, const RunData& b);

}  // namespace tactile
