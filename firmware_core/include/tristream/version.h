/* SPDX-License-Identifier: MIT */
/* The version of tristream (core, C API and tools), in one place: CMakeLists.txt reads it for the
   project version, the CMake package's version file and tristream.pc, and every tool prints it
   for --version. Semantic versioning; 0.x releases may change the API and the blob format. */
#ifndef TRISTREAM_VERSION_H
#define TRISTREAM_VERSION_H

#define TRISTREAM_VERSION "0.1.0"

#endif
