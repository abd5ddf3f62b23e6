// The output figures of a distributed curving measured by the first round's parts
// (docs/distributed.md §Curving): every element lies in exactly one of them, and later rounds only
// move some of their edges' nodes, which rank 0 sends back to them before they measure.
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

// What rank 0 keeps of a first-round part to measure the output, not the part: its vertices'
// global ids, and the edges of its interface facets by their global ends (low first), each once,
// in ascending order.
struct PartOutline {
  std::vector<Index> global_ids;
  std::vector<std::array<Index, 2>> interface_edges;
};

template <int D>
PartOutline outline_of(const MeshPart<D>& part);

// Per part, the nodes of the `written` edges of the mesh whose ends both lie in it (its vertices'
// global ids): what later rounds changed in that part.
template <int D>
std::vector<std::vector<NodeUpdate<D>>> node_updates_by_part(const Mesh<D>& mesh, std::span<const Index> written,
                                                             std::span<const PartOutline> parts);

// Writes each update's node into the part's edge with those global ends; an update whose edge the
// part lacks is passed over.
template <int D>
void apply_node_updates(MeshPart<D>& part, std::span<const NodeUpdate<D>> updates);

// Per part, the interface edges (by global ends) that an earlier part holds too: each edge's gain
// is measured once, by the first part that holds it.
std::vector<std::vector<std::array<Index, 2>>> interface_edges_measured_before(std::span<const PartOutline> parts);

// What a part measures: each element's Jacobians, in the part's order, and the gain of each edge
// it measures (not both ends on the whole mesh's boundary, not measured by an earlier part). An
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
// on its mesh, after writing `updates` into its nodes. `on_boundary`: per part vertex, whether it lies on the
// whole mesh's boundary.
template <int D>
PartMeasures measure_part(MeshPart<D>& part, const MetricField<D>& field, std::span<const NodeUpdate<D>> updates,
                          const std::vector<char>& on_boundary, std::span<const std::array<Index, 2>> measured_before, int threads);

}  // namespace hocav
