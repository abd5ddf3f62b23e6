#include "parallel/part_measures.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "base/thread_pool.hpp"
#include "bezier/mesh_quality.hpp"
#include "report/curving_report.hpp"

namespace hocav {
namespace {}  // namespace

template <int D>
PartOutline outline_of(const MeshPart<D>& part) {
  PartOutline outline{part.global_ids, {}};
  for (std::uint64_t key : interface_edge_keys(part.mesh)) {
    // Mesh::edge_key holds the lower end in the high 32 bits.
    const Index a = part.global_ids[static_cast<Index>(key >> 32)], b = part.global_ids[static_cast<Index>(key & 0xffffffffu)];
    outline.interface_edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(outline.interface_edges.begin(), outline.interface_edges.end());
  return outline;
}

template <int D>
std::vector<std::vector<NodeUpdate<D>>> node_updates_by_part(const Mesh<D>& mesh, std::span<const Index> written,
                                                             std::span<const PartOutline> parts) {
  // The parts that hold each vertex of the mesh, as offsets into one list (a vertex on an interface
  // is in several): memory for the parts' vertices, not for parts × vertices.
  std::vector<Index> offsets(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for (const PartOutline& part : parts)
    for (Index g : part.global_ids)
      if (g != kNoIndex) ++offsets[g + 1];
  for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
  std::vector<Index> holders(static_cast<std::size_t>(offsets.back())), filled(offsets.begin(), offsets.end() - 1);
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (Index g : parts[p].global_ids)
      if (g != kNoIndex) holders[filled[g]++] = static_cast<Index>(p);
  std::vector<std::vector<NodeUpdate<D>>> updates(parts.size());
  for (Index e : written) {
    const auto& ends = mesh.edge_vertices(e);
    for (Index i = offsets[ends[0]]; i < offsets[ends[0] + 1]; ++i)
      for (Index j = offsets[ends[1]]; j < offsets[ends[1] + 1]; ++j)
        if (holders[i] == holders[j]) updates[holders[i]].push_back({ends, mesh.edge_node(e)});
  }
  return updates;
}

std::vector<std::vector<std::array<Index, 2>>> interface_edges_measured_before(std::span<const PartOutline> parts) {
  std::unordered_set<std::uint64_t> held;  // the interface edges of the parts before
  std::vector<std::vector<std::array<Index, 2>>> before(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p) {
    for (const auto& [a, b] : parts[p].interface_edges)
      if (held.contains(global_edge_key({a, b}))) before[p].push_back({a, b});
    for (const auto& [a, b] : parts[p].interface_edges) held.insert(global_edge_key({a, b}));
  }
  return before;
}

template <int D>
void apply_node_updates(MeshPart<D>& part, std::span<const NodeUpdate<D>> updates) {
  Mesh<D>& mesh = part.mesh;
  if (updates.empty()) return;
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  const auto local_of = [&](Index g) {
    const auto found = local.find(g);
    return found == local.end() ? kNoIndex : found->second;
  };
  for (const NodeUpdate<D>& update : updates) {
    const Index a = local_of(update.ends[0]), b = local_of(update.ends[1]);
    if (const Index e = a == kNoIndex || b == kNoIndex ? kNoIndex : mesh.find_edge(a, b); e != kNoIndex) mesh.edge_node(e) = update.node;
  }
}

template <int D>
PartMeasures measure_part(MeshPart<D>& part, const MetricField<D>& field, std::span<const NodeUpdate<D>> updates,
                          const std::vector<char>& on_boundary, std::span<const std::array<Index, 2>> measured_before, int threads) {
  Mesh<D>& mesh = part.mesh;
  if (mesh.element_count() == 0) return {};
  apply_node_updates(part, updates);
  std::unordered_set<std::uint64_t> skipped;
  for (const auto& [a, b] : measured_before) skipped.insert(global_edge_key({a, b}));
  std::vector<Index> edges;  // the edges this part measures, in order
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto& [a, b] = mesh.edge_vertices(e);
    if (a == kNoIndex || (on_boundary[a] && on_boundary[b])) continue;
    if (!skipped.contains(global_edge_key({part.global_ids[a], part.global_ids[b]}))) edges.push_back(e);
  }
  PartMeasures measures;
  measures.elements = mesh_jacobian_quality(mesh, kReportedRefinement, threads);
  std::vector<EdgeGain> gains(edges.size());
  ThreadPool pool(std::max(1, threads));
  run_chunked(pool, edges.size(), kMeasuredChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) gains[i] = edge_gain(mesh, field, edges[i]);
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& [a, b] = mesh.edge_vertices(edges[i]);
    if (!gains[i].sampled_inside) {
      measures.deferred.push_back({part.global_ids[a], part.global_ids[b]});
      measures.deferred_in_part.push_back(gains[i].value);
    } else
      measures.gains.push_back(gains[i].value);
  }
  return measures;
}

#define HOCAV_INSTANTIATE(D)                                                                                                        \
  template PartOutline outline_of(const MeshPart<D>&);                                                                              \
  template std::vector<std::vector<NodeUpdate<D>>> node_updates_by_part(const Mesh<D>&, std::span<const Index>,                     \
                                                                        std::span<const PartOutline>);                              \
  template void apply_node_updates(MeshPart<D>&, std::span<const NodeUpdate<D>>);                                                   \
  template PartMeasures measure_part(MeshPart<D>&, const MetricField<D>&, std::span<const NodeUpdate<D>>, const std::vector<char>&, \
                                     std::span<const std::array<Index, 2>>, int);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
