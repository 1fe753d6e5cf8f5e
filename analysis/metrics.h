// Classification metrics (docs/analysis.md#metrics-metricsh): confusion matrix in counts and
// percent, per-class recall and precision, accuracy, balanced accuracy, macro-F1; the one-vs-rest
// correct rates of thesis table 4.19; and the contact-pattern error table of thesis table 4.39.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "run/contact_class.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

// Counts of (true class, predicted class) over all five contact classes. Rows are the true class,
// columns the predicted class (the thesis tables print the transpose with rows summing to 100 %;
// we keep rows = truth so that row percent = recall).
class ConfusionMatrix {
 public:
  void add(ContactClass truth, ContactClass predicted, std::size_t count = 1);
  void merge(const ConfusionMatrix& other);

  std::size_t count(ContactClass truth, ContactClass predicted) const {
    return counts_[index(truth)][index(predicted)];
  }
  std::size_t total() const;
  std::size_t trueCount(ContactClass c) const;       // row sum (support)
  std::size_t predictedCount(ContactClass c) const;  // column sum
  // Row percent: 100 * count(t, p) / trueCount(t); nullopt when the class has no true samples.
  std::optional<double> percent(ContactClass truth, ContactClass predicted) const;
  // Classes that occur as truth or as prediction, in ContactClass order.
  std::vector<ContactClass> activeClasses() const;

  bool operator==(const ConfusionMatrix&) const = default;

 private:
  static std::size_t index(ContactClass c) { return static_cast<std::size_t>(c); }
  std::array<std::array<std::size_t, kContactClassCount>, kContactClassCount> counts_{};
};

ConfusionMatrix confusionOf(const std::vector<ContactClass>& truth,
                            const std::vector<ContactClass>& predicted);

struct ClassMetrics {
  ContactClass label = ContactClass::NoContact;
  std::size_t support = 0;          // true samples
  std::size_t predicted = 0;        // samples predicted as this class
  std::optional<double> recall;     // tp / support; nullopt when support = 0
  std::optional<double> precision;  // tp / predicted; nullopt when nothing was predicted so
  double f1 = 0.0;                  // 2 tp / (2 tp + fp + fn); 0 when tp = 0
};

// Summary metrics. With no samples at all every rate is 0 and `total` is 0: callers check total.
struct Metrics {
  std::size_t total = 0;
  double accuracy = 0.0;               // trace / total
  double balancedAccuracy = 0.0;       // mean recall over classes with support > 0
  double macroF1 = 0.0;                // mean F1 over classes occurring as truth or prediction
  std::vector<ClassMetrics> perClass;  // activeClasses() order
  // Recall of a class, or nullopt when it has no support.
  std::optional<double> recallOf(ContactClass c) const;
};

Metrics computeMetrics(const ConfusionMatrix& confusion);

// A class with fewer test steps than this is "too few": its rate is shown but marked, and it
// never decides which setting is best (settable: --min-test-steps).
inline constexpr std::size_t kMinTestSteps = 30;
// Balanced accuracy over the classes with at least minSupport test steps only; nullopt when no
// class has that many.
std::optional<double> balancedAccuracyOver(const Metrics& metrics, std::size_t minSupport);

// Cohen's kappa of two raters (rows one rater, columns the other): (po - pe) / (1 - pe), with po
// the observed agreement and pe the agreement expected by chance from the row and column totals
// (Cohen 1960). nullopt when there are no samples or when pe = 1 (both raters used one and the
// same class for every sample: kappa is undefined there, as in scikit-learn).
std::optional<double> cohensKappa(const ConfusionMatrix& confusion);

// Binary confusion of one one-vs-rest classifier (thesis tables 4.1 to 4.18).
struct BinaryConfusion {
  ContactClass positive = ContactClass::Wall;
  std::size_t truePositive = 0;   // class, predicted class
  std::size_t falsePositive = 0;  // not class, predicted class
  std::size_t falseNegative = 0;  // class, predicted not class
  std::size_t trueNegative = 0;   // not class, predicted not class

  // The thesis's "correct rate" (section 4.3.3): correct identifications over all predictions of
  // that label. Class: tp / (tp + fp); "No class": tn / (tn + fn). nullopt when never predicted.
  std::optional<double> classRate() const;
  std::optional<double> restRate() const;
};

// truth[i] against a yes/no decision "is `positive`" per sample.
BinaryConfusion binaryConfusionOf(ContactClass positive, const std::vector<ContactClass>& truth,
                                  const std::vector<std::uint8_t>& predictedPositive);

// One-vs-rest counts of each class read off a multi-class confusion (the argmax decision "is c"),
// for the thesis table 4.19 layout of a classifier without rest models (sweep cells).
std::vector<BinaryConfusion> binaryConfusions(const ConfusionMatrix& confusion,
                                              const std::vector<ContactClass>& classes);

// On/off pattern of a group's sensors at a step, one character per sensor in index order ('1' where
// n or s is non-zero), as in the "Contact Situation" column of thesis table 4.39.
std::string contactPattern(const RunData& run, std::size_t step, SensorGroup group);

// Counts of true and predicted classes per on/off pattern (thesis table 4.39).
struct ContactPatternRow {
  std::string pattern;
  ContactClass truth = ContactClass::NoContact;
  std::array<std::size_t, kContactClassCount> predicted{};  // counts by predicted class
  std::size_t total() const;
  std::size_t errors() const;  // predictions other than `truth`
};

struct ContactPatternTable {
  SensorGroup group = SensorGroup::Front;
  // Sorted by truth, then number of sensors on, then pattern text.
  std::vector<ContactPatternRow> rows;

  void add(const std::string& pattern, ContactClass truth, ContactClass predicted);
  void sortRows();
};

}  // namespace tactile::analysis
