// Internal: how a run's columns are turned into stored rows and back (truth segments, block
// min/max summaries, x_ column blobs). Pure functions, tested on their own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "run/run.h"
#include "storage/run_database.h"

namespace tactile::storage {

// 88 minima followed by 88 maxima.
inline constexpr std::size_t kSummaryValues = 2 * kValuesPerStep;

struct TruthSegment {
  SensorGroup group = SensorGroup::Front;
  std::int64_t firstStep = 0;
  std::int64_t lastStep = 0;
  ContactClass cls = ContactClass::NoContact;
};

// Maximal runs of one class per group, in group order then step order, from `steps` *
// kGroupCount classes (step-major, as RunData::truth).
std::vector<TruthSegment> truthSegments(const ContactClass* truth, std::size_t steps);
// Same for a run; empty without truth.
std::vector<TruthSegment> truthSegments(const RunData& run);

// One step's eight truth classes as the steps.truth integer: group g's class code (the
// ContactClass value, 0 NoContact ... 4 DeadPath) in bits [3g, 3g + 3).
std::int64_t packTruth(const ContactClass* classes);
// False if `packed` has bits past the eighth group or a code that is no class.
bool unpackTruth(std::int64_t packed, ContactClass* classes);

// Per level of kSummaryBlockSteps: blocks * kSummaryValues values; block b covers steps
// [b * size, min((b + 1) * size, steps)).
using SummaryBlocks = std::vector<std::vector<double>>;
SummaryBlocks computeSummaryBlocks(const double* sensors, std::size_t steps);

// Finest-level minima and maxima of the steps [firstStep, firstStep + steps) of a run, one entry
// of kSummaryValues per block they touch (the first and last maybe partial). Computed per chunk
// on the import workers.
struct PartialSummary {
  std::size_t firstStep = 0;
  std::size_t steps = 0;
  std::vector<double> blocks;
};
PartialSummary summarizeSteps(const double* sensors, std::size_t firstStep, std::size_t steps);

// The blocks of a run fed in consecutive pieces of any length.
class SummaryBuilder {
 public:
  // The next `steps` steps.
  void add(const double* sensors, std::size_t steps);
  // The partial summary of the next steps; throws std::logic_error unless it starts where the
  // steps so far end.
  void merge(const PartialSummary& part);
  SummaryBlocks finish() &&;

 private:
  std::vector<double> finest_;  // level-0 blocks so far, the last one maybe partial
  std::size_t steps_ = 0;
};

// Float64 value lists stored as BLOBs (a step's 88 sensor values, a block's 176 minima and
// maxima). Two layouts, told apart by length alone:
// - dense: `count` little-endian float64, 8 * count bytes;
// - sparse: a bitmap of ceil(count / 8) bytes (bit i % 8 of byte i / 8 is set when value i is not
//   +0.0, compared bit for bit, so -0.0 is kept), then the set values as little-endian float64 in
//   order.
// The encoder writes the sparse layout only when it is strictly shorter than the dense one, so a
// blob of exactly 8 * count bytes is always dense (schema version 3 files hold only dense blobs).
inline constexpr std::size_t maxEncodedValueBytes(std::size_t count) {
  return 8 * count;
}
// Writes the encoding of `values` to `out` (room for maxEncodedValueBytes(count)); returns its
// size.
std::size_t encodeValues(const double* values, std::size_t count, unsigned char* out);
// Decodes `count` values into `out`; false if the blob has neither layout's length.
bool decodeValues(const void* data, std::size_t bytes, std::size_t count, double* out);

// Many encoded value lists back to back, built off the writer thread.
class EncodedBlobs {
 public:
  void reserve(std::size_t lists, std::size_t bytes);
  void add(const double* values, std::size_t count);
  std::size_t size() const { return offsets_.size() - 1; }
  const unsigned char* data(std::size_t i) const { return bytes_.data() + offsets_[i]; }
  std::size_t bytes(std::size_t i) const { return offsets_[i + 1] - offsets_[i]; }

 private:
  std::vector<unsigned char> bytes_;
  std::vector<std::size_t> offsets_{0};
};

// One blob list per level, block after block.
std::vector<EncodedBlobs> encodeSummaryBlocks(const SummaryBlocks& blocks);
// Every step's sensor values, step after step.
EncodedBlobs encodeStepSensors(const double* sensors, std::size_t steps);

// Lists of strings (x_ values of one step, metadata pairs, column names): for each value a 4-byte
// little-endian length, then the bytes.
std::string encodeExtra(const std::string* values, std::size_t count);
// Appends `count` values to `out`; false if the blob is malformed.
bool decodeExtra(const void* data, std::size_t bytes, std::size_t count,
                 std::vector<std::string>& out);
// Appends every value of such a blob, however many there are; false if malformed.
bool decodeStrings(const void* data, std::size_t bytes, std::vector<std::string>& out);

}  // namespace tactile::storage
