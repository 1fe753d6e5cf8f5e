// The one reader and writer of label files (docs/file-formats.md#label-file): CSV
// `run,group,first_step,last_step,class[,annotator]` with inclusive step ranges, or JSON with the
// same fields. Pure text in, records out; the database resolves run names.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

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
  std::size_t line = 0;  // 1-based source line (CSV) or 1-based segment index (JSON)
};

struct LabelFileResult {
  std::vector<LabelRecord> records;
  std::string error;  // "FILE:LINE: ..." when the file was rejected
};

// CSV: a header naming those columns in any order (annotator optional), one row per segment.
// Groups by short or long name, classes by exact spelling, 0 <= first_step <= last_step. A UTF-8
// BOM, CRLF line ends, a missing final newline and trailing blank lines are accepted; a blank line
// between rows is not. Errors read "FILE:LINE: ...".
LabelFileResult parseLabelCsv(std::string_view text, std::string_view fileName);
// JSON: {"format":"tactile-labels","version":1,"set":...,"segments":[{"run","group",
// "first_step","last_step","class"[,"annotator"]}]} or a bare array of such segment objects.
LabelFileResult parseLabelJson(std::string_view text, std::string_view fileName);

// The annotator column is written only when some record has one.
std::string formatLabelCsv(const std::vector<LabelRecord>& records);
std::string formatLabelJson(const std::vector<LabelRecord>& records, std::string_view setName,
                            std::string_view setAnnotator);

}  // namespace tactile
