#include "run/label_file.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>

#include "base/text_parse.h"
#include "base/text_rules.h"
#include "run/json_text.h"

namespace tactile {
namespace {

std::vector<std::string_view> splitComma(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const std::size_t comma = line.find(',');
    fields.push_back(line.substr(0, comma));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

// Checks one record's fields; returns an error text or empty.
std::string fillRecord(LabelRecord& record, std::string_view group, std::string_view first,
                       std::string_view last, std::string_view cls) {
  if (record.run.empty()) return "empty run name";
  if (Status name = checkName(record.run, "run"); !name) return name.error().message;
  const auto g = parseSensorGroup(group);
  if (!g) {
    return "unknown group " + quotedInput(group) + " (expected F, FLC, L, RLC, B, RRC, R, FRC)";
  }
  record.group = *g;
  if (!parseCount(first, record.firstStep)) {
    return "first_step " + quotedInput(first) +
           " is not a step number (digits only: no sign, no leading zero)";
  }
  if (!parseCount(last, record.lastStep) || record.lastStep < record.firstStep) {
    return "last_step " + quotedInput(last) + " is not a step number >= first_step";
  }
  const auto c = parseContactClass(cls);
  if (!c) {
    return "unknown class " + quotedInput(cls) +
           " (expected NoContact, Wall, Corner, LeavingWall or DeadPath)";
  }
  record.cls = *c;
  return {};
}

bool isChecksum(std::string_view text) {
  return text.size() == 16 && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

// Checks one provenance entry and adds it; returns an error text or empty.
std::string addProvenance(std::vector<LabelRunProvenance>& runs, LabelRunProvenance entry) {
  if (entry.name.empty()) return "provenance without a run name";
  if (Status name = checkName(entry.name, "run"); !name) return name.error().message;
  if (entry.steps < 0)
    return "run " + quotedInput(entry.name) + ": step count must not be negative";
  if (!isChecksum(entry.checksum)) {
    return "run " + quotedInput(entry.name) + ": checksum " + quotedInput(entry.checksum) +
           " is not 16 lower-case hex digits";
  }
  for (const LabelRunProvenance& other : runs) {
    if (other.name == entry.name)
      return "second provenance entry for run " + quotedInput(entry.name);
  }
  runs.push_back(std::move(entry));
  return {};
}

// `# run NAME steps N checksum HEX` (NAME may hold spaces: the last four words are fixed).
std::string parseProvenanceLine(std::string_view line, LabelRunProvenance& entry) {
  constexpr std::string_view kExpected = "expected '# run NAME steps N checksum HEX'";
  std::string_view rest = line.substr(std::string_view("# run ").size());
  std::array<std::string_view, 4> tail{};  // steps N checksum HEX
  for (int i = 3; i >= 0; --i) {
    const std::size_t space = rest.rfind(' ');
    if (space == std::string_view::npos) return std::string(kExpected);
    tail[static_cast<std::size_t>(i)] = rest.substr(space + 1);
    rest = rest.substr(0, space);
  }
  if (rest.empty() || tail[0] != "steps" || tail[2] != "checksum") {
    return std::string(kExpected);
  }
  entry.name = std::string(rest);
  if (!parseCount(tail[1], entry.steps)) {
    return "run " + quotedInput(entry.name) + ": step count " + quotedInput(tail[1]) +
           " is not a number (digits only: no sign, no leading zero)";
  }
  entry.checksum = std::string(tail[3]);
  return {};
}

}  // namespace

const LabelRunProvenance* findProvenance(const LabelFile& file, std::string_view run) {
  for (const LabelRunProvenance& p : file.runs) {
    if (p.name == run) return &p;
  }
  return nullptr;
}

Result<LabelFile> parseLabelCsv(std::string_view text, std::string_view fileName) {
  LabelFile result;
  auto fail = [&](std::size_t line, const std::string& message) {
    return Error(std::string(fileName), line, 0, message);
  };
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  // Column positions by name: run, group, first_step, last_step, class, annotator (optional).
  constexpr std::array<std::string_view, 6> kNames{"run",       "group", "first_step",
                                                   "last_step", "class", "annotator"};
  std::array<int, 6> position{-1, -1, -1, -1, -1, -1};
  std::size_t columnCount = 0;
  std::size_t lineNo = 0;
  bool header = true;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    ++lineNo;
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (header && line.starts_with('#')) {
      // Comments before the header; `# run ...` lines are provenance.
      if (!line.starts_with("# run ")) continue;
      LabelRunProvenance entry;
      entry.line = lineNo;
      std::string error = parseProvenanceLine(line, entry);
      if (error.empty()) error = addProvenance(result.runs, std::move(entry));
      if (!error.empty()) return fail(lineNo, error);
      continue;
    }
    if (header) {
      const auto names = splitComma(line);
      columnCount = names.size();
      for (std::size_t i = 0; i < names.size(); ++i) {
        const auto it = std::find(kNames.begin(), kNames.end(), names[i]);
        if (it == kNames.end()) {
          return fail(lineNo, "column " + std::to_string(i + 1) + ": unknown column " +
                                  quotedInput(names[i]) +
                                  " (expected run, group, first_step, last_step, class and "
                                  "optionally annotator)");
        }
        int& slot = position[it - kNames.begin()];
        if (slot >= 0) {
          return fail(lineNo, "column " + std::to_string(i + 1) + ": duplicate column " +
                                  quotedInput(names[i]));
        }
        slot = static_cast<int>(i);
      }
      for (std::size_t k = 0; k + 1 < kNames.size(); ++k) {
        if (position[k] < 0) {
          return fail(lineNo, "missing column '" + std::string(kNames[k]) + "'");
        }
      }
      header = false;
      continue;
    }
    if (line.empty()) {
      // Blank lines at the very end are tolerated, as in run files.
      if (text.find_first_not_of("\r\n") == std::string_view::npos) break;
      return fail(lineNo, "empty line between rows");
    }
    const auto fields = splitComma(line);
    if (fields.size() != columnCount) {
      return fail(lineNo, "expected " + std::to_string(columnCount) + " fields, found " +
                              std::to_string(fields.size()));
    }
    LabelRecord record;
    record.line = lineNo;
    record.run = std::string(fields[position[0]]);
    if (std::string error = fillRecord(record, fields[position[1]], fields[position[2]],
                                       fields[position[3]], fields[position[4]]);
        !error.empty()) {
      return fail(lineNo, error);
    }
    if (position[5] >= 0) {
      record.annotator = std::string(fields[position[5]]);
      if (!record.annotator.empty()) {
        if (Status name = checkName(record.annotator, "annotator"); !name) {
          return fail(lineNo, name.error().message);
        }
      }
    }
    result.records.push_back(std::move(record));
  }
  if (header && lineNo == 0) return fail(1, "empty file (expected a header)");
  if (header) return fail(lineNo, "no header after the comment lines");
  return result;
}

namespace {

// A JSON value's type in words, for "holds a string where an integer is needed".
std::string jsonTypeWords(const nlohmann::json& v) {
  if (v.is_string()) return "a string";
  if (v.is_number_float()) return "a number with a fraction or exponent";
  if (v.is_number()) return "a number";
  if (v.is_boolean()) return "true or false";
  if (v.is_null()) return "null";
  if (v.is_array()) return "an array";
  return "an object";
}

// The keys an object may have; the first other one, or nullptr.
const std::string* unknownKey(const nlohmann::json& object,
                              std::initializer_list<std::string_view> allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) return &it.key();
  }
  return nullptr;
}

}  // namespace

