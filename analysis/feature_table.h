// The bring-your-own feature table (docs/file-formats.md#feature-table): CSV with header
// `f0,...,f{D-1},label` and one sample per row; labels are free text naming the class.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"

namespace tactile::analysis {

struct FeatureTable {
  std::vector<std::string> classNames;  // in order of first appearance
  Eigen::MatrixXd features;             // N x D, one row per sample
  std::vector<int> labels;              // N indices into classNames
  std::vector<int> lines;               // N source line numbers (header = line 1), if parsed
  int dimension() const { return static_cast<int>(features.cols()); }
  int rows() const { return static_cast<int>(features.rows()); }
};

// Parses the text of a feature table; `fileName` only names the source in error messages. Numbers
// are strict std::from_chars literals and must be finite; labels must be non-empty; blank lines
// (and a trailing '\r' on every line) are ignored. An error names the file and line, and in its
// message the column ("column 2 (f1): 'x2' is not a finite number").
Result<FeatureTable> parseFeatureTable(std::string_view text, std::string_view fileName);
Result<FeatureTable> readFeatureTable(const std::filesystem::path& path);

// Writes a table in the same format (numbers with 17 significant digits, round-trip exact).
std::string formatFeatureTable(const FeatureTable& table);

// Rows of each class of `table` in row order: result[c] is N_c x D.
std::vector<Eigen::MatrixXd> splitByClass(const FeatureTable& table);
// The same for a rows x cols matrix of any layout, value (r, j) at features[r * rowStride + j *
// colStride] (a numpy array, C or Fortran order), with `labels` (`rows` of them) in [0, classes).
// Throws std::invalid_argument for a label outside it.
std::vector<Eigen::MatrixXd> splitByClass(const double* features, Eigen::Index rows,
                                          Eigen::Index cols, Eigen::Index rowStride,
                                          Eigen::Index colStride, const int* labels,
                                          std::size_t classes);

// Maps the labels of `table` onto `classNames` (e.g. a test table onto the training classes).
// Fails naming the first unknown label and its line (header = line 1).
Status remapLabels(FeatureTable& table, const std::vector<std::string>& classNames,
                   std::string_view fileName);

}  // namespace tactile::analysis
