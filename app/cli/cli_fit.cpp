// Feature-table verbs: fit, bench learn.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/feature_table.h"
#include "analysis/gmm.h"
#include "analysis/gmm_synthetic.h"
#include "app/cli/cli_classifier_options.h"
#include "app/cli/cli_common.h"
#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "run/run_csv.h"

namespace tactile::cli {
namespace {

using namespace tactile::analysis;

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Train on `train`, test on `test` (labels already mapped onto the training classes).
struct Evaluation {
  ClassifierFit fit;
  double accuracy = 0.0;
  HeldOutLogLikelihood logLik;  // the held-out mean log-likelihood and its -inf rows
  double predictSeconds = 0.0;
  // From the table in memory to the classifier: the rows split by class, the fits and the checks
  // after them (fit.fitSeconds is the fits alone).
  double trainSeconds = 0.0;
  std::vector<std::vector<long>> confusion;  // [true][predicted]
};

Evaluation trainAndTest(const FeatureTable& train, const FeatureTable& test,
                        const ClassifierOptions& options) {
  Evaluation e;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Eigen::MatrixXd> perClass = splitByClass(train);
  e.fit = trainClassifier(perClass, train.classNames, options);
  e.trainSeconds = secondsSince(start);
  if (!e.fit.ok) return e;
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::MatrixXd logLik;
  e.fit.model.logLikelihoods(test.features, logLik);
  const std::vector<int> predicted = e.fit.model.predictFromLogLikelihoods(logLik);
  e.predictSeconds = secondsSince(t0);
  const std::size_t classes = train.classNames.size();
  e.confusion.assign(classes, std::vector<long>(classes, 0));
  long correct = 0;
  for (std::size_t r = 0; r < predicted.size(); ++r) {
    const int truth = test.labels[r];
    ++e.confusion[static_cast<std::size_t>(truth)][static_cast<std::size_t>(predicted[r])];
    if (truth == predicted[r]) ++correct;
  }
  const double n = static_cast<double>(predicted.size());
  e.accuracy = n > 0 ? static_cast<double>(correct) / n : 0.0;
  e.logLik = heldOutLogLikelihood(logLik, test.labels);
  return e;
}

nlohmann::json optionalNumber(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

// Feature column names of a table as written by formatFeatureTable: f0, f1, ...
std::vector<std::string> featureNames(int dimension) {
  std::vector<std::string> names;
  for (int j = 0; j < dimension; ++j)
    names.push_back("f" + std::to_string(j));
  return names;
}

FeatureTable loadTable(const std::string& path) {
  Result<FeatureTable> r = readFeatureTable(path);
  if (!r) throw std::runtime_error(r.errorText());
  return std::move(r.value());
}

struct FitArgs {
  std::string train;
  std::string test;
  bool json = false;
};

int runFit(const FitArgs& f, const ClassifierArgs& a) {
  ClassifierOptions options = toClassifierOptions(a);
  // `fit` scores by the per-class likelihoods alone: no one-vs-rest "rest" models to fit.
  options.oneVsRest = false;
  FeatureTable train = loadTable(f.train);
  options.featureNames = featureNames(train.dimension());
  FeatureTable test = loadTable(f.test.empty() ? f.train : f.test);
  if (test.dimension() != train.dimension())
    throw std::runtime_error(f.test + ": " + std::to_string(test.dimension()) +
                             " feature columns, but the training table has " +
                             std::to_string(train.dimension()));
  const Status remapped = remapLabels(test, train.classNames, f.test.empty() ? f.train : f.test);
  if (!remapped) throw std::runtime_error(remapped.errorText());
  const Evaluation e = trainAndTest(train, test, options);
  if (!e.fit.ok) {
    printError(f.train + ": " + e.fit.reason);
    return kExitFailure;
  }
  int iterations = 0;
  for (int it : e.fit.iterations)
    iterations = std::max(iterations, it);
  bool converged = true;
  for (bool c : e.fit.converged)
    converged = converged && c;
  int dropped = 0;
  for (int k : e.fit.droppedComponents)
    dropped += k;
  std::vector<int> components;
  for (const GaussianMixture& m : e.fit.model.models())
    components.push_back(m.components());
  for (const std::string& w : e.fit.warnings)
    printWarning(w);
  const bool gaussian = options.method == ClassifierMethod::Gaussian;
  if (f.json) {
    nlohmann::json j;
    j["accuracy"] = e.accuracy;
    j["mean_loglik"] = optionalNumber(e.logLik.mean);
    j["neg_inf_rows"] = e.logLik.negInfRows;
    j["fit_s"] = e.fit.fitSeconds;
    j["train_s"] = e.trainSeconds;
    j["predict_s"] = e.predictSeconds;
    j["kernel_isa"] = kernelIsa();
    j["iterations"] = iterations;
    j["iterations_per_class"] = e.fit.iterations;
    j["converged"] = converged;
    j["classes"] = train.classNames;
    j["confusion"] = e.confusion;
    j["train_rows"] = train.rows();
    j["test_rows"] = test.rows();
    j["method"] = a.method;
    if (!gaussian) {  // the Gaussian method has no order, covariance form or initialisation
      j["order"] = a.order;
      j["covariance"] = a.cov;
      j["init"] = a.init;
    }
    j["floor"] = a.floor;
    j["regularization"] = a.reg;
    j["train_mean_loglik"] = e.fit.trainMeanLogLikelihood;
    j["components_per_class"] = components;
    j["dropped_components"] = dropped;
    j["dropped_components_per_class"] = e.fit.droppedComponents;
    // A step that lowered the log-likelihood and was undone (within rounding, or for --reg add
    // within its bound): the fall in nats per sample, 0 when none (docs/learning.md).
    j["likelihood_drop_per_class"] = e.fit.likelihoodDrop;
    j["models_fitted"] = e.fit.model.models().size() + e.fit.model.restModels().size();
    j["warnings"] = e.fit.warnings;
    std::printf("%s\n", dumpJson(j).c_str());
    return kExitOk;
  }
  if (gaussian)
    std::printf("method gaussian (unbiased covariance), floor %g (%s)\n", a.floor, a.reg.c_str());
  else
    std::printf("method gmm, order %d, %s, floor %g (%s), init %s, seed %llu\n", a.order,
                a.cov.c_str(), a.floor, a.reg.c_str(), a.init.c_str(),
                static_cast<unsigned long long>(a.seed));
  std::printf("train %d rows, test %d rows, %zu classes, dimension %d\n", train.rows(), test.rows(),
              train.classNames.size(), train.dimension());
  std::printf("accuracy     %.4f\n", e.accuracy);
  if (e.logLik.mean)
    std::printf("mean loglik  %.6f nats", *e.logLik.mean);
  else
    std::printf("mean loglik  none");
  if (e.logLik.negInfRows > 0)
    std::printf(" (%zu test rows with log-likelihood -inf left out)", e.logLik.negInfRows);
  std::printf("\n");
  if (dropped > 0)
    std::printf("components   %d dropped for lack of mass (kept per class:%s)\n", dropped,
                [&] {
                  std::string s;
                  for (int k : components)
                    s += " " + std::to_string(k);
                  return s;
                }()
                    .c_str());
  std::printf("fit          %.3f s (%d iterations max, %s)\n", e.fit.fitSeconds, iterations,
              converged ? "converged" : "NOT converged");
  std::printf("predict      %.3f s\n", e.predictSeconds);
  std::printf("confusion (rows true, columns predicted):\n");
  std::size_t width = 8;
  for (const auto& n : train.classNames)
    width = std::max(width, n.size() + 1);
  std::printf("%*s", static_cast<int>(width), "");
  for (const auto& n : train.classNames)
    std::printf("%*s", static_cast<int>(width), n.c_str());
  std::printf("\n");
  for (std::size_t r = 0; r < e.confusion.size(); ++r) {
    std::printf("%*s", static_cast<int>(width), train.classNames[r].c_str());
    for (long v : e.confusion[r])
      std::printf("%*ld", static_cast<int>(width), v);
    std::printf("\n");
  }
  return kExitOk;
}

struct BenchArgs {
  int rows = 100000;
  int testRows = 20000;
  int dimension = 10;
  int classes = 3;
  int maxOrder = 64;
  std::vector<std::string> forms;
  std::string writeTrain;
  std::string writeTest;
  bool json = false;
};

int runBenchLearn(const BenchArgs& b, const ClassifierArgs& a) {
  if (b.rows < 100 || b.testRows < 1 || b.dimension < 1 || b.classes < 1)
    throw UsageError("--rows must be >= 100 and --test-rows, --dim, --classes >= 1");
  SyntheticTableSpec spec;
  spec.rows = b.rows;
  spec.dimension = b.dimension;
  spec.classes = b.classes;
  spec.seed = 20240601;
  spec.sampleSeed = 1;
  const FeatureTable train = makeSyntheticTable(spec);
  spec.rows = b.testRows;
  spec.sampleSeed = 2;
  const FeatureTable test = makeSyntheticTable(spec);
  if (!b.writeTrain.empty() || !b.writeTest.empty()) {
    if (!b.writeTrain.empty()) {
      const Status written = writeFileAtomically(b.writeTrain, formatFeatureTable(train));
      if (!written) throw std::runtime_error(written.errorText());
    }
    if (!b.writeTest.empty()) {
      const Status written = writeFileAtomically(b.writeTest, formatFeatureTable(test));
      if (!written) throw std::runtime_error(written.errorText());
    }
    if (!b.json)
      std::printf("wrote the generated data set (%d + %d rows, D = %d, %d classes)\n", b.rows,
                  b.testRows, b.dimension, b.classes);
    return kExitOk;
  }
  std::vector<CovarianceForm> forms;
  if (b.forms.empty()) {
    forms.assign(std::begin(kAllCovarianceForms), std::end(kAllCovarianceForms));
  } else {
    for (const auto& name : b.forms) {
      const auto f = parseCovarianceForm(name);
      if (!f) throw UsageError("--forms: unknown covariance form " + quotedInput(name));
      forms.push_back(*f);
    }
  }
  ClassifierArgs base = a;
  nlohmann::json cells = nlohmann::json::array();
  if (!b.json) {
    std::printf("data: %d training rows, %d test rows, D = %d, %d classes (8 clusters each)\n",
                b.rows, b.testRows, b.dimension, b.classes);
    std::printf("floor %g (%s), init %s, tol %g (%s), max-iter %d, threads %d, kernels %s\n",
                a.floor, a.reg.c_str(), a.init.c_str(), a.tolerance, a.tolRule.c_str(),
                a.maxIterations, a.threads, kernelIsa().c_str());
    std::printf("%6s %-11s %9s %6s %12s %9s %10s\n", "order", "covariance", "fit_s", "iters",
                "mean_loglik", "accuracy", "predict_s");
  }
  for (int order = 1; order <= b.maxOrder; order *= 2) {
    for (CovarianceForm form : forms) {
      base.method = "gmm";
      base.order = order;
      base.cov = std::string(covarianceFormName(form));
      const Evaluation e = trainAndTest(train, test, toClassifierOptions(base));
      int iterations = 0;
      for (int it : e.fit.iterations)
        iterations = std::max(iterations, it);
      if (b.json) {
        nlohmann::json c;
        c["order"] = order;
        c["covariance"] = base.cov;
        c["ok"] = e.fit.ok;
        if (!e.fit.ok) c["reason"] = e.fit.reason;
        c["fit_s"] = e.fit.fitSeconds;
        c["iterations"] = iterations;
        c["mean_loglik"] = optionalNumber(e.logLik.mean);
        c["neg_inf_rows"] = e.logLik.negInfRows;
        c["accuracy"] = e.accuracy;
        c["predict_s"] = e.predictSeconds;
        cells.push_back(c);
      } else if (!e.fit.ok) {
        std::printf("%6d %-11s failed: %s\n", order, base.cov.c_str(), e.fit.reason.c_str());
      } else {
        std::printf("%6d %-11s %9.3f %6d %12.5f %9.4f %10.3f\n", order, base.cov.c_str(),
                    e.fit.fitSeconds, iterations,
                    e.logLik.mean ? *e.logLik.mean : -std::numeric_limits<double>::infinity(),
                    e.accuracy, e.predictSeconds);
      }
      std::fflush(stdout);
    }
  }
  if (b.json) {
    nlohmann::json j;
    j["rows"] = b.rows;
    j["test_rows"] = b.testRows;
    j["dimension"] = b.dimension;
    j["classes"] = b.classes;
    j["kernel_isa"] = kernelIsa();
    j["cells"] = cells;
    std::printf("%s\n", dumpJson(j).c_str());
  }
  return kExitOk;
}

}  // namespace

void registerFitVerbs(CLI::App& app, CLI::App& bench) {
  {
    auto fitArgs = std::make_shared<FitArgs>();
    auto learnArgs = std::make_shared<ClassifierArgs>();
    CLI::App* cmd = app.add_subcommand("fit", "Train and test a classifier on feature-table CSVs");
    cmd->add_option("--train", fitArgs->train, "training table (f0,...,f{D-1},label)")->required();
    cmd->add_option("--test", fitArgs->test, "test table (default: the training table)");
    addClassifierOptions(cmd, *learnArgs, true);
    cmd->add_flag("--json", fitArgs->json, "print one JSON object");
    setAction(cmd, [fitArgs, learnArgs] { return runFit(*fitArgs, *learnArgs); });
  }
  {
    auto benchArgs = std::make_shared<BenchArgs>();
    auto learnArgs = std::make_shared<ClassifierArgs>();
    learnArgs->floor = 0.01;
    CLI::App* cmd =
        bench.add_subcommand("learn", "Fit time against error over model orders and forms");
    cmd->add_option("--rows", benchArgs->rows, "training rows")->capture_default_str();
    cmd->add_option("--test-rows", benchArgs->testRows, "held-out rows")->capture_default_str();
    cmd->add_option("--dim", benchArgs->dimension, "features")->capture_default_str();
    cmd->add_option("--classes", benchArgs->classes, "classes")->capture_default_str();
    cmd->add_option("--max-order", benchArgs->maxOrder, "largest order (1, 2, 4, ... up to it)")
        ->capture_default_str();
    cmd->add_option("--forms", benchArgs->forms, "covariance forms to run (default: all four)")
        ->delimiter(',');
    cmd->add_option("--write-train", benchArgs->writeTrain,
                    "write the generated training table to this file and exit");
    cmd->add_option("--write-test", benchArgs->writeTest,
                    "write the generated test table to this file and exit");
    addClassifierOptions(cmd, *learnArgs, false);
    cmd->add_flag("--json", benchArgs->json, "print one JSON object");
    setAction(cmd, [benchArgs, learnArgs] { return runBenchLearn(*benchArgs, *learnArgs); });
  }
}

}  // namespace tactile::cli
