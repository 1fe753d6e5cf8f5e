#include "analysis/classifier.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <thread>

#include "analysis/gaussian.h"
#include "base/parallel.h"

namespace tactile::analysis {

namespace {
constexpr std::array<std::pair<ClassifierMethod, std::string_view>, 3> kMethodNames{{
    {ClassifierMethod::Gaussian, "gaussian"},
    {ClassifierMethod::Gmm, "gmm"},
    {ClassifierMethod::Gbt, "gbt"},
}};
constexpr std::array<std::pair<PriorMode, std::string_view>, 2> kPriorNames{{
    {PriorMode::Equal, "equal"},
    {PriorMode::Empirical, "empirical"},
}};
}  // namespace

std::string_view classifierMethodName(ClassifierMethod method) {
  for (const auto& [v, n] : kMethodNames)
    if (v == method) return n;
  return "?";
}
std::optional<ClassifierMethod> parseClassifierMethod(std::string_view name) {
  for (const auto& [v, n] : kMethodNames)
    if (n == name) return v;
  return std::nullopt;
}
std::string_view priorModeName(PriorMode mode) {
  for (const auto& [v, n] : kPriorNames)
    if (v == mode) return n;
  return "?";
}
std::optional<PriorMode> parsePriorMode(std::string_view name) {
  for (const auto& [v, n] : kPriorNames)
    if (n == name) return v;
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------

namespace {

// Fills empty log priors with equal ones; otherwise the reason they are unusable, or "".
std::string checkLogPriors(Eigen::VectorXd& logPriors, std::size_t classCount) {
  const auto classes = static_cast<Eigen::Index>(classCount);
  if (logPriors.size() == 0) {
    logPriors = Eigen::VectorXd::Constant(classes, -std::log(static_cast<double>(classes)));
    return {};
  }
  if (logPriors.size() != classes)
    return std::to_string(logPriors.size()) + " priors for " + std::to_string(classes) + " classes";
  if (!logPriors.allFinite()) return "the class priors must be positive";
  const double total = logSumExp(logPriors.data(), static_cast<int>(logPriors.size()));
  if (!(std::abs(total) <= 1e-9)) return "the class priors do not sum to 1";
  return {};
}

}  // namespace

Result<ClassModelSet> ClassModelSet::createTrees(std::vector<std::string> classNames,
                                                 std::shared_ptr<const GbtModel> trees,
                                                 Eigen::VectorXd logPriors) {
  if (!trees) return Error("a classifier of trees needs its trees");
  if (static_cast<int>(classNames.size()) != trees->classCount()) {
    return Error(std::to_string(classNames.size()) + " class names for trees of " +
                 std::to_string(trees->classCount()) + " classes");
  }
  if (std::string problem = checkLogPriors(logPriors, classNames.size()); !problem.empty())
    return Error(problem);
  ClassModelSet set;
  set.method_ = ClassifierMethod::Gbt;
  set.names_ = std::move(classNames);
  set.trees_ = std::move(trees);
  set.logPriors_ = std::move(logPriors);
  return set;
}

Result<ClassModelSet> ClassModelSet::create(ClassifierMethod method,
                                            std::vector<std::string> classNames,
                                            std::vector<GaussianMixture> models,
                                            Eigen::VectorXd logPriors,
                                            std::vector<GaussianMixture> restModels) {
  const auto fail = [](std::string message) { return Error(std::move(message)); };
  if (method == ClassifierMethod::Gbt) return fail("a classifier of trees is made by createTrees");
  if (models.empty()) return fail("a classifier needs at least one class model");
  if (classNames.size() != models.size())
    return fail(std::to_string(classNames.size()) + " class names for " +
                std::to_string(models.size()) + " class models");
  const int d = models.front().dimension();
  for (std::size_t c = 0; c < models.size(); ++c) {
    if (models[c].components() == 0)
      return fail("the model of class '" + classNames[c] + "' is empty");
    if (models[c].dimension() != d)
      return fail("the model of class '" + classNames[c] + "' has dimension " +
                  std::to_string(models[c].dimension()) + ", expected " + std::to_string(d));
  }
  if (std::string problem = checkLogPriors(logPriors, models.size()); !problem.empty())
    return fail(problem);
  if (!restModels.empty()) {
    if (restModels.size() != models.size())
      return fail(std::to_string(restModels.size()) + " one-vs-rest models for " +
                  std::to_string(models.size()) + " classes");
    for (std::size_t c = 0; c < restModels.size(); ++c)
      if (restModels[c].dimension() != d || restModels[c].components() == 0)
        return fail("the one-vs-rest model of class '" + classNames[c] + "' does not match");
  }
  ClassModelSet set;
  set.method_ = method;
  set.names_ = std::move(classNames);
  set.models_ = std::move(models);
  set.restModels_ = std::move(restModels);
  set.logPriors_ = std::move(logPriors);
  return set;
}

void ClassModelSet::logLikelihoods(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const {
  if (trees_) return trees_->logScaledLikelihoods(samples, out);
  out.resize(samples.rows(), classCount());
  Eigen::VectorXd col;
  for (int c = 0; c < classCount(); ++c) {
    models_[static_cast<std::size_t>(c)].logDensities(samples, col);
    out.col(c) = col;
  }
}

std::vector<int> ClassModelSet::predictFromLogLikelihoods(const Eigen::MatrixXd& logLik) const {
  std::vector<int> out(static_cast<std::size_t>(logLik.rows()), 0);
  for (Eigen::Index r = 0; r < logLik.rows(); ++r) {
    int best = 0;
    double bestScore = -std::numeric_limits<double>::infinity();
    for (Eigen::Index c = 0; c < logLik.cols(); ++c) {
      const double score = logLik(r, c) + logPriors_(c);
      if (score > bestScore) {  // strict: ties keep the lowest index; NaN never wins
        bestScore = score;
        best = static_cast<int>(c);
      }
    }
    out[static_cast<std::size_t>(r)] = best;
  }
  return out;
}

std::vector<int> ClassModelSet::predict(const Eigen::MatrixXd& samples) const {
  Eigen::MatrixXd logLik;
  logLikelihoods(samples, logLik);
  return predictFromLogLikelihoods(logLik);
}

int ClassModelSet::predictOne(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::MatrixXd row = x.transpose();
  return predict(row).front();
}

void ClassModelSet::oneVsRestLogRatio(const Eigen::MatrixXd& samples, int c,
                                      Eigen::VectorXd& out) const {
  Eigen::VectorXd rest;
  models_[static_cast<std::size_t>(c)].logDensities(samples, out);
  if (restModels_.empty()) {
    out.setZero();
    return;
  }
  restModels_[static_cast<std::size_t>(c)].logDensities(samples, rest);
  out -= rest;
}

// ---------------------------------------------------------------------------------------------

Result<GaussianMixture> fitGaussian(const Eigen::MatrixXd& samples, double varianceFloor,
                                    Regularization reg) {
  const auto fail = [](std::string message) { return Error(std::move(message)); };
  const Eigen::Index n = samples.rows();
  const Eigen::Index d = samples.cols();
  if (d < 1) return fail("samples have no features");
  if (n < 2) return fail("a Gaussian needs at least 2 samples, got " + std::to_string(n));
  // Fewer samples than dimensions leave the covariance singular unless the floor holds it up.
  if (n < d && !(varianceFloor > 0.0))
    return fail(std::to_string(n) + " samples are fewer than the " + std::to_string(d) +
                " dimensions");
  if (!samples.allFinite()) return fail("the samples contain a non-finite value");
  if (!(varianceFloor >= 0.0) || !std::isfinite(varianceFloor))
    return fail("the variance floor must be >= 0");
  if (varianceFloor > 0.0 && varianceFloor < kMinVarianceFloor) {
    return fail(
        "the variance floor is too small to hold: use 0 for no floor, or at least "
        "2.2250738585072014e-308 (the smallest normal double)");
  }
  const Eigen::RowVectorXd mean = samples.colwise().mean();
  const Eigen::MatrixXd centred = samples.rowwise() - mean;
  Eigen::MatrixXd cov = (centred.transpose() * centred) / static_cast<double>(n - 1);
  cov = 0.5 * (cov + cov.transpose());
  if (varianceFloor > 0.0) {
    if (reg == Regularization::Add)
      cov.diagonal().array() += varianceFloor;
    else
      cov = clampEigenvalues(cov, varianceFloor);
  }
  auto model =
      GaussianMixture::create(Eigen::VectorXd::Ones(1), mean, {cov}, CovarianceForm::NodalFull);
  if (!model)
    return fail(
        "the covariance is singular (constant or linearly dependent features); use a "
        "positive variance floor");
  return model;
}

namespace {

// The class priors a fit keeps: equal, or each class's share of the training rows.
Eigen::VectorXd fitLogPriors(const std::vector<Eigen::MatrixXd>& samplesPerClass, PriorMode mode) {
  const auto classes = static_cast<Eigen::Index>(samplesPerClass.size());
  Eigen::Index totalRows = 0;
  for (const auto& x : samplesPerClass)
    totalRows += x.rows();
  Eigen::VectorXd logPriors(classes);
  for (Eigen::Index c = 0; c < classes; ++c)
    logPriors(c) =
        mode == PriorMode::Equal
            ? -std::log(static_cast<double>(classes))
            : std::log(static_cast<double>(samplesPerClass[static_cast<std::size_t>(c)].rows()) /
                       static_cast<double>(totalRows));
  return logPriors;
}

// The Gbt method: one multi-class model of boosted trees over every class's rows (checked by the
// caller), on one thread with the fit's seed.
ClassifierFit trainTrees(const std::vector<Eigen::MatrixXd>& samplesPerClass,
                         const std::vector<std::string>& classNames,
                         const ClassifierOptions& options, const ProgressFn& progress) {
  ClassifierFit fit;
  const auto start = std::chrono::steady_clock::now();
  GbtSettings settings = options.gbt;
  settings.seed = options.gmm.seed;
  // The caller's progress sees the rounds as its work units; a refusal stops the fit.
  const std::size_t classes = samplesPerClass.size();
  auto trees = GbtModel::train(samplesPerClass, settings,
                               [&progress, classes](std::size_t done, std::size_t total) {
                                 return !progress || progress(done * classes / total, classes);
                               });
  if (!trees) {
    fit.reason = trees.error().message;
    return fit;
  }
  auto shared = std::make_shared<const GbtModel>(std::move(trees.value()));
  auto set =
      ClassModelSet::createTrees(classNames, shared, fitLogPriors(samplesPerClass, options.priors));
  if (!set) {
    fit.reason = set.error().message;
    return fit;
  }
  fit.model = std::move(set.value());
  fit.iterations.assign(classes, settings.trees);
  fit.converged.assign(classes, true);
  fit.droppedComponents.assign(classes, 0);
  fit.likelihoodDrop.assign(classes, 0.0);
  // Each class's mean scaled log-likelihood over its own training rows.
  for (std::size_t c = 0; c < classes; ++c) {
    Eigen::MatrixXd scaled;
    shared->logScaledLikelihoods(samplesPerClass[c], scaled);
    fit.trainMeanLogLikelihood.push_back(scaled.col(static_cast<Eigen::Index>(c)).mean());
  }
  fit.fitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress) progress(classes, classes);
  fit.ok = true;
  return fit;
}

}  // namespace

ClassifierFit trainClassifier(const std::vector<Eigen::MatrixXd>& samplesPerClass,
                              const std::vector<std::string>& classNames,
                              const ClassifierOptions& options, const ProgressFn& progress) {
  ClassifierFit fit;
  const auto fail = [&](std::string reason) {
    fit.ok = false;
    fit.reason = std::move(reason);
    return fit;
  };
  const std::size_t classes = samplesPerClass.size();
  if (classes == 0) return fail("no classes to train");
  if (classNames.size() != classes)
    return fail(std::to_string(classNames.size()) + " class names for " + std::to_string(classes) +
                " classes");
  const Eigen::Index d = samplesPerClass.front().cols();
  for (std::size_t c = 0; c < classes; ++c) {
    const Eigen::MatrixXd& x = samplesPerClass[c];
    const std::string who = "class '" + classNames[c] + "'";
    if (x.rows() == 0) return fail(who + " has no training samples");
    if (x.cols() != d)
      return fail(who + " has " + std::to_string(x.cols()) + " features, expected " +
                  std::to_string(d));
    // Trees need no more rows than features; a density does.
    const bool density = options.method != ClassifierMethod::Gbt;
    if (density && x.rows() < d && !options.fewSamples)
      return fail(who + " has " + std::to_string(x.rows()) + " training samples, fewer than its " +
                  std::to_string(d) + " dimensions");
    if (density && x.rows() < d && !(options.gmm.varianceFloor > 0.0))
      return fail(who + " has " + std::to_string(x.rows()) + " training samples, fewer than its " +
                  std::to_string(d) +
                  " dimensions: its covariance would be singular without a variance floor > 0");
    if (!x.allFinite()) return fail(who + " has a non-finite feature value");
  }

  if (options.method == ClassifierMethod::Gbt)
    return trainTrees(samplesPerClass, classNames, options, progress);

  // Tasks: one fit per class, plus (Gaussian, one-vs-rest, more than one class) one "rest" fit.
  const bool withRest =
      options.method == ClassifierMethod::Gaussian && options.oneVsRest && classes > 1;
  const std::size_t taskCount = withRest ? 2 * classes : classes;
  std::vector<Eigen::Index> taskRows(taskCount);
  Eigen::Index totalRows = 0;
  for (const auto& x : samplesPerClass)
    totalRows += x.rows();
  for (std::size_t t = 0; t < taskCount; ++t)
    taskRows[t] =
        t < classes ? samplesPerClass[t].rows() : totalRows - samplesPerClass[t - classes].rows();
  // Biggest first, so two workers finish together.
  std::vector<std::size_t> order(taskCount);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return taskRows[a] > taskRows[b]; });

