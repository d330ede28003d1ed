/* SPDX-License-Identifier: MIT */
#pragma once
// Greedy point removal (GPR), the standard baseline of mesh-based image representation:
// Demaret and Iske's adaptive thinning with the "anticipated error" significance (AT1), as
// Adams formulates it as GPR. Start from the Delaunay triangulation of every pixel, then
// repeatedly remove the vertex whose removal (Delaunay retriangulation of its hole,
// baselines/removal_mesh.h) increases the squared error of the linear interpolant least,
// until N vertices remain. The four corners are never removed; vertices on a side are. Vertex
// values are the pixel values at the vertices; the error is summed over every pixel (exact
// ownership, encoder/pixel_scan.h) and every channel. Optionally the values are then refit by
// least squares over all pixels (GPR + LSQ).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

#include "baselines/removal_mesh.h"
#include "encoder/encoder.h"
#include "encoder/planes.h"
#include "model/image.h"
#include "model/triangulation.h"

namespace tristream::baselines {

// The removal loop on one image (encoder::Planes of 1 to 4 channels whose values are the
// 8-bit pixel values, as to_planes gives grey and rgb; it must outlive the object).
// Deterministic: the significances are computed in one order of operations, and ties go to the
// lowest vertex index (y * W + x). Memory grows with the pixels: two triangles per pixel at the
// start, each with its neighbours and error, and the queue (tribaseline: 50 MB resident for a
// 512 x 512 grey image).
class PointRemoval {
 public:
  explicit PointRemoval(const encoder::Planes& target);

  std::size_t vertex_count() const { return mesh_.vertex_count(); }
  // Removes the vertex of least significance; false when only the corners remain.
  bool step();
  // The vertex the last step() removed and its significance then.
  std::uint32_t last_removed() const { return last_removed_; }
  double last_significance() const { return last_significance_; }

  // The increase of the squared error if live vertex v (not a corner) were removed, computed
  // afresh.
  double significance(std::uint32_t v) const;
  // The squared error of the current mesh, summed over its triangles.
  double total_squared_error() const;
  const RemovalMesh& removal_mesh() const { return mesh_; }
  // The current mesh: live vertices in index order, pixel values.
  Mesh mesh() const;

 private:
  struct Entry {
    double significance;
    std::uint32_t vertex, version;
    bool operator>(const Entry& o) const {
      return significance != o.significance ? significance > o.significance : vertex > o.vertex;
    }
  };
  double triangle_error(const RemovalMesh::Corners& c) const;
  void requeue(std::uint32_t v);

  const encoder::Planes& target_;
  RemovalMesh mesh_;
  std::vector<double> error_;  // per slot: the squared error of its triangle, when live
  std::vector<std::uint32_t> version_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  std::uint32_t last_removed_ = RemovalMesh::none;
  double last_significance_ = 0;
  // Scratch.
  mutable RemovalMesh::Star star_;
  mutable std::vector<RemovalMesh::Corners> fill_;
  std::vector<std::uint32_t> created_, neighbours_;
};

struct GprOptions {
  std::size_t vertices = 0;  // vertices kept, the four corners included
  VertexFit values = VertexFit::pixel;
  // Called now and then with the fraction done, in [0, 1].
  std::function<void(double)> progress;
};

struct GprResult {
  Triangulation triangulation;  // grey for a grey image, rgb for a colour one
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  double psnr = 0;     // of the 8-bit linear interpolant (render_linear) against the image
  double seconds = 0;  // wall time
};

// GPR on `image` (1 or 3 channels, at least 2 x 2). Throws DataError for an image it cannot
// take and UsageError for a vertex count below 4 or above the pixel count.
GprResult greedy_point_removal(const Image& image, const GprOptions& options);

}  // namespace tristream::baselines
