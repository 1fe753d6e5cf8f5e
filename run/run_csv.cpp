#include "run/run_csv.h"

#include <unistd.h>
#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <unordered_map>

#include "base/file_text.h"
#include "base/parallel.h"
#include "base/text_parse.h"
#include "base/text_rules.h"

namespace tactile {
namespace {

enum class ColumnKind : std::uint8_t {
  Step,
  X,
  Y,
  Theta,
  V,
  Omega,
  Blocked,
  Normal,
  Shear,
  Truth,
  Extra
};

struct Column {
  ColumnKind kind;
  int index;  // sensor, group or extra-column index
  std::string name;
};

constexpr std::array<std::string_view, 7> kPoseColumns{"step", "x",     "y",      "theta",
                                                       "v",    "omega", "blocked"};

std::string truthColumnName(int group) {
  return "truth_" + std::string(kSensorGroups[group].shortName);
}

// Maps a header name to its column role; false for a name that is not part of version 1.
bool classifyColumn(std::string_view name, Column& out) {
  for (std::size_t i = 0; i < kPoseColumns.size(); ++i) {
    if (name == kPoseColumns[i]) {
      out.kind = static_cast<ColumnKind>(i);
      out.index = 0;
      return true;
    }
  }
  if (name.size() >= 2 && (name[0] == 'n' || name[0] == 's')) {
    std::int64_t sensor = -1;
    const std::string_view digits = name.substr(1);
    // No leading zeros or signs: "n03" is not a column name.
    if (parseInteger(digits, sensor) && sensor >= 0 && sensor < kSensorCount &&
        std::to_string(sensor) == digits) {
      out.kind = name[0] == 'n' ? ColumnKind::Normal : ColumnKind::Shear;
      out.index = static_cast<int>(sensor);
      return true;
    }
  }
  if (name.starts_with("truth_")) {
    for (int g = 0; g < kGroupCount; ++g) {
      if (name.substr(6) == kSensorGroups[g].shortName) {
        out.kind = ColumnKind::Truth;
        out.index = g;
        return true;
      }
    }
    return false;
  }
  if (name.starts_with("x_") && name.size() > 2) {
    out.kind = ColumnKind::Extra;
    return true;
  }
  return false;
}

// "expected UTF-8 text in WHAT, found an invalid byte 0xHH at byte K OF".
std::string utf8Message(std::string_view what, std::string_view text, std::size_t at,
                        std::string_view of = "of the field") {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X",
                static_cast<unsigned>(static_cast<unsigned char>(text[at])));
  return "expected UTF-8 text in " + std::string(what) + ", found an invalid byte " + hex +
         " at byte " + std::to_string(at + 1) + " " + std::string(of);
}

// The name of the first control character in `text` ("a form feed (U+000C) at byte 2"), or empty.
std::string controlCharacterIn(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c != 0x7F) continue;
    const char* name = "a control character";
    switch (c) {
      case 0x00:
        name = "a NUL byte";
        break;
      case '\t':
        name = "a tab";
        break;
      case '\v':
        name = "a vertical tab";
        break;
      case '\f':
        name = "a form feed";
        break;
      case '\r':
        name = "a carriage return";
        break;
      default:
        break;
    }
    char code[16];
    std::snprintf(code, sizeof code, " (U+%04X)", static_cast<unsigned>(c));
    return std::string(name) + code + " at byte " + std::to_string(i + 1);
  }
  return {};
}

