// Feature-table verbs: fit, bench learn.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/feature_table.h"
#include "analysis/gmm.h"
#include "analysis/gmm_synthetic.h"
#include "app/cli/cli_classifier_options.h"
#include "app/cli/cli_common.h"
#include "sim/run_csv.h"

namespace tactile::cli {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Train on `train`, test on `test` (labels already mapped onto the training classes).
struct Evaluation {
  ClassifierFit fit;
  double accuracy = 0.0;
  double meanLogLik = 0.0;
  double predictSeconds = 0.0;
  std::vector<std::vector<long>> confusion;  // [true][predicted]
};

Evaluation trainAndTest(const FeatureTable& train, const FeatureTable& test,
                        const ClassifierOptions& options) {
  Evaluation e;
  const std::vector<Eigen::MatrixXd> perClass = splitByClass(train);
  e.fit = trainClassifier(perClass, train.classNames, options);
  if (!e.fit.ok) return e;
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::MatrixXd logLik;
  e.fit.model.logLikelihoods(test.features, logLik);
  const std::vector<int> predicted = e.fit.model.predictFromLogLikelihoods(logLik);
  e.predictSeconds = secondsSince(t0);
  const std::size_t classes = train.classNames.size();
  e.confusion.assign(classes, std::vector<long>(classes, 0));
  long correct = 0;
  double sum = 0.0;
  for (std::size_t r = 0; r < predicted.size(); ++r) {
    const int truth = test.labels[r];
    ++e.confusion[static_cast<std::size_t>(truth)][static_cast<std::size_t>(predicted[r])];
    if (truth == predicted[r]) ++correct;
    sum += logLik(static_cast<Eigen::Index>(r), truth);
  }
  const double n = static_cast<double>(predicted.size());
  e.accuracy = n > 0 ? static_cast<double>(correct) / n : 0.0;
  e.meanLogLik = n > 0 ? sum / n : 0.0;
  return e;
}

FeatureTable loadTable(const std::string& path) {
  FeatureTableResult r = readFeatureTable(path);
  if (!r.ok) throw std::runtime_error(r.error);
  return std::move(r.table);
}

struct FitArgs {
  std::string train;
  std::string test;
  bool json = false;
};

int runFit(const FitArgs& f, const ClassifierArgs& a) {
  const ClassifierOptions options = toClassifierOptions(a);
  FeatureTable train = loadTable(f.train);
  FeatureTable test = loadTable(f.test.empty() ? f.train : f.test);
  if (test.dimension() != train.dimension())
    throw std::runtime_error(f.test + ": " + std::to_string(test.dimension()) +
                             " feature columns, but the training table has " +
                             std::to_string(train.dimension()));
  std::string error;
  if (!remapLabels(test, train.classNames, f.test.empty() ? f.train : f.test, error))
    throw std::runtime_error(error);
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
  if (f.json) {
    nlohmann::json j;
    j["accuracy"] = e.accuracy;
    j["mean_loglik"] = e.meanLogLik;
    j["fit_s"] = e.fit.fitSeconds;
    j["predict_s"] = e.predictSeconds;
    j["iterations"] = iterations;
    j["iterations_per_class"] = e.fit.iterations;
    j["converged"] = converged;
    j["classes"] = train.classNames;
    j["confusion"] = e.confusion;
    j["train_rows"] = train.rows();
    j["test_rows"] = test.rows();
    j["method"] = a.method;
    j["order"] = a.order;
    j["covariance"] = a.cov;
    j["floor"] = a.floor;
    j["regularization"] = a.reg;
    j["init"] = a.init;
    j["train_mean_loglik"] = e.fit.trainMeanLogLikelihood;
    std::printf("%s\n", j.dump().c_str());
    return kExitOk;
  }
  if (options.method == ClassifierMethod::Gaussian)
    std::printf("method gaussian (unbiased covariance), floor %g\n", a.floor);
  else
    std::printf("method gmm, order %d, %s, floor %g (%s), init %s, seed %llu\n", a.order,
                a.cov.c_str(), a.floor, a.reg.c_str(), a.init.c_str(),
                static_cast<unsigned long long>(a.seed));
  std::printf("train %d rows, test %d rows, %zu classes, dimension %d\n", train.rows(), test.rows(),
              train.classNames.size(), train.dimension());
  std::printf("accuracy     %.4f\n", e.accuracy);
  std::printf("mean loglik  %.6f nats\n", e.meanLogLik);
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
      const std::string err = writeFileAtomically(b.writeTrain, formatFeatureTable(train));
      if (!err.empty()) throw std::runtime_error(err);
    }
    if (!b.writeTest.empty()) {
      const std::string err = writeFileAtomically(b.writeTest, formatFeatureTable(test));
      if (!err.empty()) throw std::runtime_error(err);
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
      if (!f) throw UsageError("--forms: unknown covariance form '" + name + "'");
      forms.push_back(*f);
    }
  }
  ClassifierArgs base = a;
  nlohmann::json cells = nlohmann::json::array();
  if (!b.json) {
    std::printf("data: %d training rows, %d test rows, D = %d, %d classes (8 clusters each)\n",
                b.rows, b.testRows, b.dimension, b.classes);
    std::printf("floor %g (%s), init %s, tol %g (%s), max-iter %d, threads %d\n", a.floor,
                a.reg.c_str(), a.init.c_str(), a.tolerance, a.tolRule.c_str(), a.maxIterations,
                a.threads);
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
        c["mean_loglik"] = e.meanLogLik;
        c["accuracy"] = e.accuracy;
        c["predict_s"] = e.predictSeconds;
        cells.push_back(c);
      } else if (!e.fit.ok) {
        std::printf("%6d %-11s failed: %s\n", order, base.cov.c_str(), e.fit.reason.c_str());
      } else {
        std::printf("%6d %-11s %9.3f %6d %12.5f %9.4f %10.3f\n", order, base.cov.c_str(),
                    e.fit.fitSeconds, iterations, e.meanLogLik, e.accuracy, e.predictSeconds);
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
    j["cells"] = cells;
    std::printf("%s\n", j.dump().c_str());
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