Result<LabelFile> parseLabelJson(std::string_view text, std::string_view fileName) {
  LabelFile result;
  const std::string name(fileName);
  JsonLines lines;
  Result<nlohmann::json> parsed = parseJsonText(text, fileName, &lines);
  if (!parsed) return parsed.error();
  // Every error names the line of the element it is about (the line of its key in an object).
  auto at = [&](const std::string& pointer, const std::string& message) {
    return Error(name, std::max<std::size_t>(lines.lineOf(pointer), 1), 0, message);
  };
  // "-0" is no step number (the CSV reader refuses it as a literal with a sign): so here too.
  if (!lines.negativeZeros.empty()) {
    const std::string& pointer = lines.negativeZeros.front();
    return at(pointer, pointer.substr(pointer.rfind('/') + 1) +
                           " is -0: an integer is written without a sign");
  }
  const nlohmann::json& doc = parsed.value();
  const nlohmann::json* segments = &doc;
  std::string segmentsPointer;
  if (doc.is_object()) {
    if (const std::string* key =
            unknownKey(doc, {"format", "version", "set", "annotator", "runs", "segments"})) {
      return at("/" + *key, "unknown key " + quotedInput(*key) +
                                " (expected format, version, set, annotator, runs, segments)");
    }
    if (doc.contains("format") && doc["format"] != "tactile-labels") {
      return at("/format", "format is not \"tactile-labels\"");
    }
    if (doc.contains("version") && doc["version"] != 1) {
      return at("/version", "unsupported label file version " + dumpJson(doc["version"]));
    }
    for (const char* key : {"set", "annotator"}) {
      if (doc.contains(key) && !doc[key].is_string()) {
        return at(std::string("/") + key, std::string("\"") + key + "\" holds " +
                                              jsonTypeWords(doc[key]) + " where text is needed");
      }
    }
    if (!doc.contains("segments")) {
      return at("", "missing \"segments\"");
    }
    segments = &doc["segments"];
    segmentsPointer = "/segments";
    if (doc.contains("runs")) {
      if (!doc["runs"].is_array()) {
        return at("/runs", "\"runs\" is not an array");
      }
      std::size_t index = 0;
      for (const nlohmann::json& item : doc["runs"]) {
        const std::string pointer = "/runs/" + std::to_string(index);
        ++index;
        LabelRunProvenance entry;
        entry.line = std::max<std::size_t>(lines.lineOf(pointer), 1);
        std::string error;
        const std::string* unknown =
            item.is_object() ? unknownKey(item, {"name", "steps", "checksum"}) : nullptr;
        if (unknown != nullptr) {
          return at(pointer + "/" + *unknown, "runs entry " + std::to_string(index) +
                                                  ": unknown key " + quotedInput(*unknown) +
                                                  " (expected name, steps, checksum)");
        }
        if (!item.is_object() || !item.contains("name") || !item["name"].is_string() ||
            !item.contains("steps") || !item["steps"].is_number_integer() ||
            !item.contains("checksum") || !item["checksum"].is_string()) {
          error = "expected {\"name\": text, \"steps\": integer, \"checksum\": text}";
          if (item.is_object() && item.contains("steps") && !item["steps"].is_number_integer()) {
            error =
                "\"steps\" holds " + jsonTypeWords(item["steps"]) + " where an integer is needed";
          }
        } else if (item["steps"].is_number_unsigned() &&
                   item["steps"].get<std::uint64_t>() >
                       static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
          error = "step count " + dumpJson(item["steps"]) + " is too large";
        } else {
          entry.name = item["name"].get<std::string>();
          entry.steps = item["steps"].get<std::int64_t>();
          entry.checksum = item["checksum"].get<std::string>();
          error = addProvenance(result.runs, std::move(entry));
        }
        if (!error.empty()) {
          return at(pointer, "runs entry " + std::to_string(index) + ": " + error);
        }
      }
    }
  }
  if (!segments->is_array()) {
    return at(segmentsPointer, "\"segments\" is not an array");
  }
  std::size_t index = 0;
  for (const nlohmann::json& item : *segments) {
    const std::string pointer = segmentsPointer + "/" + std::to_string(index);
    ++index;
    auto fail = [&](const std::string& message, const std::string& member = {}) {
      result.records.clear();
      result.runs.clear();
      const std::string where = member.empty() ? pointer : pointer + "/" + member;
      return at(lines.lineOf(where) != 0 ? where : pointer,
                "segment " + std::to_string(index) + ": " + message);
    };
    if (!item.is_object()) return fail("not an object");
    if (const std::string* key =
            unknownKey(item, {"run", "group", "first_step", "last_step", "class", "annotator"})) {
      return fail("unknown key " + quotedInput(*key) +
                      " (expected run, group, first_step, last_step, class, annotator)",
                  *key);
    }
    for (const char* key : {"run", "group", "class"}) {
      if (!item.contains(key)) return fail(std::string("missing text field \"") + key + "\"");
      if (!item[key].is_string()) {
        return fail(std::string("\"") + key + "\" holds " + jsonTypeWords(item[key]) +
                        " where text is needed",
                    key);
      }
    }
    for (const char* key : {"first_step", "last_step"}) {
      if (!item.contains(key)) return fail(std::string("missing integer field \"") + key + "\"");
      if (!item[key].is_number_integer()) {
        return fail(std::string("\"") + key + "\" holds " + jsonTypeWords(item[key]) +
                        " where an integer is needed",
                    key);
      }
      // Beyond int64 (e.g. 18446744073709551615) is no step number; shown as written.
      if (item[key].is_number_unsigned() &&
          item[key].get<std::uint64_t>() >
              static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        return fail(std::string(key) + " " + dumpJson(item[key]) + " is not a step number", key);
      }
    }
    LabelRecord record;
    record.line = std::max<std::size_t>(lines.lineOf(pointer), 1);
    record.run = item["run"].get<std::string>();
    const std::string first = std::to_string(item["first_step"].get<std::int64_t>());
    const std::string last = std::to_string(item["last_step"].get<std::int64_t>());
    if (std::string error = fillRecord(record, item["group"].get<std::string>(), first, last,
                                       item["class"].get<std::string>());
        !error.empty()) {
      return fail(error);
    }
    if (item.contains("annotator")) {
      if (!item["annotator"].is_string()) {
        return fail(
            "\"annotator\" holds " + jsonTypeWords(item["annotator"]) + " where text is needed",
            "annotator");
      }
      record.annotator = item["annotator"].get<std::string>();
      if (!record.annotator.empty()) {
        if (Status annotator = checkName(record.annotator, "annotator"); !annotator) {
          return fail(annotator.error().message, "annotator");
        }
      }
    }
    result.records.push_back(std::move(record));
  }
  return result;
}

