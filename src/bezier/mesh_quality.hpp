// Curved-element quality over a whole mesh: per-element min normalized Jacobian and scaled Jacobian,
// and their summaries (docs/method.md §8 quality figures; §11 min/avg/max normalized Jacobian).
#pragma once

#include <span>
#include <vector>

#include "base/index.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// One entry per element, in element order, measured on `threads` threads (the same entries for any
// count). A P1 mesh has straight elements: 1 and 1 for every positive element, −1 and −1 for an
// inverted one.
template <int D>
std::vector<JacobianQuality> mesh_jacobian_quality(const Mesh<D>& mesh, const RefinementOptions& options = {}, int threads = 1);

struct ValueSummary {
  Index count = 0;
  double min = 0.0, average = 0.0, max = 0.0;  // 0 for an empty set; the average is unweighted
  Index invalid_count = 0;                     // values ≤ 0: elements that are not valid
  // Equal bins over [histogram_lower, histogram_upper] (the last bin is closed); values outside
  // are counted in below / above, not in a bin.
  double histogram_lower = 0.0, histogram_upper = 1.0;
  std::vector<Index> histogram;
  Index below = 0, above = 0;
};

ValueSummary summarize_values(std::span<const double> values, int bin_count, double histogram_lower, double histogram_upper);

// The summary of two sets of values together, summarized apart with the same bins (the average to
// rounding: a distributed mesh's parts summarize their own elements).
ValueSummary merge_summaries(const ValueSummary& a, const ValueSummary& b);

struct MeshJacobianSummary {
  ValueSummary min_normalized_jacobian;  // histogram over [0, 1]; curved elements may exceed 1
  ValueSummary scaled_jacobian;          // histogram over [0, 1]
};

MeshJacobianSummary summarize_jacobian_quality(std::span<const JacobianQuality> qualities, int bin_count = 10);

}  // namespace hocav
