/* SPDX-License-Identifier: MIT */
#pragma once
// The message of a blob the core refuses, written once for every host tool that opens one.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "tristream/status.h"

namespace tristream {

// "<name>: byte <offset>: <status_text>", and what the status leaves open: for a checksum
// mismatch the CRC-32 the bytes have against the one the header records; for a v1 blob of
// version 1 (before the checksum) that it must be packed again. `bytes`: the blob as given.
std::string blob_error_message(std::string_view name, std::span<const std::uint8_t> bytes, core::Status status,
                               std::uint32_t offset);

}  // namespace tristream
