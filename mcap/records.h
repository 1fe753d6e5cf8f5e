// The records of an MCAP file (the format's specification, "Records"), as the reader returns
// them and the writer takes them.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tactile::mcap {

inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

enum class Opcode : std::uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Attachment = 0x09,
  AttachmentIndex = 0x0A,
  Statistics = 0x0B,
  Metadata = 0x0C,
  MetadataIndex = 0x0D,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

// Key/value pairs in file order (an MCAP map keeps the order it was written in).
using KeyValues = std::vector<std::pair<std::string, std::string>>;

struct Schema {
  std::uint16_t id = 0;
  std::string name;
  std::string encoding;
  std::string data;
  bool operator==(const Schema&) const = default;
};

struct Channel {
  std::uint16_t id = 0;
  std::uint16_t schemaId = 0;
  std::string topic;
  std::string messageEncoding;
  KeyValues metadata;
  bool operator==(const Channel&) const = default;
};

// One message as read: `data` points into the file or a decompressed chunk and is valid only
// during the callback that receives it.
struct MessageView {
  std::uint16_t channelId = 0;
  std::uint32_t sequence = 0;
  std::uint64_t logTime = 0;
  std::uint64_t publishTime = 0;
  std::string_view data;
  // Where the record starts: in the file, or (in a chunk) the chunk's file offset and the record's
  // offset within the chunk's uncompressed records.
  std::uint64_t fileOffset = 0;
  std::optional<std::uint64_t> chunkOffset;
};

struct Metadata {
  std::string name;
  KeyValues entries;
};

struct AttachmentInfo {
  std::uint64_t offset = 0;
  std::uint64_t logTime = 0;
  std::uint64_t createTime = 0;
  std::string name;
  std::string mediaType;
  std::uint64_t dataSize = 0;
};

struct ChunkIndex {
  std::uint64_t messageStartTime = 0;
  std::uint64_t messageEndTime = 0;
  std::uint64_t chunkStartOffset = 0;
  std::uint64_t chunkLength = 0;
  std::vector<std::pair<std::uint16_t, std::uint64_t>> messageIndexOffsets;
  std::uint64_t messageIndexLength = 0;
  std::string compression;
  std::uint64_t compressedSize = 0;
  std::uint64_t uncompressedSize = 0;
};

struct Statistics {
  std::uint64_t messageCount = 0;
  std::uint16_t schemaCount = 0;
  std::uint32_t channelCount = 0;
  std::uint32_t attachmentCount = 0;
  std::uint32_t metadataCount = 0;
  std::uint32_t chunkCount = 0;
  std::uint64_t messageStartTime = 0;
  std::uint64_t messageEndTime = 0;
  std::vector<std::pair<std::uint16_t, std::uint64_t>> channelMessageCounts;
};

}  // namespace tactile::mcap
