// A cap on a boundary (docs/curving.md, "Caps"), for the cap tests of the P1 loop and of the P2
// flip: a roof of two facets over a valley edge, with the two elements under the roof's inner faces.
#pragma once

#include <algorithm>
#include <array>

#include "mesh/measure.hpp"
#include "mesh/mesh.hpp"

namespace hocav::cap_test {

// The roof: a = (0, 0, h) and b = (1, 1, h) over the valley c = (1, 0, 0), d = (0, 1, 0), on a
// pyramid to e below: the cap (a, b, c, d) and the two elements (a, c, d, e), (b, c, d, e) under its
// inner faces. Boundary facets: the roof (a, b, c), (a, b, d) and the four faces to e, all ref 7.
struct Roof {
  static constexpr Index a = 0, b = 1, c = 2, d = 3, e = 4;
  Mesh<3> mesh;
  Index cap = kNoIndex;
  std::array<Index, 2> roof{};

  explicit Roof(double h) {
    for (const Vec3& p : {Vec3{{0, 0, h}}, Vec3{{1, 1, h}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0.5, 0.5, -1}}}) mesh.add_vertex(p);
    for (std::array<Index, 4> element : {std::array<Index, 4>{a, b, c, d}, {a, c, d, e}, {b, c, d, e}}) {
      const auto& x = mesh.vertices();
      if (signed_measure(x[element[0]], x[element[1]], x[element[2]], x[element[3]]) < 0) std::swap(element[0], element[1]);
      mesh.add_element(element, 1);
    }
    for (const std::array<Index, 3> facet : {std::array<Index, 3>{a, b, c}, {a, b, d}, {a, c, e}, {a, d, e}, {b, c, e}, {b, d, e}})
      mesh.add_facet(facet, 7);
    mesh.build_topology();
    mesh.orient_boundary_facets_outward();
    cap = 0;
    roof = {0, 1};
  }
};

}  // namespace hocav::cap_test