// The field in quotes for a message (quotedInput(): control characters and bytes that are not UTF-8
// as \xHH, cut after kMaxQuotedBytes), and the first control character named, so a form feed is
// never shown as nothing.
std::string shown(std::string_view text) {
  std::string out = quotedInput(text);
  if (std::string control = controlCharacterIn(text); !control.empty()) {
    out += " (holds " + control + ")";
  }
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

// Walks the text one physical line at a time; strips "\n" or "\r\n".
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text), end_(text.size()) {}
  // Lines of [begin, end) only, numbered from firstLine; `end` is a line start or the text end.
  LineCursor(std::string_view text, std::size_t begin, std::size_t end, std::size_t firstLine)
      : text_(text), pos_(begin), end_(end), line_(firstLine - 1) {}

  bool atEnd() const { return pos_ >= end_; }
  std::size_t lineNumber() const { return line_; }
  std::size_t offset() const { return pos_; }
  bool lastHadNewline() const { return hadNewline_; }
  std::size_t remaining() const { return end_ - pos_; }
  bool nextStartsWith(char c) const { return pos_ < text_.size() && text_[pos_] == c; }

  std::string_view next() {
    const char* begin = text_.data() + pos_;
    const std::size_t remaining = end_ - pos_;
    const void* nl = std::memchr(begin, '\n', remaining);
    std::size_t length = nl ? static_cast<const char*>(nl) - begin : remaining;
    pos_ += length + (nl ? 1 : 0);
    hadNewline_ = nl != nullptr;
    ++line_;
    if (nl && length > 0 && begin[length - 1] == '\r') --length;
    return {begin, length};
  }

  // True when every remaining line of the whole text (not only of the range) is empty: trailing
  // blank lines are tolerated.
  bool onlyBlankLinesLeft() const {
    for (std::size_t i = pos_; i < text_.size(); ++i) {
      if (text_[i] != '\n' && text_[i] != '\r') return false;
    }
    return true;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  std::size_t line_ = 0;
  bool hadNewline_ = false;
};

const ProgressFn kNoProgress{};

class Parser {
 public:
  Parser(std::string_view text, std::string_view fileName, const ProgressFn& progress)
      : text_(text), file_(fileName), progress_(progress), cursor_(text) {}

  RunCsvResult parse() {
    if (!parseHead() || !parseRows()) return std::move(*error_);
    return std::move(run_);
  }

  // The metadata lines and the header; false with error() set when they are invalid.
  bool parseHead() {
    if (text_.starts_with("\xEF\xBB\xBF")) {
      text_.remove_prefix(3);
      cursor_ = LineCursor(text_);
    }
    if (text_.empty()) return setError(0, "empty file: expected a header line");
    return parseMetadata() && parseHeader();
  }

  // After parseHead(): a parser for the rows of [begin, end) (offsets into text()), whose first
  // line is `firstLine` and must carry step `firstStep`.
  Parser rowParser(std::size_t begin, std::size_t end, std::size_t firstLine,
                   std::size_t firstStep) const {
    Parser rows(text_, file_, kNoProgress);
    rows.cursor_ = LineCursor(text_, begin, end, firstLine);
    rows.columns_ = columns_;
    rows.headerLine_ = headerLine_;
    rows.hasTruth_ = hasTruth_;
    rows.firstStep_ = firstStep;
    rows.run_.extraColumns = run_.extraColumns;
    return rows;
  }

  // Parses this row parser's range: its rows (no metadata) or its first error.
  RunCsvResult parseRowRange() {
    if (!parseRowLines()) return std::move(*error_);
    run_.extraColumns.clear();
    return std::move(run_);
  }

  std::string_view text() const { return text_; }
  std::size_t offset() const { return cursor_.offset(); }
  std::size_t headerLine() const { return headerLine_; }
  bool hasTruth() const { return hasTruth_; }
  const RunData& head() const { return run_; }
  const Error& error() const { return *error_; }
  Error noStepsError() const {
    return makeError(headerLine_, "no steps: the file has a header but no rows");
  }

 private:
  Error makeError(std::size_t line, std::string message, int column = -1) const {
    Error e(std::string(file_), line, 0, std::move(message));
    if (column >= 0) {
      e.column = static_cast<std::size_t>(column) + 1;
      e.message = (column < static_cast<int>(columns_.size())
                       ? "column " + quotedInput(columns_[column].name) + " (position " +
                             std::to_string(e.column) + "): "
                       : "field " + std::to_string(e.column) + ": ") +
                  e.message;
    }
    return e;
  }

  bool setError(std::size_t line, std::string message, int column = -1) {
    error_ = makeError(line, std::move(message), column);
    return false;
  }

