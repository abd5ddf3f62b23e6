// What the adaptation tests share: the structured unit square or cube, and the checker's verdict
// on a mesh that must be consistent and closed (a facet on every boundary face).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cases/structured.hpp"
#include "mesh/consistency.hpp"

namespace hocav::adapt_test {

template <int D>
Mesh<D> unit_mesh(int cells_per_side) {
  if constexpr (D == 2)
    return generate_square(cells_per_side);
  else
    return generate_cube(cells_per_side);
}

template <int D>
void expect_closed_and_consistent(const Mesh<D>& mesh) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

}  // namespace hocav::adapt_test
