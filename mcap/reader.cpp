#include "mcap/reader.h"

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "base/file_text.h"
#include "base/parallel.h"
#include "mcap/bytes.h"
#include "mcap/compression.h"
#include "mcap/crc32.h"

namespace tactile::mcap {

Error errorAt(const std::string& file, std::uint64_t offset, const std::string& message) {
  return Error(file, "byte " + std::to_string(offset) + ": " + message);
}

namespace {

using bytes::getU16;
using bytes::getU32;
using bytes::getU64;

// A fault found while reading: where (a file offset) and what.
struct Fault {
  std::uint64_t offset;
  std::string message;
};
// An error returned by the message callback, passed through untouched.
struct CallbackError {
  Error error;
};

std::string opcodeName(std::uint8_t op) {
  static constexpr std::array<const char*, 16> kNames{
      "invalid (0x00)",   "Header",     "Footer",        "Schema",         "Channel",
      "Message",          "Chunk",      "Message Index", "Chunk Index",    "Attachment",
      "Attachment Index", "Statistics", "Metadata",      "Metadata Index", "Summary Offset",
      "Data End"};
  if (op < kNames.size()) return kNames[op];
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", op);
  return std::string("unknown (") + buf + ")";
}

// Reads the fields of one record's content, each checked against the content's end. Offsets in
// faults are file offsets: `fileBase` is where byte 0 of `data` lies in the file (for records in
// a decompressed chunk, the chunk's own offset, with `where` saying more).
class Fields {
 public:
  Fields(std::string_view data, std::uint64_t fileBase, std::string what)
      : data_(data), base_(fileBase), what_(std::move(what)) {}

  std::uint8_t u8(const char* field) {
    need(1, field);
    return static_cast<std::uint8_t>(data_[pos_++]);
  }
  std::uint16_t u16(const char* field) {
    need(2, field);
    const auto v = getU16(data_.data() + pos_);
    pos_ += 2;
    return v;
  }
  std::uint32_t u32(const char* field) {
    need(4, field);
    const auto v = getU32(data_.data() + pos_);
    pos_ += 4;
    return v;
  }
  std::uint64_t u64(const char* field) {
    need(8, field);
    const auto v = getU64(data_.data() + pos_);
    pos_ += 8;
    return v;
  }
  // A uint32 length, then that many bytes (checked before anything is copied).
  std::string_view prefixed32(const char* field) {
    const std::uint32_t n = u32(field);
    if (n > data_.size() - pos_) lengthPast(field, n);
    const std::string_view s = data_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  std::string_view prefixed64(const char* field) {
    const std::uint64_t n = u64(field);
    if (n > data_.size() - pos_) lengthPast(field, n);
    const std::string_view s = data_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return s;
  }
  std::string string(const char* field) { return std::string(prefixed32(field)); }
  KeyValues stringMap(const char* field) {
    const std::uint64_t at = base_ + pos_;
    Fields inner(prefixed32(field), at + 4, what_);
    KeyValues out;
    while (!inner.atEnd()) {
      std::string key = inner.string(field);
      std::string value = inner.string(field);
      out.emplace_back(std::move(key), std::move(value));
    }
    return out;
  }
  std::vector<std::pair<std::uint16_t, std::uint64_t>> u16u64Map(const char* field) {
    const std::uint64_t at = base_ + pos_;
    const std::string_view raw = prefixed32(field);
    if (raw.size() % 10 != 0) {
      throw Fault{at, what_ + ": " + field + " holds " + std::to_string(raw.size()) +
                          " bytes, not a whole number of 10-byte entries"};
    }
    std::vector<std::pair<std::uint16_t, std::uint64_t>> out;
    out.reserve(raw.size() / 10);
    for (std::size_t i = 0; i < raw.size(); i += 10)
      out.emplace_back(getU16(raw.data() + i), getU64(raw.data() + i + 2));
    return out;
  }
  std::string_view rest() {
    const std::string_view s = data_.substr(pos_);
    pos_ = data_.size();
    return s;
  }
  bool atEnd() const { return pos_ >= data_.size(); }
  std::size_t pos() const { return pos_; }
  std::uint64_t fileOffset() const { return base_ + pos_; }

 private:
  void need(std::size_t n, const char* field) {
    if (data_.size() - pos_ < n) {
      throw Fault{base_ + pos_, what_ + " ends inside its field " + field + " (" +
                                    std::to_string(data_.size() - pos_) + " of " +
                                    std::to_string(n) + " bytes left)"};
    }
  }
  [[noreturn]] void lengthPast(const char* field, std::uint64_t n) {
    throw Fault{base_ + pos_, what_ + ": " + field + " length " + std::to_string(n) +
                                  " runs past the end of the record (" +
                                  std::to_string(data_.size() - pos_) + " bytes left)"};
  }

  std::string_view data_;
  std::size_t pos_ = 0;
  std::uint64_t base_;
  std::string what_;
};

// Decompresses the chunks, and checks their CRCs, on one more thread ahead of the scan, which
// then only walks their records. The chunk records are found by their record headers alone (a
// cheap walk over the file, no summary needed); a chunk whose fields, decompression or CRC are at
// fault is left to the scan, which reads it again and reports the fault exactly as it would
// without this. Chunks are handed over in batches (fewer waits), in file order. An exception on the
// worker (out of memory) stops it, and the scan reads the remaining chunks itself, failing as one
// thread would.
class ChunkPrefetch {
 public:
  // Nothing to do (no thread started) when the records before `footerStart` hold fewer than two
  // chunks.
  ChunkPrefetch(std::string_view bytes, std::uint64_t footerStart) : bytes_(bytes) {
    std::uint64_t pos = kMagic.size();
    while (pos < footerStart && footerStart - pos >= 9) {
      const auto op = static_cast<std::uint8_t>(bytes[pos]);
      const std::uint64_t len = getU64(bytes.data() + pos + 1);
      if (len > footerStart - pos - 9) break;
      if (op == static_cast<std::uint8_t>(Opcode::Chunk)) chunks_.push_back(pos);
      pos += 9 + len;
    }
    if (chunks_.size() < 2) return;
    ring_.resize(kSlots);
    for (Batch& batch : ring_)
      batch.items = std::make_unique<Item[]>(kBatchChunks);
    worker_ = std::make_unique<BackgroundWorkers>(
        1,
        [this] {
          if (!failure_.capture([this] { produce(); })) {
            // failed() holds now: a scan waiting for a batch is woken to see it.
            { std::lock_guard lock(mutex_); }
            changed_.notify_all();
          }
        },
        failure_);
  }
  ChunkPrefetch(const ChunkPrefetch&) = delete;
  ChunkPrefetch& operator=(const ChunkPrefetch&) = delete;
  ~ChunkPrefetch() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    worker_.reset();  // joins
  }

