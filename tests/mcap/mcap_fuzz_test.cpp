// Deterministic fuzzing of the MCAP reader and the importers built on it: truncations at every
// length, seeded bit flips and huge lengths written over length fields. Each mutant must be read
// or refused with an error naming the file and a byte offset; nothing may crash, hang or allocate
// past what the file holds (run under TACTILE_SANITIZE to see the last).
#include <gtest/gtest.h>

#include <random>

#include "mcap/bytes.h"
#include "mcap/reader.h"
#include "mcap/ros2_bag.h"
#include "mcap/run_mcap.h"
#include "run/synthetic_run.h"
#include "tests/mcap/mcap_test_util.h"

namespace tactile::mcap {
namespace {

std::string exportSample(Compression compression) {
  RunData run = makeSyntheticRun(40, true, 3);
  run.setMeta("dt", "0.1");
  RunExport what;
  what.run = &run;
  what.name = "f";
  WriterOptions o;
  o.compression = compression;
  o.chunkBytes = 3000;
  return writeRunMcap(what, o);
}

std::string bagSample() {
  WriterOptions o;
  o.profile = "ros2";
  o.chunkBytes = 1500;
  Writer w(o);
  const auto ch = w.addChannel(
      w.addSchema("std_msgs/msg/Float32MultiArray", "ros2msg", test::float32ArraySchema()),
      "/tactile", "cdr");
  for (std::uint32_t k = 0; k < 20; ++k) {
    test::CdrOut m;
    m.put<std::uint32_t>(0).put<std::uint32_t>(0).put<std::uint32_t>(88);
    for (int i = 0; i < 88; ++i)
      m.put<float>(0.01F * static_cast<float>(i % 44));
    w.addMessage(ch, k, 1000 + 10ULL * k, 1000 + 10ULL * k, m.bytes());
  }
  return w.finish();
}

// Reads a mutant every way; returns whether the scan accepted it.
bool readEveryWay(const std::string& bytes, const BagMapping& mapping) {
  auto r = scan(bytes, "m.mcap");
  if (!r.ok()) {
    EXPECT_EQ(r.error().file, "m.mcap");
    EXPECT_EQ(r.error().message.rfind("byte ", 0), 0U) << r.errorText();
  }
  auto own = readRunMcap(bytes, "m.mcap");
  if (!own.ok()) {
    EXPECT_EQ(own.error().file, "m.mcap") << own.errorText();
  }
  auto bag = readRos2Bag(bytes, "m.mcap", mapping);
  if (!bag.ok()) {
    EXPECT_EQ(bag.error().file, "m.mcap") << bag.errorText();
  }
  return r.ok();
}

TEST(McapFuzz, TruncationsFlipsAndHugeLengths) {
  auto mapping = parseMapping(R"({"tactile": {"topic": "/tactile"}})", "map.json");
  ASSERT_TRUE(mapping.ok());
  std::mt19937_64 rng(2024);
  int refused = 0;
  int total = 0;
  for (const std::string& good : {exportSample(Compression::Zstd), exportSample(Compression::Lz4),
                                  exportSample(Compression::None), bagSample()}) {
    ASSERT_TRUE(scan(good, "g.mcap").ok());
    // Every truncation: a file cut anywhere is refused (its footer and magic are gone).
    const std::size_t step = std::max<std::size_t>(1, good.size() / 400);
    for (std::size_t n = 0; n < good.size(); n += step) {
      ++total;
      EXPECT_FALSE(readEveryWay(good.substr(0, n), mapping.value())) << "cut at " << n;
      ++refused;
    }
    // Bit flips anywhere.
    for (int i = 0; i < 400; ++i) {
      std::string bad = good;
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng);
      bad[at] = static_cast<char>(bad[at] ^ (1 << (rng() % 8)));
      ++total;
      refused += readEveryWay(bad, mapping.value()) ? 0 : 1;
    }
    // Huge values over each record's length field, and over random 8-byte words.
    std::size_t pos = 8;
    while (pos + 9 <= good.size() - 8) {
      const std::uint64_t len = bytes::getU64(good.data() + pos + 1);
      for (const std::uint64_t huge :
           {std::uint64_t{~0ULL}, std::uint64_t{1} << 62, std::uint64_t{good.size()}}) {
        std::string bad = good;
        for (int b = 0; b < 8; ++b)
          bad[pos + 1 + static_cast<std::size_t>(b)] = static_cast<char>((huge >> (8 * b)) & 0xFF);
        ++total;
        EXPECT_FALSE(readEveryWay(bad, mapping.value())) << "record at " << pos;
        ++refused;
      }
      pos += 9 + static_cast<std::size_t>(len);
    }
    for (int i = 0; i < 200; ++i) {
      std::string bad = good;
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bad.size() - 8)(rng);
      const std::uint64_t huge = rng() | (1ULL << 40);
      for (int b = 0; b < 8; ++b)
        bad[at + static_cast<std::size_t>(b)] = static_cast<char>((huge >> (8 * b)) & 0xFF);
      ++total;
      refused += readEveryWay(bad, mapping.value()) ? 0 : 1;
    }
  }
  // Most random damage is caught (CRCs, lengths, decompression); the count guards against a
  // reader that accepts everything.
  EXPECT_GT(refused, total * 9 / 10) << refused << " of " << total;
}

}  // namespace
}  // namespace tactile::mcap