std::string formatLabelCsv(const std::vector<LabelRecord>& records,
                           const std::vector<LabelRunProvenance>& runs) {
  bool withAnnotator = false;
  for (const LabelRecord& r : records)
    withAnnotator = withAnnotator || !r.annotator.empty();
  std::string out;
  for (const LabelRunProvenance& p : runs) {
    out +=
        "# run " + p.name + " steps " + std::to_string(p.steps) + " checksum " + p.checksum + '\n';
  }
  out += withAnnotator ? "run,group,first_step,last_step,class,annotator\n"
                       : "run,group,first_step,last_step,class\n";
  for (const LabelRecord& r : records) {
    out += r.run;
    out += ',';
    out += groupInfo(r.group).shortName;
    out += ',' + std::to_string(r.firstStep) + ',' + std::to_string(r.lastStep) + ',';
    out += contactClassName(r.cls);
    if (withAnnotator) out += ',' + r.annotator;
    out += '\n';
  }
  return out;
}

std::string formatLabelJson(const std::vector<LabelRecord>& records, std::string_view setName,
                            std::string_view setAnnotator,
                            const std::vector<LabelRunProvenance>& runs) {
  nlohmann::json segments = nlohmann::json::array();
  for (const LabelRecord& r : records) {
    nlohmann::json item = {{"run", r.run},
                           {"group", groupInfo(r.group).shortName},
                           {"first_step", r.firstStep},
                           {"last_step", r.lastStep},
                           {"class", contactClassName(r.cls)}};
    if (!r.annotator.empty()) item["annotator"] = r.annotator;
    segments.push_back(std::move(item));
  }
  nlohmann::json doc = {
      {"format", "tactile-labels"}, {"version", 1}, {"set", setName}, {"annotator", setAnnotator}};
  if (!runs.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const LabelRunProvenance& p : runs) {
      list.push_back({{"name", p.name}, {"steps", p.steps}, {"checksum", p.checksum}});
    }
    doc["runs"] = std::move(list);
  }
  doc["segments"] = std::move(segments);
  return dumpJson(doc, 1) + "\n";
}

}  // namespace tactile
