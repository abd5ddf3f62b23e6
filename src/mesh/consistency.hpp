// The consistency checker: every invariant of Mesh<D> that operators and readers must keep.
// Used by the tests after every operation and by `hocav stats`.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct ConsistencyOptions {
  // Straight (P1) elements must have positive measure. Off for curved meshes, where a valid P2
  // element may be an inverted P1 element.
  bool require_positive_orientation = true;
  // Every face on the domain boundary must carry a boundary facet.
  bool require_boundary_facets = false;
  // Stop after this many problems.
  std::size_t max_problems = 20;
};

// Returns the problems found, each one line naming the entity (1-based ids); empty = consistent.
// Builds nothing: the mesh must have its topology (and its edge table when P2).
template <int D>
std::vector<std::string> check_consistency(const Mesh<D>& mesh, const ConsistencyOptions& options = {});

}  // namespace hocav
