// Internal: how a run's columns are turned into stored rows and back (truth segments, block
// min/max summaries, x_ column blobs). Pure functions, tested on their own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/run.h"
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

// Maximal runs of one class per group, in group order then step order; empty without truth.
std::vector<TruthSegment> truthSegments(const RunData& run);

// Per level of kSummaryBlockSteps: blocks * kSummaryValues values; block b covers steps
// [b * size, min((b + 1) * size, steps)).
using SummaryBlocks = std::vector<std::vector<double>>;
SummaryBlocks computeSummaryBlocks(const double* sensors, std::size_t steps);

// Lists of strings (x_ values of one step, metadata pairs, column names): for each value a 4-byte
// little-endian length, then the bytes.
std::string encodeExtra(const std::string* values, std::size_t count);
// Appends `count` values to `out`; false if the blob is malformed.
bool decodeExtra(const void* data, std::size_t bytes, std::size_t count,
                 std::vector<std::string>& out);
// Appends every value of such a blob, however many there are; false if malformed.
bool decodeStrings(const void* data, std::size_t bytes, std::vector<std::string>& out);

}  // namespace tactile::storage