  // The records of the chunk record at `pos`, decompressed and checked against the chunk's CRC,
  // when the worker has them (valid until the next call); else nothing, and the caller reads the
  // chunk itself.
  std::optional<std::string_view> take(std::uint64_t pos) {
    if (!worker_ || next_ >= chunks_.size() || chunks_[next_] != pos) return std::nullopt;
    if (held_ == kNone || taken_ == ring_[held_ % kSlots].count) {
      // The next batch; the one held so far is done with.
      const std::size_t batch = held_ == kNone ? 0 : held_ + 1;
      std::unique_lock lock(mutex_);
      released_ = batch;
      changed_.notify_all();
      changed_.wait(lock, [&] { return produced_ > batch || failure_.failed(); });
      if (produced_ <= batch) return std::nullopt;
      held_ = batch;
      taken_ = 0;
    }
    const Item& item = ring_[held_ % kSlots].items[taken_++];
    ++next_;
    if (!item.ok) return std::nullopt;
    return item.inPlace ? item.plain : item.buffer->view();
  }

 private:
  // A batch ends after this many chunks or once its records reach this size, so a file of big
  // chunks holds at most a few of them (and each slot at most one buffer above the size).
  static constexpr std::size_t kBatchChunks = 64;
  static constexpr std::uint64_t kBatchBytes = std::uint64_t{1} << 20;
  static constexpr std::size_t kSlots = 4;
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  struct Item {
    bool ok = false;
    bool inPlace = false;    // uncompressed: the records in the file
    std::string_view plain;  // when inPlace
    std::unique_ptr<Buffer> buffer = std::make_unique<Buffer>();
  };
  struct Batch {
    std::unique_ptr<Item[]> items;  // kBatchChunks
    std::size_t count = 0;          // items filled
  };

