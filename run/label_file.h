// The one reader and writer of label files (docs/file-formats.md#label-file): CSV
// `run,group,first_step,last_step,class[,annotator]` with inclusive step ranges, or JSON with the
// same fields, plus optional provenance per run (its step count and checksum, so labels are never
// applied to another run of the same name unnoticed). Pure text in, records out; the database and
// the CLI resolve run names and check the provenance.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile {

struct LabelRecord {
  std::string run;
  SensorGroup group = SensorGroup::Front;
  std::int64_t firstStep = 0;
  std::int64_t lastStep = 0;
  ContactClass cls = ContactClass::NoContact;
  std::string annotator;
  std::size_t line = 0;  // 1-based source line (JSON: the line the segment's object starts on)
};

// The run a label file was made for: its name, step count and checksum (the 16 hex digits of the
// run file's checksum, docs/file-formats.md#label-file). CSV: a comment line before the header,
// `# run NAME steps N checksum HEX`; JSON: an entry of the `runs` array.
struct LabelRunProvenance {
  std::string name;
  std::int64_t steps = 0;
  std::string checksum;
  std::size_t line = 0;  // 1-based source line (JSON: the line the `runs` entry starts on)
  bool operator==(const LabelRunProvenance& o) const {
    return name == o.name && steps == o.steps && checksum == o.checksum;
  }
};

// A parsed label file.
struct LabelFile {
  std::vector<LabelRecord> records;
  std::vector<LabelRunProvenance> runs;  // in file order; at most one per run name
};

// CSV: optional comment lines (`#`) before the header, of which `# run NAME steps N checksum HEX`
// lines are provenance (a malformed one is an error); then a header naming those columns in any
// order (annotator optional), one row per segment.
// Groups by short or long name, classes by exact spelling, 0 <= first_step <= last_step. A UTF-8
// BOM, CRLF line ends, a missing final newline and trailing blank lines are accepted; a blank line
// between rows is not. Errors name the file and line.
Result<LabelFile> parseLabelCsv(std::string_view text, std::string_view fileName);
// JSON: {"format":"tactile-labels","version":1,"set":...,["runs":[{"name","steps","checksum"}],]
// "segments":[{"run","group","first_step","last_step","class"[,"annotator"]}]} or a bare array of
// such segment objects. The CSV reader's rules hold here too: a repeated key, a key the format does
// not have, and an integer written "-0" are refused. Errors name the file and the line of the
// element they are about.
Result<LabelFile> parseLabelJson(std::string_view text, std::string_view fileName);

// The annotator column is written only when some record has one; provenance lines (CSV) or the
// `runs` array (JSON) only when `runs` is not empty.
std::string formatLabelCsv(const std::vector<LabelRecord>& records,
                           const std::vector<LabelRunProvenance>& runs = {});
std::string formatLabelJson(const std::vector<LabelRecord>& records, std::string_view setName,
                            std::string_view setAnnotator,
                            const std::vector<LabelRunProvenance>& runs = {});

// The provenance entry for `run`, or nullptr.
const LabelRunProvenance* findProvenance(const LabelFile& file, std::string_view run);

}  // namespace tactile
