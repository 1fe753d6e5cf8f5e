#include "sim/file_text.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <utility>

#include "sim/run_csv.h"

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

bool FileText::load(const std::filesystem::path& path, std::string& error) {
  release();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
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
      return true;
    }
  }
  ::close(fd);
  // Empty files, pipes, and anything mmap refuses are read the ordinary way.
  return readFileText(path, buffer_, error);
}

}  // namespace tactile
