#include "analysis/gbt.h"

#include <xgboost/c_api.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

namespace tactile::analysis {
namespace {

// XGBoost's own message for its last failed call.
std::string xgboostError(const char* what) {
  const char* text = XGBGetLastError();
  return std::string("gradient-boosted trees: ") + what + ": " +
         (text != nullptr && *text != '\0' ? text : "unknown error");
}

// A DMatrix that frees itself.
struct Matrix {
  DMatrixHandle handle = nullptr;
  ~Matrix() {
    if (handle != nullptr) XGDMatrixFree(handle);
  }
};

// Rows as XGBoost takes them: row-major 32-bit floats.
std::vector<float> rowMajorFloats(const Eigen::MatrixXd& samples) {
  std::vector<float> out(static_cast<std::size_t>(samples.rows() * samples.cols()));
  for (Eigen::Index r = 0; r < samples.rows(); ++r) {
    for (Eigen::Index c = 0; c < samples.cols(); ++c)
      out[static_cast<std::size_t>(r * samples.cols() + c)] = static_cast<float>(samples(r, c));
  }
  return out;
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

}  // namespace

std::string describeGbtSettings(const GbtSettings& s) {
  std::ostringstream text;
  text << "trees " << s.trees << ", depth " << s.depth << ", learning rate " << s.learningRate
       << ", min child weight " << s.minChildWeight;
  return text.str();
}

std::string checkGbtSettings(const GbtSettings& s) {
  if (s.trees < 1 || s.trees > 5000)
    return "trees " + std::to_string(s.trees) + " is out of range: a whole number from 1 to 5000";
  if (s.depth < 1 || s.depth > 16)
    return "depth " + std::to_string(s.depth) + " is out of range: a whole number from 1 to 16";
  if (!(s.learningRate > 0.0 && s.learningRate <= 1.0))
    return "learning rate " + number(s.learningRate) + " is out of range: above 0, at most 1";
  if (!(s.minChildWeight >= 0.0) || !std::isfinite(s.minChildWeight))
    return "min child weight " + number(s.minChildWeight) + " is out of range: 0 or more";
  return {};
}

struct GbtModel::Booster {
  BoosterHandle handle = nullptr;
  ~Booster() {
    if (handle != nullptr) XGBoosterFree(handle);
  }
  // One thread always: the model and its predictions do not depend on the machine.
  bool singleThreaded() { return XGBoosterSetParam(handle, "nthread", "1") == 0; }
};

GbtModel::GbtModel() = default;
GbtModel::~GbtModel() = default;
GbtModel::GbtModel(GbtModel&&) noexcept = default;
GbtModel& GbtModel::operator=(GbtModel&&) noexcept = default;

Result<GbtModel> GbtModel::train(const std::vector<Eigen::MatrixXd>& samplesPerClass,
                                 const GbtSettings& settings, const ProgressFn& progress) {
  if (std::string problem = checkGbtSettings(settings); !problem.empty())
    return Result<GbtModel>::failure(problem);
  const auto classes = static_cast<int>(samplesPerClass.size());
  if (classes < 2) {
    return Result<GbtModel>::failure(
        "gradient-boosted trees need at least two classes with rows, got " +
        std::to_string(classes));
  }
  const Eigen::Index dimension = samplesPerClass.front().cols();
  Eigen::Index rows = 0;
  for (int c = 0; c < classes; ++c) {
    const Eigen::MatrixXd& m = samplesPerClass[static_cast<std::size_t>(c)];
    if (m.rows() == 0)
      return Result<GbtModel>::failure("class " + std::to_string(c) + " has no training rows");
    if (m.cols() != dimension || dimension == 0) {
      return Result<GbtModel>::failure("class " + std::to_string(c) + " has " +
                                       std::to_string(m.cols()) + " features, class 0 " +
                                       std::to_string(dimension));
    }
    if (!m.allFinite()) {
      return Result<GbtModel>::failure("class " + std::to_string(c) +
                                       " has a value that is not a finite number");
    }
    rows += m.rows();
  }

  // Rows, labels and class-balanced weights (each class's weights sum to rows / classes).
  std::vector<float> data;
  std::vector<float> labels;
  std::vector<float> weights;
  data.reserve(static_cast<std::size_t>(rows * dimension));
  for (int c = 0; c < classes; ++c) {
    const Eigen::MatrixXd& m = samplesPerClass[static_cast<std::size_t>(c)];
    const std::vector<float> part = rowMajorFloats(m);
    data.insert(data.end(), part.begin(), part.end());
    const auto weight =
        static_cast<float>(static_cast<double>(rows) / (static_cast<double>(classes) * m.rows()));
    labels.insert(labels.end(), static_cast<std::size_t>(m.rows()), static_cast<float>(c));
    weights.insert(weights.end(), static_cast<std::size_t>(m.rows()), weight);
  }
  Matrix train;
  if (XGDMatrixCreateFromMat(data.data(), static_cast<bst_ulong>(rows),
                             static_cast<bst_ulong>(dimension),
                             std::numeric_limits<float>::quiet_NaN(), &train.handle) != 0 ||
      XGDMatrixSetFloatInfo(train.handle, "label", labels.data(),
                            static_cast<bst_ulong>(labels.size())) != 0 ||
      XGDMatrixSetFloatInfo(train.handle, "weight", weights.data(),
                            static_cast<bst_ulong>(weights.size())) != 0) {
    return Result<GbtModel>::failure(xgboostError("cannot hold the training rows"));
  }

  GbtModel model;
  model.booster_ = std::make_unique<Booster>();
  model.classes_ = classes;
  model.dimension_ = static_cast<int>(dimension);
  if (XGBoosterCreate(&train.handle, 1, &model.booster_->handle) != 0)
    return Result<GbtModel>::failure(xgboostError("cannot make a booster"));
  const std::pair<const char*, std::string> params[] = {
      {"objective", "multi:softprob"},
      {"num_class", std::to_string(classes)},
      {"max_depth", std::to_string(settings.depth)},
      {"eta", number(settings.learningRate)},
      {"min_child_weight", number(settings.minChildWeight)},
      {"tree_method", "hist"},
      {"seed", std::to_string(settings.seed)},
      {"verbosity", "0"},
  };
  if (!model.booster_->singleThreaded())
    return Result<GbtModel>::failure(xgboostError("cannot set one thread"));
  for (const auto& [key, value] : params) {
    if (XGBoosterSetParam(model.booster_->handle, key, value.c_str()) != 0)
      return Result<GbtModel>::failure(xgboostError(key));
  }
  for (int round = 0; round < settings.trees; ++round) {
    if (XGBoosterUpdateOneIter(model.booster_->handle, round, train.handle) != 0)
      return Result<GbtModel>::failure(xgboostError("training failed"));
    if (progress &&
        !progress(static_cast<std::size_t>(round) + 1, static_cast<std::size_t>(settings.trees)))
      return Result<GbtModel>::failure("cancelled");
  }
  return model;
}

Result<std::string> GbtModel::serialize() const {
  if (!booster_) return Result<std::string>::failure("no trees to store");
  bst_ulong length = 0;
  const char* bytes = nullptr;
  if (XGBoosterSaveModelToBuffer(booster_->handle, R"({"format": "json"})", &length, &bytes) != 0)
    return Result<std::string>::failure(xgboostError("cannot write the trees"));
  return std::string(bytes, static_cast<std::size_t>(length));
}

Result<GbtModel> GbtModel::load(const std::string& bytes, int classCount, int dimension) {
  if (classCount < 2 || dimension < 1) {
    return Result<GbtModel>::failure("stored trees need at least two classes and one feature");
  }
  GbtModel model;
  model.booster_ = std::make_unique<Booster>();
  model.classes_ = classCount;
  model.dimension_ = dimension;
  if (XGBoosterCreate(nullptr, 0, &model.booster_->handle) != 0 ||
      XGBoosterLoadModelFromBuffer(model.booster_->handle, bytes.data(),
                                   static_cast<bst_ulong>(bytes.size())) != 0) {
    return Result<GbtModel>::failure(xgboostError("the stored trees do not load"));
  }
  if (!model.booster_->singleThreaded())
    return Result<GbtModel>::failure(xgboostError("cannot set one thread"));
  // The trees must answer with one probability per class for a row of `dimension` features.
  Eigen::MatrixXd probe = Eigen::MatrixXd::Zero(1, dimension);
  Eigen::MatrixXd out;
  if (!model.predict(probe, out) || !out.allFinite()) {
    return Result<GbtModel>::failure("the stored trees are not a classifier of " +
                                     std::to_string(classCount) + " classes over " +
                                     std::to_string(dimension) + " features");
  }
  return model;
}

bool GbtModel::predict(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const {
  const Eigen::Index n = samples.rows();
  out.resize(n, classes_);
  if (n == 0) return true;
  if (!booster_) return false;
  const std::vector<float> data = rowMajorFloats(samples);
  // In place from the dense rows (no DMatrix is built), as raw margins: the log posteriors are
  // their log-softmax, taken here in double precision (no probability rounded to float, none
  // clamped away from 0 before its log).
  char values[192];
  std::snprintf(values, sizeof values,
                R"({"data": [%llu, true], "shape": [%lld, %lld], "typestr": "<f4", "version": 3})",
                static_cast<unsigned long long>(reinterpret_cast<std::uintptr_t>(data.data())),
                static_cast<long long>(n), static_cast<long long>(samples.cols()));
  static constexpr const char* kMarginConfig =
      R"({"type": 1, "training": false, "iteration_begin": 0, "iteration_end": 0, )"
      R"("strict_shape": true, "missing": NaN, "cache_id": 0})";
  const bst_ulong* shape = nullptr;
  bst_ulong dimensions = 0;
  const float* margins = nullptr;
  if (XGBoosterPredictFromDense(booster_->handle, values, kMarginConfig, nullptr, &shape,
                                &dimensions, &margins) != 0 ||
      dimensions != 2 || shape[0] != static_cast<bst_ulong>(n) ||
      shape[1] != static_cast<bst_ulong>(classes_)) {
    return false;
  }
  for (Eigen::Index r = 0; r < n; ++r) {
    double largest = -std::numeric_limits<double>::infinity();
    for (int c = 0; c < classes_; ++c) {
      const float m = margins[r * classes_ + c];
      if (!std::isfinite(m)) return false;
      out(r, c) = m;
      largest = std::max(largest, static_cast<double>(m));
    }
    double sum = 0.0;
    for (int c = 0; c < classes_; ++c)
      sum += std::exp(out(r, c) - largest);
    out.row(r).array() -= largest + std::log(sum);
  }
  return true;
}

void GbtModel::logPosteriors(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const {
  // Never a NaN: without an answer every class is equally likely.
  if (!predict(samples, out)) out.setConstant(-std::log(static_cast<double>(classes_)));
}

void GbtModel::logScaledLikelihoods(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const {
  logPosteriors(samples, out);
  out.array() += std::log(static_cast<double>(classes_));
}

}  // namespace tactile::analysis
