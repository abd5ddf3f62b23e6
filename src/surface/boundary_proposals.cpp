// Boundary-node proposals (docs/method.md §9).
#include "surface/boundary_proposals.hpp"

#include <unordered_set>

#include "surface/cubic_patch.hpp"

namespace hocav {

namespace {

// The edges of the facets with the scope's frozen ref.
template <int D>
std::unordered_set<std::uint64_t> frozen_edges(const Mesh<D>& mesh, const ProposalScope& scope) {
  std::unordered_set<std::uint64_t> frozen;
  if (!scope.frozen_facet_ref) return frozen;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == *scope.frozen_facet_ref)
      for (const auto& ends : kPatchEdges<D>) frozen.insert(Mesh<D>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]]));
  return frozen;
}

}  // namespace

template <int D>
BoundaryProposals<D>::BoundaryProposals(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, const ProposalScope& scope) {
  const std::unordered_set<std::uint64_t> frozen = frozen_edges(mesh, scope);
  auto proposed = [&](Index a, Index b) {
    if (!scope.region.empty() && !(scope.region[a] && scope.region[b])) return false;
    return frozen.empty() || !frozen.contains(Mesh<D>::edge_key(a, b));
  };
  // Each boundary edge once, with the refs of (up to two different) facets around it.
  std::vector<BoundaryEdge<D>> edges;
  slot_of_edge_.reserve(static_cast<std::size_t>(mesh.facet_count()) * CubicPatch<D>::kEdges);
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const int ref = mesh.facet_ref(f);
    for (const auto& ends : kPatchEdges<D>) {  // the facet's edges
      const Index a = mesh.facet(f)[ends[0]], b = mesh.facet(f)[ends[1]];
      if (!proposed(a, b)) continue;
      const Index slot = slot_of_edge_.insert(Mesh<D>::edge_key(a, b), static_cast<Index>(edges.size()));
      if (slot < static_cast<Index>(edges.size())) {
        edges[slot].refs[1] = ref;
        continue;
      }
      const Index mesh_edge = mesh.is_p2() ? mesh.find_edge(a, b) : kNoIndex;
      const Vec<D> node = mesh_edge != kNoIndex ? mesh.edge_node(mesh_edge) : 0.5 * (mesh.vertex(a) + mesh.vertex(b));
      edges.push_back({a, b, node, {ref, ref}});
    }
  }
  nodes_.resize(edges.size());
  ends_.resize(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    ends_[i] = {edges[i].a, edges[i].b};
    if (!scope.geometry_ids.empty()) edges[i].a = scope.geometry_ids[edges[i].a], edges[i].b = scope.geometry_ids[edges[i].b];
    nodes_[i] = geometry.propose_edge_node(edges[i]);
  }
}

template <int D>
std::vector<typename BoundaryProposals<D>::Left> BoundaryProposals<D>::left() const {
  std::vector<Left> waiting;
  for (std::size_t slot = 0; slot < ends_.size(); ++slot) {
    const auto [a, b] = ends_[slot];
    if (slot_of_edge_.find(Mesh<D>::edge_key(a, b)) != kNoIndex) waiting.push_back({a, b, nodes_[slot]});
  }
  return waiting;
}

template <int D>
std::optional<Vec<D>> BoundaryProposals<D>::find(Index a, Index b) const {
  const Index slot = slot_of_edge_.find(Mesh<D>::edge_key(a, b));
  if (slot == kNoIndex) return std::nullopt;
  return nodes_[slot];
}

template <int D>
std::optional<Vec<D>> BoundaryProposals<D>::take(Index a, Index b) {
  std::optional<Vec<D>> node = find(a, b);
  if (node) slot_of_edge_.erase(Mesh<D>::edge_key(a, b));
  return node;
}

template <int D>
Index apply_boundary_proposals(Mesh<D>& mesh, BoundaryProposals<D>& proposals) {
  if (!mesh.is_p2()) mesh.make_p2();
  Index curved = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (const auto& ends : kPatchEdges<D>) {
      const Index a = mesh.facet(f)[ends[0]], b = mesh.facet(f)[ends[1]];
      if (std::optional<Vec<D>> node = proposals.take(a, b)) {
        mesh.edge_node(mesh.find_edge(a, b)) = *node;
        ++curved;
      }
    }
  return curved;
}

template class BoundaryProposals<2>;
template class BoundaryProposals<3>;
template Index apply_boundary_proposals(Mesh<2>&, BoundaryProposals<2>&);
template Index apply_boundary_proposals(Mesh<3>&, BoundaryProposals<3>&);

}  // namespace hocav
