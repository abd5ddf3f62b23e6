// The migration test of the distributed adaptation (docs/distributed.md §Migration), run by ctest
// under `mpirun -np N` (N = 2, 3, 4): rank 0 splits a cube into N parts and sends part r to rank r;
// each rank sends its part to the next rank, which sends it back, so that its elements cross ranks
// twice: the part must come back byte for byte. Then rank 0 gathers the parts into one (their
// shipments made into one part, as migrate_part gathers them): the cube again. Exit code 0 when all holds, 1 otherwise (with a message).
#include <algorithm>
#include <iostream>
#include <string>

#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/mesh_parts.hpp"
#include "parallel/part_message.hpp"
#include "parallel/part_shipment.hpp"
#include "whole_mesh_of.hpp"

namespace hocav {
namespace {

Mesh<3> classified_cube() {
  Mesh<3> cube = generate_cube(6);
  cube.build_topology();
  classify_vertices(cube, 45);
  return cube;
}

std::vector<std::byte> packed(const MeshPart<3>& part) { return pack_part(part.mesh, std::span<const Index>(part.global_ids)); }

// Rank 0: the parts out, then back after their round trip; gathered, they must be the cube.
bool run_root(int count) {
  const Mesh<3> cube = classified_cube();
  const std::vector<double> loads(static_cast<std::size_t>(cube.element_count()), 1.0);
  const std::vector<int> part_of = partition_graph(element_graph(cube, loads, {}), count);
  std::vector<MeshPart<3>> parts = split_mesh(cube, part_of, count);
  for (int p = 1; p < count; ++p) send_bytes(p, packed(parts[p]));
  const std::vector<std::byte> own = packed(parts[0]);
  send_bytes(1, own);
  bool ok = receive_bytes(1) == own;
  if (!ok) std::cerr << "migration: rank 0's part came back from rank 1 changed\n";
  std::vector<std::byte> traveller = receive_bytes(count - 1);  // the last rank's part, served
  send_bytes(count - 1, traveller);
  for (int p = 1; p < count; ++p) {
    const std::vector<std::byte> back = receive_bytes(p);
    if (back != packed(parts[p])) {
      std::cerr << "migration: part " << p << " came back changed\n";
      ok = false;
    }
    parts[p] = unpack_part<3>(back);
  }
  std::vector<Shipment<3>> shipments;
  for (MeshPart<3>& part : parts) {
    part.mesh.build_topology();
    part.pinned.assign(part.global_ids.size(), 0);  // (a message carries none; the cube has no required vertex)
    const std::vector<int> to_root(static_cast<std::size_t>(part.mesh.element_count()), 0);
    pack_shipments<3>(part, to_root, 1, [&](int, Shipment<3> shipment) { shipments.push_back(std::move(shipment)); });
  }
  const Mesh<3> merged = whole_mesh_of(part_of_shipments(shipments));
  const bool same = merged.vertex_count() == cube.vertex_count() && merged.element_count() == cube.element_count() &&
                    merged.facet_count() == cube.facet_count() && merged.line_count() == cube.line_count() &&
                    std::equal(cube.vertices().begin(), cube.vertices().end(), merged.vertices().begin());
  if (!same) std::cerr << "migration: the gathered parts are not the cube\n";
  return ok && same;
}

// Rank r > 0: receives its part, sends it to the next rank and serves the previous one's, gets it back.
bool run_other(int rank, int count) {
  const std::vector<std::byte> part = receive_bytes(0);
  const int next = (rank + 1) % count;
  const int previous = rank - 1;
  // Serve the previous rank's part first (rank 0 sends its own before it waits), then send ours.
  const std::vector<std::byte> served = receive_bytes(previous);
  send_bytes(previous, served);
  send_bytes(next, part);
  const bool ok = receive_bytes(next) == part;
  if (!ok) std::cerr << "migration: rank " << rank << "'s part came back from rank " << next << " changed\n";
  send_bytes(0, part);
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  hocav::MpiSession mpi(argc, argv);
  const int count = hocav::process_count(), rank = hocav::process_rank();
  if (count < 2) {
    std::cerr << "migration: run it under mpirun with 2 or more processes\n";
    return 1;
  }
  try {
    const bool ok = rank == 0 ? hocav::run_root(count) : hocav::run_other(rank, count);
    return ok ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "migration: rank " << rank << ": " << error.what() << '\n';
    hocav::abort_processes(1);
  }
}
