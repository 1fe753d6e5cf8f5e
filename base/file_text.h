// The bytes of a file for parsing: memory-mapped when the file is a regular file (no copy, no
// zero-filled buffer), read into memory otherwise (pipes, special files).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "base/error.h"

namespace tactile {

class FileText {
 public:
  FileText() = default;
  FileText(FileText&& other) noexcept;
  FileText& operator=(FileText&& other) noexcept;
  FileText(const FileText&) = delete;
  FileText& operator=(const FileText&) = delete;
  ~FileText();

  // Loads `path`; an error names it ("FILE: cannot open: ...").
  Status load(const std::filesystem::path& path);

  std::string_view view() const {
    return mapped_ != nullptr ? std::string_view(static_cast<const char*>(mapped_), mappedSize_)
                              : std::string_view(buffer_);
  }

 private:
  void release();

  void* mapped_ = nullptr;
  std::size_t mappedSize_ = 0;
  std::string buffer_;
};

// Reads a whole file into memory; an error names the file.
Result<std::string> readFileText(const std::filesystem::path& path);

// Checks, before any long work, that `path` could be written: its folder exists and a file can be
// created in it, and the path is not a folder. Creates nothing that stays.
Status checkWritable(const std::filesystem::path& path);

// Writes text atomically (temporary file, then rename): a failure never leaves a partial file. An
// error names the file.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace tactile
