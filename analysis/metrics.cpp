#include "analysis/metrics.h"

#include <algorithm>

namespace tactile::analysis {

void ConfusionMatrix::add(ContactClass truth, ContactClass predicted, std::size_t count) {
  counts_[index(truth)][index(predicted)] += count;
}

void ConfusionMatrix::merge(const ConfusionMatrix& other) {
  for (std::size_t t = 0; t < counts_.size(); ++t) {
    for (std::size_t p = 0; p < counts_.size(); ++p)
      counts_[t][p] += other.counts_[t][p];
  }
}

std::size_t ConfusionMatrix::total() const {
  std::size_t sum = 0;
  for (const auto& row : counts_) {
    for (std::size_t v : row)
      sum += v;
  }
  return sum;
}

std::size_t ConfusionMatrix::trueCount(ContactClass c) const {
  std::size_t sum = 0;
  for (std::size_t v : counts_[index(c)])
    sum += v;
  return sum;
}

std::size_t ConfusionMatrix::predictedCount(ContactClass c) const {
  std::size_t sum = 0;
  for (const auto& row : counts_)
    sum += row[index(c)];
  return sum;
}

std::optional<double> ConfusionMatrix::percent(ContactClass truth, ContactClass predicted) const {
  const std::size_t support = trueCount(truth);
  if (support == 0) return std::nullopt;
  return 100.0 * static_cast<double>(count(truth, predicted)) / static_cast<double>(support);
}

std::vector<ContactClass> ConfusionMatrix::activeClasses() const {
  std::vector<ContactClass> out;
  for (int c = 0; c < kContactClassCount; ++c) {
    const auto cls = static_cast<ContactClass>(c);
    if (trueCount(cls) > 0 || predictedCount(cls) > 0) out.push_back(cls);
  }
  return out;
}

ConfusionMatrix confusionOf(const std::vector<ContactClass>& truth,
                            const std::vector<ContactClass>& predicted) {
  ConfusionMatrix m;
  const std::size_t n = std::min(truth.size(), predicted.size());
  for (std::size_t i = 0; i < n; ++i)
    m.add(truth[i], predicted[i]);
  return m;
}

std::optional<double> Metrics::recallOf(ContactClass c) const {
  for (const ClassMetrics& m : perClass) {
    if (m.label == c) return m.recall;
  }
  return std::nullopt;
}

// recall_c = tp_c / support_c, precision_c = tp_c / predicted_c, F1_c = 2 tp / (2 tp + fp + fn);
// balanced accuracy = mean of recall_c over classes with support; macro-F1 = mean of F1_c over
// classes occurring as truth or prediction (scikit-learn's convention, zero_division = 0).
std::optional<double> cohensKappa(const ConfusionMatrix& confusion) {
  const std::size_t total = confusion.total();
  if (total == 0) return std::nullopt;
  const auto n = static_cast<double>(total);
  double observed = 0.0;
  double chance = 0.0;
  for (int i = 0; i < kContactClassCount; ++i) {
    const auto c = static_cast<ContactClass>(i);
    observed += static_cast<double>(confusion.count(c, c));
    chance += static_cast<double>(confusion.trueCount(c)) *
              static_cast<double>(confusion.predictedCount(c));
  }
  observed /= n;
  chance /= n * n;
  if (chance >= 1.0) return std::nullopt;
  return (observed - chance) / (1.0 - chance);
}

Metrics computeMetrics(const ConfusionMatrix& confusion) {
  Metrics out;
  out.total = confusion.total();
  std::size_t correct = 0;
  double recallSum = 0.0;
  std::size_t recallClasses = 0;
  double f1Sum = 0.0;
  for (ContactClass c : confusion.activeClasses()) {
    ClassMetrics m;
    m.label = c;
    m.support = confusion.trueCount(c);
    m.predicted = confusion.predictedCount(c);
    const std::size_t tp = confusion.count(c, c);
    correct += tp;
    if (m.support > 0) {
      m.recall = static_cast<double>(tp) / static_cast<double>(m.support);
      recallSum += *m.recall;
      ++recallClasses;
    }
    if (m.predicted > 0) m.precision = static_cast<double>(tp) / static_cast<double>(m.predicted);
    const std::size_t fp = m.predicted - tp;
    const std::size_t fn = m.support - tp;
    if (tp > 0) m.f1 = 2.0 * tp / static_cast<double>(2 * tp + fp + fn);
    f1Sum += m.f1;
    out.perClass.push_back(m);
  }
  if (out.total > 0) out.accuracy = static_cast<double>(correct) / static_cast<double>(out.total);
  if (recallClasses > 0) out.balancedAccuracy = recallSum / static_cast<double>(recallClasses);
  if (!out.perClass.empty()) out.macroF1 = f1Sum / static_cast<double>(out.perClass.size());
  return out;
}

std::optional<double> balancedAccuracyOver(const Metrics& metrics, std::size_t minSupport) {
  double sum = 0.0;
  int n = 0;
  for (const ClassMetrics& c : metrics.perClass) {
    if (c.support == 0 || c.support < minSupport || !c.recall) continue;
    sum += *c.recall;
    ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

std::optional<double> BinaryConfusion::classRate() const {
  const std::size_t predicted = truePositive + falsePositive;
  if (predicted == 0) return std::nullopt;
  return static_cast<double>(truePositive) / static_cast<double>(predicted);
}

std::optional<double> BinaryConfusion::restRate() const {
  const std::size_t predicted = trueNegative + falseNegative;
  if (predicted == 0) return std::nullopt;
  return static_cast<double>(trueNegative) / static_cast<double>(predicted);
}

BinaryConfusion binaryConfusionOf(ContactClass positive, const std::vector<ContactClass>& truth,
                                  const std::vector<std::uint8_t>& predictedPositive) {
  BinaryConfusion b;
  b.positive = positive;
  const std::size_t n = std::min(truth.size(), predictedPositive.size());
  for (std::size_t i = 0; i < n; ++i) {
    const bool isClass = truth[i] == positive;
    const bool saysClass = predictedPositive[i] != 0;
    if (isClass && saysClass) ++b.truePositive;
    if (!isClass && saysClass) ++b.falsePositive;
    if (isClass && !saysClass) ++b.falseNegative;
    if (!isClass && !saysClass) ++b.trueNegative;
  }
  return b;
}

std::vector<BinaryConfusion> binaryConfusions(const ConfusionMatrix& confusion,
                                              const std::vector<ContactClass>& classes) {
  std::vector<BinaryConfusion> out;
  const std::size_t total = confusion.total();
  for (ContactClass c : classes) {
    BinaryConfusion b;
    b.positive = c;
    b.truePositive = confusion.count(c, c);
    b.falsePositive = confusion.predictedCount(c) - b.truePositive;
    b.falseNegative = confusion.trueCount(c) - b.truePositive;
    b.trueNegative = total - b.truePositive - b.falsePositive - b.falseNegative;
    out.push_back(b);
  }
  return out;
}

std::string contactPattern(const RunData& run, std::size_t step, SensorGroup group) {
  const GroupInfo& info = groupInfo(group);
  std::string out(static_cast<std::size_t>(info.sensorCount), '0');
  for (int i = 0; i < info.sensorCount; ++i) {
    const int sensor = info.firstSensor + i;
    if (run.normal(step, sensor) != 0.0 || run.shear(step, sensor) != 0.0) {
      out[static_cast<std::size_t>(i)] = '1';
    }
  }
  return out;
}

std::size_t ContactPatternRow::total() const {
  std::size_t sum = 0;
  for (std::size_t v : predicted)
    sum += v;
  return sum;
}

std::size_t ContactPatternRow::errors() const {
  return total() - predicted[static_cast<std::size_t>(truth)];
}

void ContactPatternTable::add(const std::string& pattern, ContactClass truth,
                              ContactClass predicted) {
  auto it = std::find_if(rows.begin(), rows.end(), [&](const ContactPatternRow& r) {
    return r.truth == truth && r.pattern == pattern;
  });
  if (it == rows.end()) {
    rows.push_back({pattern, truth, {}});
    it = rows.end() - 1;
  }
  ++it->predicted[static_cast<std::size_t>(predicted)];
}

void ContactPatternTable::sortRows() {
  std::sort(rows.begin(), rows.end(), [](const ContactPatternRow& a, const ContactPatternRow& b) {
    if (a.truth != b.truth) return a.truth < b.truth;
    const auto onA = std::count(a.pattern.begin(), a.pattern.end(), '1');
    const auto onB = std::count(b.pattern.begin(), b.pattern.end(), '1');
    if (onA != onB) return onA < onB;
    return a.pattern < b.pattern;
  });
}

}  // namespace tactile::analysis