  void produce() {
    std::size_t next = 0;
    for (std::size_t b = 0; next < chunks_.size(); ++b) {
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return stop_ || b < released_ + kSlots; });
        if (stop_) return;
      }
      Batch& batch = ring_[b % kSlots];
      for (std::size_t k = 0; k < kBatchChunks; ++k) {
        if (batch.items[k].buffer->capacity() > kBatchBytes)
          batch.items[k].buffer = std::make_unique<Buffer>();
      }
      batch.count = 0;
      std::uint64_t bytes = 0;
      while (next < chunks_.size() && batch.count < kBatchChunks && bytes < kBatchBytes)
        bytes += prepare(chunks_[next++], batch.items[batch.count++]);
      {
        std::lock_guard lock(mutex_);
        produced_ = b + 1;
      }
      changed_.notify_all();
    }
  }

  // The chunk's records as Scanner::chunkRecord reads them; `ok` only when all is in order.
  // Returns the bytes it holds for them.
  std::uint64_t prepare(std::uint64_t pos, Item& item) {
    item.ok = false;
    item.inPlace = false;
    const std::uint64_t len = getU64(bytes_.data() + pos + 1);
    const std::string_view content = bytes_.substr(pos + 9, static_cast<std::size_t>(len));
    constexpr std::size_t kFixed = 8 + 8 + 8 + 4;
    if (content.size() < kFixed + 4) return 0;
    const std::uint64_t uncompressedSize = getU64(content.data() + 16);
    const std::uint32_t crc = getU32(content.data() + 24);
    const std::uint32_t nameLen = getU32(content.data() + kFixed);
    if (nameLen > content.size() - kFixed - 4 || content.size() - kFixed - 4 - nameLen < 8)
      return 0;
    const auto kind = parseCompression(content.substr(kFixed + 4, nameLen));
    if (!kind) return 0;
    const std::size_t recordsAt = kFixed + 4 + nameLen + 8;
    const std::uint64_t recordsLen = getU64(content.data() + recordsAt - 8);
    if (recordsLen > content.size() - recordsAt) return 0;
    const std::string_view records =
        content.substr(recordsAt, static_cast<std::size_t>(recordsLen));
    std::string_view plain = records;
    if (*kind != Compression::None) {
      if (decompressor_.decompress(*kind, records, uncompressedSize, *item.buffer)) return 0;
      plain = item.buffer->view();
    } else if (records.size() != uncompressedSize) {
      return 0;
    } else {
      item.inPlace = true;
      item.plain = records;
    }
    if (crc != 0 && crc32(plain) != crc) return 0;
    item.ok = true;
    return item.inPlace ? 0 : plain.size();
  }

  std::string_view bytes_;
  std::vector<std::uint64_t> chunks_;  // offsets of the chunk records, in file order
  std::vector<Batch> ring_;            // batch b in slot b % kSlots
  Decompressor decompressor_;          // the worker's
  std::size_t next_ = 0;               // the caller's: the next chunk it takes,
  std::size_t held_ = kNone;           // the batch it takes from,
  std::size_t taken_ = 0;              // and how many of that batch's chunks it took
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t produced_ = 0;  // batches ready
  std::size_t released_ = 0;  // batches the caller is done with
  bool stop_ = false;
  FirstException failure_;
  std::unique_ptr<BackgroundWorkers> worker_;  // last: joined before the rest goes
};

class Scanner {
 public:
  Scanner(std::string_view bytes, const std::string& file, const MessageFn& onMessage,
          unsigned threads)
      : bytes_(bytes), file_(file), onMessage_(onMessage), threads_(threads) {
    channelById_.fill(nullptr);
    schemaOfChannel_.fill(nullptr);
  }

