// Split and gathering of mesh parts (src/parallel/mesh_parts.hpp, part_shipment.hpp) and their messages
// (src/parallel/part_message.hpp), without MPI: a mesh split along a partition and gathered back
// unchanged is the same mesh; every part is a consistent mesh whose interface faces are required
// facets; a part survives its message unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <unordered_set>

#include "../mesh/pinched_mesh.hpp"
#include "adapt/vertex_classes.hpp"
#include "base/error.hpp"
#include "cases/structured.hpp"
#include "mesh/consistency.hpp"
#include "parallel/mesh_parts.hpp"
#include "parallel/part_measures.hpp"
#include "parallel/part_message.hpp"
#include "parallel/part_shipment.hpp"
#include "whole_mesh_of.hpp"

namespace hocav {
namespace {

// A cube with its corners and feature lines (as the adaptation classifies them), and a partition of
// its elements into `parts` slabs along x.
struct SlicedCube {
  Mesh<3> mesh = generate_cube(4);
  std::vector<int> part_of;

  explicit SlicedCube(int parts) {
    mesh.build_topology();
    classify_vertices(mesh, 45);
    for (Index k = 0; k < mesh.element_count(); ++k) {
      double x = 0;
      for (Index v : mesh.element(k)) x += mesh.vertex(v)[0] / 4;
      part_of.push_back(std::min(parts - 1, static_cast<int>(x * parts)));
    }
  }
};

template <typename Entities>
std::multiset<std::vector<double>> placed(const Mesh<3>& mesh, const Entities& entities, std::span<const int> refs) {
  std::multiset<std::vector<double>> out;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    std::vector<double> row{static_cast<double>(refs[i])};
    for (Index v : entities[i])
      for (int d = 0; d < 3; ++d) row.push_back(mesh.vertex(v)[d]);
    out.insert(row);
  }
  return out;
}

std::set<std::vector<double>> tagged_points(const Mesh<3>& mesh, const std::vector<Index>& vertices) {
  std::set<std::vector<double>> out;
  for (Index v : vertices) out.insert({mesh.vertex(v)[0], mesh.vertex(v)[1], mesh.vertex(v)[2]});
  return out;
}

// The parts gathered into one as migrate_part gathers them on one process: every part's shipment, in
// order, made into one part, which is the whole mesh.
Mesh<3> gathered(std::vector<MeshPart<3>> parts) {
  std::vector<Shipment<3>> shipments;
  for (MeshPart<3>& part : parts) {
    part.mesh.build_topology();
    const std::vector<int> to_one(static_cast<std::size_t>(part.mesh.element_count()), 0);
    pack_shipments<3>(part, to_one, 1, [&](int, Shipment<3> shipment) { shipments.push_back(std::move(shipment)); });
  }
  return whole_mesh_of(part_of_shipments(shipments));
}

TEST(MeshParts, SplitAndGatheredGiveTheSameMesh) {
  for (int parts : {1, 2, 4}) {  // slabs along the grid planes of the 4 x 4 x 4 cells
    SlicedCube cube(parts);
    const auto split = split_mesh(cube.mesh, cube.part_of, parts);
    ASSERT_EQ(split.size(), static_cast<std::size_t>(parts));
    const Mesh<3> out = gathered(split);
    ASSERT_EQ(out.vertex_count(), cube.mesh.vertex_count());
    for (Index v = 0; v < out.vertex_count(); ++v) EXPECT_EQ(out.vertex(v), cube.mesh.vertex(v)) << v;
    EXPECT_EQ(placed(out, out.elements(), out.element_refs()), placed(cube.mesh, cube.mesh.elements(), cube.mesh.element_refs()));
    EXPECT_EQ(placed(out, out.facets(), out.facet_refs()), placed(cube.mesh, cube.mesh.facets(), cube.mesh.facet_refs()));
    EXPECT_EQ(placed(out, out.lines(), out.line_refs()), placed(cube.mesh, cube.mesh.lines(), cube.mesh.line_refs()));
    EXPECT_EQ(tagged_points(out, out.corners()), tagged_points(cube.mesh, cube.mesh.corners()));
    EXPECT_EQ(out.ridges().size(), cube.mesh.ridges().size());
    EXPECT_TRUE(out.required_vertices().empty());
    EXPECT_TRUE(out.required_triangles().empty());
  }
}

TEST(MeshParts, PartsAreConsistentWithRequiredInterfaces) {
  SlicedCube cube(3);
  for (MeshPart<3> part : split_mesh(cube.mesh, cube.part_of, 3)) {
    part.mesh.build_topology();
    ConsistencyOptions options;
    options.require_boundary_facets = true;
    EXPECT_EQ(check_consistency(part.mesh, options), std::vector<std::string>{});
    Index interface_facets = 0;
    for (Index f = 0; f < part.mesh.facet_count(); ++f)
      if (part.mesh.facet_ref(f) == kInterfaceRef) {
        ++interface_facets;
        EXPECT_NE(std::find(part.mesh.required_triangles().begin(), part.mesh.required_triangles().end(), f),
                  part.mesh.required_triangles().end());
        for (Index v : part.mesh.facet(f))
          EXPECT_NE(std::find(part.mesh.required_vertices().begin(), part.mesh.required_vertices().end(), v),
                    part.mesh.required_vertices().end());
      }
    EXPECT_GT(interface_facets, 0);
    for (Index v = 0; v < part.mesh.vertex_count(); ++v) EXPECT_EQ(part.mesh.vertex(v), cube.mesh.vertex(part.global_ids[v]));
  }
}

// Two cubes sharing an edge, a cube in each part: no interface face between them, yet each part
// holds one side of the shared edge, so its vertices are required in both (a part's loop must
// neither split the edge on its side nor move them); gathered back, they are not required.
TEST(MeshParts, NonManifoldPlacesAreRequiredInEveryPart) {
  Mesh<3> mesh = mesh_test::cubes_sharing_an_edge(2);
  mesh.build_topology();
  std::vector<int> part_of(static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) part_of[k] = mesh.element_ref(k) == 2 ? 1 : 0;
  const std::vector<MeshPart<3>> parts = split_mesh(mesh, part_of, 2);
  for (const MeshPart<3>& part : parts) {
    EXPECT_EQ(part.mesh.required_vertices().size(), 3u);
    for (Index v : part.mesh.required_vertices()) {
      EXPECT_EQ(part.mesh.vertex(v)[0], 1);
      EXPECT_EQ(part.mesh.vertex(v)[1], 1);
    }
  }
  EXPECT_TRUE(gathered(parts).required_vertices().empty());
}

// The whole mesh as one part (the scatter's start, the gather's end: part_migration.hpp): pinned by
// the mesh its required vertex, as a non-manifold place the shared edge's; back as a mesh, only the
// mesh's required vertex is required, and everything else is the mesh's.
TEST(MeshParts, TheWholeMeshAsAPartKeepsWhyItsVerticesArePinned) {
  Mesh<3> mesh = mesh_test::cubes_sharing_an_edge(2);
  mesh.build_topology();
  mesh.required_vertices().push_back(0);
  const MeshPart<3> part = whole_mesh_part(mesh);
  ASSERT_EQ(part.pinned.size(), static_cast<std::size_t>(mesh.vertex_count()));
  int non_manifold = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(part.global_ids[v], v);
    EXPECT_EQ((part.pinned[v] & kPinnedByMesh) != 0, v == 0);
    if (part.pinned[v] & kPinnedNonManifold) {
      ++non_manifold;
      EXPECT_EQ(mesh.vertex(v)[0], 1);
      EXPECT_EQ(mesh.vertex(v)[1], 1);
    }
  }
  EXPECT_EQ(non_manifold, 3);
  const Mesh<3> back = whole_mesh_of(part);
  EXPECT_EQ(back.required_vertices(), std::vector<Index>{0});
  EXPECT_TRUE(std::equal(back.vertices().begin(), back.vertices().end(), mesh.vertices().begin(), mesh.vertices().end()));
  EXPECT_TRUE(std::equal(back.elements().begin(), back.elements().end(), mesh.elements().begin(), mesh.elements().end()));
  EXPECT_EQ(back.facet_count(), mesh.facet_count());
}

