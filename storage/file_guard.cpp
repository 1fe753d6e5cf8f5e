#include "storage/file_guard.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cstring>
#include <vector>

#include "storage/sqlite/sqlite_connection.h"

namespace tactile::storage::db {
namespace {

std::uint32_t big32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

// A file descriptor that closes itself.
struct Fd {
  int fd = -1;
  explicit Fd(const std::filesystem::path& path)
      : fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  bool ok() const { return fd >= 0; }
  bool regular() const {
    struct stat info {};
    return ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode);
  }
  std::int64_t size() const {
    struct stat info {};
    return ::fstat(fd, &info) == 0 ? static_cast<std::int64_t>(info.st_size) : -1;
  }
  // Reads exactly `bytes` at `offset`; false on a short read.
  bool readAt(void* into, std::size_t bytes, std::int64_t offset) const {
    auto* out = static_cast<unsigned char*>(into);
    std::size_t done = 0;
    while (done < bytes) {
      const ssize_t n = ::pread(fd, out + done, bytes - done, static_cast<off_t>(offset + done));
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }
};

// SQLite's WAL checksum (file format page, section 4.1): over 32-bit words in the byte order the
// log's magic number names, two running sums, continued from the previous frame.
struct WalChecksum {
  bool bigEndianWords = true;
  std::uint32_t s1 = 0;
  std::uint32_t s2 = 0;
  void add(const unsigned char* data, std::size_t bytes) {
    for (std::size_t i = 0; i + 8 <= bytes; i += 8) {
      std::uint32_t a = 0;
      std::uint32_t b = 0;
      if (bigEndianWords) {
        a = big32(data + i);
        b = big32(data + i + 4);
      } else {
        std::memcpy(&a, data + i, 4);  // the log names little-endian words (x86's own order)
        std::memcpy(&b, data + i + 4, 4);
        if constexpr (std::endian::native == std::endian::big) {
          a = __builtin_bswap32(a);
          b = __builtin_bswap32(b);
        }
      }
      s1 += a + s2;
      s2 += b + s1;
    }
  }
};

// Another process holds the database open: each SQLite connection in WAL mode keeps a shared lock
// on one byte of the -shm file (the unix VFS's "DMS" byte, offset 128) while it is open.
bool otherProcessHasShm(const std::filesystem::path& shm) {
  const Fd file(shm);
  if (!file.ok() || !file.regular()) return false;
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = 128;
  lock.l_len = 1;
  if (::fcntl(file.fd, F_GETLK, &lock) != 0) return false;
  return lock.l_type != F_UNLCK;
}

constexpr std::uint32_t kWalMagicLittle = 0x377f0682;
constexpr std::uint32_t kWalMagicBig = 0x377f0683;
constexpr std::uint32_t kWalVersion = 3007000;

std::int64_t pageSizeOf(const unsigned char* header) {
  const std::uint32_t raw = (std::uint32_t{header[16]} << 8) | header[17];
  return raw == 1 ? 65536 : raw;
}

// The identity a page-1 image carries (see kIdentityViewPrefix), or an empty string.
std::string identityOf(const std::vector<unsigned char>& page) {
  const std::string_view bytes(reinterpret_cast<const char*>(page.data()), page.size());
  const std::size_t at = bytes.find(kIdentityViewPrefix);
  if (at == std::string_view::npos) return {};
  const std::size_t from = at + kIdentityViewPrefix.size();
  if (from + kIdentityHexDigits > bytes.size()) return {};
  return std::string(bytes.substr(from, kIdentityHexDigits));
}

}  // namespace

std::optional<std::string> notRegularFile(const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;  // absent (or unreadable: SQLite says)
  if (S_ISREG(info.st_mode)) return std::nullopt;
  if (S_ISDIR(info.st_mode)) return std::string("a folder");
  if (S_ISFIFO(info.st_mode)) return std::string("a FIFO (named pipe)");
  if (S_ISCHR(info.st_mode)) return std::string("a character device");
  if (S_ISBLK(info.st_mode)) return std::string("a block device");
  if (S_ISSOCK(info.st_mode)) return std::string("a socket");
  return std::string("not a regular file");
}

namespace {

// What the committed page-1 images of a log say, gathered frame by frame (a log may hold tens of
// thousands of them; none is kept).
struct PageOneFacts {
  bool any = false;
  std::uint32_t firstCounter = 0;  // change counter of the first image
  bool equalsFile = false;         // some image is byte for byte the file's page 1
  std::string otherIdentity;       // an identity other than the file's, when one was seen

