// The MCAP reader and writer: known answers (CRC-32, byte layout of the smallest file), every
// record kind and chunk layout read back, and damaged files refused with the file and the offset.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mcap/bytes.h"
#include "mcap/crc32.h"
#include "mcap/reader.h"
#include "mcap/writer.h"

namespace tactile::mcap {
namespace {

TEST(McapCrc, KnownAnswers) {
  // The check value of CRC-32/ISO-HDLC (zlib's crc32), and Python's zlib.crc32(b"MCAP") too.
  EXPECT_EQ(crc32("123456789"), 0xCBF43926U);
  EXPECT_EQ(crc32(""), 0U);
  EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339U);
  // Continuing over pieces equals one pass (the tail loop and the sixteen-byte loop both run).
  const std::string text = "0123456789abcdefghijklmnopqrstuvwxyz-0123456789";
  EXPECT_EQ(crc32(text.substr(13), crc32(text.substr(0, 13))), crc32(text));
}

TEST(McapCrc, LongBuffersEqualTheBitwiseDefinition) {
  // Long buffers take the three-stream path; every length around its thresholds and pieces
  // continued across it give the CRC of the definition, bit by bit.
  auto bitwise = [](std::string_view s) {
    std::uint32_t c = 0xFFFFFFFFU;
    for (const char ch : s) {
      c ^= static_cast<unsigned char>(ch);
      for (int k = 0; k < 8; ++k)
        c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    }
    return ~c;
  };
  std::string data(70000, '\0');
  std::uint32_t x = 12345;
  for (char& ch : data) {
    x = x * 1103515245U + 12345U;
    ch = static_cast<char>(x >> 24);
  }
  for (const std::size_t n : {16383UL, 16384UL, 16385UL, 16391UL, 50001UL, 70000UL}) {
    const std::string_view piece(data.data(), n);
    EXPECT_EQ(crc32(piece), bitwise(piece)) << n << " bytes";
  }
  const std::string_view all(data);
  EXPECT_EQ(crc32(all.substr(20000), crc32(all.substr(0, 20000))), bitwise(all));
  EXPECT_EQ(crc32(all.substr(69990), crc32(all.substr(0, 69990))), bitwise(all));
}

// Writes a file with two schemas, three channels (one without a schema), messages on each,
// metadata and an attachment.
std::string sampleFile(const WriterOptions& options) {
  Writer w(options);
  const auto s1 = w.addSchema("a.A", "jsonschema", R"({"type":"object"})");
  const auto s2 = w.addSchema("b.B", "jsonschema", "{}");
  const auto c1 = w.addChannel(s1, "/a", "json", {{"k", "v"}});
  const auto c2 = w.addChannel(s2, "/b", "json");
  const auto c3 = w.addChannel(0, "/raw", "json");
  w.addMetadata("first", {{"x", "1"}, {"y", "2"}});
  for (std::uint32_t i = 0; i < 300; ++i) {
    w.addMessage(c1, i, 1000 + 10ULL * i, 1000 + 10ULL * i, "{\"i\":" + std::to_string(i) + "}");
    if (i % 3 == 0) w.addMessage(c2, i, 1005 + 10ULL * i, 1005 + 10ULL * i, "{}");
  }
  w.addAttachment("notes.txt", "text/plain", 7, "hello");
  w.addMessage(c3, 0, 5000, 5000, "[1,2]");
  w.addMetadata("second", {});
  return w.finish();
}

struct Layout {
  const char* name;
  WriterOptions options;
};

std::vector<Layout> layouts() {
  std::vector<Layout> out;
  WriterOptions zstd;
  zstd.chunkBytes = 2000;  // many chunks
  out.push_back({"zstd", zstd});
  WriterOptions lz4 = zstd;
  lz4.compression = Compression::Lz4;
  out.push_back({"lz4", lz4});
  WriterOptions none = zstd;
  none.compression = Compression::None;
  out.push_back({"uncompressed chunks", none});
  WriterOptions flat;
  flat.chunked = false;
  out.push_back({"no chunks", flat});
  WriterOptions bare = zstd;
  bare.summary = false;
  out.push_back({"no summary", bare});
  WriterOptions flatBare = flat;
  flatBare.summary = false;
  out.push_back({"no chunks, no summary", flatBare});
  return out;
}

TEST(McapFormat, EveryLayoutReadsBack) {
  for (const Layout& layout : layouts()) {
    SCOPED_TRACE(layout.name);
    const std::string file = sampleFile(layout.options);
    std::vector<std::uint64_t> times;
    std::vector<std::string> payloads;
    auto result =
        scan(file, "t.mcap", [&](const MessageView& m, const Channel& c, const Schema* s) {
          if (c.topic == "/a") {
            EXPECT_NE(s, nullptr);
            times.push_back(m.logTime);
            payloads.emplace_back(m.data);
          }
          if (c.topic == "/raw") {
            EXPECT_EQ(s, nullptr);
          }
          return Status{};
        });
    ASSERT_TRUE(result.ok()) << result.errorText();
    const ScanResult& r = result.value();
    EXPECT_EQ(r.library, "tactile");
    EXPECT_EQ(r.messageCount, 300U + 100U + 1U);
    EXPECT_EQ(r.channelMessageCounts.at(1), 300U);
    EXPECT_EQ(r.channelMessageCounts.at(2), 100U);
    EXPECT_EQ(r.channelMessageCounts.at(3), 1U);
    EXPECT_EQ(r.messageStartTime, 1000U);
    EXPECT_EQ(r.messageEndTime, 5000U);
    ASSERT_EQ(r.schemas.size(), 2U);
    EXPECT_EQ(r.schemas.at(1).name, "a.A");
    ASSERT_EQ(r.channels.size(), 3U);
    EXPECT_EQ(r.channels.at(1).metadata, (KeyValues{{"k", "v"}}));
    ASSERT_EQ(r.metadata.size(), 2U);
    EXPECT_EQ(r.metadata[0].name, "first");
    EXPECT_EQ(r.metadata[0].entries, (KeyValues{{"x", "1"}, {"y", "2"}}));
    ASSERT_EQ(r.attachments.size(), 1U);
    EXPECT_EQ(r.attachments[0].name, "notes.txt");
    EXPECT_EQ(r.attachments[0].dataSize, 5U);
    EXPECT_TRUE(r.hasDataEnd);
    ASSERT_EQ(times.size(), 300U);
    EXPECT_EQ(times[299], 1000U + 2990U);
    EXPECT_EQ(payloads[17], "{\"i\":17}");
    if (layout.options.chunked) {
      EXPECT_GT(r.chunkCount, 3U);
      EXPECT_EQ(r.messagesOutsideChunks, 0U);
      EXPECT_EQ(r.chunkCompressions.size(), 1U);
      EXPECT_GE(r.messageIndexCount, r.chunkCount - 2);  // chunks closed by metadata may be empty
    } else {
      EXPECT_EQ(r.chunkCount, 0U);
      EXPECT_EQ(r.messagesOutsideChunks, r.messageCount);
    }
    EXPECT_EQ(r.hasSummary, layout.options.summary);
    if (layout.options.summary) {
      ASSERT_TRUE(r.statistics.has_value());
      EXPECT_EQ(r.statistics->messageCount, r.messageCount);
      EXPECT_EQ(r.statistics->channelCount, 3U);
      EXPECT_EQ(r.statistics->metadataCount, 2U);
      EXPECT_EQ(r.statistics->attachmentCount, 1U);
      EXPECT_EQ(r.chunkIndexes.size(), r.chunkCount);
      EXPECT_EQ(r.metadataIndexCount, 2U);
      EXPECT_EQ(r.attachmentIndexCount, 1U);
      EXPECT_GT(r.summaryOffsetCount, 3U);
    } else {
      EXPECT_FALSE(r.statistics.has_value());
    }
  }
}

TEST(McapFormat, SmallestFileByteForByte) {
  // Magic, Header (profile "", library "x"), Data End (CRC of what precedes it), Footer without
  // a summary (0, 0, CRC 0), magic: written out by hand from the specification.
  WriterOptions o;
  o.library = "x";
  o.summary = false;
  const std::string file = Writer(o).finish();
  std::string expected(kMagic);
  expected += std::string("\x01", 1) + std::string("\x09\0\0\0\0\0\0\0", 8) +
              std::string("\0\0\0\0", 4) + std::string("\x01\0\0\0x", 5);
  const std::uint32_t crc = crc32(expected);
  expected += std::string("\x0F", 1) + std::string("\x04\0\0\0\0\0\0\0", 8);
  for (int i = 0; i < 4; ++i)
    expected.push_back(static_cast<char>((crc >> (8 * i)) & 0xFF));
  expected += std::string("\x02", 1) + std::string("\x14\0\0\0\0\0\0\0", 8) + std::string(20, '\0');
  expected += kMagic;
  EXPECT_EQ(file, expected);
  EXPECT_TRUE(scan(file, "s.mcap").ok());
}

TEST(McapFormat, ChunkIndexPointsAtChunksAndIndexes) {
  WriterOptions o;
  o.chunkBytes = 500;
  const std::string file = sampleFile(o);
  auto r = scan(file, "t.mcap");
  ASSERT_TRUE(r.ok()) << r.errorText();
  ASSERT_FALSE(r->chunkIndexes.empty());
  for (const ChunkIndex& c : r->chunkIndexes) {
    EXPECT_EQ(static_cast<std::uint8_t>(file[c.chunkStartOffset]), 0x06);
    EXPECT_EQ(bytes::getU64(file.data() + c.chunkStartOffset + 1) + 9, c.chunkLength);
    EXPECT_EQ(c.compression, "zstd");
    for (const auto& [channel, offset] : c.messageIndexOffsets) {
      EXPECT_EQ(static_cast<std::uint8_t>(file[offset]), 0x07);
      EXPECT_EQ(bytes::getU16(file.data() + offset + 9), channel);
    }
    EXPECT_LE(c.messageStartTime, c.messageEndTime);
  }
}

// A damaged copy must be refused naming the file and a byte offset.
void expectRefused(const std::string& bytes, const std::string& what) {
  auto r = scan(bytes, "bad.mcap");
  ASSERT_FALSE(r.ok()) << what << " was accepted";
  EXPECT_EQ(r.error().file, "bad.mcap");
  EXPECT_EQ(r.error().message.rfind("byte ", 0), 0U) << r.errorText();
}

TEST(McapFormat, DamageIsRefusedWithTheOffset) {
  const std::string good = sampleFile(WriterOptions{});
  expectRefused("", "an empty file");
  expectRefused("not an mcap file at all, just text", "text");
  expectRefused(good.substr(0, good.size() - 1), "a file one byte short");
  expectRefused(good.substr(0, good.size() / 2), "half a file");
  {
    std::string bad = good;
    bad[8] = 0x05;  // the Header's opcode
    expectRefused(bad, "a file that does not start with the Header");
  }
  {
    // A flipped bit in the compressed records: zstd or the chunk CRC notices.
    auto r = scan(good, "t.mcap");
    ASSERT_TRUE(r.ok());
    const ChunkIndex& c = r->chunkIndexes.front();
    std::string bad = good;
    bad[c.chunkStartOffset + c.chunkLength - 10] ^= 0x10;
    expectRefused(bad, "a flipped bit in a chunk");
  }
  {
    // A huge record length: refused before anything is allocated.
    std::string bad = good;
    const std::size_t at = 8 + 9 + bytes::getU64(good.data() + 9);  // the record after the Header
    for (int i = 0; i < 8; ++i)
      bad[at + 1 + static_cast<std::size_t>(i)] = static_cast<char>(0xFF);
    auto r = scan(bad, "bad.mcap");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errorText().find("byte " + std::to_string(at + 1)), std::string::npos)
        << r.errorText();
    EXPECT_NE(r.errorText().find("runs past the end"), std::string::npos) << r.errorText();
  }
}