TEST(MeshParts, AGatheredMeshWithAnInterfaceLeftIsRefused) {
  SlicedCube cube(2);
  EXPECT_THROW(whole_mesh_of(split_mesh(cube.mesh, cube.part_of, 2)[0]), Error);
}

TEST(PartMessage, APartComesBackUnchanged) {
  SlicedCube cube(2);
  for (const MeshPart<3>& part : split_mesh(cube.mesh, cube.part_of, 2)) {
    const std::vector<std::byte> bytes = pack_part(part.mesh, std::span<const Index>(part.global_ids));
    EXPECT_EQ(packed_dimension(bytes), 3);
    const MeshPart<3> back = unpack_part<3>(bytes);
    EXPECT_EQ(pack_part(back.mesh, std::span<const Index>(back.global_ids)), bytes);
    EXPECT_EQ(back.global_ids, part.global_ids);
  }
}

TEST(PartMessage, RefusesBrokenMessages) {
  SlicedCube cube(2);
  const MeshPart<3> part = split_mesh(cube.mesh, cube.part_of, 2).front();
  std::vector<std::byte> bytes = pack_part(part.mesh, std::span<const Index>(part.global_ids));
  EXPECT_THROW(unpack_part<2>(bytes), Error);
  bytes.pop_back();
  EXPECT_THROW(unpack_part<3>(bytes), Error);
}