  ScanResult run() {
    const std::uint64_t size = bytes_.size();
    out_.fileSize = size;
    constexpr std::uint64_t kFooterRecord = 1 + 8 + 20;
    if (size < kMagic.size() || bytes_.substr(0, kMagic.size()) != kMagic) {
      throw Fault{0, "not an MCAP file (it does not start with the MCAP magic bytes)"};
    }
    if (size < 2 * kMagic.size() + kFooterRecord || bytes_.substr(size - kMagic.size()) != kMagic) {
      throw Fault{size,
                  "the file is cut short: it does not end with a Footer record and the MCAP "
                  "magic bytes (" +
                      std::to_string(size) + " bytes)"};
    }
    const std::uint64_t footerStart = size - kMagic.size() - kFooterRecord;
    if (static_cast<std::uint8_t>(bytes_[footerStart]) !=
            static_cast<std::uint8_t>(Opcode::Footer) ||
        getU64(bytes_.data() + footerStart + 1) != 20) {
      throw Fault{footerStart,
                  "expected the Footer record (opcode 0x02, length 20) before the "
                  "closing magic bytes"};
    }
    const std::uint64_t summaryStart = getU64(bytes_.data() + footerStart + 9);
    const std::uint64_t summaryOffsetStart = getU64(bytes_.data() + footerStart + 17);
    const std::uint32_t summaryCrc = getU32(bytes_.data() + footerStart + 25);
    if (summaryStart != 0 && (summaryStart < kMagic.size() || summaryStart > footerStart)) {
      throw Fault{footerStart + 9, "the Footer's summary_start " + std::to_string(summaryStart) +
                                       " lies outside the records (" +
                                       std::to_string(kMagic.size()) + " to " +
                                       std::to_string(footerStart) + ")"};
    }
    if (summaryOffsetStart != 0 &&
        (summaryOffsetStart < kMagic.size() || summaryOffsetStart > footerStart ||
         (summaryStart != 0 && summaryOffsetStart < summaryStart))) {
      throw Fault{footerStart + 17, "the Footer's summary_offset_start " +
                                        std::to_string(summaryOffsetStart) +
                                        " lies outside the summary"};
    }

    if (workerThreadCount(threads_, 2) >= 2) {
      prefetch_ = std::make_unique<ChunkPrefetch>(bytes_, footerStart);
    }
    std::uint64_t pos = kMagic.size();
    bool first = true;
    bool inSummary = false;
    std::uint64_t summaryBegins = 0;
    std::uint64_t firstSummaryOffset = 0;
    std::set<std::uint8_t> summaryGroupsSeen;
    std::uint8_t lastSummaryOp = 0;
    while (pos < footerStart) {
      if (footerStart - pos < 9) {
        throw Fault{pos, "a record header (9 bytes) runs into the Footer at byte " +
                             std::to_string(footerStart)};
      }
      const auto op = static_cast<std::uint8_t>(bytes_[pos]);
      const std::uint64_t len = getU64(bytes_.data() + pos + 1);
      if (len > footerStart - pos - 9) {
        throw Fault{pos + 1, opcodeName(op) + " record: length " + std::to_string(len) +
                                 " runs past the end of the records (" +
                                 std::to_string(footerStart - pos - 9) +
                                 " bytes left before the Footer at byte " +
                                 std::to_string(footerStart) + ")"};
      }
      const std::string_view content = bytes_.substr(pos + 9, static_cast<std::size_t>(len));
      if (first) {
        if (op != static_cast<std::uint8_t>(Opcode::Header)) {
          throw Fault{pos, "the first record is a " + opcodeName(op) + " record, not the Header"};
        }
        Fields f(content, pos + 9, "Header record");
        out_.profile = f.string("profile");
        out_.library = f.string("library");
        first = false;
        pos += 9 + len;
        continue;
      }
      if (!inSummary && summaryStart != 0 && pos == summaryStart) {
        inSummary = true;
        summaryBegins = pos;
      }
      if (!inSummary && summaryStart != 0 && pos > summaryStart) {
        throw Fault{pos, "the Footer's summary_start " + std::to_string(summaryStart) +
                             " is not the start of a record"};
      }
      if (inSummary) {
        if (summaryGroupsSeen.count(op) != 0 && op != lastSummaryOp) {
          throw Fault{pos, "summary records are not grouped by opcode: a second group of " +
                               opcodeName(op) + " records"};
        }
        summaryGroupsSeen.insert(op);
        lastSummaryOp = op;
        if (op == static_cast<std::uint8_t>(Opcode::SummaryOffset) && firstSummaryOffset == 0) {
          firstSummaryOffset = pos;
        }
        summaryRecord(op, content, pos);
      } else {
        dataRecord(op, content, pos);
        if (op == static_cast<std::uint8_t>(Opcode::DataEnd)) {
          inSummary = true;  // whatever follows is the summary
          summaryBegins = pos + 9 + len;
        }
      }
      pos += 9 + len;
    }
    if (first) throw Fault{pos, "the file holds no Header record"};
    if (summaryStart != 0 && summaryStart != summaryBegins) {
      throw Fault{footerStart + 9, "the Footer's summary_start " + std::to_string(summaryStart) +
                                       " is not where the summary begins (byte " +
                                       std::to_string(summaryBegins) + ")"};
    }
    if (summaryOffsetStart != 0 && summaryOffsetStart != firstSummaryOffset) {
      throw Fault{footerStart + 17, "the Footer's summary_offset_start " +
                                        std::to_string(summaryOffsetStart) +
                                        " is not the first Summary Offset record"};
    }
    if (summaryCrc != 0) {
      const std::uint64_t from = summaryStart != 0 ? summaryStart : footerStart;
      const std::uint32_t crc = crc32(bytes_.substr(from, footerStart + 9 + 16 - from));
      if (crc != summaryCrc) {
        throw Fault{footerStart + 25, "the summary's CRC does not match (the Footer says " +
                                          hex(summaryCrc) + ", the bytes give " + hex(crc) + ")"};
      }
    }
    out_.hasSummary = summaryStart != 0 && summaryStart < footerStart;
    crossCheck(footerStart);
    return std::move(out_);
  }

 private:
  static std::string hex(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08X", v);
    return buf;
  }