  bool parseMetadata() {
    std::vector<double> numbers;
    while (cursor_.nextStartsWith('#')) {
      const std::string_view line = cursor_.next();
      const std::size_t lineNo = cursor_.lineNumber();
      if (const std::size_t bad = invalidUtf8At(line); bad != std::string_view::npos) {
        const std::size_t colon = line.find(':');
        std::string what = "the metadata line";
        if (colon != std::string_view::npos && colon < bad) {
          what = "the value of metadata key " + quotedInput(trim(line.substr(1, colon - 1)));
        }
        return setError(lineNo, utf8Message(what, line, bad, "of the line"));
      }
      const std::string_view body = line.substr(1);
      const std::size_t colon = body.find(':');
      const std::string_view key =
          colon == std::string_view::npos ? "" : trim(body.substr(0, colon));
      if (key.empty() || key.find_first_of(" \t") != std::string_view::npos) {
        return setError(lineNo, "expected a metadata line '# key: value', found " + shown(line));
      }
      const std::string value(trim(body.substr(colon + 1)));
      if (run_.metadata.size() >= kMaxRunMetadataLines) {
        return setError(lineNo, "too many metadata lines: a run file holds at most " +
                                    std::to_string(kMaxRunMetadataLines));
      }
      // Keys point into the text, which outlives the parser.
      if (const auto [at, added] = metadataLines_.emplace(key, lineNo); !added) {
        return setError(lineNo, "repeated metadata key " + shown(key) + " (first given on line " +
                                    std::to_string(at->second) + ")");
      }
      if (key == "format" && value != kRunFormat) {
        return setError(lineNo,
                        "expected format '" + std::string(kRunFormat) + "', found " + shown(value));
      }
      double dt = 0.0;
      if (key == "dt" && !(parseFiniteDouble(value, dt) && dt > 0.0)) {
        return setError(lineNo,
                        "expected 'dt' to be a positive number of seconds, found " + shown(value));
      }
      if (key == "start" && !parseDoubleList(value, 3, numbers)) {
        return setError(lineNo,
                        "expected 'start' as three numbers x,y,theta, found " + shown(value));
      }
      if (key == "goal" && !parseDoubleList(value, 2, numbers)) {
        return setError(lineNo, "expected 'goal' as two numbers x,y, found " + shown(value));
      }
      if (key == "outcome" && !parseRunOutcome(value)) {
        return setError(
            lineNo,
            "expected 'outcome' to be success, gave-up, unreachable, timeout or unknown, found " +
                shown(value));
      }
      run_.metadata.emplace_back(std::string(key), value);
    }
    return true;
  }

