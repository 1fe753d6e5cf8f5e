// k-means++ seeding and Lloyd's k-means, used to initialise EM.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "analysis/gaussian.h"

namespace tactile::analysis {

// Greedy k-means++ seeding (Arthur & Vassilvitskii 2007; the greedy variant of scikit-learn): the
// first centre is a uniformly random row; for each next centre, 2 + floor(ln k) candidates are
// drawn with probability D(x_n)^2 / sum_m D(x_m)^2 (D = distance to the nearest centre chosen so
// far) and the one leaving the smallest sum of D^2 is kept. When every row coincides with a chosen
// centre (fewer distinct rows than k) the next centre is again a uniformly random row. Returns k x
// D centres. samples: N x D, one row per sample, N >= 1.
// `threads` workers share the distance passes; the result does not depend on their number.
Eigen::MatrixXd kmeansPlusPlus(const Eigen::Ref<const Eigen::MatrixXd>& samples, int k, Rng& rng,
                               int threads = 1);

// Index of the nearest centre of every row (ties go to the lowest index), from the squared
// distances |x - c_i|^2 computed directly (vectorised over rows). Returns the sum of squared
// distances (inertia).
double assignNearest(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                     const Eigen::MatrixXd& centres, std::vector<int>& assignment, int threads = 1);

// Lloyd iterations: assign rows to the nearest centre, move each centre to the mean of its rows
// (a centre with no rows stays where it is), until no assignment changes or `iterations` are
// done. Returns the number of iterations run; `assignment` holds the final assignment.
int lloydIterations(const Eigen::Ref<const Eigen::MatrixXd>& samples, Eigen::MatrixXd& centres,
                    int iterations, std::vector<int>& assignment, int threads = 1);

}  // namespace tactile::analysis