  void add(const std::vector<unsigned char>& image, const std::vector<unsigned char>& filePage,
           const std::string& fileIdentity) {
    if (!any) firstCounter = big32(image.data() + 24);
    any = true;
    equalsFile = equalsFile || (!filePage.empty() && image == filePage);
    const std::string identity = identityOf(image);
    if (otherIdentity.empty() && !identity.empty() && !fileIdentity.empty() &&
        identity != fileIdentity) {
      otherIdentity = identity;
    }
  }
  void merge(const PageOneFacts& later) {
    if (!later.any) return;
    if (!any) firstCounter = later.firstCounter;
    any = true;
    equalsFile = equalsFile || later.equalsFile;
    if (otherIdentity.empty()) otherIdentity = later.otherIdentity;
  }
};

// The log's valid frames: those of its current generation (salts) whose running checksum holds,
// up to the last commit frame, as SQLite would apply them. `filePage` (the file's page 1, or
// empty) is compared with every committed page-1 image.
struct WalScan {
  std::int64_t pageSize = 0;
  std::uint32_t checkpointSequence = 0;  // times the log was restarted from its beginning
  std::int64_t commitFrames = 0;
  PageOneFacts pageOnes;
};

WalScan scanWal(const std::filesystem::path& database, const std::vector<unsigned char>& filePage,
                const std::string& fileIdentity) {
  WalScan scan;
  const Fd log(std::filesystem::path(database.string() + "-wal"));
  if (!log.ok() || !log.regular()) return scan;
  const std::int64_t walBytes = log.size();
  unsigned char header[32];
  if (walBytes < 32 || !log.readAt(header, sizeof header, 0)) return scan;
  const std::uint32_t magic = big32(header);
  const std::int64_t pageSize = big32(header + 8);
  if ((magic != kWalMagicLittle && magic != kWalMagicBig) || big32(header + 4) != kWalVersion ||
      pageSize < 512 || pageSize > 65536 || (pageSize & (pageSize - 1)) != 0) {
    return scan;  // SQLite ignores a log without a valid header and starts it afresh
  }
  WalChecksum sum;
  sum.bigEndianWords = magic == kWalMagicBig;
  sum.add(header, 24);
  if (sum.s1 != big32(header + 24) || sum.s2 != big32(header + 28)) return scan;
  const std::uint32_t salt1 = big32(header + 16);
  const std::uint32_t salt2 = big32(header + 20);
  scan.pageSize = pageSize;
  scan.checkpointSequence = big32(header + 12);

  std::vector<unsigned char> frame(static_cast<std::size_t>(24 + pageSize));
  std::vector<unsigned char> image;
  PageOneFacts pending;  // page-1 images since the last commit frame
  std::int64_t frames = 0;
  for (std::int64_t offset = 32; offset + 24 + pageSize <= walBytes; offset += 24 + pageSize) {
    if (!log.readAt(frame.data(), frame.size(), offset)) break;
    if (big32(frame.data() + 8) != salt1 || big32(frame.data() + 12) != salt2) break;
    sum.add(frame.data(), 8);
    sum.add(frame.data() + 24, static_cast<std::size_t>(pageSize));
    if (sum.s1 != big32(frame.data() + 16) || sum.s2 != big32(frame.data() + 20)) break;
    ++frames;
    if (big32(frame.data()) == 1) {
      image.assign(frame.begin() + 24, frame.end());
      pending.add(image, filePage, fileIdentity);
    }
    if (big32(frame.data() + 4) != 0) {  // a commit frame: everything before it is applied
      scan.commitFrames = frames;
      scan.pageOnes.merge(pending);
      pending = PageOneFacts{};
    }
  }
  return scan;
}

}  // namespace

std::int64_t walCommitFrames(const std::filesystem::path& database) {
  return scanWal(database, {}, {}).commitFrames;
}

WalState inspectWal(const std::filesystem::path& database) {
  WalState state;
  if (isOpenInThisProcess(database)) {
    state.kind = WalState::Kind::Live;  // never a descriptor beside a live connection of ours
    return state;
  }
  // The file's header and page 1 first, so the log is read once.
  const Fd file(database);
  const bool fileThere = file.ok() && file.regular();
  unsigned char dbHeader[100] = {};
  const bool headerRead = fileThere && file.readAt(dbHeader, sizeof dbHeader, 0);
  std::vector<unsigned char> pageOne;
  if (headerRead) {
    pageOne.resize(static_cast<std::size_t>(pageSizeOf(dbHeader)));
    if (pageOne.size() < 100 || !file.readAt(pageOne.data(), pageOne.size(), 0)) pageOne.clear();
  }
  const std::string fileIdentity = pageOne.empty() ? std::string() : identityOf(pageOne);
  const WalScan scan = scanWal(database, pageOne, fileIdentity);
  state.commitFrames = scan.commitFrames;
  if (state.commitFrames == 0) return state;

  // A log in use by another process belongs to the file.
  if (otherProcessHasShm(database.string() + "-shm")) {
    state.kind = WalState::Kind::Live;
    return state;
  }
  if (!fileThere || file.size() == 0) {
    // A new database's first commits, before any checkpoint: nothing in the file to lose.
    state.kind = fileThere ? WalState::Kind::Belongs : WalState::Kind::Foreign;
    if (!fileThere) state.reason = "its database file is missing";
    return state;
  }
  if (!headerRead) {
    state.kind = WalState::Kind::Foreign;
    state.reason = "the database file is shorter than its 100-byte header";
    return state;
  }
  if (pageSizeOf(dbHeader) != scan.pageSize) {
    state.kind = WalState::Kind::Foreign;
    state.reason = "the log's pages are " + std::to_string(scan.pageSize) + " bytes, the file's " +
                   std::to_string(pageSizeOf(dbHeader));
    return state;
  }
  const PageOneFacts& facts = scan.pageOnes;
  if (!facts.any) {
    state.kind = WalState::Kind::Unproven;
    return state;
  }
  if (!facts.otherIdentity.empty()) {
    state.kind = WalState::Kind::Foreign;
    state.reason = "the log was written by another database: identity " + facts.otherIdentity +
                   ", the file's " + fileIdentity;
    return state;
  }
  // A connection writes every page-1 image with the change counter it first read plus one; in WAL
  // mode it does not read the counter again while it keeps the page cached. So the file's page 1
  // is either the state the log started from (its counter one below the log's first page 1), or
  // one of the log's own page-1 images (a checkpoint copied it back), or, once the log was
  // restarted after a complete checkpoint, the last image of the log's previous generation: the
  // same connection then goes on writing images with the very counter the checkpoint put into the
  // file. (Refusing that last case would tell a user whose long session was killed to move away
  // a log that holds their newest committed work.)
  const std::uint32_t fileCounter = big32(dbHeader + 24);
  const bool restartedBySameWriter =
      scan.checkpointSequence > 0 && fileCounter == facts.firstCounter;
  if (fileCounter + 1 == facts.firstCounter || facts.equalsFile || restartedBySameWriter) {
    state.kind = WalState::Kind::Belongs;
  } else {
    state.kind = WalState::Kind::Foreign;
    state.reason = "it continues the file at change counter " +
                   std::to_string(facts.firstCounter - 1) + ", but the file is at " +
                   std::to_string(fileCounter);
  }
  return state;
}

bool removeUnusedIndex(const std::filesystem::path& database) {
  const std::filesystem::path shm = database.string() + "-shm";
  if (isOpenInThisProcess(database) || otherProcessHasShm(shm)) return false;
  return ::unlink(shm.c_str()) == 0;
}

std::string foreignWalMessage(const std::filesystem::path& database, const std::string& reason) {
  const std::string name = database.string();
  return "the write-ahead log " + name + "-wal does not belong to this database (" + reason +
         "), so it was not applied and neither file was changed. If " + name +
         " was restored from a backup or copied here, move " + name + "-wal and " + name +
         "-shm away and open it again; if the log holds the newest work, put back the database "
         "file it was written with";
}

std::optional<std::string> truncationProblem(const std::filesystem::path& database) {
  const Fd file(database);
  if (!file.ok() || !file.regular()) return std::nullopt;
  unsigned char header[100];
  const std::int64_t bytes = file.size();
  if (bytes < 100 || !file.readAt(header, sizeof header, 0)) return std::nullopt;
  // The header's page count is valid when its "version-valid-for" equals the change counter.
  if (big32(header + 92) != big32(header + 24)) return std::nullopt;
  const std::int64_t pages = big32(header + 28);
  const std::int64_t pageSize = pageSizeOf(header);
  if (pages == 0 || bytes >= pages * pageSize) return std::nullopt;
  return "cut short: its header says " + std::to_string(pages) + " pages of " +
         std::to_string(pageSize) + " bytes (" + std::to_string(pages * pageSize) +
         " bytes), the file holds " + std::to_string(bytes) +
         "; what lies past the end would read as zeros. Restore it from a backup";
}

}  // namespace tactile::storage::db
