// SPDX-License-Identifier: MIT
#include <array>

#include "reference/methods/bezier.h"
#include "reference/methods/bilinear.h"
#include "reference/methods/clough_tocher.h"
#include "reference/methods/coons.h"
#include "reference/methods/natural.h"
#include "reference/methods/voronoi.h"
#include "reference/methods/zienkiewicz.h"
#include "reference/render.h"

namespace tristream {
namespace {

// The method table: one line per method, in the order of docs and tables.
constexpr std::array methods{
    MethodInfo{"bilinear", "linear over each triangle (thesis 3.1)", render_bilinear},
    MethodInfo{"zienkiewicz",
               "Zienkiewicz's cubic with the file's gradients, else area-weighted normal ones (thesis 3.2)",
               render_zienkiewicz},
    MethodInfo{"bezier", "second-degree Bezier triangle patches over each triangle and its neighbours (thesis 3.3)",
               render_bezier},
    MethodInfo{"coons", "Coons patches over each triangle and its neighbours (thesis 3.4)", render_coons},
    MethodInfo{"voronoi", "Meyer polygon coordinates in Voronoi cells, zienkiewicz cell-vertex values (thesis 3.5)",
               render_voronoi},
    MethodInfo{"natural", "Sibson natural-neighbour coordinates on the Delaunay triangulation (thesis 3.6)",
               render_natural},
    MethodInfo{"clough-tocher", "C1 cubic over the Clough-Tocher split, zienkiewicz's gradients", render_clough_tocher},
};

}  // namespace

std::span<const MethodInfo> reference_methods() { return methods; }

const MethodInfo* find_reference_method(std::string_view name) {
  for (const MethodInfo& m : methods)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace tristream
