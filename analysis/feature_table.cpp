#include "analysis/feature_table.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/run_csv.h"

namespace tactile::analysis {

namespace {

Error located(std::string_view file, std::size_t line, std::string message) {
  return Error(std::string(file), line, 0, std::move(message));
}

// Next line of text (without its '\n' and a trailing '\r'); advances pos.
std::string_view nextLine(std::string_view text, std::size_t& pos) {
  const std::size_t end = text.find('\n', pos);
  std::string_view line =
      text.substr(pos, end == std::string_view::npos ? text.size() - pos : end - pos);
  pos = end == std::string_view::npos ? text.size() + 1 : end + 1;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

}  // namespace

Result<FeatureTable> parseFeatureTable(std::string_view text, std::string_view fileName) {
  std::size_t pos = 0;
  std::size_t lineNo = 0;
  std::string_view header;
  while (pos <= text.size()) {
    header = nextLine(text, pos);
    ++lineNo;
    if (!header.empty()) break;
  }
  if (header.empty()) {
    return located(fileName, 1, "empty file: expected the header f0,...,f{D-1},label");
  }
  // Header: f0,f1,...,f{D-1},label
  std::vector<std::string_view> names;
  for (std::size_t start = 0;;) {
    const std::size_t comma = header.find(',', start);
    names.push_back(header.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (names.size() < 2 || names.back() != "label") {
    return located(fileName, lineNo,
                   "header must be f0,...,f{D-1},label (the last column must be 'label')");
  }
  const std::size_t d = names.size() - 1;
  for (std::size_t j = 0; j < d; ++j) {
    if (names[j] != "f" + std::to_string(j)) {
      return located(fileName, lineNo,
                     "column " + std::to_string(j + 1) + ": header " + quotedInput(names[j]) +
                         ", expected 'f" + std::to_string(j) + "'");
    }
  }
  std::vector<double> values;
  values.reserve(text.size() / 8);
  std::vector<int> labels;
  std::unordered_map<std::string, int> classIndex;
  FeatureTable table;
  while (pos <= text.size()) {
    const std::string_view line = nextLine(text, pos);
    ++lineNo;
    if (line.empty()) continue;
    const char* p = line.data();
    const char* end = line.data() + line.size();
    for (std::size_t j = 0; j < d; ++j) {
      const char* fieldEnd = p;
      while (fieldEnd < end && *fieldEnd != ',')
        ++fieldEnd;
      if (fieldEnd == end) {
        return located(
            fileName, lineNo,
            "expected " + std::to_string(d + 1) + " fields, got " + std::to_string(j + 1));
      }
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(p, fieldEnd, v, std::chars_format::general);
      if (ec != std::errc() || ptr != fieldEnd || !std::isfinite(v)) {
        return located(
            fileName, lineNo,
            "column " + std::to_string(j + 1) + " (f" + std::to_string(j) +
                "): " + quotedInput(std::string_view(p, static_cast<std::size_t>(fieldEnd - p))) +
                " is not a finite number");
      }
      values.push_back(v);
      p = fieldEnd + 1;
    }
    const std::string_view label(p, static_cast<std::size_t>(end - p));
    if (label.find(',') != std::string_view::npos) {
      return located(fileName, lineNo, "more than " + std::to_string(d + 1) + " fields");
    }
    if (label.empty()) {
      return located(fileName, lineNo, "column " + std::to_string(d + 1) + " (label): empty label");
    }
    auto [it, inserted] =
        classIndex.try_emplace(std::string(label), static_cast<int>(table.classNames.size()));
    if (inserted) table.classNames.emplace_back(label);
    labels.push_back(it->second);
    table.lines.push_back(static_cast<int>(lineNo));
  }
  const Eigen::Index n = static_cast<Eigen::Index>(labels.size());
  if (n == 0) {
    return located(fileName, lineNo, "the table has a header but no rows");
  }
  table.features =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          values.data(), n, static_cast<Eigen::Index>(d));
  table.labels = std::move(labels);
  return table;
}

Result<FeatureTable> readFeatureTable(const std::filesystem::path& path) {
  Result<std::string> text = readFileText(path);
  if (!text) return text.error();
  return parseFeatureTable(text.value(), path.string());
}

std::string formatFeatureTable(const FeatureTable& table) {
  std::string out;
  const int d = table.dimension();
  for (int j = 0; j < d; ++j)
    out += "f" + std::to_string(j) + ",";
  out += "label\n";
  char buffer[64];
  for (Eigen::Index r = 0; r < table.features.rows(); ++r) {
    for (int j = 0; j < d; ++j) {
      const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, table.features(r, j));
      out.append(buffer, ec == std::errc() ? ptr : buffer);
      out += ',';
    }
    out += table.classNames[static_cast<std::size_t>(table.labels[static_cast<std::size_t>(r)])];
    out += '\n';
  }
  return out;
}

std::vector<Eigen::MatrixXd> splitByClass(const FeatureTable& table) {
  return splitByClass(table.features.data(), table.features.rows(), table.features.cols(), 1,
                      table.features.rows(), table.labels.data(), table.classNames.size());
}

std::vector<Eigen::MatrixXd> splitByClass(const double* features, Eigen::Index rows,
                                          Eigen::Index cols, Eigen::Index rowStride,
                                          Eigen::Index colStride, const int* labels,
                                          std::size_t classes) {
  // Counts first, then one column at a time, each class's rows in row order: reads and writes
  // run along columns, as both sides are stored in a column-major table. No per-row index: the
  // split allocates nothing beside its result.
  std::vector<Eigen::Index> counts(classes, 0);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const int l = labels[r];
    if (l < 0 || static_cast<std::size_t>(l) >= classes)
      throw std::invalid_argument("label " + std::to_string(l) + " of row " + std::to_string(r) +
                                  " is not a class index below " + std::to_string(classes));
    ++counts[static_cast<std::size_t>(l)];
  }
  std::vector<Eigen::MatrixXd> out(classes);
  for (std::size_t c = 0; c < classes; ++c)
    out[c].resize(counts[c], cols);
  std::vector<double*> next(classes);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (std::size_t c = 0; c < classes; ++c)
      next[c] = out[c].col(j).data();
    const double* column = features + j * colStride;
    for (Eigen::Index r = 0; r < rows; ++r)
      *next[static_cast<std::size_t>(labels[r])]++ = column[r * rowStride];
  }
  return out;
}

Status remapLabels(FeatureTable& table, const std::vector<std::string>& classNames,
                   std::string_view fileName) {
  std::vector<int> map(table.classNames.size(), -1);
  for (std::size_t c = 0; c < table.classNames.size(); ++c)
    for (std::size_t t = 0; t < classNames.size(); ++t)
      if (classNames[t] == table.classNames[c]) map[c] = static_cast<int>(t);
  for (std::size_t r = 0; r < table.labels.size(); ++r) {
    const int m = map[static_cast<std::size_t>(table.labels[r])];
    if (m < 0) {
      const std::size_t line =
          r < table.lines.size() ? static_cast<std::size_t>(table.lines[r]) : r + 2;
      return located(fileName, line,
                     "label " +
                         quotedInput(table.classNames[static_cast<std::size_t>(table.labels[r])]) +
                         " does not occur in the training table");
    }
    table.labels[r] = m;
  }
  table.classNames = classNames;
  return Status::success();
}

}  // namespace tactile::analysis