  void dataRecord(std::uint8_t op, std::string_view content, std::uint64_t pos) {
    switch (static_cast<Opcode>(op)) {
      case Opcode::Schema:
        schemaRecord(content, pos + 9, "Schema record", false);
        return;
      case Opcode::Channel:
        channelRecord(content, pos + 9, "Channel record", false);
        return;
      case Opcode::Message:
        ++out_.messagesOutsideChunks;
        messageRecord(content, pos, pos + 9, std::nullopt);
        return;
      case Opcode::Chunk:
        chunkRecord(content, pos);
        return;
      case Opcode::MessageIndex: {
        Fields f(content, pos + 9, "Message Index record");
        f.u16("channel_id");
        const std::uint64_t at = f.fileOffset();
        const std::string_view entries = f.prefixed32("records");
        if (entries.size() % 16 != 0) {
          throw Fault{at, "Message Index record: records hold " + std::to_string(entries.size()) +
                              " bytes, not a whole number of 16-byte entries"};
        }
        ++out_.messageIndexCount;
        return;
      }
      case Opcode::Attachment:
        attachmentRecord(content, pos);
        return;
      case Opcode::Metadata: {
        Fields f(content, pos + 9, "Metadata record");
        Metadata m;
        m.name = f.string("name");
        m.entries = f.stringMap("metadata");
        out_.metadata.push_back(std::move(m));
        return;
      }
      case Opcode::DataEnd: {
        Fields f(content, pos + 9, "Data End record");
        const std::uint32_t crc = f.u32("data_section_crc");
        out_.hasDataEnd = true;
        if (crc != 0) {
          const std::uint32_t actual = crc32(bytes_.substr(0, pos));
          if (actual != crc) {
            throw Fault{pos + 9,
                        "the data section's CRC does not match (the Data End record says " +
                            hex(crc) + ", the bytes give " + hex(actual) + ")"};
          }
        }
        return;
      }
      case Opcode::Header:
      case Opcode::Footer:
        throw Fault{pos, "a second " + opcodeName(op) + " record"};
      case Opcode::ChunkIndex:
      case Opcode::AttachmentIndex:
      case Opcode::Statistics:
      case Opcode::MetadataIndex:
      case Opcode::SummaryOffset:
        // Summary records in a file without a Data End record and summary_start: taken as they
        // are (older writers).
        summaryRecord(op, content, pos);
        return;
    }
    if (op == 0) throw Fault{pos, "invalid record opcode 0x00"};
    // Unknown (newer or private) records are skipped, as the specification asks.
  }

  void summaryRecord(std::uint8_t op, std::string_view content, std::uint64_t pos) {
    switch (static_cast<Opcode>(op)) {
      case Opcode::Schema:
        schemaRecord(content, pos + 9, "Schema record (summary)", true);
        return;
      case Opcode::Channel:
        channelRecord(content, pos + 9, "Channel record (summary)", true);
        return;
      case Opcode::ChunkIndex: {
        Fields f(content, pos + 9, "Chunk Index record");
        ChunkIndex c;
        c.messageStartTime = f.u64("message_start_time");
        c.messageEndTime = f.u64("message_end_time");
        c.chunkStartOffset = f.u64("chunk_start_offset");
        c.chunkLength = f.u64("chunk_length");
        c.messageIndexOffsets = f.u16u64Map("message_index_offsets");
        c.messageIndexLength = f.u64("message_index_length");
        c.compression = f.string("compression");
        c.compressedSize = f.u64("compressed_size");
        c.uncompressedSize = f.u64("uncompressed_size");
        chunkIndexAt_.push_back(pos);
        out_.chunkIndexes.push_back(std::move(c));
        return;
      }
      case Opcode::AttachmentIndex: {
        Fields f(content, pos + 9, "Attachment Index record");
        for (const char* field : {"offset", "length", "log_time", "create_time", "data_size"})
          f.u64(field);
        f.prefixed32("name");
        f.prefixed32("media_type");
        ++out_.attachmentIndexCount;
        return;
      }
      case Opcode::Statistics: {
        Fields f(content, pos + 9, "Statistics record");
        if (out_.statistics) throw Fault{pos, "a second Statistics record"};
        Statistics s;
        s.messageCount = f.u64("message_count");
        s.schemaCount = f.u16("schema_count");
        s.channelCount = f.u32("channel_count");
        s.attachmentCount = f.u32("attachment_count");
        s.metadataCount = f.u32("metadata_count");
        s.chunkCount = f.u32("chunk_count");
        s.messageStartTime = f.u64("message_start_time");
        s.messageEndTime = f.u64("message_end_time");
        s.channelMessageCounts = f.u16u64Map("channel_message_counts");
        statisticsAt_ = pos;
        out_.statistics = std::move(s);
        return;
      }
      case Opcode::MetadataIndex: {
        Fields f(content, pos + 9, "Metadata Index record");
        f.u64("offset");
        f.u64("length");
        f.prefixed32("name");
        ++out_.metadataIndexCount;
        return;
      }
      case Opcode::SummaryOffset: {
        Fields f(content, pos + 9, "Summary Offset record");
        f.u8("group_opcode");
        const std::uint64_t start = f.u64("group_start");
        const std::uint64_t length = f.u64("group_length");
        if (start > out_.fileSize || length > out_.fileSize - start) {
          throw Fault{pos + 10, "Summary Offset record: the group at " + std::to_string(start) +
                                    " of " + std::to_string(length) +
                                    " bytes runs past the end of the file"};
        }
        ++out_.summaryOffsetCount;
        return;
      }
      case Opcode::Metadata:
      case Opcode::Attachment:
      case Opcode::Message:
      case Opcode::Chunk:
      case Opcode::MessageIndex:
      case Opcode::DataEnd:
      case Opcode::Header:
      case Opcode::Footer:
        throw Fault{pos, "a " + opcodeName(op) + " record may not be in the summary section"};
    }
    if (op == 0) throw Fault{pos, "invalid record opcode 0x00"};
  }

