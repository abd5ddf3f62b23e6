// The last runs' region cut among the processes (docs/distributed.md §The scheme, step 5), run by ctest
// under `mpirun -np N` (N = 2, 3, 4). Every process makes the same Kuhn cube and square of kCells
// cells a side and keeps its part of it: slabs of x on 2 and 3 processes (each interface faces one
// other process, and the slabs are wide enough that the regions of two interfaces do not touch), the
// quadrants of x and y on 4 (four parts meet along a line). Then:
// - every element within the rings of an interface vertex is in the region and goes to a process,
//   the others stay where they are;
// - on slabs the region goes to region_taker of the interfaces' two processes, and with loads per
//   process to the lighter;
// - a face between two elements of the region that go to different processes (inside a part or
//   across an interface) has every vertex among the seams, and every seam vertex is on such a face;
// - on slabs there is no seam at all (each interface lies inside one part after the cut), on the
//   quadrants there are seams, all near the line where the four parts meet.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/interface_sides.hpp"
#include "parallel/last_run_region.hpp"
#include "parallel/mesh_parts.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

constexpr int kRings = 2;
constexpr int kCells = 18;

bool fail(const std::string& what) {
  std::cerr << "last run region (rank " << process_rank() << "): " << what << '\n';
  return false;
}

bool quadrants() { return process_count() == 4; }

int slab(double x) { return std::clamp(static_cast<int>(std::floor(x * process_count())), 0, process_count() - 1); }

template <int D>
int part_at(const Vec<D>& centroid) {
  if (!quadrants()) return slab(centroid[0]);
  return (centroid[0] < 0.5 ? 0 : 1) + (centroid[1] < 0.5 ? 0 : 2);
}

// This process's part of the mesh.
template <int D>
MeshPart<D> own_part(Mesh<D> mesh) {
  mesh.build_topology();
  std::vector<int> part_of;
  for (Index k = 0; k < mesh.element_count(); ++k) part_of.push_back(part_at<D>(centroid(mesh, k)));
  return std::move(split_mesh(mesh, part_of, process_count()).at(static_cast<std::size_t>(process_rank())));
}

template <int D>
struct DestinationSide {
  FaceKey<D> face;
  int process;
  int destination;  // of the side's element
};

// The part's faces (by sorted global key) between elements of the region going to different
// processes, the interface faces' told by their other sides (both sides are the region's).
template <int D>
std::vector<FaceKey<D>> split_faces(const MeshPart<D>& part, const std::vector<int>& destination, const std::vector<char>& near) {
  std::unordered_map<FaceKey<D>, int, FaceKeyHash<D>> seen;
  std::vector<FaceKey<D>> split;
  for (Index k = 0; k < part.mesh.element_count(); ++k)
    for (int face = 0; near[k] && face <= D; ++face) {
      FaceKey<D> local;
      for (int i = 0; i < D; ++i) local[i] = part.mesh.element(k)[face_vertices<D>(face)[i]];
      const FaceKey<D> key = global_key<D>(part, local);
      const auto [at, added] = seen.emplace(key, destination[k]);
      if (!added && at->second != destination[k]) split.push_back(key);
    }
  std::vector<DestinationSide<D>> own;
  for (Index f = 0; f < part.mesh.facet_count(); ++f)
    if (part.mesh.facet_ref(f) == kInterfaceRef) {
      FaceKey<D> local;
      std::copy_n(part.mesh.facet(f).begin(), D, local.begin());
      const FaceKey<D> key = global_key<D>(part, local);
      own.push_back({key, process_rank(), seen.at(key)});
    }
  const auto across = sides_across<D, DestinationSide<D>>(own);
  for (const DestinationSide<D>& side : own)
    if (across.at(side.face).destination != side.destination) split.push_back(side.face);
  return split;
}

std::unordered_set<Index> gathered(const std::vector<Index>& ids) {
  const std::vector<Index> all = all_gather_values_joined(ids);
  return {all.begin(), all.end()};
}

template <int D>
bool check(Mesh<D> mesh) {
  const std::string name = std::to_string(D) + "D";
  const MeshPart<D> part = own_part(std::move(mesh));
  const RegionCut cut = cut_last_run_region(part, kRings);
  const std::vector<char> near = elements_near(part.mesh, interface_vertex_flags(part.mesh), kRings);
  bool ok = true;
  if (cut.destination.size() != near.size()) return fail(name + ": a destination per element expected");
  const int rank = process_rank();
  for (Index k = 0; k < part.mesh.element_count(); ++k) {
    const int to = cut.destination[k];
    if (to < 0 || to >= process_count() || (!near[k] && to != rank))
      return fail(name + ": element " + std::to_string(k) + " goes to " + std::to_string(to));
    // On slabs the region goes to the interfaces' takers.
    if (near[k] && !quadrants() && to != region_taker(0, 1) && (process_count() == 2 || to != region_taker(1, 2)))
      ok = fail(name + ": element " + std::to_string(k) + " of the region goes to " + std::to_string(to) + ", no interface's taker");
  }
  if (!quadrants()) {  // by loads (rank 0 the lightest): each interface's region to its lower process
    std::vector<Index> loads;
    for (int p = 0; p < process_count(); ++p) loads.push_back(p + 1);
    const RegionCut by_loads = cut_last_run_region(part, kRings, loads);
    for (Index k = 0; k < part.mesh.element_count(); ++k) {
      const int to = by_loads.destination[k];
      if (near[k] && ((to != rank && to != rank - 1) || to == process_count() - 1))
        ok = fail(name + ": by loads, element " + std::to_string(k) + " of the region goes to " + std::to_string(to));
    }
  }
  if (cut.region_elements != static_cast<Index>(std::count(near.begin(), near.end(), 1)))
    ok = fail(name + ": " + std::to_string(cut.region_elements) + " region elements counted");
  if (cut.in_region != near) ok = fail(name + ": the region's elements are not those within the rings");
  const std::unordered_set<Index> seams = gathered(cut.seams);
  std::vector<Index> on_split_faces;
  for (const FaceKey<D>& face : split_faces(part, cut.destination, near))
    for (Index id : face) {
      on_split_faces.push_back(id);
      if (!seams.contains(id)) ok = fail(name + ": vertex " + std::to_string(id) + " of a face between two destinations is no seam's");
    }
  const std::unordered_set<Index> split = gathered(on_split_faces);
  for (Index id : seams)
    if (!split.contains(id)) ok = fail(name + ": seam vertex " + std::to_string(id) + " on no face between two destinations");
  if (!quadrants() && !seams.empty()) ok = fail(name + ": " + std::to_string(seams.size()) + " seam vertices on slabs");
  if (quadrants() && seams.empty()) ok = fail(name + ": no seam where four parts meet");
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  for (Index id : cut.seams) {  // near the line x = y = 0.5, where two interfaces' rings meet
    const Vec<D>& point = part.mesh.vertex(local.at(id));
    if (std::hypot(point[0] - 0.5, point[1] - 0.5) > (kRings + 2) * std::sqrt(2.0) / kCells)
      ok = fail(name + ": seam vertex " + std::to_string(id) + " far from where the parts meet");
  }
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "last run region", [] {
    return hocav::check<3>(hocav::generate_cube(hocav::kCells)) & hocav::check<2>(hocav::generate_square(hocav::kCells));
  });
}
