#include "base/file_text.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

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

Status writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
  std::filesystem::path temp = path;
  static std::atomic<unsigned> counter{0};
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (f == nullptr) {
    return Error(path.string(), std::string("cannot write: ") + std::strerror(errno));
  }
  const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const bool closed = std::fclose(f) == 0;
  std::error_code ec;
  if (!wrote || !closed) {
    std::filesystem::remove(temp, ec);
    return Error(path.string(), "write failed (disk full?)");
  }
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    return Error(path.string(), "cannot replace the file: " + ec.message());
  }
  return {};
}

Status checkWritable(const std::filesystem::path& path) {
  std::error_code ec;
  if (path.empty()) return Error("an output path is empty");
  if (std::filesystem::is_directory(path, ec)) return Error(path.string(), "is a folder");
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  if (!std::filesystem::is_directory(folder, ec)) {
    return Error(path.string(), "cannot write: no folder " + folder.string());
  }
  std::filesystem::path probe = folder;
  probe /= ".tactile-write-check-" + std::to_string(::getpid());
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (f == nullptr)
    return Error(path.string(), std::string("cannot write: ") + std::strerror(errno));
  std::fclose(f);
  std::filesystem::remove(probe, ec);
  return Status::success();
}

}  // namespace tactile
