// Classifier and EM options shared by `fit`, `bench learn` and `train`: one set of names,
// defaults, help texts and checks.
#pragma once

#include <cstdint>
#include <string>

#include "analysis/classifier.h"
#include "app/cli/cli_common.h"

namespace tactile::cli {

// The options as typed on the command line.
struct ClassifierArgs {
  std::string method = "gmm";
  int order = 16;
  std::string cov = "nodal-diag";
  double floor = 0.01;
  std::string reg = "floor";
  std::string init = "kmeans++";
  std::uint64_t seed = 1;
  int restarts = 1;
  int threads = 0;
  int maxIterations = 100;
  double tolerance = 1e-3;
  std::string tolRule = "relative";
  int kmeansIterations = 10;
  std::string priors = "equal";
  // Gradient-boosted trees (--method gbt).
  int trees = 100;
  int depth = 6;
  double learningRate = 0.1;
  double minChildWeight = 1.0;
};

// Adds the options to `cmd`; `withMethodAndForm` adds --method, --order, --cov and the trees'
// --trees, --depth, --learning-rate and --min-child-weight too.
void addClassifierOptions(CLI::App* cmd, ClassifierArgs& a, bool withMethodAndForm);

// Checks the typed options; throws UsageError naming the option at fault.
analysis::ClassifierOptions toClassifierOptions(const ClassifierArgs& a);

}  // namespace tactile::cli
