// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/errors.h"
#include "io/atomic_file.h"

using namespace tristream;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "tristream_atomic_XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  int entries() const { return int(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("a failed write is reported, ENOSPC included, and /dev/full stays a device") {
  struct stat st {};
  REQUIRE(::stat("/dev/full", &st) == 0);
  REQUIRE(S_ISCHR(st.st_mode));
  CHECK_THROWS_WITH(write_file_atomically("/dev/full", "data"),
                    Catch::Contains("/dev/full") && Catch::Contains("No space left"));
  REQUIRE(::stat("/dev/full", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
}

TEST_CASE("a FIFO destination is written through and stays a FIFO") {
  TempDir dir;
  const std::string fifo = dir / "out.fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  write_file_atomically(fifo, "through the pipe");
  char buf[64] = {};
  const ssize_t n = ::read(reader, buf, sizeof buf);
  ::close(reader);
  CHECK(std::string(buf, n > 0 ? std::size_t(n) : 0) == "through the pipe");
  struct stat st {};
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(dir.entries() == 1);
}

TEST_CASE("a symbolic link destination stays a link and its target is replaced") {
  TempDir dir;
  const std::string target = dir / "target.bin", link = dir / "link.bin";
  write_file_atomically(target, "old");
  fs::create_symlink(target, link);
  write_file_atomically(link, "new");
  CHECK(fs::is_symlink(link));
  CHECK(slurp(target) == "new");
  CHECK(dir.entries() == 2);
  fs::remove(target);
  CHECK_THROWS_AS(write_file_atomically(link, "dangling"), OutputError);
  CHECK(fs::is_symlink(link));
}

TEST_CASE("a link planted at the old predictable temporary name is not followed") {
  TempDir dir;
  const std::string victim = dir / "victim", out = dir / "out.png";
  write_file_atomically(victim, "precious");
  ::chmod(victim.c_str(), 0600);
  fs::create_symlink(victim, out + ".tmp." + std::to_string(::getpid()));
  write_file_atomically(out, "output");
  CHECK(slurp(victim) == "precious");
  CHECK(slurp(out) == "output");
}

TEST_CASE("an existing destination keeps its permissions; a new one gets 0666 less the umask") {
  TempDir dir;
  const std::string out = dir / "out.tri";
  write_file_atomically(out, "one");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat st {};
  REQUIRE(::stat(out.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == (0666 & ~mask));
  REQUIRE(::chmod(out.c_str(), 0640) == 0);
  write_file_atomically(out, "two");
  REQUIRE(::stat(out.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0640);
  CHECK(slurp(out) == "two");
}

TEST_CASE("a directory destination is refused; nothing is left behind") {
  TempDir dir;
  fs::create_directory(dir / "sub");
  CHECK_THROWS_WITH(write_file_atomically(dir / "sub", "x"), Catch::Contains("directory"));
  CHECK_THROWS_AS(write_file_atomically(dir / "missing/x", "x"), OutputError);
  CHECK(dir.entries() == 1);
}

TEST_CASE("an abandoned file leaves the destination as it was and no temporary file") {
  TempDir dir;
  const std::string out = dir / "out.bin";
  write_file_atomically(out, "kept");
  {
    AtomicFile f(out);
    f.write("half");
    CHECK(fs::exists(f.temporary_path()));
    CHECK(fs::path(f.temporary_path()).parent_path() == dir.path);
  }
  CHECK(slurp(out) == "kept");
  CHECK(dir.entries() == 1);
}

TEST_CASE("SIGTERM, SIGINT, SIGHUP or SIGQUIT during a write removes the temporary file") {
  for (int sig : {SIGTERM, SIGINT, SIGHUP, SIGQUIT}) {
    TempDir dir;
    const std::string out = dir / "out.png";
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      const struct rlimit no_core {0, 0};
      ::setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT's default action dumps core
      ::signal(sig, SIG_DFL);
      AtomicFile f(out);
      f.write("partial");
      ::raise(sig);
      ::_exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(dir.entries() == 0);
  }
}

TEST_CASE("a file-size limit fails the write (EFBIG) instead of killing the program") {
  TempDir dir;
  const std::string out = dir / "out.bin";
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_DFL);
    const struct rlimit limit {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_file_atomically(out, std::string(10000, 'x'));
    } catch (const OutputError& e) {
      ::_exit(std::string(e.what()).find("File too large") != std::string::npos ? 3 : 4);
    }
    ::_exit(5);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));  // not killed by SIGXFSZ
  CHECK(WEXITSTATUS(status) == 3);
  CHECK(dir.entries() == 0);
}

TEST_CASE("an output name of NAME_MAX bytes is written: the temporary's name is cut to fit") {
  TempDir dir;
  for (std::size_t n : {std::size_t(244), std::size_t(245), std::size_t(NAME_MAX)}) {
    const std::string out = dir / std::string(n, 'n');
    {
      AtomicFile f(out);
      f.write("x");
      CHECK(fs::path(f.temporary_path()).filename().string().size() <= NAME_MAX);
      CHECK(fs::path(f.temporary_path()).parent_path() == dir.path);
      f.commit();
    }
    CHECK(slurp(out) == "x");
    fs::remove(out);
  }
  // A name of multi-byte characters is cut at a character's boundary.
  std::string utf8 = "a";  // then U+00E9 (two bytes) up to NAME_MAX: the cut falls inside one
  while (utf8.size() + 2 <= NAME_MAX) utf8 += "\xc3\xa9";
  AtomicFile f(dir / utf8);
  const std::string tmp_name = fs::path(f.temporary_path()).filename().string();
  const std::string kept = tmp_name.substr(0, tmp_name.size() - std::string(".tmp.XXXXXX").size());
  CHECK(kept.size() % 2 == 1);
  CHECK(kept.size() + 1 == NAME_MAX - std::string(".tmp.XXXXXX").size());
  CHECK(utf8.compare(0, kept.size(), kept) == 0);
}

TEST_CASE("read_file refuses directories, FIFOs and files over the limit") {
  TempDir dir;
  CHECK_THROWS_WITH(read_file(dir.path.string()), Catch::Contains("directory"));
  CHECK_THROWS_AS(read_file(dir.path.string()), InputError);
  const std::string fifo = dir / "in.fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(read_file(fifo), Catch::Contains("not a regular file"));  // and does not block
  CHECK_THROWS_AS(read_file("/dev/zero"), InputError);
  const std::string big = dir / "big";
  write_file_atomically(big, std::string(101, 'x'));
  CHECK(read_file(big, 101).size() == 101);
  CHECK_THROWS_AS(read_file(big, 100), DataError);
  CHECK_THROWS_WITH(read_file(big, 100), Catch::Contains("at most 100 bytes") && Catch::Contains("limit"));
  write_file_atomically(big, "");
  CHECK(read_file(big).empty());
}