  bool parseHeader() {
    if (cursor_.atEnd()) {
      return setError(cursor_.lineNumber(), "expected a header line after the metadata lines");
    }
    const std::string_view line = cursor_.next();
    headerLine_ = cursor_.lineNumber();
    if (line.empty()) return setError(headerLine_, "expected the header line, found an empty line");
    std::size_t start = 0;
    std::array<int, kPoseColumns.size()> poseSeen{};
    std::array<int, kValuesPerStep> sensorSeen{};
    std::array<int, kGroupCount> truthSeen{};
    poseSeen.fill(-1);
    sensorSeen.fill(-1);
    truthSeen.fill(-1);
    // `x_` columns by name (views into the text), with their positions: one look-up per column.
    std::unordered_map<std::string_view, int> extraSeen;
    while (true) {
      const std::size_t comma = line.find(',', start);
      const std::string_view name = line.substr(
          start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
      const int position = static_cast<int>(columns_.size());
      if (columns_.size() >= kMaxRunColumns) {
        return setError(headerLine_, "too many columns: a run file holds at most " +
                                         std::to_string(kMaxRunColumns) +
                                         " (found more at position " +
                                         std::to_string(position + 1) + ")");
      }
      Column column{ColumnKind::Extra, 0, std::string(name)};
      if (const std::size_t bad = invalidUtf8At(name); bad != std::string_view::npos) {
        columns_.push_back(Column{ColumnKind::Extra, 0, std::string(name)});
        return setError(headerLine_, utf8Message("the column name", name, bad), position);
      }
      if (name.empty()) {
        columns_.push_back(column);
        return setError(headerLine_, "expected a column name, found an empty field", position);
      }
      if (!classifyColumn(name, column)) {
        columns_.push_back(column);
        return setError(headerLine_,
                        "unknown column " + shown(name) +
                            " (expected step, x, y, theta, v, omega, blocked, n0..n43, s0..s43, "
                            "truth_<group>, or a name prefixed 'x_')",
                        position);
      }
      int* seen = nullptr;
      switch (column.kind) {
        case ColumnKind::Normal:
          seen = &sensorSeen[normalOffset(column.index)];
          break;
        case ColumnKind::Shear:
          seen = &sensorSeen[shearOffset(column.index)];
          break;
        case ColumnKind::Truth:
          seen = &truthSeen[column.index];
          break;
        case ColumnKind::Extra:
          if (const auto [at, added] = extraSeen.emplace(name, position); !added) {
            columns_.push_back(column);
            return setError(headerLine_,
                            "duplicate column " + shown(name) + " (first at position " +
                                std::to_string(at->second + 1) + ")",
                            position);
          }
          column.index = static_cast<int>(run_.extraColumns.size());
          run_.extraColumns.emplace_back(name);
          break;
        default:
          seen = &poseSeen[static_cast<std::size_t>(column.kind)];
      }
      if (seen != nullptr) {
        if (*seen >= 0) {
          columns_.push_back(column);
          return setError(headerLine_,
                          "duplicate column " + shown(name) + " (first at position " +
                              std::to_string(*seen + 1) + ")",
                          position);
        }
        *seen = position;
      }
      columns_.push_back(std::move(column));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    for (std::size_t i = 0; i < poseSeen.size(); ++i) {
      if (poseSeen[i] < 0) {
        return setError(headerLine_, "missing column '" + std::string(kPoseColumns[i]) + "'");
      }
    }
    for (int v = 0; v < kValuesPerStep; ++v) {
      if (sensorSeen[v] < 0) {
        return setError(headerLine_, std::string("missing column '") + (v % 2 ? 's' : 'n') +
                                         std::to_string(v / 2) + "'");
      }
    }
    int truthCount = 0;
    for (int g = 0; g < kGroupCount; ++g)
      truthCount += truthSeen[g] >= 0;
    if (truthCount != 0 && truthCount != kGroupCount) {
      for (int g = 0; g < kGroupCount; ++g) {
        if (truthSeen[g] < 0) {
          return setError(headerLine_, "missing column '" + truthColumnName(g) +
                                           "' (truth columns come all eight or none)");
        }
      }
    }
    hasTruth_ = truthCount == kGroupCount;
    return true;
  }

  std::string fieldCountMessage(std::size_t found, bool lastLine) const {
    std::string m =
        "expected " + std::to_string(columns_.size()) + " fields, found " + std::to_string(found);
    if (lastLine) m = "truncated last line: " + m;
    return m;
  }

  bool parseRows() {
    if (!parseRowLines()) return false;
    if (run_.stepCount() == 0) {
      error_ = noStepsError();
      return false;
    }
    if (progress_) progress_(text_.size(), text_.size());
    return true;
  }

  bool parseRowLines() {
    // Reserve from the first row's length so long runs do not reallocate repeatedly.
    const std::size_t remaining = cursor_.remaining();
    std::size_t firstLength = remaining;
    if (const void* nl = std::memchr(text_.data() + cursor_.offset(), '\n', remaining)) {
      firstLength = static_cast<const char*>(nl) - (text_.data() + cursor_.offset()) + 1;
    }
    const std::size_t estimate = remaining / std::max<std::size_t>(firstLength, 1) + 16;
    run_.reserve(estimate, hasTruth_);
    const std::size_t extraCount = run_.extraColumns.size();
    if (extraCount > 0) run_.extraValues.reserve(estimate * extraCount);

    constexpr std::size_t kProgressBytes = 1 << 20;
    std::size_t nextProgress = kProgressBytes;
    std::array<double, kValuesPerStep> values{};
    std::array<ContactClass, kGroupCount> truth{};
    std::array<double, 5> pose{};
    std::size_t step = firstStep_;
    std::int64_t blocked = 0;

    while (!cursor_.atEnd()) {
      const std::string_view line = cursor_.next();
      const std::size_t lineNo = cursor_.lineNumber();
      if (line.empty()) {
        if (cursor_.onlyBlankLinesLeft()) break;
        return setError(lineNo, "empty line between rows (expected a row of " +
                                    std::to_string(columns_.size()) + " fields)");
      }
      if (line.front() == '#') {
        return setError(lineNo, "metadata line '#' after the header (metadata lines go first)");
      }
      const bool lastLine = !cursor_.lastHadNewline();
      const char* p = line.data();
      const char* const end = line.data() + line.size();
      const std::size_t extraBase = run_.extraValues.size();
      for (std::size_t c = 0; c < columns_.size(); ++c) {
        const Column& column = columns_[c];
        const bool lastColumn = c + 1 == columns_.size();
        // Fast path for the 88 sensor fields: a clean in-range number parsed in place.
        const char* fieldEnd = nullptr;
        if (column.kind == ColumnKind::Normal || column.kind == ColumnKind::Shear) {
          fieldEnd = parseSensorInPlace(p, end, column, values);
        }
        const bool parsed = fieldEnd != nullptr;
        // Otherwise the field runs to the next comma (or the end of the line).
        if (!parsed) fieldEnd = static_cast<const char*>(std::memchr(p, ',', end - p));
        if (fieldEnd == nullptr) fieldEnd = end;
        if (fieldEnd == end && !lastColumn) {
          run_.extraValues.resize(extraBase);
          return setError(lineNo, fieldCountMessage(c + 1, lastLine), static_cast<int>(c + 1));
        }
        if (fieldEnd != end && lastColumn) {
          std::size_t found = columns_.size();
          for (const char* q = fieldEnd; q < end; ++q)
            found += *q == ',';
          run_.extraValues.resize(extraBase);
          return setError(lineNo, fieldCountMessage(found, false),
                          static_cast<int>(columns_.size()));
        }
        const std::string_view field(p, fieldEnd - p);
        p = fieldEnd + 1;
        if (!parsed && !parseField(column, field, lineNo, static_cast<int>(c), step, values, truth,
                                   pose, blocked)) {
          run_.extraValues.resize(extraBase);
          return false;
        }
      }
      run_.appendStep(pose[0], pose[1], pose[2], pose[3], pose[4], blocked != 0, values.data(),
                      hasTruth_ ? truth.data() : nullptr);
      ++step;
      if (progress_ && cursor_.offset() >= nextProgress) {
        nextProgress = cursor_.offset() + kProgressBytes;
        if (!progress_(cursor_.offset(), text_.size())) {
          return setError(lineNo, "reading cancelled");
        }
      }
    }
    return true;
  }

  // Parses a normal or shear value that ends at a comma or the line end and lies in range;
  // returns where it ended, or nullptr to let the checked path report what is wrong.
  static const char* parseSensorInPlace(const char* p, const char* end, const Column& column,
                                        std::array<double, kValuesPerStep>& values) {
    const bool normal = column.kind == ColumnKind::Normal;
    double& out = values[normal ? normalOffset(column.index) : shearOffset(column.index)];
    if (p < end && *p == '0' && (p + 1 == end || p[1] == ',')) {
      out = 0.0;
      return p + 1;
    }
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(p, end, v, std::chars_format::general);
    if (ec != std::errc() || ptr == p || (ptr != end && *ptr != ',')) return nullptr;
    const bool inRange =
        normal ? (v >= 0.0 && v <= kMaxNormal) : (v >= -kMaxShear && v <= kMaxShear);
    if (!inRange) return nullptr;  // also rejects NaN
    out = v;
    return ptr;
  }

  bool numberError(std::size_t lineNo, int c, std::string_view field, const char* what) {
    if (field.empty()) {
      return setError(lineNo, std::string("expected ") + what + ", found an empty field", c);
    }
    return setError(lineNo, std::string("expected ") + what + ", found " + shown(field), c);
  }

  bool parseNumber(std::string_view field, std::size_t lineNo, int c, double& out) {
    const char* end = field.data() + field.size();
    auto [ptr, ec] = std::from_chars(field.data(), end, out, std::chars_format::general);
    if (ptr != end || field.empty() ||
        (ec != std::errc() && ec != std::errc::result_out_of_range)) {
      return numberError(lineNo, c, field, "a number");
    }
    if (ec == std::errc::result_out_of_range) {
      if (underflows(field)) {
        return setError(lineNo,
                        "expected a number a double can hold, found " + shown(field) +
                            ": it underflows (nonzero, but closer to zero than the smallest "
                            "double, about 4.9e-324; write 0 for zero)",
                        c);
      }
      return setError(lineNo,
                      "expected a finite number, found " + shown(field) +
                          ": it overflows (larger in magnitude than the largest double, about "
                          "1.8e308)",
                      c);
    }
    if (!std::isfinite(out)) {
      return numberError(lineNo, c, field, "a finite number (no NaN or infinity)");
    }
    return true;
  }

  // For a number literal std::from_chars found out of range for a double: true when it is too
  // close to zero rather than too large.
  static bool underflows(std::string_view field) {
    long double wide = 0.0L;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, wide, std::chars_format::general);
    if (ec == std::errc() && ptr == end) return std::fabs(wide) < 1.0L;
    // Beyond even a long double: the sign of the exponent decides, else the integer digits.
    const std::size_t e = field.find_first_of("eE");
    if (e != std::string_view::npos && e + 1 < field.size()) return field[e + 1] == '-';
    const std::string_view mantissa = field.substr(field.starts_with('-') ? 1 : 0);
    return mantissa.substr(0, mantissa.find('.')).find_first_not_of('0') == std::string_view::npos;
  }

  bool parseField(const Column& column, std::string_view field, std::size_t lineNo, int c,
                  std::size_t step, std::array<double, kValuesPerStep>& values,
                  std::array<ContactClass, kGroupCount>& truth, std::array<double, 5>& pose,
                  std::int64_t& blocked) {
    switch (column.kind) {
      case ColumnKind::Normal: {
        double& v = values[normalOffset(column.index)];
        if (!parseNumber(field, lineNo, c, v)) return false;
        if (v < 0.0 || v > kMaxNormal) {
          return numberError(lineNo, c, field, "a normal value in [0, 5]");
        }
        return true;
      }
      case ColumnKind::Shear: {
        double& v = values[shearOffset(column.index)];
        if (!parseNumber(field, lineNo, c, v)) return false;
        if (v < -kMaxShear || v > kMaxShear) {
          return numberError(lineNo, c, field, "a shear value in [-5, 5]");
        }
        return true;
      }
      case ColumnKind::X:
      case ColumnKind::Y:
      case ColumnKind::Theta:
      case ColumnKind::V:
      case ColumnKind::Omega:
        return parseNumber(
            field, lineNo, c,
            pose[static_cast<std::size_t>(column.kind) - static_cast<std::size_t>(ColumnKind::X)]);
      case ColumnKind::Step: {
        std::int64_t value = -1;
        if (!parseCount(field, value)) {
          return numberError(lineNo, c, field,
                             "an integer step (digits only: no sign, no leading zero)");
        }
        if (value != static_cast<std::int64_t>(step)) {
          return setError(lineNo,
                          "expected step " + std::to_string(step) +
                              " (steps count from 0 by 1), found " + shown(field),
                          c);
        }
        return true;
      }
      case ColumnKind::Blocked:
        // Exactly "0" or "1": an integer literal, no sign, no leading zero.
        if (field != "0" && field != "1") return numberError(lineNo, c, field, "0 or 1");
        blocked = field[0] - '0';
        return true;
      case ColumnKind::Truth: {
        const std::optional<ContactClass> cls = parseContactClass(field);
        if (!cls) {
          return numberError(lineNo, c, field,
                             "a contact class (NoContact, Wall, Corner, LeavingWall or DeadPath)");
        }
        truth[column.index] = *cls;
        return true;
      }
      case ColumnKind::Extra:
        if (const std::size_t bad = invalidUtf8At(field); bad != std::string_view::npos) {
          return setError(lineNo, utf8Message("a text field", field, bad), c);
        }
        run_.extraValues.emplace_back(field);
        return true;
    }
    return true;
  }

  std::string_view text_;
  std::string_view file_;
  const ProgressFn& progress_;
  LineCursor cursor_;
  RunData run_;
  // Metadata keys (views into the text) and the line each was given on.
  std::unordered_map<std::string_view, std::size_t> metadataLines_;
  std::vector<Column> columns_;
  std::size_t headerLine_ = 0;
  std::size_t firstStep_ = 0;
  bool hasTruth_ = false;
  std::optional<Error> error_;
};

// Appends rows (a chunk's RunData: no metadata) to `run`.
void appendRows(RunData& run, const RunData& rows) {
  const auto append = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  append(run.x, rows.x);
  append(run.y, rows.y);
  append(run.theta, rows.theta);
  append(run.v, rows.v);
  append(run.omega, rows.omega);
  append(run.blocked, rows.blocked);
  append(run.sensors, rows.sensors);
  append(run.truth, rows.truth);
  append(run.extraValues, rows.extraValues);
}

// Appends the shortest decimal text that reads back as exactly `value`.
inline char* putDouble(char* out, double value) {
  if (value == 0.0 && !std::signbit(value)) {
    *out = '0';
    return out + 1;
  }
  return std::to_chars(out, out + 32, value).ptr;
}

}  // namespace

