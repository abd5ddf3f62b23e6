// A mesh that rank 0 holds, scattered with its metrics (scatter_from_root, docs/distributed.md
// §Curving in the parts), run by ctest under `mpirun -np N` (N = 2, 3, 4) on a square and a cube,
// P1 and P2, that only rank 0 passes, each vertex with a metric of its own:
// 1. every process gets a part, and every element of the mesh lies in exactly one part (the parts'
//    element counts add up to the mesh's, and their elements' global vertex ids are the mesh's
//    elements, each once);
// 2. each part vertex has the mesh vertex's point and its own metric (a metric sent for another
//    vertex, or in another order, differs);
// 3. a P2 mesh gives P2 parts with the mesh's nodes.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <array>
#include <iostream>
#include <set>
#include <string>

#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/root_mesh_scatter.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "scatter from rank 0 (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// A metric that names its vertex.
template <int D>
SymMat<D> metric_of(Index vertex) {
  Vec<D> diagonal{};
  for (int i = 0; i < D; ++i) diagonal[i] = 1.0 + static_cast<double>(vertex) + 0.25 * i;
  return SymMat<D>::from_diagonal(diagonal);
}

// The elements by their sorted global vertex ids.
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

template <int D>
bool check(Mesh<D> mesh, bool p2) {
  const std::string name = std::string(D == 2 ? "square" : "cube") + (p2 ? " P2" : " P1");
  if (p2) mesh.make_p2();
  const bool root = process_rank() == 0;
  std::vector<SymMat<D>> metrics;
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.push_back(metric_of<D>(v));
  const ScatteredPart<D> scattered = scatter_from_root(root ? mesh : Mesh<D>{}, root ? metrics : std::vector<SymMat<D>>{}, 7);
  const MeshPart<D>& part = scattered.part;
  // (Every collective call before the first check: a process that fails returns early.)
  std::vector<std::array<Index, D + 1>> gathered;
  for (const auto& each : exchange_values(std::vector<std::vector<std::array<Index, D + 1>>>(static_cast<std::size_t>(process_count()),
                                                                                             elements_by_ids(part.mesh, part.global_ids))))
    gathered.insert(gathered.end(), each.begin(), each.end());
  std::sort(gathered.begin(), gathered.end());
  if (part.mesh.element_count() == 0) return fail(name + ": an empty part");
  if (part.mesh.is_p2() != p2) return fail(name + ": the part's order is not the mesh's");
  if (scattered.metrics.size() != static_cast<std::size_t>(part.mesh.vertex_count())) return fail(name + ": not a metric per vertex");
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    const Index g = part.global_ids[v];
    if (g < 0 || g >= mesh.vertex_count() || part.mesh.vertex(v) != mesh.vertex(g)) return fail(name + ": a vertex not the mesh's");
    if (scattered.metrics[v].entries != metric_of<D>(g).entries) return fail(name + ": a vertex with another vertex's metric");
  }
  if (p2)
    for (Index e = 0; e < part.mesh.edge_count(); ++e) {
      const auto& ends = part.mesh.edge_vertices(e);
      if (ends[0] == kNoIndex) continue;
      const Index whole = mesh.find_edge(part.global_ids[ends[0]], part.global_ids[ends[1]]);
      if (whole == kNoIndex || part.mesh.edge_node(e) != mesh.edge_node(whole)) return fail(name + ": an edge node not the mesh's");
    }
  std::vector<std::array<Index, D + 1>> whole = elements_by_ids(mesh, {});
  std::sort(whole.begin(), whole.end());
  if (gathered != whole) return fail(name + ": the parts' elements are not the mesh's, each once");
  std::cerr << name << ": part of " << part.mesh.element_count() << " elements on rank " << process_rank() << '\n';
  return true;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "scatter from rank 0", [] {
    bool ok = true;
    for (bool p2 : {false, true}) ok = hocav::check(hocav::generate_square(16), p2) & hocav::check(hocav::generate_cube(6), p2) & ok;
    return ok;
  });
}
