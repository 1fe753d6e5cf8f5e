#include "storage/run_codec.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

namespace tactile::storage {

std::vector<TruthSegment> truthSegments(const ContactClass* truth, std::size_t steps) {
  std::vector<TruthSegment> segments;
  if (steps == 0) return segments;
  const auto at = [&](std::size_t step, int group) {
    return truth[step * kGroupCount + static_cast<std::size_t>(group)];
  };
  for (const GroupInfo& info : kSensorGroups) {
    const int g = groupIndex(info.group);
    std::size_t start = 0;
    for (std::size_t i = 1; i <= steps; ++i) {
      if (i == steps || at(i, g) != at(start, g)) {
        segments.push_back({info.group, static_cast<std::int64_t>(start),
                            static_cast<std::int64_t>(i - 1), at(start, g)});
        start = i;
      }
    }
  }
  return segments;
}

std::vector<TruthSegment> truthSegments(const RunData& run) {
  if (!run.hasTruth()) return {};
  return truthSegments(run.truth.data(), run.stepCount());
}

static_assert(kContactClassCount <= 8 && kGroupCount * 3 <= 63, "truth codes fit 3 bits a group");

std::int64_t packTruth(const ContactClass* classes) {
  std::int64_t packed = 0;
  for (int g = 0; g < kGroupCount; ++g)
    packed |= static_cast<std::int64_t>(classes[g]) << (3 * g);
  return packed;
}

bool unpackTruth(std::int64_t packed, ContactClass* classes) {
  if (packed < 0 || (packed >> (3 * kGroupCount)) != 0) return false;
  for (int g = 0; g < kGroupCount; ++g) {
    const auto code = static_cast<int>((packed >> (3 * g)) & 7);
    if (code >= kContactClassCount) return false;
    classes[g] = static_cast<ContactClass>(code);
  }
  return true;
}

SummaryBlocks computeSummaryBlocks(const double* sensors, std::size_t steps) {
  SummaryBuilder builder;
  builder.add(sensors, steps);
  return std::move(builder).finish();
}

PartialSummary summarizeSteps(const double* sensors, std::size_t firstStep, std::size_t steps) {
  const auto size = static_cast<std::size_t>(kSummaryBlockSteps[0]);
  PartialSummary part;
  part.firstStep = firstStep;
  part.steps = steps;
  if (steps == 0) return part;
  part.blocks.reserve(((firstStep + steps - 1) / size - firstStep / size + 1) * kSummaryValues);
  for (std::size_t s = 0; s < steps; ++s) {
    const double* row = sensors + s * kValuesPerStep;
    if (s == 0 || (firstStep + s) % size == 0) {
      part.blocks.insert(part.blocks.end(), row, row + kValuesPerStep);  // minima
      part.blocks.insert(part.blocks.end(), row, row + kValuesPerStep);  // maxima
      continue;
    }
    double* mins = part.blocks.data() + part.blocks.size() - kSummaryValues;
    double* maxs = mins + kValuesPerStep;
    for (int k = 0; k < kValuesPerStep; ++k) {
      mins[k] = std::min(mins[k], row[k]);
      maxs[k] = std::max(maxs[k], row[k]);
    }
  }
  return part;
}

void SummaryBuilder::add(const double* sensors, std::size_t steps) {
  merge(summarizeSteps(sensors, steps_, steps));
}

void SummaryBuilder::merge(const PartialSummary& part) {
  if (part.firstStep != steps_) throw std::logic_error("summary part does not follow on");
  if (part.steps == 0) return;
  const double* from = part.blocks.data();
  // A part that starts inside a block finishes the last block so far.
  if (steps_ % static_cast<std::size_t>(kSummaryBlockSteps[0]) != 0) {
    double* mins = finest_.data() + finest_.size() - kSummaryValues;
    double* maxs = mins + kValuesPerStep;
    for (int k = 0; k < kValuesPerStep; ++k) {
      mins[k] = std::min(mins[k], from[k]);
      maxs[k] = std::max(maxs[k], from[kValuesPerStep + k]);
    }
    from += kSummaryValues;
  }
  finest_.insert(finest_.end(), from, part.blocks.data() + part.blocks.size());
  steps_ += part.steps;
}

SummaryBlocks SummaryBuilder::finish() && {
  SummaryBlocks levels(kSummaryBlockSteps.size());
  levels[0] = std::move(finest_);
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

std::size_t encodeValues(const double* values, std::size_t count, unsigned char* out) {
  const std::size_t bitmapBytes = (count + 7) / 8;
  // Count first: the common all-zero and mostly-zero rows then cost one pass and a short copy.
  std::size_t set = 0;
  for (std::size_t i = 0; i < count; ++i)
    set += std::bit_cast<std::uint64_t>(values[i]) != 0;
  if (bitmapBytes + 8 * set >= 8 * count) {
    std::memcpy(out, values, 8 * count);
    return 8 * count;
  }
  std::memset(out, 0, bitmapBytes);
  unsigned char* next = out + bitmapBytes;
  for (std::size_t i = 0; i < count; ++i) {
    if (std::bit_cast<std::uint64_t>(values[i]) != 0) {
      out[i / 8] = static_cast<unsigned char>(out[i / 8] | (1u << (i % 8)));
      std::memcpy(next, values + i, 8);
      next += 8;
    }
  }
  return static_cast<std::size_t>(next - out);
}

bool decodeValues(const void* data, std::size_t bytes, std::size_t count, double* out) {
  const auto* p = static_cast<const unsigned char*>(data);
  if (bytes == 8 * count) {
    std::memcpy(out, p, bytes);
    return true;
  }
  const std::size_t bitmapBytes = (count + 7) / 8;
  if (bytes < bitmapBytes) return false;
  std::size_t set = 0;
  for (std::size_t b = 0; b < bitmapBytes; ++b)
    set += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(p[b])));
  // Bits past `count` in the last byte would name values that do not exist.
  if (count % 8 != 0 && (p[bitmapBytes - 1] >> (count % 8)) != 0) return false;
  if (bytes != bitmapBytes + 8 * set || bytes >= 8 * count) return false;
  std::fill(out, out + count, 0.0);
  const unsigned char* next = p + bitmapBytes;
  for (std::size_t b = 0; b < bitmapBytes; ++b) {
    unsigned bits = p[b];
    while (bits != 0) {
      const std::size_t i = b * 8 + static_cast<std::size_t>(std::countr_zero(bits));
      std::memcpy(out + i, next, 8);
      next += 8;
      bits &= bits - 1;
    }
  }
  return true;
}

