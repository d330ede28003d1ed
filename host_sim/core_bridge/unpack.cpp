// SPDX-License-Identifier: MIT
#include "core_bridge/unpack.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "common/errors.h"
#include "core_bridge/blob_error.h"
#include "geometry/mesh_check.h"
#include "tristream/compressed_blob.h"
#include "tristream/config.h"
#include "bytes.h"
#include "wire_layout.h"

namespace tristream {

namespace {

constexpr double position_scale = 1.0 / double(1 << core::config::subpixel_bits);

ColorSpace host_space(core::ColorSpace s) {
  return s == core::ColorSpace::grey ? ColorSpace::grey : s == core::ColorSpace::rgb ? ColorSpace::rgb : ColorSpace::ycbcr;
}

const char* layer_name(ColorSpace space, std::size_t layer) {
  static const char* const rgb[] = {"r", "g", "b"};
  static const char* const ycbcr[] = {"y", "cb", "cr"};
  return space == ColorSpace::rgb ? rgb[layer] : ycbcr[layer];
}

std::string at_byte(std::string_view name, const core::Blob& blob, const std::uint8_t* p) {
  return std::string(name) + ": byte " + std::to_string(p - blob.bytes);
}

// The checks of the .tri reader that open_blob leaves out: distinct positions among the vertices
// triangles use, interiors that do not overlap, edge to edge.
void check_drawable(const Mesh& mesh, const core::BlobLayer& layer, const core::Blob& blob, std::string_view name) {
  std::vector<std::uint32_t> order = mesh.used_vertices();
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Point &p = mesh.points[a], &q = mesh.points[b];
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && a < b)));
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Point &p = mesh.points[order[k - 1]], &q = mesh.points[order[k]];
    if (p.x == q.x && p.y == q.y)
      throw DataError(at_byte(name, blob, layer.positions + core::wire::position::bytes * order[k]) + ": expected distinct vertex positions, found vertex " +
                      std::to_string(order[k]) + " at the position of vertex " + std::to_string(order[k - 1]));
  }
  const auto defect = find_mesh_defect(mesh.points, mesh.triangles);
  if (!defect) return;
  const std::uint8_t* second = layer.triangles + core::wire::triangle::bytes * std::max(defect->a, defect->b);
  if (defect->kind == MeshDefect::Kind::overlap)
    throw DataError(at_byte(name, blob, second) + ": expected triangles whose interiors do not overlap, found triangle " +
                    std::to_string(std::max(defect->a, defect->b)) + " overlapping triangle " +
                    std::to_string(std::min(defect->a, defect->b)));
  throw DataError(at_byte(name, blob, layer.triangles + core::wire::triangle::bytes * defect->a) +
                  ": expected triangles that meet edge to edge, found vertex " + std::to_string(defect->vertex) +
                  " inside an edge of triangle " + std::to_string(defect->a));
}

}  // namespace

bool is_blob(std::span<const std::uint8_t> bytes) {
  // TSTB, TSTC: never .tri text
  if (bytes.size() >= 3 && std::memcmp(bytes.data(), core::wire::v1_magic, 3) == 0) return true;
  static_assert(core::wire::v1_magic[2] == core::wire::compressed_magic[2], "the magics share 3 bytes");
  core::Blob blob;
  core::BlobError error;
  const core::Status s = core::open_blob(bytes.data(), bytes.size(), &blob, &error);
  return s != core::Status::bad_magic && s != core::Status::truncated && s != core::Status::null_argument;
}

core::Blob open_blob_or_throw(std::span<const std::uint8_t> bytes, std::string_view name) {
  core::Blob blob;
  core::BlobError error;
  const core::Status s = core::open_blob(bytes.data(), bytes.size(), &blob, &error);
  if (s != core::Status::ok) throw DataError(blob_error_message(name, bytes, s, error.offset));
  return blob;
}