RunCsvResult parseRunCsv(std::string_view text, std::string_view fileName,
                         const ProgressFn& progress) {
  return Parser(text, fileName, progress).parse();
}

struct RunCsvChunks::State {
  struct Chunk {
    std::size_t begin = 0;  // offsets into the text (after a byte-order mark)
    std::size_t end = 0;
    std::size_t firstLine = 0;
    std::size_t firstStep = 0;
  };
  State(std::string_view text, std::string name)
      : file(std::move(name)), head(text, file, kNoProgress) {}
  std::string file;
  Parser head;
  bool ok = false;
  std::vector<Chunk> chunks;
};

RunCsvChunks::RunCsvChunks(std::string_view text, std::string_view fileName, std::size_t chunkBytes)
    : state_(std::make_unique<State>(text, std::string(fileName))) {
  State& st = *state_;
  st.ok = st.head.parseHead();
  if (!st.ok) return;
  const std::string_view body = st.head.text();
  chunkBytes = std::max<std::size_t>(chunkBytes, 1);
  std::size_t begin = st.head.offset();
  std::size_t line = st.head.headerLine() + 1;
  std::size_t step = 0;
  // Every line before a chunk must be a row (a blank line among rows is an error its chunk
  // reports), so a chunk's first step is the number of lines before it.
  do {
    std::size_t end = body.size();
    if (body.size() - begin > chunkBytes) {
      const std::size_t from = begin + chunkBytes - 1;
      if (const void* nl = std::memchr(body.data() + from, '\n', body.size() - from)) {
        end = static_cast<std::size_t>(static_cast<const char*>(nl) - body.data()) + 1;
      }
    }
    st.chunks.push_back({begin, end, line, step});
    std::size_t lines = 0;
    const char* const stop = body.data() + end;
    for (const char* p = body.data() + begin; p < stop; ++lines) {
      const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(stop - p));
      if (nl == nullptr) break;
      p = static_cast<const char*>(nl) + 1;
    }
    line += lines;
    step += lines;
    begin = end;
  } while (begin < body.size());
}