void EncodedBlobs::reserve(std::size_t lists, std::size_t bytes) {
  offsets_.reserve(lists + 1);
  bytes_.reserve(bytes);
}

void EncodedBlobs::add(const double* values, std::size_t count) {
  if (count > kSummaryValues) throw std::invalid_argument("EncodedBlobs: list too long");
  unsigned char buffer[maxEncodedValueBytes(kSummaryValues)];
  const std::size_t written = encodeValues(values, count, buffer);
  bytes_.insert(bytes_.end(), buffer, buffer + written);
  offsets_.push_back(bytes_.size());
}

std::vector<EncodedBlobs> encodeSummaryBlocks(const SummaryBlocks& blocks) {
  std::vector<EncodedBlobs> encoded(blocks.size());
  for (std::size_t level = 0; level < blocks.size(); ++level) {
    const std::size_t count = blocks[level].size() / kSummaryValues;
    encoded[level].reserve(count, count * 64);
    for (std::size_t b = 0; b < count; ++b)
      encoded[level].add(blocks[level].data() + b * kSummaryValues, kSummaryValues);
  }
  return encoded;
}

EncodedBlobs encodeStepSensors(const double* sensors, std::size_t steps) {
  EncodedBlobs encoded;
  encoded.reserve(steps, steps * 64);
  for (std::size_t i = 0; i < steps; ++i)
    encoded.add(sensors + i * kValuesPerStep, kValuesPerStep);
  return encoded;
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
