#include "app/cli/cli_classifier_options.h"

#include <cmath>

#include "base/text_rules.h"

namespace tactile::cli {

using namespace tactile::analysis;

void addClassifierOptions(CLI::App* cmd, ClassifierArgs& a, bool withMethodAndForm) {
  if (withMethodAndForm) {
    cmd->add_option("--method", a.method, "gmm, gaussian or gbt (gradient-boosted trees)")
        ->capture_default_str();
    cmd->add_option("--order", a.order, "GMM components per class")->capture_default_str();
    cmd->add_option("--cov", a.cov, "nodal-full, nodal-diag, grand-full or grand-diag")
        ->capture_default_str();
    cmd->add_option("--trees", a.trees, "gbt: boosting rounds (a tree per class each)")
        ->capture_default_str();
    cmd->add_option("--depth", a.depth, "gbt: largest tree depth")->capture_default_str();
    cmd->add_option("--learning-rate", a.learningRate, "gbt: shrinkage of each round")
        ->capture_default_str();
    cmd->add_option("--min-child-weight", a.minChildWeight, "gbt: least weight in a leaf")
        ->capture_default_str();
  }
  cmd->add_option("--floor", a.floor, "variance floor (or reg_covar with --reg add)")
      ->capture_default_str();
  cmd->add_option("--reg", a.reg, "floor (clamp) or add (constant on the diagonal)")
      ->capture_default_str();
  cmd->add_option("--init", a.init, "kmeans++ or random-from-data")->capture_default_str();
  cmd->add_option("--seed", a.seed, "random seed")->capture_default_str();
  cmd->add_option("--restarts", a.restarts, "EM initialisations, best kept")->capture_default_str();
  cmd->add_option("--threads", a.threads, "worker threads (0 = all cores)")->capture_default_str();
  cmd->add_option("--max-iter", a.maxIterations, "EM iteration limit")->capture_default_str();
  cmd->add_option("--tol", a.tolerance, "convergence tolerance on the mean log-likelihood")
      ->capture_default_str();
  cmd->add_option("--tol-rule", a.tolRule,
                  "relative: |dl| < tol*max(1,|l|); absolute: |dl| < tol (scikit-learn)")
      ->capture_default_str();
  cmd->add_option("--kmeans-iter", a.kmeansIterations, "Lloyd iterations after k-means++ seeding")
      ->capture_default_str();
  cmd->add_option("--priors", a.priors, "equal or empirical class priors")->capture_default_str();
}

ClassifierOptions toClassifierOptions(const ClassifierArgs& a) {
  ClassifierOptions o;
  const auto method = parseClassifierMethod(a.method);
  if (!method) {
    throw UsageError("--method must be gmm, gaussian or gbt, got " + quotedInput(a.method));
  }
  o.method = *method;
  o.gbt.trees = a.trees;
  o.gbt.depth = a.depth;
  o.gbt.learningRate = a.learningRate;
  o.gbt.minChildWeight = a.minChildWeight;
  if (std::string problem = checkGbtSettings(o.gbt); !problem.empty())
    throw UsageError("gbt: " + problem);
  const auto form = parseCovarianceForm(a.cov);
  if (!form)
    throw UsageError("--cov must be nodal-full, nodal-diag, grand-full or grand-diag, got " +
                     quotedInput(a.cov));
  const auto reg = parseRegularization(a.reg);
  if (!reg) throw UsageError("--reg must be floor or add, got " + quotedInput(a.reg));
  const auto init = parseGmmInit(a.init);
  if (!init)
    throw UsageError("--init must be kmeans++ or random-from-data, got " + quotedInput(a.init));
  const auto rule = parseConvergenceRule(a.tolRule);
  if (!rule)
    throw UsageError("--tol-rule must be relative or absolute, got " + quotedInput(a.tolRule));
  const auto priors = parsePriorMode(a.priors);
  if (!priors)
    throw UsageError("--priors must be equal or empirical, got " + quotedInput(a.priors));
  checkOrderOption("--order", a.order);
  checkFloorOption("--floor", a.floor);
  if (a.restarts < 1) throw UsageError("--restarts must be at least 1");
  if (a.threads < 0) throw UsageError("--threads must be >= 0");
  if (a.maxIterations < 1) throw UsageError("--max-iter must be at least 1");
  checkNumberOption("--tol", a.tolerance, 0.0, RangeEnd::Closed, HUGE_VAL, RangeEnd::Open);
  if (a.kmeansIterations < 0) throw UsageError("--kmeans-iter must be >= 0");
  o.gmm.components = a.order;
  o.gmm.form = *form;
  o.gmm.varianceFloor = a.floor;
  o.gmm.reg = *reg;
  o.gmm.init = *init;
  o.gmm.seed = a.seed;
  o.gmm.restarts = a.restarts;
  o.gmm.maxIterations = a.maxIterations;
  o.gmm.tolerance = a.tolerance;
  o.gmm.rule = *rule;
  o.gmm.kmeansIterations = a.kmeansIterations;
  o.priors = *priors;
  o.threads = a.threads;
  o.gmm.threads = a.threads;
  return o;
}

}  // namespace tactile::cli
