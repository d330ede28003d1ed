/* SPDX-License-Identifier: MIT */
#pragma once
// Whole-file writes that never leave a half-written file behind, and whole-file reads with a size limit.
#include <cstdint>
#include <string>
#include <string_view>

#include "io/limits.h"

namespace tristream {

// A file written under a temporary name and renamed over `path` by commit(). The temporary file
// is created exclusively (mkstemp: O_CREAT | O_EXCL, never through a planted link) in the
// directory of the file that is finally replaced; a link at `path` is followed, so the link stays
// and its target is replaced. An existing destination keeps its permission bits (and its owner
// where the process may set it); a new one gets 0666 less the umask. The data is fsync'ed
// before the rename. A destination that exists and is not a regular file (a device, a FIFO) is
// written through, without a temporary file. The temporary file is removed when the object is
// destroyed without commit() and when SIGINT or SIGTERM ends the process meanwhile (if those
// signals have their default action). Every failure, ENOSPC included, throws OutputError
// naming `path` and the system error.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  void write(std::string_view bytes);
  // Flushes what was written to the disk (fsync) before commit(), which then has less to do.
  void sync();
  void commit();

  // The temporary file's name ("" when writing through to a non-regular destination).
  const std::string& temporary_path() const { return tmp_; }
  // The file commit() replaces: the path given, or the target of a link there.
  const std::string& target_path() const { return target_; }
  // Whether the destination is a device or a FIFO, written directly (commit() renames nothing).
  bool written_through() const { return through_; }

 private:
  [[noreturn]] void fail(const std::string& what, int error);  // discards, then throws OutputError
  void discard();                                                  // closes and removes the temporary file

  std::string path_;    // as given, for messages
  std::string target_;  // the file the rename replaces (path_, or a link's target)
  std::string tmp_;
  int fd_ = -1;
  int slot_ = -1;       // index in the signal handler's table of temporary files
  bool through_ = false;  // a non-regular destination, written directly
  bool committed_ = false;
};

// A file name followed by `suffix`, the name cut so that the whole stays within NAME_MAX bytes
// (never inside a UTF-8 sequence): the names of the files written beside a target.
std::string name_with_suffix(const std::string& name, std::string_view suffix);

// AtomicFile(path), write(bytes), commit().
void write_file_atomically(const std::string& path, std::string_view bytes);

// Creates the directory `path` and its missing parents (nothing when it exists). Throws
// OutputError naming `what` and `path` when it cannot, or when `path` is not a directory.
void make_directories(const std::string& path, const std::string& what);

// Reads a whole regular file of at most `max_bytes` bytes. Throws InputError naming the path
// when it cannot be opened or read, is a directory, a device, a FIFO or a socket (which could
// block or never end); DataError when it is larger than `max_bytes` (the message names the limit).
std::string read_file(const std::string& path, std::uint64_t max_bytes = limits::max_input_bytes);

}  // namespace tristream
