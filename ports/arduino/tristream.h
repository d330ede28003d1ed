/* SPDX-License-Identifier: MIT */
/* The Arduino library's header: the C API of the core (tristream/tristream.h) under the name the
   Arduino builder finds the library by, a header at the top of its src/ folder. */
#ifndef TRISTREAM_ARDUINO_H
#define TRISTREAM_ARDUINO_H

#include "tristream/tristream.h"
#include "tristream/version.h"

#endif