RunCsvChunks::RunCsvChunks(RunCsvChunks&&) noexcept = default;
RunCsvChunks& RunCsvChunks::operator=(RunCsvChunks&&) noexcept = default;
RunCsvChunks::~RunCsvChunks() = default;

const Error* RunCsvChunks::error() const {
  return state_->ok ? nullptr : &state_->head.error();
}

const RunData& RunCsvChunks::header() const {
  return state_->head.head();
}

bool RunCsvChunks::hasTruth() const {
  return state_->head.hasTruth();
}

std::size_t RunCsvChunks::size() const {
  return state_->chunks.size();
}

std::size_t RunCsvChunks::firstStep(std::size_t chunk) const {
  return state_->chunks.at(chunk).firstStep;
}

std::size_t RunCsvChunks::bytes(std::size_t chunk) const {
  const State::Chunk& c = state_->chunks.at(chunk);
  return c.end - c.begin;
}

RunCsvResult RunCsvChunks::parse(std::size_t chunk) const {
  const State::Chunk& c = state_->chunks.at(chunk);
  return state_->head.rowParser(c.begin, c.end, c.firstLine, c.firstStep).parseRowRange();
}

std::optional<Error> RunCsvChunks::checkStepCount(std::size_t steps) const {
  if (steps == 0) return state_->head.noStepsError();
  return std::nullopt;
}

