// What the adaptation tests share: the structured unit square or cube (the metric tests' own), and
// the checker's verdict on a mesh that must be consistent and closed (a facet on every boundary face).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../metric/metric_test_support.hpp"
#include "mesh/consistency.hpp"

namespace hocav::adapt_test {

using metric_test::unit_mesh;

template <int D>
void expect_closed_and_consistent(const Mesh<D>& mesh) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

}  // namespace hocav::adapt_test
