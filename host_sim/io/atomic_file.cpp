// SPDX-License-Identifier: MIT
#include "io/atomic_file.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "common/errors.h"

namespace tristream {
namespace {

// Temporary files the signal handler removes. A slot is filled, then marked in use; the handler
// reads only slots in use, and only calls async-signal-safe functions (unlink, sigaction, raise).
constexpr int max_open_files = 8;
struct Slot {
  char path[PATH_MAX];
  volatile sig_atomic_t in_use;
};
Slot g_slots[max_open_files];

extern "C" void remove_temporaries_and_die(int sig) {
  for (Slot& s : g_slots)
    if (s.in_use) ::unlink(s.path);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

// The signals whose default action ends the program while a temporary may exist.
constexpr int ending_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// Installs the handler for each ending signal that still has its default action (a signal the
// caller ignores or handles is left alone), and ignores SIGXFSZ: past a file-size limit
// (ulimit -f) write then fails with EFBIG, which is reported and cleaned up like a full disk
// instead of killing the tool with its temporary left behind. Checked on every file: cheap, and
// it sees a disposition the program changed meanwhile.
void install_handlers() {
  for (int sig : ending_signals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = remove_temporaries_and_die;
    sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
  struct sigaction old {};
  if (::sigaction(SIGXFSZ, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) {
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    ::sigaction(SIGXFSZ, &ign, nullptr);
  }
}

// The temporary's name beside the target: the suffix ".tmp.XXXXXX" after the target's name, cut
// to keep it within NAME_MAX (a valid target name of up to NAME_MAX bytes can be written).
std::string temporary_name(const std::string& target_name) { return name_with_suffix(target_name, ".tmp.XXXXXX"); }

int claim_slot(const std::string& tmp) {
  if (tmp.size() >= PATH_MAX) return -1;
  for (int i = 0; i < max_open_files; ++i)
    if (!g_slots[i].in_use) {
      std::memcpy(g_slots[i].path, tmp.c_str(), tmp.size() + 1);
      g_slots[i].in_use = 1;
      return i;
    }
  return -1;  // more files open at once than slots: still written, only not removed on a signal
}

std::string errno_text(int error) { return std::strerror(error); }

bool write_all(int fd, std::string_view bytes, int& error) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      error = errno;
      return false;
    }
    bytes.remove_prefix(std::size_t(n));
  }
  return true;
}

}  // namespace

std::string name_with_suffix(const std::string& name, std::string_view suffix) {
  std::size_t keep = std::min(name.size(), std::size_t(NAME_MAX) - std::min(suffix.size(), std::size_t(NAME_MAX)));
  while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
  return name.substr(0, keep) + std::string(suffix);
}

AtomicFile::AtomicFile(const std::string& path) : path_(path), target_(path) {
  namespace fs = std::filesystem;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail("cannot write: it is a directory", 0);
    if (!S_ISREG(st.st_mode)) {  // a device or a FIFO: written through, there is nothing to replace
      fd_ = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd_ < 0) fail("cannot write", errno);
      through_ = true;
      return;
    }
    struct stat lst {};
    if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
      char resolved[PATH_MAX];
      if (!::realpath(path.c_str(), resolved)) fail("cannot write: cannot resolve the link", errno);
      target_ = resolved;
    }
  } else {
    const int e = errno;
    struct stat lst {};
    if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode))
      fail("cannot write: it is a symbolic link to a missing file", 0);
    if (e != ENOENT) fail("cannot write", e);
  }
  const fs::path target(target_);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string tmpl = (dir / temporary_name(target.filename().string())).string();
  install_handlers();
  // Signals are blocked while the name is created and registered, so no handler runs between
  // the two and misses the file.
  sigset_t block, old;
  sigemptyset(&block);
  for (int sig : ending_signals) sigaddset(&block, sig);
  ::sigprocmask(SIG_BLOCK, &block, &old);
  fd_ = ::mkostemp(tmpl.data(), O_CLOEXEC);
  const int e = errno;
  if (fd_ >= 0) {
    tmp_ = tmpl;
    slot_ = claim_slot(tmp_);
  }
  ::sigprocmask(SIG_SETMASK, &old, nullptr);
  if (fd_ < 0) fail("cannot write", e);
  if (::stat(target_.c_str(), &st) == 0) {
    if (::fchown(fd_, st.st_uid, st.st_gid) != 0) {
      // Only root (or the owner, for the group) may; the file then belongs to the writer.
    }
    if (::fchmod(fd_, st.st_mode & 07777) != 0) fail("cannot set the permissions of the temporary file", errno);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd_, 0666 & ~mask) != 0) fail("cannot set the permissions of the temporary file", errno);
  }
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
  tmp_.clear();
  if (slot_ >= 0) g_slots[slot_].in_use = 0;
  slot_ = -1;
}