RunCsvResult RunCsvChunks::join(std::vector<RunCsvResult> parts) const {
  if (const Error* e = error()) return *e;
  std::size_t total = 0;
  for (const RunCsvResult& part : parts) {
    if (!part.ok()) return part.error();
    total += part.value().stepCount();
  }
  if (auto e = checkStepCount(total)) return std::move(*e);
  RunData run;
  run.metadata = header().metadata;
  run.extraColumns = header().extraColumns;
  run.reserve(total, hasTruth());
  run.extraValues.reserve(total * run.extraColumns.size());
  for (const RunCsvResult& part : parts)
    appendRows(run, part.value());
  return run;
}

RunCsvResult parseRunCsvParallel(std::string_view text, std::string_view fileName, unsigned threads,
                                 std::size_t chunkBytes) {
  const RunCsvChunks chunks(text, fileName, chunkBytes);
  if (const Error* e = chunks.error()) return *e;
  std::vector<std::optional<RunCsvResult>> parsed(chunks.size());
  parallelFor(chunks.size(), std::max(threads, 1u),
              [&](std::size_t i) { parsed[i].emplace(chunks.parse(i)); });
  std::vector<RunCsvResult> parts;
  parts.reserve(parsed.size());
  for (auto& part : parsed)
    parts.push_back(std::move(*part));
  return chunks.join(std::move(parts));
}