  void schemaRecord(std::string_view content, std::uint64_t at, const std::string& what,
                    bool summary) {
    Fields f(content, at, what);
    Schema s;
    s.id = f.u16("id");
    s.name = f.string("name");
    s.encoding = f.string("encoding");
    s.data = std::string(f.prefixed32("data"));
    if (s.id == 0) return;  // invalid, ignored (the specification)
    auto [it, added] = out_.schemas.emplace(s.id, s);
    if (!added && !(it->second == s)) {
      throw Fault{at, what + ": schema " + std::to_string(s.id) +
                          " differs from an earlier Schema record with the same id"};
    }
    (void)summary;
  }

  void channelRecord(std::string_view content, std::uint64_t at, const std::string& what,
                     bool summary) {
    Fields f(content, at, what);
    Channel c;
    c.id = f.u16("id");
    c.schemaId = f.u16("schema_id");
    c.topic = f.string("topic");
    c.messageEncoding = f.string("message_encoding");
    c.metadata = f.stringMap("metadata");
    if (c.schemaId != 0 && out_.schemas.count(c.schemaId) == 0) {
      throw Fault{at, what + ": channel " + std::to_string(c.id) + " (" + c.topic +
                          ") names schema " + std::to_string(c.schemaId) +
                          ", which no earlier Schema record defines"};
    }
    auto [it, added] = out_.channels.emplace(c.id, c);
    if (!added && !(it->second == c)) {
      throw Fault{at, what + ": channel " + std::to_string(c.id) +
                          " differs from an earlier Channel record with the same id"};
    }
    if (added) {
      channelById_[c.id] = &it->second;
      const auto schema = out_.schemas.find(c.schemaId);
      schemaOfChannel_[c.id] = schema == out_.schemas.end() ? nullptr : &schema->second;
    }
    (void)summary;
  }

  // `recordStart`: the file offset of the record (or of the chunk holding it), `contentAt` the
  // offset errors name.
  void messageRecord(std::string_view content, std::uint64_t recordStart, std::uint64_t contentAt,
                     std::optional<std::uint64_t> chunkOffset) {
    if (content.size() < 22) {
      throw Fault{contentAt, "Message record of " + std::to_string(content.size()) +
                                 " bytes is shorter than its 22 bytes of fixed fields"};
    }
    MessageView m;
    m.channelId = getU16(content.data());
    m.sequence = getU32(content.data() + 2);
    m.logTime = getU64(content.data() + 6);
    m.publishTime = getU64(content.data() + 14);
    m.data = content.substr(22);
    m.fileOffset = recordStart;
    m.chunkOffset = chunkOffset;
    const Channel* channel = channelById_[m.channelId];
    if (channel == nullptr) {
      throw Fault{contentAt, "Message record on channel " + std::to_string(m.channelId) +
                                 ", which no earlier Channel record defines"};
    }
    if (out_.messageCount == 0 || m.logTime < out_.messageStartTime) {
      out_.messageStartTime = m.logTime;
    }
    if (out_.messageCount == 0 || m.logTime > out_.messageEndTime) {
      out_.messageEndTime = m.logTime;
    }
    ++out_.messageCount;
    ++out_.channelMessageCounts[m.channelId];
    if (onMessage_) {
      Status s = onMessage_(m, *channel, schemaOfChannel_[m.channelId]);
      if (!s) throw CallbackError{s.error()};
    }
  }

