// Writing an MCAP file, in memory or streamed to a sink as it goes: Schema, Channel and Message
// records in chunks (zstd, lz4 or none) with a Message Index after each chunk, Metadata and
// Attachment records, and a summary (copies of the Schema and Channel records, Statistics, Chunk
// Indexes, Metadata and Attachment Indexes, Summary Offsets), with every CRC filled in.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mcap/buffer.h"
#include "mcap/compression.h"
#include "mcap/records.h"

namespace tactile::mcap {

struct WriterOptions {
  std::string profile;
  std::string library = "tactile";
  Compression compression = Compression::Zstd;
  int zstdLevel = 1;
  // zstd's hash table, log2 of its entries (0: the level's own). 12 keeps it in the first-level
  // caches: on this program's JSON chunks at level 1, 11% faster and 1% smaller than the level's
  // own 14 (docs/BENCHMARKS.md).
  int zstdHashLog = 12;
  // A chunk is closed once its uncompressed records reach this size.
  std::size_t chunkBytes = std::size_t{1} << 20;
  // false: messages go straight into the data section, with no chunks and no indexes.
  bool chunked = true;
  // false: no summary section (the Footer says 0 for it).
  bool summary = true;
  // Memory to set aside for the file at the start (a guess saves copies as it grows; in memory
  // only).
  std::size_t reserveBytes = 0;
};

// Where a streaming writer's bytes go, in file order, a piece at a time (each chunk with its
// message indexes, then the summary). A sink that fails throws; the writer is then unusable.
using Sink = std::function<void(std::string_view bytes)>;

class Writer {
 public:
  // Without a sink the file is built in memory and finish() returns it; with one, the bytes go to
  // the sink as chunks are finished and finish() returns an empty string.
  explicit Writer(WriterOptions options = {}, Sink sink = {});
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Ids are given out from 1 in the order of the calls.
  std::uint16_t addSchema(std::string_view name, std::string_view encoding, std::string_view data);
  std::uint16_t addChannel(std::uint16_t schemaId, std::string_view topic,
                           std::string_view messageEncoding, const KeyValues& metadata = {});
  void addMessage(std::uint16_t channelId, std::uint32_t sequence, std::uint64_t logTime,
                  std::uint64_t publishTime, std::string_view data);
  // Writes a message whose data the caller builds in place: `fill` appends the message's bytes
  // with the Appender it is given (saves a copy per message).
  template <class Fill>
  void addMessageWith(std::uint16_t channelId, std::uint32_t sequence, std::uint64_t logTime,
                      std::uint64_t publishTime, Fill&& fill) {
    Buffer& out = beginMessage(channelId, sequence, logTime, publishTime);
    {
      Appender a(out);
      fill(a);
    }
    endMessage();
  }
  void addMetadata(std::string_view name, const KeyValues& entries);
  void addAttachment(std::string_view name, std::string_view mediaType, std::uint64_t logTime,
                     std::string_view data);

  // Closes the file and returns its bytes (empty when streamed to a sink); the writer is then
  // empty.
  std::string finish();
  // Bytes of the file so far (written to the sink or still held).
  std::uint64_t position() const { return flushed_ + file_.size(); }

 private:
  Buffer& beginMessage(std::uint16_t channelId, std::uint32_t sequence, std::uint64_t logTime,
                       std::uint64_t publishTime);
  void endMessage();
  void flushChunk();
  // Hands the bytes held to the sink (when there is one), keeping the data section's CRC.
  void flushFile(bool dataSection);
  // Where records go now: the open chunk, or the file itself.
  Buffer& target() { return options_.chunked ? chunk_ : file_; }

  WriterOptions options_;
  Sink sink_;
  std::unique_ptr<Compressor> compressor_;
  Buffer file_;  // the file's bytes not yet handed to the sink
  std::uint64_t flushed_ = 0;
  std::uint32_t dataCrc_ = 0;  // of the bytes handed to the sink so far
  Buffer chunk_;
  std::size_t messageStart_ = 0;
  std::uint16_t messageChannel_ = 0;
  std::uint64_t messageTime_ = 0;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<ChunkIndex> chunkIndexes_;
  struct MetadataEntry {
    std::uint64_t offset, length;
    std::string name;
  };
  std::vector<MetadataEntry> metadataIndexes_;
  struct AttachmentEntry {
    std::uint64_t offset, length, logTime, dataSize;
    std::string name, mediaType;
  };
  std::vector<AttachmentEntry> attachmentIndexes_;
  // The open chunk's message index: per channel, (log time, offset in the chunk's records).
  std::vector<std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunkIndex_;
  std::vector<std::uint16_t> chunkChannels_;
  std::uint64_t chunkStart_ = 0;
  std::uint64_t chunkEnd_ = 0;
  std::uint64_t chunkMessages_ = 0;
  std::uint64_t messageCount_ = 0;
  std::uint64_t startTime_ = 0;
  std::uint64_t endTime_ = 0;
  std::vector<std::uint64_t> channelCounts_;
  std::uint32_t chunkCount_ = 0;
};

}  // namespace tactile::mcap
