/* SPDX-License-Identifier: MIT */
/* Fault injection for the command-line tests, loaded with LD_PRELOAD: TS_FAIL_RENAME=N makes the
   N-th call of rename() (1-based) fail with ENOSPC, as a directory that cannot grow would;
   TS_FAIL_LINK=1 makes every link() fail with EPERM, as a file system without hard links does.
   Every other call goes to the C library. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdlib.h>

typedef int (*two_paths)(const char*, const char*);

static two_paths next_of(const char* name) { return (two_paths)dlsym(RTLD_NEXT, name); }

int rename(const char* from, const char* to) {
  static int calls;
  const char* at = getenv("TS_FAIL_RENAME");
  if (at && ++calls == atoi(at)) {
    errno = ENOSPC;
    return -1;
  }
  return next_of("rename")(from, to);
}

int link(const char* from, const char* to) {
  const char* fail = getenv("TS_FAIL_LINK");
  if (fail && fail[0] == '1') {
    errno = EPERM;
    return -1;
  }
  return next_of("link")(from, to);
}
