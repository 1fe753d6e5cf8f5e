#include "base/file_text.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <random>
#include <utility>
#include <vector>

namespace tactile {

FileText::FileText(FileText&& other) noexcept
    : mapped_(std::exchange(other.mapped_, nullptr)),
      mappedSize_(std::exchange(other.mappedSize_, 0)),
      buffer_(std::move(other.buffer_)) {}

FileText& FileText::operator=(FileText&& other) noexcept {
  if (this != &other) {
    release();
    mapped_ = std::exchange(other.mapped_, nullptr);
    mappedSize_ = std::exchange(other.mappedSize_, 0);
    buffer_ = std::move(other.buffer_);
  }
  return *this;
}

FileText::~FileText() {
  release();
}

void FileText::release() {
  if (mapped_ != nullptr) ::munmap(mapped_, mappedSize_);
  mapped_ = nullptr;
  mappedSize_ = 0;
  buffer_.clear();
}

Status FileText::load(const std::filesystem::path& path) {
  release();
  noteInputFile(path);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Error(path.string(), std::string("cannot open: ") + std::strerror(errno));
  struct stat info {};
  const bool regular = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0;
  if (regular) {
    void* p = ::mmap(nullptr, static_cast<std::size_t>(info.st_size), PROT_READ,
                     MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p != MAP_FAILED) {
      ::madvise(p, static_cast<std::size_t>(info.st_size), MADV_SEQUENTIAL);
      mapped_ = p;
      mappedSize_ = static_cast<std::size_t>(info.st_size);
      ::close(fd);
      return Status::success();
    }
  }
  ::close(fd);
  // Empty files, pipes, and anything mmap refuses are read the ordinary way.
  Result<std::string> text = readFileText(path);
  if (!text) return text.error();
  buffer_ = std::move(text.value());
  return Status::success();
}

Result<std::string> readFileText(const std::filesystem::path& path) {
  noteInputFile(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr)
    return Error(path.string(), std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  try {
    if (!ec) text.resize(size);
    std::size_t got = ec ? 0 : std::fread(text.data(), 1, text.size(), f);
    // Files that grow while read, or report no size (pipes), are read to the end.
    char buffer[65536];
    text.resize(got);
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, f))
      text.append(buffer, n);
  } catch (const std::exception&) {  // std::bad_alloc, std::length_error
    const std::size_t got = text.size();
    std::fclose(f);
    return Error(path.string(), "too large to read into memory (out of memory after " +
                                    std::to_string(got) + " bytes)");
  }
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return Error(path.string(), "read error");
  return text;
}

namespace {

// Files this process has read as inputs (device and inode), so that an output never replaces one.
std::mutex gInputsMutex;
std::vector<std::pair<dev_t, ino_t>>& inputFiles() {
  static std::vector<std::pair<dev_t, ino_t>> files;
  return files;
}

std::atomic<bool> gGuardInputs{false};

bool isInputFile(const struct stat& info) {
  std::lock_guard lock(gInputsMutex);
  for (const auto& [device, inode] : inputFiles()) {
    if (device == info.st_dev && inode == info.st_ino) return true;
  }
  return false;
}

std::string errnoText(int error) {
  return error == 0 ? std::string("unknown error") : std::string(std::strerror(error));
}

// Writes all of `text` to `fd`; the errno of a failure, or 0.
int writeAll(int fd, std::string_view text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// Paths under /dev and /proc are streams (a terminal, a pipe behind /dev/stdout): never replaced.
bool isSystemPath(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  if (ec) return false;
  const std::string text = absolute.lexically_normal().string();
  return text.rfind("/dev/", 0) == 0 || text.rfind("/proc/", 0) == 0;
}

// What `--out` names: a new name or a regular file (replaced atomically), a stream (a character
// device, a FIFO, /dev/stdout: written in place), or something refused.
enum class Target { Replace, Stream, Refuse };

struct TargetInfo {
  Target kind = Target::Replace;
  bool exists = false;
  struct stat info {};  // of the regular file replaced
  std::string refusal;
};

TargetInfo classifyTarget(const std::filesystem::path& path) {
  TargetInfo target;
  struct stat link {};
  if (::lstat(path.c_str(), &link) != 0) {
    if (errno != ENOENT) {
      target.kind = Target::Refuse;
      target.refusal = "cannot write: " + errnoText(errno);
    }
    return target;  // a new name
  }
  struct stat info {};
  const bool resolved = ::stat(path.c_str(), &info) == 0;
  if (S_ISLNK(link.st_mode) && (!resolved || S_ISREG(info.st_mode)) && !isSystemPath(path)) {
    return target;  // an ordinary link: the link is replaced by the new file, never followed
  }
  if (!resolved) info = link;
  if (S_ISDIR(info.st_mode)) {
    target.kind = Target::Refuse;
    target.refusal = "is a folder, not a file";
  } else if (S_ISBLK(info.st_mode)) {
    target.kind = Target::Refuse;
    target.refusal = "is a block device (a disk); not written";
  } else if (S_ISSOCK(info.st_mode)) {
    target.kind = Target::Refuse;
    target.refusal = "is a socket; not written";
  } else if (S_ISCHR(info.st_mode) || S_ISFIFO(info.st_mode) || isSystemPath(path)) {
    target.kind = Target::Stream;
    target.info = info;
  } else {
    target.exists = true;
    target.info = info;
  }
  return target;
}

}  // namespace

void guardInputFiles(bool on) {
  gGuardInputs = on;
}

void noteInputFile(const std::filesystem::path& path) {
  if (!gGuardInputs) return;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return;
  std::lock_guard lock(gInputsMutex);
  for (const auto& [device, inode] : inputFiles()) {
    if (device == info.st_dev && inode == info.st_ino) return;
  }
  inputFiles().emplace_back(info.st_dev, info.st_ino);
}

Status checkNotAnInput(const std::filesystem::path& output,
                       const std::vector<std::filesystem::path>& inputs) {
  struct stat out {};
  if (output.empty() || ::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) return {};
  for (const std::filesystem::path& input : inputs) {
    struct stat in {};
    if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino) {
      return Error(output.string(), "is also an input (" + input.string() +
                                        "); writing it would destroy that input. Choose "
                                        "another output file");
    }
  }
  if (isInputFile(out)) {
    return Error(output.string(),
                 "was read as an input of this command; writing it would destroy that input. "
                 "Choose another output file");
  }
  return {};
}