// The cube made P2, every node moved off its edge's midpoint by its own amount.
Mesh<3> curved_cube(const SlicedCube& cube) {
  Mesh<3> mesh = cube.mesh;
  mesh.make_p2();
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const Vec<3> mid = mesh.edge_node(e);
    mesh.edge_node(e) = mid + Vec<3>{0.01 * std::sin(7 * mid[1]), 0.01 * std::cos(5 * mid[2]), 0.003 * (e % 7)};
  }
  return mesh;
}

TEST(MeshParts, P2NodesGoThroughSplitMessagesAndGathering) {
  SlicedCube cube(3);
  const Mesh<3> mesh = curved_cube(cube);
  std::vector<MeshPart<3>> parts = split_mesh(mesh, cube.part_of, 3);
  for (MeshPart<3>& part : parts) {
    ASSERT_TRUE(part.mesh.is_p2());
    for (Index e = 0; e < part.mesh.edge_count(); ++e) {
      const auto [a, b] = part.mesh.edge_vertices(e);
      EXPECT_EQ(part.mesh.edge_node(e), mesh.edge_node(mesh.find_edge(part.global_ids[a], part.global_ids[b])));
    }
    const std::vector<std::byte> bytes = pack_part(part.mesh, std::span<const Index>(part.global_ids));
    part = unpack_part<3>(bytes);
    ASSERT_TRUE(part.mesh.is_p2());
    EXPECT_EQ(pack_part(part.mesh, std::span<const Index>(part.global_ids)), bytes) << "byte for byte";
    part.pinned.assign(part.global_ids.size(), 0);  // (a message carries none)
  }
  const Mesh<3> whole = gathered(parts);
  ASSERT_TRUE(whole.is_p2());
  ASSERT_EQ(whole.edge_count(), mesh.edge_count());
  for (Index e = 0; e < whole.edge_count(); ++e) {  // every vertex in a part: the mesh's vertex ids
    const auto [a, b] = whole.edge_vertices(e);
    EXPECT_EQ(whole.edge_node(e), mesh.edge_node(mesh.find_edge(a, b))) << a << ' ' << b;
  }
}

// A shipment carries each edge's node once (all a part's edges when all its elements go), and a
// shipment whose nodes do not match its elements' edges is refused: one missing or one too many.
TEST(MeshParts, AShipmentCarriesEachEdgeNodeOnce) {
  SlicedCube cube(2);
  MeshPart<3> part = split_mesh(curved_cube(cube), cube.part_of, 2).front();
  part.mesh.build_topology();
  std::vector<Shipment<3>> shipments;
  const std::vector<int> to_one(static_cast<std::size_t>(part.mesh.element_count()), 0);
  pack_shipments<3>(part, to_one, 1, [&](int, Shipment<3> shipment) { shipments.push_back(std::move(shipment)); });
  ASSERT_EQ(shipments.front().nodes.size(), static_cast<std::size_t>(part.mesh.edge_count()));
  EXPECT_NO_THROW(part_of_shipments(shipments));
  std::vector<Shipment<3>> fewer = shipments, more = shipments;
  fewer.front().nodes.pop_back();
  more.front().nodes.push_back(more.front().nodes.front());
  EXPECT_THROW(part_of_shipments(fewer), Error);
  EXPECT_THROW(part_of_shipments(more), Error);
}

