// The peer-to-peer migration and the distributed partition (docs/distributed.md §Migration), run by
// ctest under `mpirun -np N` (N = 2, 3, 4). Every process makes the same square and cube (the
// fixture) and keeps its part of a first partition; from there only parts move:
// 1. to a partition in slabs of x: each process's new part must be split_mesh's part of that
//    partition (entity by entity, by global ids);
// 2. back home: every element that crossed to another process twice comes back identical, and each
//    process has its first part again;
// 3. the distributed dual graph of the slab parts is the whole mesh's (every face, both ways, once),
//    and PT-Scotch's partition of it is balanced; migrated by it, the parts merge into the mesh;
// 4. the graph of groups of neighbouring elements is symmetric, its arcs weigh the faces between
//    groups, it has at most half as many rows, and the partition of the elements by it is balanced.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numeric>
#include <string>

#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/mesh_parts.hpp"
#include "parallel/part_migration.hpp"
#include "part_description.hpp"

namespace hocav {
namespace {

int rank() { return process_rank(); }

bool fail(const std::string& what) {
  std::cerr << "part migration (rank " << rank() << "): " << what << '\n';
  return false;
}

template <int D>
bool same(const MeshPart<D>& got, const MeshPart<D>& expected, const std::string& what) {
  const std::string difference = part_difference(got, expected);
  return difference.empty() || fail(what + ": " + difference);
}

template <int D>
Vec<D> centroid(const MeshPart<D>& part, Index k) {
  Vec<D> sum{};
  for (Index v : part.mesh.element(k)) sum = sum + part.mesh.vertex(v);
  return (1.0 / (D + 1)) * sum;
}

int slab(double x) { return std::clamp(static_cast<int>(std::floor(x * process_count())), 0, process_count() - 1); }

template <int D>
std::vector<int> slabs_of(const Mesh<D>& mesh) {
  MeshPart<D> whole{mesh, {}, {}};
  std::vector<int> out;
  for (Index k = 0; k < mesh.element_count(); ++k) out.push_back(slab(centroid(whole, k)[0]));
  return out;
}

template <int D>
std::vector<int> slabs_of(const MeshPart<D>& part) {
  std::vector<int> out;
  for (Index k = 0; k < part.mesh.element_count(); ++k) out.push_back(slab(centroid(part, k)[0]));
  return out;
}

// Per element of `part`: its process in `home` (per element of `mesh`), found by its global vertex ids.
template <int D>
std::vector<int> homes(const MeshPart<D>& part, const Mesh<D>& mesh, const std::vector<int>& home) {
  std::map<std::array<Index, D + 1>, int> by_vertices;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    auto key = mesh.element(k);
    std::sort(key.begin(), key.end());
    by_vertices[key] = home[k];
  }
  std::vector<int> out;
  for (Index k = 0; k < part.mesh.element_count(); ++k) {
    std::array<Index, D + 1> key{};
    for (int i = 0; i <= D; ++i) key[i] = part.global_ids[part.mesh.element(k)[i]];
    std::sort(key.begin(), key.end());
    out.push_back(by_vertices.at(key));
  }
  return out;
}

// The whole graph's rows, gathered: every face of `mesh` both ways once, with the serial graph's weights.
// Every process's sum of `value`.
std::int64_t summed(std::int64_t value) {
  std::int64_t total = 0;
  for (std::int64_t each : all_gather_value(value)) total += each;
  return total;
}

// Whether each arc's reverse, with the same weight, is some process's: sent to the owner of its head.
bool graph_is_symmetric(const DistributedGraph& graph) {
  std::vector<std::vector<std::array<std::int64_t, 3>>> arcs(static_cast<std::size_t>(process_count()));
  const std::vector<std::int64_t> firsts = all_gather_value(graph.first);
  const auto owner = [&](std::int64_t row) {
    return static_cast<int>(std::upper_bound(firsts.begin(), firsts.end(), row) - firsts.begin()) - 1;
  };
  for (std::size_t i = 0; i + 1 < graph.rows.offsets.size(); ++i)
    for (std::int64_t a = graph.rows.offsets[i]; a < graph.rows.offsets[i + 1]; ++a)
      arcs[owner(graph.rows.neighbours[a])].push_back(
          {graph.rows.neighbours[a], graph.first + static_cast<std::int64_t>(i), graph.rows.edge_weights[a]});
  for (const std::vector<std::byte>& bytes : exchange_bytes(bytes_of_messages(arcs)))
    for (const auto& [row, head, weight] : values_of_bytes<std::array<std::int64_t, 3>>(bytes)) {
      const auto i = static_cast<std::size_t>(row - graph.first);
      bool found = false;
      for (std::int64_t a = graph.rows.offsets[i]; a < graph.rows.offsets[i + 1]; ++a)
        found = found || (graph.rows.neighbours[a] == head && graph.rows.edge_weights[a] == weight);
      if (!found) return fail("arc " + std::to_string(head) + " -> " + std::to_string(row) + " has no reverse");
    }
  return true;
}

bool graph_is_the_meshes(const DistributedGraph& graph, const WeightedGraph& serial) {
  const std::int64_t total = summed(static_cast<std::int64_t>(graph.rows.neighbours.size()));
  if (total != static_cast<std::int64_t>(serial.neighbours.size()))
    return fail("the distributed graph has " + std::to_string(total) + " arcs, the mesh's " + std::to_string(serial.neighbours.size()));
  return graph_is_symmetric(graph);
}

// The graph of `part`'s groups of neighbouring elements (unit loads, no old interface): symmetric,
// its arcs' weights summing to the faces between groups (both ways) that the element graph
// `elements` has, at most half as many rows as elements; the elements' partition by it balanced.
template <int D>
bool grouped_graph_holds(const MeshPart<D>& part, const DistributedGraph& elements, Index element_count, const std::string& name) {
  const std::vector<double> loads(static_cast<std::size_t>(part.mesh.element_count()), 1.0);
  const ElementGroups groups = neighbouring_element_groups(part.mesh);
  const DistributedGraph graph = distributed_element_graph(part, loads, {}, groups);
  bool ok = graph_is_symmetric(graph);
  std::int64_t between = 0;  // the element graph's arcs between groups: faces, each way, all of weight 1
  for (std::size_t k = 0; k + 1 < elements.rows.offsets.size(); ++k)
    for (std::int64_t a = elements.rows.offsets[k]; a < elements.rows.offsets[k + 1]; ++a) {
      const std::int64_t other = elements.rows.neighbours[a] - elements.first;
      between += other < 0 || other >= static_cast<std::int64_t>(groups.group_of.size()) || groups.group_of[other] != groups.group_of[k];
    }
  const std::int64_t weight = summed(std::accumulate(graph.rows.edge_weights.begin(), graph.rows.edge_weights.end(), std::int64_t{0}));
  if (weight != summed(between))
    ok = fail(name + ": the grouped graph's arcs weigh " + std::to_string(weight) + ", the faces between groups are " +
              std::to_string(summed(between)));
  if (2 * summed(static_cast<std::int64_t>(groups.count)) > element_count) ok = fail(name + ": the groups are not coarser");
  const std::vector<int> cut = partition_distributed_part(part, loads, {}, 0);
  const std::vector<Index> got = all_gather_value(migrate_part(part, cut).mesh.element_count());
  const double mean = static_cast<double>(element_count) / process_count();
  for (int p = 0; p < process_count(); ++p)
    if (got[p] > 1.1 * mean + 1)
      ok = fail(name + ": the grouped partition's part " + std::to_string(p) + " has " + std::to_string(got[p]) + " elements");
  return ok;
}

template <int D>
bool run(const Mesh<D>& mesh) {
  const int count = process_count();
  const std::string name = D == 2 ? "square" : "cube";
  const std::vector<double> unit_loads(static_cast<std::size_t>(mesh.element_count()), 1.0);
  const WeightedGraph serial = element_graph(mesh, unit_loads, {});
  const std::vector<int> first_partition = partition_graph(serial, count);
  MeshPart<D> home = split_mesh(mesh, first_partition, count)[rank()];
  home.mesh.build_topology();

  // 1. To slabs of x, peer to peer.
  const MeshPart<D> slabbed = migrate_part(home, slabs_of(home));
  MeshPart<D> slabs = split_mesh(mesh, slabs_of(mesh), count)[rank()];
  slabs.mesh.build_topology();
  bool ok = same(slabbed, slabs, name + " in slabs against split_mesh");

  // 2. Back home: the elements that crossed twice are the ones they were.
  const std::vector<int> back = homes(slabbed, mesh, first_partition);
  const std::vector<int> crossed = all_gather_value(
      static_cast<int>(std::count_if(back.begin(), back.end(), [](int p) { return p != rank(); })));
  if (std::all_of(crossed.begin(), crossed.end(), [](int n) { return n == 0; })) ok = fail(name + ": no element crossed twice");
  ok = same(migrate_part(slabbed, back), home, name + " back home") && ok;

  // 3. The distributed graph of the slab parts, cut by PT-Scotch, and the parts it makes.
  const DistributedGraph graph = distributed_element_graph(slabbed,
                                                           std::vector<double>(static_cast<std::size_t>(slabbed.mesh.element_count()), 1.0),
                                                           {}, single_element_groups(slabbed.mesh.element_count()));
  ok = graph_is_the_meshes(graph, serial) && ok;
  ok = grouped_graph_holds(slabbed, graph, mesh.element_count(), name) && ok;
  const std::vector<int> cut = partition_distributed_graph(graph, count);
  const MeshPart<D> balanced = migrate_part(slabbed, cut);
  const std::vector<Index> got = all_gather_value(balanced.mesh.element_count());
  const double mean = static_cast<double>(mesh.element_count()) / count;
  for (int p = 0; p < count; ++p)
    if (got[p] > 1.1 * mean + 1)
      ok = fail(name + ": PT-Scotch's part " + std::to_string(p) + " has " + std::to_string(got[p]) + " elements of " +
                std::to_string(mesh.element_count()));
  {
    // Each part against split_mesh's of the partition they make together (gathered, for the check).
    std::vector<std::array<Index, D + 1>> keys;
    for (Index k = 0; k < balanced.mesh.element_count(); ++k) {
      std::array<Index, D + 1> key{};
      for (int i = 0; i <= D; ++i) key[i] = balanced.global_ids[balanced.mesh.element(k)[i]];
      keys.push_back(key);
    }
    std::vector<std::vector<std::byte>> everywhere(static_cast<std::size_t>(count), bytes_of_values(keys));
    std::map<std::array<Index, D + 1>, int> process_of;
    const std::vector<std::vector<std::byte>> all = exchange_bytes(everywhere);
    for (int p = 0; p < count; ++p)
      for (auto key : values_of_bytes<std::array<Index, D + 1>>(all[p])) {
        std::sort(key.begin(), key.end());
        process_of[key] = p;
      }
    std::vector<int> part_of;
    for (Index k = 0; k < mesh.element_count(); ++k) {
      auto key = mesh.element(k);
      std::sort(key.begin(), key.end());
      const auto found = process_of.find(key);
      if (found == process_of.end()) return fail(name + ": an element is in no part after PT-Scotch's migration");
      part_of.push_back(found->second);
    }
    MeshPart<D> expected = split_mesh(mesh, part_of, count)[rank()];
    expected.mesh.build_topology();
    ok = same(balanced, expected, name + " in PT-Scotch's parts against split_mesh") && ok;
  }
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "part migration", [] {
    hocav::Mesh<2> square = hocav::generate_square(12);
    hocav::Mesh<3> cube = hocav::generate_cube(6);
    square.build_topology();
    cube.build_topology();
    hocav::classify_vertices(square, 45);
    hocav::classify_vertices(cube, 45);
    // Some required vertices, inside and on the boundary: pinned in every part they fall in.
    for (hocav::Index v = 0; v < square.vertex_count(); v += 7) square.required_vertices().push_back(v);
    for (hocav::Index v = 0; v < cube.vertex_count(); v += 7) cube.required_vertices().push_back(v);
    hocav::Mesh<3> p2_cube = cube;
    p2_cube.make_p2();
    return hocav::run(square) & hocav::run(cube) & hocav::run(p2_cube);  // every process runs all three
  });
}
