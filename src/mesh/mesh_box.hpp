// Axis-aligned bounding boxes of a mesh's vertices and of its elements.
#pragma once

#include "geom/box.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// The box of all the mesh's vertices (empty for no vertex).
template <int D>
Box<D> vertex_box(const Mesh<D>& mesh) {
  Box<D> box = Box<D>::empty();
  for (const Vec<D>& x : mesh.vertices()) box.add(x);
  return box;
}

// The box of element k's vertices.
template <int D>
Box<D> element_box(const Mesh<D>& mesh, Index k) {
  Box<D> box = Box<D>::empty();
  for (Index v : mesh.element(k)) box.add(mesh.vertex(v));
  return box;
}

}  // namespace hocav
