/* SPDX-License-Identifier: MIT */
#pragma once
// Reading a blob back into the host model: the mesh firmware links, for the reference renderer
// and for measuring it (trisim render|compare|bench of a blob file).
#include <cstdint>
#include <span>
#include <string_view>

#include "core_bridge/pack.h"
#include "model/triangulation.h"
#include "tristream/blob.h"

namespace tristream {

// Whether `bytes` are meant as a blob rather than a .tri text: open_blob recognizes their magic
// (it reports anything but bad_magic), or they start with "TST" (the blobs' magics "TSTB" and
// "TSTC"; a .tri starts with "tri", a comment or a BOM). Decided by the content, never by the
// file name, so any variant open_blob accepts is taken, and one it does not is refused as a blob.
bool is_blob(std::span<const std::uint8_t> bytes);

// The mesh a blob draws. Positions are the blob's fixed-point positions in pixels, values its
// q8_8 values / 256, triangles in the blob's order and rotation (positively oriented); layer names
// as a .tri file has them (r g b, y cb cr). pack_blob(tri, method, name, &gradients) gives the
// blob's bytes back.
struct UnpackedBlob {
  Triangulation tri;
  core::Method method = core::Method::bilinear;
  BlobGradients gradients;  // zienkiewicz: per layer, per vertex and value gx, gy (q19_12); else empty
};

// Reads an opened blob. Throws DataError ("<name>: byte N: ...") when the mesh cannot be drawn by
// the reference: two vertices at one position, triangles whose interiors overlap or that do not
// meet edge to edge (open_blob does not check these), or sections the core validated but this
// reader cannot see (a blob variant without in-place v1 sections).
UnpackedBlob unpack_blob(const core::Blob& blob, std::string_view name = "blob");

// open_blob, then unpack_blob; an invalid blob throws DataError "<name>: byte N: <status>".
UnpackedBlob unpack_blob(std::span<const std::uint8_t> bytes, std::string_view name = "blob");

// Opens `bytes` as a blob; throws DataError "<name>: byte N: <status>" when open_blob refuses it.
core::Blob open_blob_or_throw(std::span<const std::uint8_t> bytes, std::string_view name);

}  // namespace tristream