TEST(McapFormat, UnknownCompressionIsNamed) {
  // The first chunk's compression "zstd" renamed "zstX" in place.
  WriterOptions z;
  std::string zfile = sampleFile(z);
  auto zr = scan(zfile, "t.mcap");
  ASSERT_TRUE(zr.ok());
  const std::size_t nameAt = zr->chunkIndexes.front().chunkStartOffset + 9 + 8 + 8 + 8 + 4 + 4;
  ASSERT_EQ(zfile.substr(nameAt, 4), "zstd");
  zfile[nameAt + 3] = 'X';
  auto bad = scan(zfile, "u.mcap");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.errorText().find("unknown compression 'zstX'"), std::string::npos)
      << bad.errorText();
  EXPECT_NE(bad.errorText().find("u.mcap: byte " + std::to_string(nameAt - 4)), std::string::npos)
      << bad.errorText();
}

TEST(McapFormat, SummaryMustAgreeWithTheData) {
  // Statistics that count one message more than the file holds.
  std::string file = sampleFile(WriterOptions{});
  auto r = scan(file, "t.mcap");
  ASSERT_TRUE(r.ok());
  // Find the Statistics record in the summary (opcode 0x0B) and bump its message_count; the
  // summary CRC would catch it, so clear that CRC (0 = not given) to reach the cross-check.
  const std::size_t footer = file.size() - 8 - 29;
  const std::uint64_t summaryStart = bytes::getU64(file.data() + footer + 9);
  std::size_t pos = summaryStart;
  while (static_cast<std::uint8_t>(file[pos]) != 0x0B)
    pos += 9 + bytes::getU64(file.data() + pos + 1);
  file[pos + 9] = static_cast<char>(file[pos + 9] + 1);
  for (int i = 0; i < 4; ++i)
    file[footer + 25 + static_cast<std::size_t>(i)] = 0;
  auto bad = scan(file, "s.mcap");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.errorText().find("the Statistics record counts 402 messages, the file holds 401"),
            std::string::npos)
      << bad.errorText();
}

}  // namespace
}  // namespace tactile::mcap
