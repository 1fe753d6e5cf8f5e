// The bytes of a file for parsing: memory-mapped when the file is a regular file (no copy, no
// zero-filled buffer), read into memory otherwise (pipes, special files).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

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

// Checks, before any long work, that `path` could be written (docs/cli.md#output-files): a new
// name in an existing folder where a file can be created, a regular file, or a stream (a character
// device, a FIFO, anything under /dev or /proc); not a folder, block device or socket, and not a
// file this process has read as an input. Creates nothing that stays.
Status checkWritable(const std::filesystem::path& path);

// Writes text to `path`. A new name or a regular file is replaced atomically: a temporary file in
// the same folder (created with O_EXCL | O_NOFOLLOW under an unpredictable name), written, synced
// and renamed over it, keeping the replaced file's permission bits; a failure leaves the old file
// and no temporary one. A link at `path` is replaced, never followed. A character device, a FIFO
// or a path under /dev or /proc (/dev/stdout, /dev/null) is written in place as a stream. A
// folder, a block device, a socket or a file read as an input of this process is refused. An
// error names the file.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view text);

// The same, written a piece at a time (a file too large to build in memory first): open(), any
// number of write() calls, commit(). Until commit() the file at `path` is untouched; a failed
// write, or a writer destroyed before commit(), removes the temporary file. A stream is written
// in place as the pieces come. Errors name the file, as writeFileAtomically's do.
class AtomicFileWriter {
 public:
  AtomicFileWriter() = default;
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  Status open(const std::filesystem::path& path);
  Status write(std::string_view bytes);
  Status commit();
  // Drops what was written (a cancelled export); the file at the path stays as it was.
  void abandon();

 private:
  Status failure();

  std::filesystem::path path_;
  std::filesystem::path temp_;  // empty for a stream
  int fd_ = -1;
  int error_ = 0;
};

// Remembers that this process read `path` (by device and inode) once guardInputFiles(true) ran;
// FileText::load, readFileText and the run database's open call it, so no output of a command
// replaces one of its inputs. Off by default: a program that keeps running (the workbench) may
// save over a file it read earlier at the user's request. The command line turns it on.
void guardInputFiles(bool on);
void noteInputFile(const std::filesystem::path& path);

// Refuses an output that is the same file (device and inode) as one of `inputs` or as any file
// this process has read. An error names both.
Status checkNotAnInput(const std::filesystem::path& output,
                       const std::vector<std::filesystem::path>& inputs);

}  // namespace tactile