  int threads = options.threads > 0
                    ? options.threads
                    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // One fit per worker when there are several fits; all workers inside EM otherwise.
  const int workers = std::clamp<int>(threads, 1, static_cast<int>(taskCount));
  const int innerThreads = workers > 1 ? 1 : threads;

  std::vector<std::optional<GaussianMixture>> results(taskCount);
  std::vector<std::string> reasons(taskCount);
  fit.iterations.assign(classes, 0);
  std::vector<char> converged(classes, 0);  // not vector<bool>: written from several threads
  fit.trainMeanLogLikelihood.assign(classes, 0.0);
  fit.droppedComponents.assign(classes, 0);
  fit.likelihoodDrop.assign(classes, 0.0);
  std::atomic<bool> cancelled{false};
  std::mutex progressMutex;
  std::size_t done = 0;
  // Called by every running fit after each EM iteration: consults the caller's progress, so a
  // cancel stops running fits within one iteration.
  const ProgressFn inner = [&](std::size_t, std::size_t) {
    if (cancelled.load()) return false;
    if (!progress) return true;
    std::lock_guard<std::mutex> lock(progressMutex);
    if (cancelled.load()) return false;
    if (!progress(done, taskCount)) cancelled = true;
    return !cancelled.load();
  };

  const auto runTask = [&](std::size_t t) {
    if (t < classes) {
      const Eigen::MatrixXd& x = samplesPerClass[t];
      if (options.method == ClassifierMethod::Gaussian) {
        Result<GaussianMixture> g = fitGaussian(x, options.gmm.varianceFloor, options.gmm.reg);
        if (g) {
          results[t] = std::move(g.value());
        } else {
          reasons[t] = g.error().message;
        }
        fit.iterations[t] = 1;
        converged[t] = results[t].has_value() ? 1 : 0;
        if (results[t]) fit.trainMeanLogLikelihood[t] = results[t]->meanLogLikelihood(x);
      } else {
        GmmOptions o = options.gmm;
        o.threads = innerThreads;
        GmmFit g = fitGmm(x, o, inner);
        if (g.ok) {
          results[t] = std::move(g.model);
          fit.iterations[t] = g.iterations;
          converged[t] = g.converged ? 1 : 0;
          fit.trainMeanLogLikelihood[t] = g.meanLogLikelihood;
          fit.droppedComponents[t] = g.droppedComponents;
          fit.likelihoodDrop[t] = g.likelihoodDrop;
        } else {
          reasons[t] = g.reason;
        }
      }
    } else {
      const std::size_t c = t - classes;
      Eigen::MatrixXd rest(totalRows - samplesPerClass[c].rows(), d);
      Eigen::Index row = 0;
      for (std::size_t o = 0; o < classes; ++o) {
        if (o == c) continue;
        rest.middleRows(row, samplesPerClass[o].rows()) = samplesPerClass[o];
        row += samplesPerClass[o].rows();
      }
      Result<GaussianMixture> g = fitGaussian(rest, options.gmm.varianceFloor, options.gmm.reg);
      if (g) {
        results[t] = std::move(g.value());
      } else {
        reasons[t] = g.error().message;
      }
    }
    std::lock_guard<std::mutex> lock(progressMutex);
    ++done;
    if (!cancelled.load() && progress && !progress(done, taskCount)) cancelled = true;
  };
  const auto start = std::chrono::steady_clock::now();
  // An exception in any fit (out of memory) reaches the caller after every worker stopped.
  parallelFor(taskCount, static_cast<unsigned>(workers), [&](std::size_t i) {
    if (cancelled.load()) return false;
    runTask(order[i]);
    return !cancelled.load();
  });
  fit.fitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cancelled.load()) return fail("cancelled");
  for (char c : converged)
    fit.converged.push_back(c != 0);

  std::vector<GaussianMixture> models;
  std::vector<GaussianMixture> rest;
  for (std::size_t t = 0; t < taskCount; ++t) {
    if (!results[t]) {
      const std::size_t c = t < classes ? t : t - classes;
      return fail(std::string(t < classes ? "class '" : "the one-vs-rest model of class '") +
                  classNames[c] + "': " + reasons[t]);
    }
    (t < classes ? models : rest).push_back(std::move(*results[t]));
  }
  auto set = ClassModelSet::create(options.method, classNames, std::move(models),
                                   fitLogPriors(samplesPerClass, options.priors), std::move(rest));
  if (!set) return fail(set.error().message);
  fit.model = std::move(set.value());
  // The floor against each feature's variance over every class's rows together: the spread that
  // could tell the classes apart (read where the rows are, not copied into one table).
  fit.warnings =
      varianceFloorWarnings(samplesPerClass, options.gmm.varianceFloor, options.featureNames);
  fit.ok = true;
  return fit;
}

HeldOutLogLikelihood heldOutLogLikelihood(const Eigen::MatrixXd& logLik,
                                          const std::vector<int>& truth) {
  HeldOutLogLikelihood out;
  double sum = 0.0;
  for (std::size_t r = 0; r < truth.size(); ++r) {
    const int c = truth[r];
    if (c < 0) continue;
    const double v = logLik(static_cast<Eigen::Index>(r), c);
    if (!std::isfinite(v)) {
      ++out.negInfRows;
      continue;
    }
    sum += v;
    ++out.rows;
  }
  if (out.rows > 0) out.mean = sum / static_cast<double>(out.rows);
  return out;
}

}  // namespace tactile::analysis
