// Checks of a mesh cut into parts with its metrics (a ScatteredPart: from rank 0, or from a file
// read in pieces), shared by the MPI tests of both: every element of the mesh in exactly one part,
// each part vertex the mesh vertex's point with its own metric (metric_of names its vertex), each
// part element's id that of the mesh element with its vertices (and each facet's and feature
// line's), and a P2 part's nodes the mesh's.
#pragma once

#include <algorithm>
#include <array>
#include <iostream>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/root_mesh_scatter.hpp"

namespace hocav {

inline bool fail_scattered(const std::string& what) {
  std::cerr << "parts (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// A metric that names its vertex.
template <int D>
SymMat<D> metric_of(Index vertex) {
  Vec<D> diagonal{};
  for (int i = 0; i < D; ++i) diagonal[i] = 1.0 + static_cast<double>(vertex) + 0.25 * i;
  return SymMat<D>::from_diagonal(diagonal);
}

// The elements by their sorted global vertex ids (`ids` empty: the mesh's own).
template <int D>
std::vector<std::array<Index, D + 1>> elements_by_ids(const Mesh<D>& mesh, const std::vector<Index>& ids) {
  std::vector<std::array<Index, D + 1>> out;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    std::array<Index, D + 1> element;
    for (int i = 0; i <= D; ++i) element[i] = ids.empty() ? mesh.element(k)[i] : ids[mesh.element(k)[i]];
    std::sort(element.begin(), element.end());
    out.push_back(element);
  }
  return out;
}

// A facet by its sorted global vertex ids (`ids` empty: the mesh's own).
template <std::size_t N>
std::array<Index, N> facet_by_ids(std::array<Index, N> facet, const std::vector<Index>& ids) {
  if (!ids.empty())
    for (Index& v : facet) v = ids[static_cast<std::size_t>(v)];
  std::sort(facet.begin(), facet.end());
  return facet;
}

// Collective (every process calls it, with the same `mesh`, before any early return): whether
// `scattered` is a part of `mesh` as the file header says, `name` in each message.
template <int D>
bool check_scattered_part(const Mesh<D>& mesh, const ScatteredPart<D>& scattered, const std::string& name) {
  const MeshPart<D>& part = scattered.part;
  std::vector<std::array<Index, D + 1>> gathered;
  for (const auto& each : exchange_values(std::vector<std::vector<std::array<Index, D + 1>>>(static_cast<std::size_t>(process_count()),
                                                                                             elements_by_ids(part.mesh, part.global_ids))))
    gathered.insert(gathered.end(), each.begin(), each.end());
  std::sort(gathered.begin(), gathered.end());
  const Index facet_ids_everywhere = sum_over_processes(static_cast<Index>(scattered.facet_ids.size()));
  if (part.mesh.element_count() == 0) return fail_scattered(name + ": an empty part");
  if (part.mesh.is_p2() != mesh.is_p2()) return fail_scattered(name + ": the part's order is not the mesh's");
  if (scattered.metrics.size() != static_cast<std::size_t>(part.mesh.vertex_count()))
    return fail_scattered(name + ": not a metric per vertex");
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    const Index g = part.global_ids[v];
    if (g < 0 || g >= mesh.vertex_count() || part.mesh.vertex(v) != mesh.vertex(g))
      return fail_scattered(name + ": a vertex not the mesh's");
    if (scattered.metrics[v].entries != metric_of<D>(g).entries) return fail_scattered(name + ": a vertex with another vertex's metric");
  }
  if (scattered.element_ids.size() != static_cast<std::size_t>(part.mesh.element_count()))
    return fail_scattered(name + ": not an element id per element");
  const std::vector<std::array<Index, D + 1>> own = elements_by_ids(part.mesh, part.global_ids), all = elements_by_ids(mesh, {});
  for (std::size_t k = 0; k < own.size(); ++k) {
    const Index id = scattered.element_ids[k];
    if (id < 0 || id >= mesh.element_count() || own[k] != all[static_cast<std::size_t>(id)])
      return fail_scattered(name + ": an element whose id is another element's");
  }
  for (std::size_t i = 0; i < scattered.facet_ids.size(); ++i) {  // (the part's facets but the interfaces', which come last)
    const auto f = static_cast<Index>(i);
    const Index id = scattered.facet_ids[i];
    if (f >= part.mesh.facet_count() || part.mesh.facet_ref(f) == kInterfaceRef || id < 0 || id >= mesh.facet_count() ||
        part.mesh.facet_ref(f) != mesh.facet_ref(id) ||
        facet_by_ids(part.mesh.facet(f), part.global_ids) != facet_by_ids(mesh.facet(id), {}))
      return fail_scattered(name + ": a facet whose id is another facet's");
  }
  Index own_facets = 0;
  for (Index f = 0; f < part.mesh.facet_count(); ++f) own_facets += part.mesh.facet_ref(f) != kInterfaceRef;
  if (facet_ids_everywhere != mesh.facet_count() || own_facets != static_cast<Index>(scattered.facet_ids.size()))
    return fail_scattered(name + ": not a facet id per facet");
  if (scattered.line_ids.size() != static_cast<std::size_t>(part.mesh.line_count()))
    return fail_scattered(name + ": not a line id per line");
  for (Index l = 0; l < part.mesh.line_count(); ++l) {
    const Index id = scattered.line_ids[static_cast<std::size_t>(l)];
    if (id < 0 || id >= mesh.line_count() || part.mesh.line_ref(l) != mesh.line_ref(id) ||
        facet_by_ids(part.mesh.line(l), part.global_ids) != facet_by_ids(mesh.line(id), {}))
      return fail_scattered(name + ": a line whose id is another line's");
  }
  if (mesh.is_p2())
    for (Index e = 0; e < part.mesh.edge_count(); ++e) {
      const auto& ends = part.mesh.edge_vertices(e);
      if (ends[0] == kNoIndex) continue;
      const Index whole = mesh.find_edge(part.global_ids[ends[0]], part.global_ids[ends[1]]);
      if (whole == kNoIndex || part.mesh.edge_node(e) != mesh.edge_node(whole))
        return fail_scattered(name + ": an edge node not the mesh's");
    }
  std::vector<std::array<Index, D + 1>> whole = elements_by_ids(mesh, {});
  std::sort(whole.begin(), whole.end());
  if (gathered != whole) return fail_scattered(name + ": the parts' elements are not the mesh's, each once");
  std::cerr << name << ": part of " << part.mesh.element_count() << " elements on rank " << process_rank() << '\n';
  return true;
}

}  // namespace hocav
