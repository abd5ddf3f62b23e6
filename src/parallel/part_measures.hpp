// The output figures of a distributed curving measured by its parts (docs/distributed.md §Curving in
// the parts): every element lies in exactly one of them, each interface edge is measured once, and
// the nodes a later round moved reach the parts as updates by global ends.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "bezier/jacobian_bounds.hpp"
#include "geom/sym_mat.hpp"
#include "metric/metric_field.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// An edge's node by the edge's ends in the whole mesh.
template <int D>
struct NodeUpdate {
  std::array<Index, 2> ends;
  Vec<D> node;
};

// An edge's key by its ends' global ids, in either order.
inline std::uint64_t global_edge_key(const std::array<Index, 2>& ends) { return Mesh<3>::edge_key(ends[0], ends[1]); }

// The edges of a part's interface facets by their global ends (low first), each once, in ascending
// order.
template <int D>
std::vector<std::array<Index, 2>> interface_edges_by_global_ends(const MeshPart<D>& part);

// Per process p (of `processes`), the nodes of the part's edges that its elements from p hold
// (`source`, per element: the process it came from), each once, but those of edges on the part's
// interface facets, frozen: what a band's curving wrote, for the parts it came from. An edge off the
// interface facets has all its elements in the part, so the updates touch only elements it curved.
template <int D>
std::vector<std::vector<NodeUpdate<D>>> node_updates_by_source(const MeshPart<D>& part, std::span<const int> source, int processes);

// Writes each update's node into the part's edge with those global ends; an update whose edge the
// part lacks is passed over.
template <int D>
void apply_node_updates(MeshPart<D>& part, std::span<const NodeUpdate<D>> updates);

// What a part measures: each element's Jacobians, in the part's order, and the gain of each edge
// it measures (not both ends on the whole mesh's boundary, not measured by another part). An
// edge whose curved node or straight middle lies outside the part is left to the whole mesh's
// field (`deferred`, by global ends): the part's field there is an extension, and its gain would
// be another (a gain of 0.77 where the whole field gives 0.10, on the layered shell).
struct PartMeasures {
  std::vector<JacobianQuality> elements;
  std::vector<double> gains;
  std::vector<std::array<Index, 2>> deferred;
  std::vector<double> deferred_in_part;  // per deferred edge, its gain in the part's own field
};

// Measures a curved part (P2, with its topology) in `field`, made of its own vertices' log-metrics
// on its mesh. `on_boundary`: per part vertex, whether it lies on the whole mesh's boundary;
// `measured_elsewhere`: the edges (by global ends) another part measures.
template <int D>
PartMeasures measure_part(const MeshPart<D>& part, const MetricField<D>& field, const std::vector<char>& on_boundary,
                          std::span<const std::array<Index, 2>> measured_elsewhere, int threads);

}  // namespace hocav