UnpackedBlob unpack_blob(const core::Blob& blob, std::string_view name) {
  using core::detail::load_i32;
  using core::detail::load_u16;
  namespace w = core::wire;
  UnpackedBlob out;
  out.method = blob.method;
  out.tri.width = blob.width;
  out.tri.height = blob.height;
  out.tri.space = host_space(blob.space);
  for (std::size_t l = 0; l < blob.layer_count; ++l) {
    const core::BlobLayer& layer = blob.layers[l];
    if (!layer.positions || !layer.values || !layer.triangles ||
        (blob.method == core::Method::zienkiewicz && !layer.gradients))
      throw DataError(std::string(name) + ": byte 0: expected a blob whose sections are stored in place (v1), found "
                      "a variant this reader cannot read back");
    Mesh mesh;
    mesh.value_count = blob.values_per_vertex;
    if (blob.layer_count > 1) mesh.name = layer_name(out.tri.space, l);
    const std::size_t nv = layer.vertex_count, nval = nv * blob.values_per_vertex;
    mesh.points.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) {
      const std::uint8_t* p = layer.positions + w::position::bytes * v;
      mesh.points[v] = {load_u16(p + w::position::x) * position_scale, load_u16(p + w::position::y) * position_scale};
    }
    mesh.values.resize(nval);
    for (std::size_t k = 0; k < nval; ++k) mesh.values[k] = load_u16(layer.values + w::value::bytes * k) / 256.0;
    mesh.triangles.resize(layer.triangle_count);
    for (std::size_t t = 0; t < layer.triangle_count; ++t) {
      const std::uint8_t* p = layer.triangles + w::triangle::bytes * t;
      mesh.triangles[t].v = {load_u16(p + w::triangle::corner(0)), load_u16(p + w::triangle::corner(1)),
                             load_u16(p + w::triangle::corner(2))};
    }
    check_drawable(mesh, layer, blob, name);
    if (blob.method == core::Method::zienkiewicz) {
      std::vector<std::int32_t> g(2 * nval);
      for (std::size_t k = 0; k < nval; ++k) {
        const std::uint8_t* p = layer.gradients + w::gradient::bytes * k;
        g[2 * k] = load_i32(p + w::gradient::gx);
        g[2 * k + 1] = load_i32(p + w::gradient::gy);
      }
      // The reference draws with the blob's gradients, not an estimate of its own.
      mesh.gradients.resize(g.size());
      for (std::size_t k = 0; k < g.size(); ++k)
        mesh.gradients[k] = std::ldexp(double(g[k]), -core::config::gradient_frac_bits);
      out.gradients.push_back(std::move(g));
    }
    out.tri.layers.push_back(std::move(mesh));
  }
  return out;
}

std::vector<std::uint8_t> expand_compressed_or_throw(std::span<const std::uint8_t> bytes, std::string_view name,
                                                     std::size_t* workspace_bytes) {
  core::CompressedBlob blob;
  core::BlobError error;
  core::Status s = core::open_compressed_blob(bytes.data(), bytes.size(), &blob, &error);
  std::vector<std::uint8_t> out, workspace;
  if (s == core::Status::ok) {
    out.assign(core::expanded_blob_size(blob), 0);
    workspace.assign(std::max<std::size_t>(core::expand_workspace_size(blob), 1), 0);
    s = core::expand_compressed_blob(blob, out.data(), out.size(), workspace.data(), workspace.size(), &error);
  }
  if (s != core::Status::ok) throw DataError(blob_error_message(name, bytes, s, error.offset));
  if (workspace_bytes) *workspace_bytes = core::expand_workspace_size(blob);
  return out;
}

std::vector<std::uint8_t> v1_blob_bytes(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (core::is_compressed_blob(bytes.data(), bytes.size())) return expand_compressed_or_throw(bytes, name);
  return {bytes.begin(), bytes.end()};
}

UnpackedBlob unpack_blob(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (!core::is_compressed_blob(bytes.data(), bytes.size())) return unpack_blob(open_blob_or_throw(bytes, name), name);
  const std::vector<std::uint8_t> v1 = expand_compressed_or_throw(bytes, name);
  const std::string expanded = std::string(name) + " (expanded to v1)";
  return unpack_blob(open_blob_or_throw(v1, expanded), expanded);
}

}  // namespace tristream
