#include "storage/run_codec.h"

#include <algorithm>
#include <cstring>

namespace tactile::storage {

std::vector<TruthSegment> truthSegments(const RunData& run) {
  std::vector<TruthSegment> segments;
  if (!run.hasTruth()) return segments;
  const std::int64_t steps = static_cast<std::int64_t>(run.stepCount());
  for (const GroupInfo& info : kSensorGroups) {
    std::int64_t start = 0;
    for (std::int64_t i = 1; i <= steps; ++i) {
      if (i == steps || run.truthAt(static_cast<std::size_t>(i), info.group) !=
                            run.truthAt(static_cast<std::size_t>(start), info.group)) {
        segments.push_back(
            {info.group, start, i - 1, run.truthAt(static_cast<std::size_t>(start), info.group)});
        start = i;
      }
    }
  }
  return segments;
}

SummaryBlocks computeSummaryBlocks(const double* sensors, std::size_t steps) {
  SummaryBlocks levels(kSummaryBlockSteps.size());
  if (steps == 0) return levels;
  // Finest level from the steps.
  {
    const std::size_t size = static_cast<std::size_t>(kSummaryBlockSteps[0]);
    const std::size_t blocks = (steps + size - 1) / size;
    std::vector<double>& out = levels[0];
    out.resize(blocks * kSummaryValues);
    for (std::size_t b = 0; b < blocks; ++b) {
      double* mins = out.data() + b * kSummaryValues;
      double* maxs = mins + kValuesPerStep;
      const double* first = sensors + b * size * kValuesPerStep;
      std::copy(first, first + kValuesPerStep, mins);
      std::copy(first, first + kValuesPerStep, maxs);
      const std::size_t end = std::min(steps, (b + 1) * size);
      for (std::size_t s = b * size + 1; s < end; ++s) {
        const double* row = sensors + s * kValuesPerStep;
        for (int k = 0; k < kValuesPerStep; ++k) {
          mins[k] = std::min(mins[k], row[k]);
          maxs[k] = std::max(maxs[k], row[k]);
        }
      }
    }
  }
  // Coarser levels from the level below.
  for (std::size_t level = 1; level < kSummaryBlockSteps.size(); ++level) {
    const std::size_t ratio =
        static_cast<std::size_t>(kSummaryBlockSteps[level] / kSummaryBlockSteps[level - 1]);
    const std::vector<double>& below = levels[level - 1];
    const std::size_t belowCount = below.size() / kSummaryValues;
    const std::size_t blocks = (belowCount + ratio - 1) / ratio;
    std::vector<double>& out = levels[level];
    out.resize(blocks * kSummaryValues);
    for (std::size_t b = 0; b < blocks; ++b) {
      double* mins = out.data() + b * kSummaryValues;
      double* maxs = mins + kValuesPerStep;
      const double* first = below.data() + b * ratio * kSummaryValues;
      std::copy(first, first + kSummaryValues, mins);
      const std::size_t end = std::min(belowCount, (b + 1) * ratio);
      for (std::size_t c = b * ratio + 1; c < end; ++c) {
        const double* child = below.data() + c * kSummaryValues;
        for (int k = 0; k < kValuesPerStep; ++k) {
          mins[k] = std::min(mins[k], child[k]);
          maxs[k] = std::max(maxs[k], child[kValuesPerStep + k]);
        }
      }
    }
  }
  return levels;
}

std::string encodeExtra(const std::string* values, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) {
    const auto length = static_cast<std::uint32_t>(values[i].size());
    char prefix[4] = {static_cast<char>(length & 0xFF), static_cast<char>((length >> 8) & 0xFF),
                      static_cast<char>((length >> 16) & 0xFF),
                      static_cast<char>((length >> 24) & 0xFF)};
    out.append(prefix, 4);
    out.append(values[i]);
  }
  return out;
}

bool decodeStrings(const void* data, std::size_t bytes, std::vector<std::string>& out) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t offset = 0;
  while (offset < bytes) {
    if (bytes - offset < 4) return false;
    const std::uint32_t length = p[offset] | (p[offset + 1] << 8) | (p[offset + 2] << 16) |
                                 (static_cast<std::uint32_t>(p[offset + 3]) << 24);
    offset += 4;
    if (bytes - offset < length) return false;
    out.emplace_back(reinterpret_cast<const char*>(p + offset), length);
    offset += length;
  }
  return true;
}

bool decodeExtra(const void* data, std::size_t bytes, std::size_t count,
                 std::vector<std::string>& out) {
  const std::size_t before = out.size();
  return decodeStrings(data, bytes, out) && out.size() - before == count;
}

}  // namespace tactile::storage
