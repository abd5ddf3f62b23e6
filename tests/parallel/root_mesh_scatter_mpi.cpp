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
#include <string>

#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "scattered_part_checks.hpp"

namespace hocav {
namespace {

template <int D>
bool check(Mesh<D> mesh, bool p2) {
  const std::string name = std::string(D == 2 ? "square" : "cube") + (p2 ? " P2" : " P1");
  if (p2) mesh.make_p2();
  const bool root = process_rank() == 0;
  std::vector<SymMat<D>> metrics;
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.push_back(metric_of<D>(v));
  const ScatteredPart<D> scattered = scatter_from_root(root ? mesh : Mesh<D>{}, root ? metrics : std::vector<SymMat<D>>{}, 7);
  return check_scattered_part(mesh, scattered, name);
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