RunCsvResult readRunCsv(const std::filesystem::path& path, const ProgressFn& progress) {
  FileText text;
  if (Status loaded = text.load(path); !loaded) return loaded.error();
  return parseRunCsv(text.view(), path.string(), progress);
}

namespace {

// The header lines: metadata comments and the column names.
std::string csvHeader(const RunData& run) {
  std::string out;
  for (const auto& [key, value] : run.metadata) {
    out += "# ";
    out += key;
    out += ": ";
    out += value;
    out += '\n';
  }
  out += "step,x,y,theta,v,omega,blocked";
  for (int s = 0; s < kSensorCount; ++s) {
    out += ",n" + std::to_string(s) + ",s" + std::to_string(s);
  }
  if (run.hasTruth()) {
    for (int g = 0; g < kGroupCount; ++g)
      out += "," + truthColumnName(g);
  }
  for (const std::string& name : run.extraColumns)
    out += "," + name;
  out += '\n';
  return out;
}

// The lines of steps [first, end), appended to `out`.
void appendCsvSteps(const RunData& run, std::size_t first, std::size_t end, std::string& out) {
  const std::size_t extras = run.extraColumns.size();
  // Worst case per value: 24 characters plus a comma.
  char line[32 * (8 + kValuesPerStep) + 16 * kGroupCount];
  for (std::size_t i = first; i < end; ++i) {
    char* p = line;
    p = std::to_chars(p, p + 24, i).ptr;
    for (double value : {run.x[i], run.y[i], run.theta[i], run.v[i], run.omega[i]}) {
      *p++ = ',';
      p = putDouble(p, value);
    }
    *p++ = ',';
    *p++ = run.blocked[i] ? '1' : '0';
    const double* values = run.stepSensors(i);
    for (int v = 0; v < kValuesPerStep; ++v) {
      *p++ = ',';
      p = putDouble(p, values[v]);
    }
    out.append(line, static_cast<std::size_t>(p - line));
    if (run.hasTruth()) {
      for (int g = 0; g < kGroupCount; ++g) {
        out += ',';
        out += contactClassName(run.truth[i * kGroupCount + g]);
      }
    }
    for (std::size_t e = 0; e < extras; ++e) {
      out += ',';
      out += run.extraValues[i * extras + e];
    }
    out += '\n';
  }
}

constexpr std::size_t kCsvBlockSteps = 8192;

}  // namespace

std::string formatRunCsv(const RunData& run) {
  const std::size_t steps = run.stepCount();
  std::string out = csvHeader(run);
  out.reserve(out.size() + steps * (kValuesPerStep * 4 + 64 + (run.hasTruth() ? 64 : 0)));
  appendCsvSteps(run, 0, steps, out);
  return out;
}

void formatRunCsvPieces(const RunData& run, unsigned threads,
                        const std::function<void(std::string_view)>& sink) {
  sink(csvHeader(run));
  const std::size_t steps = run.stepCount();
  const std::size_t blocks = (steps + kCsvBlockSteps - 1) / kCsvBlockSteps;
  const unsigned workers = workerThreadCount(threads, blocks);
  // Rounds of a few blocks per thread: formatted side by side, handed over in order.
  const std::size_t perRound = static_cast<std::size_t>(workers) * 2;
  std::vector<std::string> pieces(perRound);
  for (std::size_t round = 0; round < blocks; round += perRound) {
    const std::size_t count = std::min(perRound, blocks - round);
    parallelFor(count, workers, [&](std::size_t k) {
      const std::size_t first = (round + k) * kCsvBlockSteps;
      pieces[k].clear();
      appendCsvSteps(run, first, std::min(steps, first + kCsvBlockSteps), pieces[k]);
    });
    for (std::size_t k = 0; k < count; ++k)
      sink(pieces[k]);
  }
}

Status writeRunCsv(const RunData& run, const std::filesystem::path& path) {
  return writeFileAtomically(path, formatRunCsv(run));
}

}  // namespace tactile
