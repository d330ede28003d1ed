/* SPDX-License-Identifier: MIT */
#pragma once
// Reading a blob back into the host model: the mesh firmware links, for the reference renderer
// and for measuring it (trisim render|compare|bench of a blob file).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

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
// q8_8 values / 256, triangles in the blob's order and rotation (positively oriented), for
// zienkiewicz the gradients (Mesh::gradients, q19_12 / 4096, so the reference draws with the
// blob's gradients); layer names as a .tri file has them (r g b, y cb cr). pack_blob(tri, method, name, &gradients)
// gives the blob's bytes back.
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

// open_blob, then unpack_blob; an invalid blob throws DataError "<name>: byte N: <status>". A
// compressed blob is expanded first (expand_compressed_or_throw); the checks of the mesh then name
// byte offsets of its expansion, "<name> (expanded to v1): byte N: ...".
UnpackedBlob unpack_blob(std::span<const std::uint8_t> bytes, std::string_view name = "blob");

// A compressed blob (magic "TSTC", tristream/compressed_blob.h) expanded into the v1 blob it
// stands for by the core's own expand_compressed_blob, in buffers of expanded_blob_size and
// expand_workspace_size bytes; the v1 blob renders bit-identically (its vertices are renumbered in
// raster order). Throws DataError "<name>: byte N: <status>" with the offset the decoder reports
// when open_compressed_blob or the stream refuses the bytes. `workspace_bytes`, when given,
// receives the ring the expansion needed (expand_workspace_size).
std::vector<std::uint8_t> expand_compressed_or_throw(std::span<const std::uint8_t> bytes, std::string_view name,
                                                     std::size_t* workspace_bytes = nullptr);

// The bytes of a v1 blob: a compressed blob's expansion (expand_compressed_or_throw), anything
// else as it is (for open_blob to judge).
std::vector<std::uint8_t> v1_blob_bytes(std::span<const std::uint8_t> bytes, std::string_view name);

// Opens `bytes` as a blob; throws DataError "<name>: byte N: <status>" when open_blob refuses it.
core::Blob open_blob_or_throw(std::span<const std::uint8_t> bytes, std::string_view name);

}  // namespace tristream
