// A Gaussian mixture's parameters and densities (docs/learning.md). Densities are evaluated in log
// space, in a frame centred on the weighted mean of the component means, through the kernels of
// analysis/gmm_kernels.h.
#include "analysis/gaussian_mixture.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace tactile::analysis {

namespace {

constexpr std::array<std::pair<CovarianceForm, std::string_view>, 4> kFormNames{{
    {CovarianceForm::NodalFull, "nodal-full"},
    {CovarianceForm::NodalDiag, "nodal-diag"},
    {CovarianceForm::GrandFull, "grand-full"},
    {CovarianceForm::GrandDiag, "grand-diag"},
}};

std::string formatDouble(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string_view covarianceFormName(CovarianceForm form) {
  for (const auto& [value, name] : kFormNames)
    if (value == form) return name;
  return "?";
}

std::optional<CovarianceForm> parseCovarianceForm(std::string_view name) {
  for (const auto& [value, text] : kFormNames)
    if (text == name) return value;
  return std::nullopt;
}

Result<GaussianMixture> GaussianMixture::create(const Eigen::VectorXd& weights,
                                                const Eigen::MatrixXd& means,
                                                const std::vector<Eigen::MatrixXd>& covariances,
                                                CovarianceForm form) {
  const auto fail = [](std::string message) { return Error(std::move(message)); };
  const Eigen::Index k = weights.size();
  if (k < 1) return fail("a mixture needs at least one component");
  if (means.rows() != k)
    return fail("means have " + std::to_string(means.rows()) + " rows for " + std::to_string(k) +
                " weights");
  const Eigen::Index d = means.cols();
  if (d < 1) return fail("means have no columns (dimension 0)");
  const std::size_t covCount = isNodal(form) ? static_cast<std::size_t>(k) : 1;
  if (covariances.size() != covCount)
    return fail(std::string(covarianceFormName(form)) + " needs " + std::to_string(covCount) +
                " covariance matrices, got " + std::to_string(covariances.size()));
  if (!weights.allFinite()) return fail("weights are not all finite");
  if (!means.allFinite()) return fail("means are not all finite");
  for (Eigen::Index i = 0; i < k; ++i)
    if (weights(i) < 0.0) {
      return fail("the weight of component " + std::to_string(i + 1) + " of " + std::to_string(k) +
                  " (counting from 1) is negative");
    }
  const double sum = weights.sum();
  if (!(std::abs(sum - 1.0) <= 1e-9))
    return fail("weights sum to " + formatDouble(sum) + ", not 1");
  for (std::size_t i = 0; i < covCount; ++i) {
    const Eigen::MatrixXd& c = covariances[i];
    const std::string which = covCount == 1
                                  ? std::string("the covariance")
                                  : "the covariance of component " + std::to_string(i + 1) +
                                        " of " + std::to_string(covCount) + " (counting from 1)";
    if (c.rows() != d || c.cols() != d)
      return fail(which + " is " + std::to_string(c.rows()) + "x" + std::to_string(c.cols()) +
                  ", expected " + std::to_string(d) + "x" + std::to_string(d));
    if (!c.allFinite()) return fail(which + " is not all finite");
    const double scale = c.cwiseAbs().maxCoeff();
    for (Eigen::Index r = 0; r < d; ++r) {
      for (Eigen::Index s = 0; s < r; ++s) {
        if (std::abs(c(r, s) - c(s, r)) > 1e-12 * scale) return fail(which + " is not symmetric");
        if (isDiagonal(form) && (c(r, s) != 0.0 || c(s, r) != 0.0))
          return fail(which + " has off-diagonal entries but the form is " +
                      std::string(covarianceFormName(form)));
      }
    }
  }
  GaussianMixture m;
  m.form_ = form;
  m.weights_ = weights;
  m.means_ = means;
  m.covariances_ = covariances;
  std::string error;
  if (!m.buildCache(&error)) return fail(error);
  return m;
}

bool GaussianMixture::buildCache(std::string* error) {
  centre_ = means_.transpose() * weights_;
  const Eigen::MatrixXd shifted = means_.rowwise() - centre_.transpose();
  int bad = -1;
  if (!buildDensityCache(weights_, shifted, covariances_, isDiagonal(form_), isNodal(form_), cache_,
                         &bad)) {
    if (error) {
      *error = (isNodal(form_) ? "the covariance of component " + std::to_string(bad + 1) +
                                     " (counting from 1)"
                               : std::string("the covariance")) +
               " is not positive definite";
    }
    return false;
  }
  return true;
}

void GaussianMixture::logDensities(const Eigen::MatrixXd& samples, Eigen::VectorXd& out) const {
  const Eigen::Index n = samples.rows();
  const int k = components();
  const int d = dimension();
  out.resize(n);
  if (k == 0) {
    out.setConstant(-std::numeric_limits<double>::infinity());
    return;
  }
  const int ld = static_cast<int>(kDensityBlockRows);
  Eigen::MatrixXd xb = Eigen::MatrixXd::Zero(kDensityBlockRows, d);
  Eigen::MatrixXd logp(kDensityBlockRows, k);
  Eigen::VectorXd scratch(2 * kDensityBlockRows);
  Eigen::VectorXd lse(kDensityBlockRows);
  for (Eigen::Index start = 0; start < n; start += kDensityBlockRows) {
    const Eigen::Index b = std::min(kDensityBlockRows, n - start);
    xb.topRows(b) = samples.middleRows(start, b).rowwise() - centre_.transpose();
    blockComponentLogDensities(cache_, xb.data(), kDensityBlockRows, paddedRows(b), logp.data(),
                               ld);
    blockLogSumExp(logp.data(), ld, paddedRows(b), k, lse.data(), nullptr, scratch.data());
    out.segment(start, b) = lse.head(b);
  }
}

void GaussianMixture::blockLogDensities(const double* x, Eigen::Index ldx, Eigen::Index rows,
                                        double* out, BlockScratch& scratch) const {
  const int k = components();
  const int d = dimension();
  if (k == 0) {
    for (Eigen::Index r = 0; r < rows; ++r)
      out[r] = -std::numeric_limits<double>::infinity();
    return;
  }
  if (rows <= 0) return;
  if (scratch.centred.rows() != kDensityBlockRows || scratch.centred.cols() != d)
    scratch.centred = Eigen::MatrixXd::Zero(kDensityBlockRows, d);
  if (scratch.logp.rows() != kDensityBlockRows || scratch.logp.cols() != k)
    scratch.logp.resize(kDensityBlockRows, k);
  if (scratch.logSum.size() != kDensityBlockRows) scratch.logSum.resize(kDensityBlockRows);
  const int ld = static_cast<int>(kDensityBlockRows);
  for (int j = 0; j < d; ++j) {
    const double c = centre_[j];
    const double* from = x + j * ldx;
    double* to = scratch.centred.col(j).data();
    for (Eigen::Index r = 0; r < rows; ++r)
      to[r] = from[r] - c;
  }
  blockComponentLogDensities(cache_, scratch.centred.data(), kDensityBlockRows, paddedRows(rows),
                             scratch.logp.data(), ld);
  blockLogSumExp(scratch.logp.data(), ld, paddedRows(rows), k, scratch.logSum.data(), nullptr,
                 nullptr);
  for (Eigen::Index r = 0; r < rows; ++r)
    out[r] = scratch.logSum[r];
}

double GaussianMixture::logDensity(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (components() == 0) return -std::numeric_limits<double>::infinity();
  Eigen::MatrixXd row = x.transpose();
  Eigen::VectorXd out;
  logDensities(row, out);
  return out(0);
}

Eigen::VectorXd GaussianMixture::responsibilities(
    const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const int k = components();
  const int d = dimension();
  Eigen::VectorXd resp(k);
  if (k == 0) return resp;
  Eigen::MatrixXd xb = Eigen::MatrixXd::Zero(8, d);
  xb.row(0) = (x - centre_).transpose();
  Eigen::MatrixXd logp(8, k);
  blockComponentLogDensities(cache_, xb.data(), 8, 8, logp.data(), 8);
  Eigen::MatrixXd r(8, k);
  Eigen::VectorXd scratch(16);
  Eigen::VectorXd logSum(8);
  blockLogSumExp(logp.data(), 8, 8, k, logSum.data(), r.data(), scratch.data());
  resp = r.row(0).transpose();
  return resp;
}

double GaussianMixture::meanLogLikelihood(const Eigen::MatrixXd& samples) const {
  if (samples.rows() == 0) return 0.0;
  Eigen::VectorXd out;
  logDensities(samples, out);
  return out.mean();
}

int GaussianMixture::parameterCount() const {
  const int k = components();
  const int d = dimension();
  int cov = 0;
  switch (form_) {
    case CovarianceForm::NodalFull:
      cov = k * d * (d + 1) / 2;
      break;
    case CovarianceForm::NodalDiag:
      cov = k * d;
      break;
    case CovarianceForm::GrandFull:
      cov = d * (d + 1) / 2;
      break;
    case CovarianceForm::GrandDiag:
      cov = d;
      break;
  }
  return (k - 1) + k * d + cov;
}

}  // namespace tactile::analysis