void AtomicFile::fail(const std::string& what, int error) {
  discard();
  std::string message = path_ + ": " + what;
  if (error) message += " (" + errno_text(error) + ")";
  throw OutputError(message);
}

void AtomicFile::write(std::string_view bytes) {
  int e = 0;
  if (!write_all(fd_, bytes, e)) fail("write failed", e);
}

void AtomicFile::sync() {
  if (fd_ < 0) fail("write failed", EBADF);
  if (!through_ && ::fsync(fd_) != 0) fail("write failed (fsync)", errno);
}

void AtomicFile::commit() {
  if (fd_ < 0) fail("write failed", EBADF);
  if (through_) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("write failed", errno);
    committed_ = true;
    return;
  }
  if (::fsync(fd_) != 0) fail("write failed (fsync)", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("write failed", errno);
  if (::rename(tmp_.c_str(), target_.c_str()) != 0) fail("cannot rename the temporary file", errno);
  committed_ = true;
  if (slot_ >= 0) g_slots[slot_].in_use = 0;
  slot_ = -1;
  // The rename is durable once the directory is synced; a directory that cannot be synced
  // (some file systems refuse) does not make the write fail.
  const std::filesystem::path target(target_);
  const std::string dir = target.has_parent_path() ? target.parent_path().string() : ".";
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  AtomicFile f(path);
  f.write(bytes);
  f.commit();
}

void make_directories(const std::string& path, const std::string& what) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) throw OutputError(what + ": " + path + ": cannot create the directory (" + ec.message() + ")");
  if (!std::filesystem::is_directory(path, ec))
    throw OutputError(what + ": " + path + ": cannot write into it: not a directory");
}

std::string read_file(const std::string& path, std::uint64_t max_bytes) {
  // O_NONBLOCK: opening a FIFO without a writer must not block (it is refused below).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open (" + errno_text(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw InputError(path + ": cannot open (" + errno_text(errno) + ")");
  if (S_ISDIR(st.st_mode)) throw InputError(path + ": cannot read: it is a directory, expected a file");
  if (!S_ISREG(st.st_mode))
    throw InputError(path + ": cannot read: not a regular file (devices, FIFOs and sockets are not read)");
  auto too_large = [&](std::uint64_t size) {
    return DataError(path + ": expected an input file of at most " + std::to_string(max_bytes) +
                     " bytes (the limit for an input file), found " + std::to_string(size) + " bytes");
  };
  if (std::uint64_t(st.st_size) > max_bytes) throw too_large(std::uint64_t(st.st_size));
  std::string out(std::size_t(st.st_size), '\0');
  std::size_t have = 0;
  while (true) {
    if (have == out.size()) {  // the file may have grown since fstat
      if (out.size() >= max_bytes) {
        char probe;
        const ssize_t n = ::read(fd, &probe, 1);
        if (n == 0) break;
        if (n > 0) throw too_large(out.size() + 1);
        if (errno == EINTR) continue;
        throw InputError(path + ": read failed (" + errno_text(errno) + ")");
      }
      out.resize(std::min<std::uint64_t>(max_bytes, out.size() + 65536));
    }
    const ssize_t n = ::read(fd, out.data() + have, out.size() - have);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path + ": read failed (" + errno_text(errno) + ")");
    }
    if (n == 0) break;
    have += std::size_t(n);
  }
  out.resize(have);
  return out;
}

}  // namespace tristream