// Parts of the middle slab and of the last, the first slab in no part; each part moves the nodes of
// its edges off the interfaces, and its elements are said to come from two processes in turn. Each
// process's updates are exactly the moved edges its elements hold (none on an interface facet), with
// the moved nodes; written into the whole mesh, they make exactly those moves and keep every other
// node and its elements.
TEST(MeshParts, CurvedNodesGoBackToTheProcessesThatHoldTheirEdges) {
  SlicedCube cube(3);
  Mesh<3> mesh = curved_cube(cube);
  std::vector<int> part_of = cube.part_of;
  for (int& p : part_of) p -= 1;  // slab 0 in no part
  std::vector<MeshPart<3>> parts = split_mesh(mesh, part_of, 2);
  Mesh<3> expected = mesh;
  Index moved = 0;
  std::vector<NodeUpdate<3>> updates;
  for (MeshPart<3>& part : parts) {
    part.mesh.build_topology();
    const std::unordered_set<std::uint64_t> interface = interface_edge_keys(part.mesh);
    for (Index e = 0; e < part.mesh.edge_count(); ++e) {
      const auto [a, b] = part.mesh.edge_vertices(e);
      if (interface.contains(Mesh<3>::edge_key(a, b))) continue;
      part.mesh.edge_node(e)[0] += 1e-3;
      expected.edge_node(expected.find_edge(part.global_ids[a], part.global_ids[b]))[0] += 1e-3;
      ++moved;
    }
    std::vector<int> source;
    std::vector<std::set<std::pair<Index, Index>>> held(2);  // per process, the moved edges its elements hold
    for (Index k = 0; k < part.mesh.element_count(); ++k) {
      source.push_back(static_cast<int>(k % 2));
      for (int e = 0; e < 6; ++e) {
        const auto [a, b] = part.mesh.edge_vertices(part.mesh.element_edge(k, e));
        if (!interface.contains(Mesh<3>::edge_key(a, b))) held[k % 2].insert(std::minmax(part.global_ids[a], part.global_ids[b]));
      }
    }
    const auto by_source = node_updates_by_source(part, source, 2);
    ASSERT_EQ(by_source.size(), 2u);
    for (int p = 0; p < 2; ++p) {
      std::set<std::pair<Index, Index>> sent;
      for (const NodeUpdate<3>& update : by_source[p]) {
        EXPECT_TRUE(sent.insert(std::minmax(update.ends[0], update.ends[1])).second) << "an edge sent twice to " << p;
        EXPECT_EQ(update.node, expected.edge_node(expected.find_edge(update.ends[0], update.ends[1])));
        updates.push_back(update);
      }
      EXPECT_EQ(sent, held[p]) << "process " << p;
    }
  }
  ASSERT_GT(moved, 0);
  MeshPart<3> whole = whole_mesh_part(mesh);
  apply_node_updates<3>(whole, updates);
  EXPECT_EQ(std::vector<Vec<3>>(whole.mesh.edge_nodes().begin(), whole.mesh.edge_nodes().end()),
            std::vector<Vec<3>>(expected.edge_nodes().begin(), expected.edge_nodes().end()));
  EXPECT_TRUE(
      std::equal(whole.mesh.elements().begin(), whole.mesh.elements().end(), cube.mesh.elements().begin(), cube.mesh.elements().end()));
}

TEST(PartMessage, RefusesP2NodesThatDoNotFit) {
  SlicedCube cube(2);
  const Mesh<3> mesh = curved_cube(cube);
  const MeshPart<3> part = split_mesh(mesh, cube.part_of, 2).front();
  std::vector<std::byte> bytes = pack_part(part.mesh, std::span<const Index>(part.global_ids));
  // The nodes are the message's last array: one node fewer, with the count to match.
  bytes.resize(bytes.size() - sizeof(Vec<3>));
  const std::size_t node_bytes = part.mesh.edge_count() * sizeof(Vec<3>);
  std::uint64_t count = part.mesh.edge_count() - 1;
  std::memcpy(bytes.data() + bytes.size() - (node_bytes - sizeof(Vec<3>)) - sizeof count, &count, sizeof count);
  EXPECT_THROW(unpack_part<3>(bytes), Error);
}

}  // namespace
}  // namespace hocav
