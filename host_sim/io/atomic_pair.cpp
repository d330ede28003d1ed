// SPDX-License-Identifier: MIT
#include "io/atomic_pair.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <random>

#include "common/errors.h"
#include "io/atomic_file.h"

namespace tristream {
namespace {

std::string directory_of(const std::string& path) {
  const std::filesystem::path p(path);
  return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

// An exclusive flock on a directory, released when the object goes. A file system without locks
// (flock fails) leaves the pair unserialized, as it would be without this.
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ < 0) return;
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock() {
    if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
  }

 private:
  int fd_;
};

// The ending signals held back while the pair is committed; the old mask is restored on exit, and
// a signal that came meanwhile is then delivered.
class HeldSignals {
 public:
  HeldSignals() {
    sigset_t block;
    sigemptyset(&block);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&block, sig);
    ::sigprocmask(SIG_BLOCK, &block, &old_);
  }
  HeldSignals(const HeldSignals&) = delete;
  HeldSignals& operator=(const HeldSignals&) = delete;
  ~HeldSignals() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

// The old contents of a file while its replacement is committed: a hard link beside it, or (where
// the file system refuses hard links) its bytes. Nothing when the file did not exist.
class Backup {
 public:
  explicit Backup(const std::string& target) : target_(target) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) return;  // no old file: restoring removes the new one
    existed_ = true;
    const std::filesystem::path t(target);
    std::mt19937 random(std::random_device{}());
    for (int attempt = 0; attempt < 100; ++attempt) {
      std::string suffix = ".old.";
      for (int k = 0; k < 6; ++k) suffix += "abcdefghijklmnopqrstuvwxyz0123456789"[random() % 36];
      const std::string name =
          (std::filesystem::path(directory_of(target)) / name_with_suffix(t.filename().string(), suffix)).string();
      if (::link(target.c_str(), name.c_str()) == 0) {
        link_ = name;
        return;
      }
      if (errno != EEXIST) break;
    }
    try {
      bytes_ = read_file(target);
    } catch (const std::exception& e) {
      throw OutputError(target + ": cannot keep the old file while its replacement is written (" + e.what() + ")");
    }
  }
  Backup(const Backup&) = delete;
  Backup& operator=(const Backup&) = delete;
  ~Backup() {
    if (!link_.empty()) ::unlink(link_.c_str());
  }

  // Puts the old file back (removes the new one if there was none); "" or what failed.
  std::string restore() {
    if (!existed_) return ::unlink(target_.c_str()) == 0 ? "" : std::strerror(errno);
    if (!link_.empty()) {
      if (::rename(link_.c_str(), target_.c_str()) != 0) return std::strerror(errno);
      link_.clear();
      return "";
    }
    try {
      write_file_atomically(target_, *bytes_);
    } catch (const OutputError& e) {
      return e.what();
    }
    return "";
  }

 private:
  std::string target_;
  bool existed_ = false;
  std::string link_;                  // the hard link to the old file
  std::optional<std::string> bytes_;  // or its bytes
};

}  // namespace

void write_pair_atomically(const std::string& first, std::string_view first_bytes, const std::string& second,
                           std::string_view second_bytes) {
  AtomicFile a(first), b(second);
  a.write(first_bytes);
  b.write(second_bytes);
  a.sync();
  b.sync();
  const DirectoryLock lock(directory_of(second));
  const HeldSignals held;
  std::optional<Backup> old_first;
  if (!a.written_through() && !b.written_through()) old_first.emplace(a.target_path());
  a.commit();
  try {
    b.commit();
  } catch (const OutputError& e) {
    if (!old_first) throw;
    const std::string failed = old_first->restore();
    if (failed.empty()) throw OutputError(std::string(e.what()) + "; " + first + " is as it was");
    throw OutputError(std::string(e.what()) + "; " + first + " could not be restored (" + failed +
                      "): it belongs to the new " + second + ", which was not written");
  }
}

}  // namespace tristream
