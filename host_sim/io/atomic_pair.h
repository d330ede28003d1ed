/* SPDX-License-Identifier: MIT */
#pragma once
// Two files written as one unit (tripack -o x.c: x.h and x.c): both replaced, or neither changed.
#include <string>
#include <string_view>

namespace tristream {

// Writes `first_bytes` to `first` and `second_bytes` to `second` (each as AtomicFile does:
// temporary beside the target, permissions kept, links followed) so that on any failure both
// files are as they were, or absent if they were absent:
// - both temporaries are written and fsync'ed before anything is renamed, so a full disk or a
//   file-size limit (EFBIG) changes nothing;
// - the old `first` is kept under a hard link beside it (a copy in memory where the file system
//   has no hard links) while `first`, then `second` are renamed into place; when the second rename
//   fails, the old `first` is renamed back (or the new one removed if there was none);
// - the renames hold an exclusive flock on the directory of `second` as given, so concurrent
//   writers of the same pair (two tripack runs) commit one after the other and the last one's
//   pair is what stays, never a header of one with the source of the other;
// - SIGINT, SIGTERM, SIGHUP and SIGQUIT are held back from the first rename to the end, so a
//   signal ends the program after the pair is complete or restored.
// A crash of the machine between the two renames can still leave the new `first` beside the old
// `second` (and the link named <first>.old.*): the C pair's compile-time check (c_source.h) catches it.
// A destination that is a device or a FIFO is written through, without that guarantee. Every
// failure throws OutputError naming the file and the system error, and says when `first` was restored.
void write_pair_atomically(const std::string& first, std::string_view first_bytes, const std::string& second,
                           std::string_view second_bytes);

}  // namespace tristream
