// The partition of a mesh rank 0 holds (partition_from_root, docs/distributed.md §Curving), run by
// ctest under `mpirun -np N` (N = 2, 3, 4) on a square and a cube that only rank 0 passes:
// 1. every element gets a part in [0, N), and every part holds about 1/N of the elements (within
//    PT-Scotch's imbalance and one element);
// 2. the cut is a partitioner's: at most twice the faces Scotch's serial partition of the whole
//    graph cuts (a piece's parts written back to the wrong elements scatter them, and cut many
//    times more);
// 3. the same mesh and seed give the same parts.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <iostream>
#include <string>

#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/root_mesh_partition.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "partition from rank 0 (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// The faces between elements of different parts.
template <int D>
Index cut_faces(const Mesh<D>& mesh, const std::vector<int>& part_of) {
  Index count = 0;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (const Index other = mesh.neighbor(k, face); other != kNoIndex && other > k && part_of[other] != part_of[k]) ++count;
  return count;
}

template <int D>
bool check(Mesh<D> mesh) {
  const std::string name = D == 2 ? "square" : "cube";
  const int parts = process_count();
  const bool root = process_rank() == 0;
  if (root) mesh.build_topology();
  const Mesh<D> none;
  const Mesh<D>& passed = root ? mesh : none;
  const std::vector<int> part_of = partition_from_root(passed, 7);
  const std::vector<int> again = partition_from_root(passed, 7);
  if (!root) return part_of.empty() || fail(name + ": a process other than rank 0 got parts");
  if (part_of.size() != static_cast<std::size_t>(mesh.element_count())) return fail(name + ": not a part per element");
  if (again != part_of) return fail(name + ": the same mesh and seed gave other parts");
  std::vector<Index> sizes(static_cast<std::size_t>(parts), 0);
  for (int p : part_of) {
    if (p < 0 || p >= parts) return fail(name + ": part " + std::to_string(p) + " out of range");
    ++sizes[p];
  }
  const double fair = static_cast<double>(mesh.element_count()) / parts;
  for (int p = 0; p < parts; ++p)
    if (sizes[p] > (1 + kPartImbalance) * fair + 1)
      return fail(name + ": part " + std::to_string(p) + " holds " + std::to_string(sizes[p]) + " elements of " +
                  std::to_string(mesh.element_count()));
  const std::vector<double> loads(static_cast<std::size_t>(mesh.element_count()), 1.0);
  const Index cut = cut_faces(mesh, part_of), serial_cut = cut_faces(mesh, partition_graph(element_graph(mesh, loads, {}), parts));
  std::cerr << name << " in " << parts << " parts: " << cut << " faces cut (Scotch's serial partition: " << serial_cut << ")\n";
  if (cut > 2 * serial_cut)
    return fail(name + ": " + std::to_string(cut) + " faces cut, Scotch's serial partition " + std::to_string(serial_cut));
  return true;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "partition from rank 0", [] {
    return hocav::check(hocav::generate_square(24)) & hocav::check(hocav::generate_cube(10));  // every process runs both
  });
}
