#include "mcap/writer.h"

#include <algorithm>
#include <stdexcept>

#include "mcap/bytes.h"
#include "mcap/crc32.h"

namespace tactile::mcap {

using namespace bytes;

namespace {

// The bytes held before they go to a sink (a few chunks' worth: few, large writes).
constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

// Opens a record: opcode and a length to patch; returns where the length is.
std::size_t openRecord(Buffer& out, Opcode op) {
  putU8(out, static_cast<std::uint8_t>(op));
  const std::size_t at = out.size();
  putU64(out, 0);
  return at;
}
void closeRecord(Buffer& out, std::size_t lengthAt) {
  patchU64(out, lengthAt, out.size() - lengthAt - 8);
}

void putStringMap(Buffer& out, const KeyValues& entries) {
  std::uint64_t n = 0;
  for (const auto& [k, v] : entries)
    n += 8 + k.size() + v.size();
  putU32(out, static_cast<std::uint32_t>(n));
  for (const auto& [k, v] : entries) {
    putString(out, k);
    putString(out, v);
  }
}

void putSchema(Buffer& out, const Schema& s) {
  const std::size_t at = openRecord(out, Opcode::Schema);
  putU16(out, s.id);
  putString(out, s.name);
  putString(out, s.encoding);
  putString(out, s.data);
  closeRecord(out, at);
}

void putChannel(Buffer& out, const Channel& c) {
  const std::size_t at = openRecord(out, Opcode::Channel);
  putU16(out, c.id);
  putU16(out, c.schemaId);
  putString(out, c.topic);
  putString(out, c.messageEncoding);
  putStringMap(out, c.metadata);
  closeRecord(out, at);
}

}  // namespace

Writer::Writer(WriterOptions options, Sink sink)
    : options_(std::move(options)), sink_(std::move(sink)) {
  compressor_ =
      std::make_unique<Compressor>(options_.compression, options_.zstdLevel, options_.zstdHashLog);
  file_.append(kMagic);
  const std::size_t at = openRecord(file_, Opcode::Header);
  putString(file_, options_.profile);
  putString(file_, options_.library);
  closeRecord(file_, at);
  chunk_.reserve(options_.chunkBytes + (options_.chunkBytes >> 2));
  file_.reserve(sink_ ? 2 * kFlushBytes : options_.reserveBytes);
}

Writer::~Writer() = default;

std::uint16_t Writer::addSchema(std::string_view name, std::string_view encoding,
                                std::string_view data) {
  if (schemas_.size() >= 65535) throw std::length_error("an MCAP file holds at most 65535 schemas");
  Schema s;
  s.id = static_cast<std::uint16_t>(schemas_.size() + 1);
  s.name = name;
  s.encoding = encoding;
  s.data = data;
  putSchema(target(), s);
  schemas_.push_back(std::move(s));
  return schemas_.back().id;
}

std::uint16_t Writer::addChannel(std::uint16_t schemaId, std::string_view topic,
                                 std::string_view messageEncoding, const KeyValues& metadata) {
  if (channels_.size() >= 65535)
    throw std::length_error("an MCAP file holds at most 65535 channels");
  Channel c;
  c.id = static_cast<std::uint16_t>(channels_.size() + 1);
  c.schemaId = schemaId;
  c.topic = topic;
  c.messageEncoding = messageEncoding;
  c.metadata = metadata;
  putChannel(target(), c);
  channels_.push_back(std::move(c));
  channelCounts_.push_back(0);
  chunkIndex_.emplace_back();
  return channels_.back().id;
}

Buffer& Writer::beginMessage(std::uint16_t channelId, std::uint32_t sequence, std::uint64_t logTime,
                             std::uint64_t publishTime) {
  if (channelId == 0 || channelId > channels_.size()) {
    throw std::invalid_argument("message on channel " + std::to_string(channelId) +
                                ", which was not added");
  }
  Buffer& out = target();
  messageStart_ = out.size();
  messageChannel_ = channelId;
  messageTime_ = logTime;
  Appender a(out);
  a.room(31);
  a.put(static_cast<char>(Opcode::Message));
  a.u64(0);
  a.u16(channelId);
  a.u32(sequence);
  a.u64(logTime);
  a.u64(publishTime);
  return out;
}

void Writer::endMessage() {
  Buffer& out = target();
  patchU64(out, messageStart_ + 1, out.size() - messageStart_ - 9);
  if (messageCount_ == 0 || messageTime_ < startTime_) startTime_ = messageTime_;
  if (messageCount_ == 0 || messageTime_ > endTime_) endTime_ = messageTime_;
  ++messageCount_;
  ++channelCounts_[messageChannel_ - 1];
  if (!options_.chunked) return;
  auto& index = chunkIndex_[messageChannel_ - 1];
  if (index.empty()) chunkChannels_.push_back(messageChannel_);
  index.emplace_back(messageTime_, messageStart_);
  if (chunkMessages_ == 0 || messageTime_ < chunkStart_) chunkStart_ = messageTime_;
  if (chunkMessages_ == 0 || messageTime_ > chunkEnd_) chunkEnd_ = messageTime_;
  ++chunkMessages_;
  if (chunk_.size() >= options_.chunkBytes) flushChunk();
}

void Writer::flushFile(bool dataSection) {
  if (!sink_ || file_.empty()) return;
  if (dataSection) dataCrc_ = crc32(file_.view(), dataCrc_);
  sink_(file_.view());
  flushed_ += file_.size();
  file_.clear();
}

void Writer::addMessage(std::uint16_t channelId, std::uint32_t sequence, std::uint64_t logTime,
                        std::uint64_t publishTime, std::string_view data) {
  addMessageWith(channelId, sequence, logTime, publishTime, [&](Appender& out) { out.text(data); });
}

void Writer::flushChunk() {
  if (chunk_.empty()) return;
  const std::string_view compressed = compressor_->compress(chunk_.view());
  ChunkIndex index;
  index.messageStartTime = chunkMessages_ > 0 ? chunkStart_ : 0;
  index.messageEndTime = chunkMessages_ > 0 ? chunkEnd_ : 0;
  index.chunkStartOffset = position();
  index.compression = std::string(compressionName(options_.compression));
  index.compressedSize = compressed.size();
  index.uncompressedSize = chunk_.size();
  const std::size_t at = openRecord(file_, Opcode::Chunk);
  putU64(file_, index.messageStartTime);
  putU64(file_, index.messageEndTime);
  putU64(file_, chunk_.size());
  putU32(file_, crc32(chunk_.view()));
  putString(file_, index.compression);
  putU64(file_, compressed.size());
  file_.append(compressed);
  closeRecord(file_, at);
  index.chunkLength = position() - index.chunkStartOffset;
  // One Message Index record per channel with messages in the chunk, by channel id.
  std::sort(chunkChannels_.begin(), chunkChannels_.end());
  const std::uint64_t indexStart = position();
  for (const std::uint16_t channel : chunkChannels_) {
    auto& entries = chunkIndex_[channel - 1];
    index.messageIndexOffsets.emplace_back(channel, position());
    const std::size_t rec = openRecord(file_, Opcode::MessageIndex);
    putU16(file_, channel);
    putU32(file_, static_cast<std::uint32_t>(16 * entries.size()));
    for (const auto& [time, offset] : entries) {
      putU64(file_, time);
      putU64(file_, offset);
    }
    closeRecord(file_, rec);
    entries.clear();
  }
  index.messageIndexLength = position() - indexStart;
  chunkIndexes_.push_back(std::move(index));
  chunkChannels_.clear();
  chunk_.clear();
  chunkMessages_ = 0;
  ++chunkCount_;
  if (file_.size() >= kFlushBytes) flushFile(true);
}

void Writer::addMetadata(std::string_view name, const KeyValues& entries) {
  flushChunk();  // Metadata records stand outside chunks.
  MetadataEntry e{position(), 0, std::string(name)};
  const std::size_t at = openRecord(file_, Opcode::Metadata);
  putString(file_, name);
  putStringMap(file_, entries);
  closeRecord(file_, at);
  e.length = position() - e.offset;
  metadataIndexes_.push_back(std::move(e));
}

void Writer::addAttachment(std::string_view name, std::string_view mediaType, std::uint64_t logTime,
                           std::string_view data) {
  flushChunk();
  AttachmentEntry e{position(), 0, logTime, data.size(), std::string(name), std::string(mediaType)};
  const std::size_t at = openRecord(file_, Opcode::Attachment);
  const std::size_t contentStart = file_.size();
  putU64(file_, logTime);
  putU64(file_, 0);
  putString(file_, name);
  putString(file_, mediaType);
  putU64(file_, data.size());
  file_.append(data);
  putU32(file_, crc32(file_.view().substr(contentStart)));
  closeRecord(file_, at);
  e.length = position() - e.offset;
  attachmentIndexes_.push_back(std::move(e));
}

std::string Writer::finish() {
  flushChunk();
  // Data End, with the CRC of everything before it.
  flushFile(true);
  const std::uint32_t dataCrc = crc32(file_.view(), dataCrc_);
  std::size_t at = openRecord(file_, Opcode::DataEnd);
  putU32(file_, dataCrc);
  closeRecord(file_, at);
  flushFile(false);

  std::uint64_t summaryStart = 0;
  std::uint64_t summaryOffsetStart = 0;
  if (options_.summary) {
    summaryStart = position();
    struct Group {
      Opcode op;
      std::uint64_t start, length;
    };
    std::vector<Group> groups;
    auto group = [&](Opcode op, auto&& write) {
      const std::uint64_t start = position();
      write();
      if (position() > start) groups.push_back({op, start, position() - start});
    };
    group(Opcode::Schema, [&] {
      for (const Schema& s : schemas_)
        putSchema(file_, s);
    });
    group(Opcode::Channel, [&] {
      for (const Channel& c : channels_)
        putChannel(file_, c);
    });
    group(Opcode::Statistics, [&] {
      at = openRecord(file_, Opcode::Statistics);
      putU64(file_, messageCount_);
      putU16(file_, static_cast<std::uint16_t>(schemas_.size()));
      putU32(file_, static_cast<std::uint32_t>(channels_.size()));
      putU32(file_, static_cast<std::uint32_t>(attachmentIndexes_.size()));
      putU32(file_, static_cast<std::uint32_t>(metadataIndexes_.size()));
      putU32(file_, chunkCount_);
      putU64(file_, messageCount_ > 0 ? startTime_ : 0);
      putU64(file_, messageCount_ > 0 ? endTime_ : 0);
      std::uint32_t n = 0;
      for (const std::uint64_t c : channelCounts_)
        n += c > 0 ? 10 : 0;
      putU32(file_, n);
      for (std::size_t i = 0; i < channelCounts_.size(); ++i) {
        if (channelCounts_[i] == 0) continue;
        putU16(file_, static_cast<std::uint16_t>(i + 1));
        putU64(file_, channelCounts_[i]);
      }
      closeRecord(file_, at);
    });
    group(Opcode::ChunkIndex, [&] {
      for (const ChunkIndex& c : chunkIndexes_) {
        at = openRecord(file_, Opcode::ChunkIndex);
        putU64(file_, c.messageStartTime);
        putU64(file_, c.messageEndTime);
        putU64(file_, c.chunkStartOffset);
        putU64(file_, c.chunkLength);
        putU32(file_, static_cast<std::uint32_t>(10 * c.messageIndexOffsets.size()));
        for (const auto& [channel, offset] : c.messageIndexOffsets) {
          putU16(file_, channel);
          putU64(file_, offset);
        }
        putU64(file_, c.messageIndexLength);
        putString(file_, c.compression);
        putU64(file_, c.compressedSize);
        putU64(file_, c.uncompressedSize);
        closeRecord(file_, at);
      }
    });
    group(Opcode::AttachmentIndex, [&] {
      for (const AttachmentEntry& a : attachmentIndexes_) {
        at = openRecord(file_, Opcode::AttachmentIndex);
        putU64(file_, a.offset);
        putU64(file_, a.length);
        putU64(file_, a.logTime);
        putU64(file_, 0);
        putU64(file_, a.dataSize);
        putString(file_, a.name);
        putString(file_, a.mediaType);
        closeRecord(file_, at);
      }
    });
    group(Opcode::MetadataIndex, [&] {
      for (const MetadataEntry& m : metadataIndexes_) {
        at = openRecord(file_, Opcode::MetadataIndex);
        putU64(file_, m.offset);
        putU64(file_, m.length);
        putString(file_, m.name);
        closeRecord(file_, at);
      }
    });
    summaryOffsetStart = groups.empty() ? 0 : position();
    for (const Group& g : groups) {
      at = openRecord(file_, Opcode::SummaryOffset);
      putU8(file_, static_cast<std::uint8_t>(g.op));
      putU64(file_, g.start);
      putU64(file_, g.length);
      closeRecord(file_, at);
    }
  }
  const std::size_t footerAt = file_.size();
  putU8(file_, static_cast<std::uint8_t>(Opcode::Footer));
  putU64(file_, 20);
  putU64(file_, summaryStart);
  putU64(file_, summaryOffsetStart);
  const std::size_t crcFrom =
      summaryStart != 0 ? static_cast<std::size_t>(summaryStart - flushed_) : footerAt;
  putU32(file_, options_.summary ? crc32(file_.view().substr(crcFrom)) : 0);
  file_.append(kMagic);
  std::string out;
  if (sink_) {
    flushFile(false);
  } else {
    out.assign(file_.view());
  }
  file_.clear();
  flushed_ = 0;
  dataCrc_ = 0;
  return out;
}

}  // namespace tactile::mcap