  void chunkRecord(std::string_view content, std::uint64_t pos) {
    Fields f(content, pos + 9, "Chunk record");
    const std::uint64_t start = f.u64("message_start_time");
    const std::uint64_t end = f.u64("message_end_time");
    const std::uint64_t uncompressedSize = f.u64("uncompressed_size");
    const std::uint32_t crc = f.u32("uncompressed_crc");
    const std::uint64_t compressionAt = f.fileOffset();
    const std::string compression = f.string("compression");
    const std::uint64_t recordsAt = f.fileOffset() + 8;
    const std::string_view records = f.prefixed64("records");
    const auto kind = parseCompression(compression);
    if (!kind) {
      throw Fault{compressionAt, "Chunk record: unknown compression '" + compression +
                                     "' (this reader knows zstd, lz4 and none)"};
    }
    std::string_view plain = records;
    std::optional<std::string_view> prefetched;
    if (prefetch_) prefetched = prefetch_->take(pos);
    if (prefetched) {
      plain = *prefetched;  // decompressed and its CRC checked
    } else if (*kind != Compression::None) {
      if (auto problem = decompressor_.decompress(*kind, records, uncompressedSize, chunkBuffer_)) {
        throw Fault{recordsAt, "Chunk record: " + *problem};
      }
      plain = chunkBuffer_.view();
    } else if (records.size() != uncompressedSize) {
      throw Fault{recordsAt, "Chunk record: " + std::to_string(records.size()) +
                                 " bytes of uncompressed records, its uncompressed_size says " +
                                 std::to_string(uncompressedSize)};
    }
    if (crc != 0 && !prefetched) {
      const std::uint32_t actual = crc32(plain);
      if (actual != crc) {
        throw Fault{pos + 9 + 24, "Chunk record: the CRC of its records does not match (it says " +
                                      hex(crc) + ", the records give " + hex(actual) + ")"};
      }
    }
    ++out_.chunkCount;
    ++out_.chunkCompressions[compression];
    chunks_.emplace_back(pos, 9 + content.size());
    const std::uint64_t messagesBefore = out_.messageCount;
    std::uint64_t first = 0;
    std::uint64_t last = 0;
    // Records inside: Schema, Channel and Message (others are skipped when unknown).
    std::size_t at = 0;
    const std::string where = "in the chunk at byte " + std::to_string(pos);
    while (at < plain.size()) {
      // Faults name the chunk's records offset: the file offset means nothing inside
      // compressed data.
      const std::uint64_t fileAt = *kind == Compression::None ? recordsAt + at : pos;
      auto inner = [&](const std::string& what) {
        return what + " (" + where + ", offset " + std::to_string(at) + " of its records)";
      };
      if (plain.size() - at < 9) {
        throw Fault{fileAt,
                    inner("a record header (9 bytes) runs past the end of the chunk's records")};
      }
      const auto op = static_cast<std::uint8_t>(plain[at]);
      const std::uint64_t len = getU64(plain.data() + at + 1);
      if (len > plain.size() - at - 9) {
        throw Fault{fileAt, inner(opcodeName(op) + " record: length " + std::to_string(len) +
                                  " runs past the end of the chunk's records (" +
                                  std::to_string(plain.size() - at - 9) + " bytes left)")};
      }
      const std::string_view body = plain.substr(at + 9, static_cast<std::size_t>(len));
      try {
        switch (static_cast<Opcode>(op)) {
          case Opcode::Schema:
            schemaRecord(body, fileAt, "Schema record", false);
            break;
          case Opcode::Channel:
            channelRecord(body, fileAt, "Channel record", false);
            break;
          case Opcode::Message: {
            const std::uint64_t before = out_.messageCount;
            messageRecord(body, pos, fileAt, at);
            (void)before;
            const std::uint64_t t = getU64(body.data() + 6);
            if (out_.messageCount - messagesBefore == 1 || t < first) first = t;
            if (out_.messageCount - messagesBefore == 1 || t > last) last = t;
            break;
          }
          default:
            if (op == 0 || op < 0x80) {
              if (op == 0 || op <= static_cast<std::uint8_t>(Opcode::DataEnd)) {
                throw Fault{fileAt, "a " + opcodeName(op) + " record may not be inside a chunk"};
              }
            }
            break;
        }
      } catch (Fault& fault) {
        if (*kind != Compression::None && fault.message.find(where) == std::string::npos) {
          fault.message = inner(fault.message);
        }
        throw;
      }
      at += 9 + static_cast<std::size_t>(len);
    }
    const bool hasMessages = out_.messageCount > messagesBefore;
    if (hasMessages && (first != start || last != end)) {
      throw Fault{pos + 9, "Chunk record: its message times say " + std::to_string(start) + " to " +
                               std::to_string(end) + ", its messages run from " +
                               std::to_string(first) + " to " + std::to_string(last)};
    }
  }

  void attachmentRecord(std::string_view content, std::uint64_t pos) {
    Fields f(content, pos + 9, "Attachment record");
    AttachmentInfo a;
    a.offset = pos;
    a.logTime = f.u64("log_time");
    a.createTime = f.u64("create_time");
    a.name = f.string("name");
    a.mediaType = f.string("media_type");
    a.dataSize = f.prefixed64("data").size();
    const std::size_t crcAt = f.pos();
    const std::uint32_t crc = f.u32("crc");
    if (crc != 0) {
      const std::uint32_t actual = crc32(content.substr(0, crcAt));
      if (actual != crc) {
        throw Fault{pos + 9 + crcAt, "Attachment record '" + a.name +
                                         "': the CRC does not match (it says " + hex(crc) +
                                         ", the bytes give " + hex(actual) + ")"};
      }
    }
    out_.attachments.push_back(std::move(a));
  }

