// Reading an MCAP file: one pass over every record, in file order, checking the file against the
// format's specification as it goes. Chunks are decompressed (zstd, lz4 or none) and their CRCs
// checked, as are the data section's, the summary's and each attachment's where the writer gave
// one. Every length is checked against the bytes that are there before anything is allocated;
// decompressed chunks grow only as their data actually decompresses. Any fault is an Error naming
// the file and the byte offset ("run.mcap: byte 1234: ..."), never a crash.
//
// A file with or without a summary, chunked or not, is read the same way; where a summary is
// present, its Statistics, Chunk Indexes and copies of Schema and Channel records are checked
// against what the data section holds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "mcap/records.h"

namespace tactile::mcap {

struct ScanResult {
  std::uint64_t fileSize = 0;
  std::string profile;
  std::string library;
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<Metadata> metadata;
  std::vector<AttachmentInfo> attachments;
  std::uint64_t messageCount = 0;
  std::map<std::uint16_t, std::uint64_t> channelMessageCounts;
  // Earliest and latest log time (both 0 without messages).
  std::uint64_t messageStartTime = 0;
  std::uint64_t messageEndTime = 0;
  std::uint64_t chunkCount = 0;
  // Chunks by compression ("zstd", "lz4", "" for none).
  std::map<std::string, std::uint64_t> chunkCompressions;
  std::uint64_t messagesOutsideChunks = 0;
  std::uint64_t messageIndexCount = 0;
  bool hasDataEnd = false;
  bool hasSummary = false;
  std::optional<Statistics> statistics;
  std::vector<ChunkIndex> chunkIndexes;
  std::uint64_t attachmentIndexCount = 0;
  std::uint64_t metadataIndexCount = 0;
  std::uint64_t summaryOffsetCount = 0;
};

// Called for every message in file order with its channel and the channel's schema (null for a
// channel without one). An error it returns stops the scan and is returned as is.
using MessageFn = std::function<Status(const MessageView&, const Channel&, const Schema*)>;

// Reads the MCAP file held in `bytes`; `fileName` names it in errors. With `threads` other than 1
// (0: one per core) and two cores or more, chunks are decompressed and their CRCs checked on
// another thread ahead of the scan; the result, the calls to `onMessage` and any error are the
// same as with one thread.
Result<ScanResult> scan(std::string_view bytes, const std::string& fileName,
                        const MessageFn& onMessage = {}, unsigned threads = 0);
// Reads the file at `path` (memory-mapped).
Result<ScanResult> scanFile(const std::filesystem::path& path, const MessageFn& onMessage = {});

// The message count the summary's Statistics record gives for the channels on `topic`, read
// without reading the data section (for sizing what a reader builds). Nothing when the file has
// no summary, no Statistics, or anything in the way is out of bounds; the figure is the file's
// claim, not checked against its messages.
std::optional<std::uint64_t> summaryTopicMessageCount(std::string_view bytes,
                                                      std::string_view topic);

// An error about `file` at byte `offset`: "FILE: byte OFFSET: message".
Error errorAt(const std::string& file, std::uint64_t offset, const std::string& message);

}  // namespace tactile::mcap