AtomicFileWriter::~AtomicFileWriter() {
  abandon();
}

void AtomicFileWriter::abandon() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

Status AtomicFileWriter::open(const std::filesystem::path& path) {
  abandon();
  path_ = path;
  error_ = 0;
  if (path.empty()) return Error("an output path is empty");
  const TargetInfo target = classifyTarget(path);
  if (target.kind == Target::Refuse) return Error(path.string(), target.refusal);
  if (Status notInput = checkNotAnInput(path, {}); !notInput) return notInput;
  if (target.kind == Target::Stream) {
    fd_ = ::open(path.c_str(),
                 O_WRONLY | O_CLOEXEC | O_NOCTTY | (S_ISREG(target.info.st_mode) ? O_TRUNC : 0));
    if (fd_ < 0) return Error(path.string(), "cannot write: " + errnoText(errno));
    return {};
  }
  // The temporary file: in the target's folder (so the rename is atomic), created afresh with
  // O_EXCL | O_NOFOLLOW under a name nobody can predict, so a link planted there is never written
  // through (another name is tried).
  static std::atomic<unsigned> counter{0};
  std::random_device random;
  std::filesystem::path temp;
  for (int attempt = 0; attempt < 64 && fd_ < 0; ++attempt) {
    char suffix[48];
    std::snprintf(suffix, sizeof suffix, ".tmp-%d-%u-%08x", static_cast<int>(::getpid()), counter++,
                  random());
    temp = path;
    temp += suffix;
    fd_ = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) {
      return Error(path.string(), "cannot write: " + errnoText(errno));
    }
  }
  if (fd_ < 0) return Error(path.string(), "cannot create a temporary file beside it");
  temp_ = temp;
  // The file replaced keeps its permission bits (and, for root, its owner).
  if (target.exists) {
    (void)::fchmod(fd_, target.info.st_mode & 07777);
    if (::geteuid() == 0) (void)::fchown(fd_, target.info.st_uid, target.info.st_gid);
  }
  return {};
}

Status AtomicFileWriter::write(std::string_view bytes) {
  if (fd_ < 0) return Error(path_.string(), "write failed: the file is not open");
  if (error_ == 0) error_ = writeAll(fd_, bytes);
  if (error_ != 0) return failure();
  return {};
}

Status AtomicFileWriter::failure() {
  const int error = error_;
  const bool stream = temp_.empty();
  abandon();
  if (stream) return Error(path_.string(), "write failed: " + errnoText(error));
  if (error == ENOSPC || error == EFBIG || error == EDQUOT) {
    return Error(path_.string(), "write failed (" + errnoText(error) + "); left unchanged");
  }
  return Error(path_.string(), "write failed: " + errnoText(error) + "; left unchanged");
}

Status AtomicFileWriter::commit() {
  if (fd_ < 0) return Error(path_.string(), "write failed: the file is not open");
  if (temp_.empty()) {
    // A stream: written in place.
    ::close(fd_);
    fd_ = -1;
    return {};
  }
  if (error_ == 0 && ::fsync(fd_) != 0) error_ = errno;
  if (::close(fd_) != 0 && error_ == 0) error_ = errno;
  fd_ = -1;
  if (error_ != 0) return failure();
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    abandon();
    return Error(path_.string(), "cannot replace the file: " + errnoText(error));
  }
  temp_.clear();
  return {};
}

Status writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
  AtomicFileWriter file;
  if (Status opened = file.open(path); !opened) return opened;
  if (Status written = file.write(text); !written) return written;
  return file.commit();
}

Status checkWritable(const std::filesystem::path& path) {
  if (path.empty()) return Error("an output path is empty");
  const TargetInfo target = classifyTarget(path);
  if (target.kind == Target::Refuse) return Error(path.string(), target.refusal);
  if (Status notInput = checkNotAnInput(path, {}); !notInput) return notInput;
  if (target.kind == Target::Stream) {
    if (::access(path.c_str(), W_OK) != 0) {
      return Error(path.string(), "cannot write: " + errnoText(errno));
    }
    return {};
  }
  std::error_code ec;
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  if (!std::filesystem::is_directory(folder, ec)) {
    return Error(path.string(), "cannot write: no folder " + folder.string());
  }
  // A file can be created there (the check leaves nothing behind).
  std::filesystem::path probe = folder;
  probe /= ".tactile-write-check-" + std::to_string(::getpid()) + "-" +
           std::to_string(std::random_device{}());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return Error(path.string(), "cannot write: " + errnoText(errno));
  ::close(fd);
  ::unlink(probe.c_str());
  return {};
}

}  // namespace tactile