  // The summary against the data section.
  void crossCheck(std::uint64_t footerStart) {
    if (const auto& s = out_.statistics) {
      if (s->messageCount != out_.messageCount) {
        throw Fault{statisticsAt_,
                    "the Statistics record counts " + std::to_string(s->messageCount) +
                        " messages, the file holds " + std::to_string(out_.messageCount)};
      }
      if (s->chunkCount != out_.chunkCount) {
        throw Fault{statisticsAt_, "the Statistics record counts " + std::to_string(s->chunkCount) +
                                       " chunks, the file holds " +
                                       std::to_string(out_.chunkCount)};
      }
      for (const auto& [id, count] : s->channelMessageCounts) {
        const auto it = out_.channelMessageCounts.find(id);
        const std::uint64_t have = it == out_.channelMessageCounts.end() ? 0 : it->second;
        if (have != count) {
          throw Fault{statisticsAt_, "the Statistics record counts " + std::to_string(count) +
                                         " messages on channel " + std::to_string(id) +
                                         ", the file holds " + std::to_string(have)};
        }
      }
    }
    for (std::size_t i = 0; i < out_.chunkIndexes.size(); ++i) {
      const ChunkIndex& c = out_.chunkIndexes[i];
      // chunks_ is in file order, so sorted by offset (a search per index: a file of 70,000
      // chunks took 0.7 s looking through them all for each).
      const auto at = std::lower_bound(
          chunks_.begin(), chunks_.end(), c.chunkStartOffset,
          [](const auto& chunk, std::uint64_t offset) { return chunk.first < offset; });
      const bool found =
          at != chunks_.end() && at->first == c.chunkStartOffset && at->second == c.chunkLength;
      if (!found) {
        throw Fault{chunkIndexAt_[i], "Chunk Index record: no chunk of " +
                                          std::to_string(c.chunkLength) + " bytes starts at byte " +
                                          std::to_string(c.chunkStartOffset)};
      }
      for (const auto& [channel, offset] : c.messageIndexOffsets) {
        if (offset >= footerStart || static_cast<std::uint8_t>(bytes_[offset]) !=
                                         static_cast<std::uint8_t>(Opcode::MessageIndex)) {
          throw Fault{chunkIndexAt_[i], "Chunk Index record: the message index of channel " +
                                            std::to_string(channel) + " at byte " +
                                            std::to_string(offset) +
                                            " is not a Message Index record"};
        }
      }
    }
  }

  std::string_view bytes_;
  const std::string& file_;
  const MessageFn& onMessage_;
  ScanResult out_;
  std::array<const Channel*, 65536> channelById_{};
  std::array<const Schema*, 65536> schemaOfChannel_{};
  Buffer chunkBuffer_;
  Decompressor decompressor_;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> chunks_;  // (offset, length)
  std::vector<std::uint64_t> chunkIndexAt_;
  std::uint64_t statisticsAt_ = 0;
  unsigned threads_;
  std::unique_ptr<ChunkPrefetch> prefetch_;
};

}  // namespace

std::optional<std::uint64_t> summaryTopicMessageCount(std::string_view bytes,
                                                      std::string_view topic) {
  using bytes::getU16;
  using bytes::getU32;
  using bytes::getU64;
  constexpr std::size_t kFooterRecord = 1 + 8 + 8 + 8 + 4;
  if (bytes.size() < 2 * kMagic.size() + kFooterRecord) return std::nullopt;
  const std::size_t footer = bytes.size() - kMagic.size() - kFooterRecord;
  if (static_cast<std::uint8_t>(bytes[footer]) != static_cast<std::uint8_t>(Opcode::Footer))
    return std::nullopt;
  const std::uint64_t summaryStart = getU64(bytes.data() + footer + 9);
  if (summaryStart < kMagic.size() || summaryStart >= footer) return std::nullopt;
  std::vector<std::uint16_t> channels;
  std::optional<std::uint64_t> count;
  std::size_t pos = static_cast<std::size_t>(summaryStart);
  while (pos + 9 <= footer) {
    const auto op = static_cast<Opcode>(bytes[pos]);
    const std::uint64_t len = getU64(bytes.data() + pos + 1);
    if (len > footer - pos - 9) return std::nullopt;
    const char* c = bytes.data() + pos + 9;
    if (op == Opcode::Channel && len >= 8) {
      const std::uint32_t topicLen = getU32(c + 4);
      if (topicLen <= len - 8 && std::string_view(c + 8, topicLen) == topic)
        channels.push_back(getU16(c));
    } else if (op == Opcode::Statistics && len >= 46) {
      const std::uint32_t mapLen = getU32(c + 42);
      if (mapLen > len - 46) return std::nullopt;
      std::uint64_t n = 0;
      for (std::size_t at = 0; at + 10 <= mapLen; at += 10) {
        const std::uint16_t id = getU16(c + 46 + at);
        if (std::find(channels.begin(), channels.end(), id) != channels.end())
          n += getU64(c + 46 + at + 2);
      }
      count = n;
    }
    pos += 9 + static_cast<std::size_t>(len);
  }
  // Channel records come before Statistics in a summary; a count without one is no answer.
  if (channels.empty()) return std::nullopt;
  return count;
}

Result<ScanResult> scan(std::string_view bytes, const std::string& fileName,
                        const MessageFn& onMessage, unsigned threads) {
  try {
    auto scanner = std::make_unique<Scanner>(bytes, fileName, onMessage, threads);
    return scanner->run();
  } catch (const Fault& fault) {
    return errorAt(fileName, fault.offset, fault.message);
  } catch (const CallbackError& e) {
    return e.error;
  }
}

Result<ScanResult> scanFile(const std::filesystem::path& path, const MessageFn& onMessage) {
  FileText text;
  if (Status loaded = text.load(path); !loaded) return loaded.error();
  return scan(text.view(), path.string(), onMessage);
}

}  // namespace tactile::mcap
