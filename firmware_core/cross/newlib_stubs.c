/* SPDX-License-Identifier: MIT */
/* libstdc++'s random_device refers to getentropy, which newlib's semihosting library lacks;
   Catch2 links it in. The test never asks for entropy. */
#include <errno.h>
#include <stddef.h>
int getentropy(void* buffer, size_t length) {
  (void)buffer;
  (void)length;
  errno = ENOSYS;
  return -1;
}
