#include "parallel/part_adaptation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "../adapt/adapt_test_support.hpp"
#include "../mesh/inner_facet_meshes.hpp"
#include "adapt/adaptation_loop.hpp"
#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "metric/analytic_metric.hpp"
#include "parallel/face_key.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {
namespace {

std::vector<SymMat<3>> unit_metrics(const Mesh<3>& mesh) {
  SymMat<3> identity;
  for (int i = 0; i < 3; ++i) identity(i, i) = 1;
  return std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), identity);
}

// The settling at the end of a distributed run (docs/distributed.md §The end in the parts): each part
// moves its boundary vertices back onto the geometry but its interface vertices, which both sides
// keep where they are, and keeps the whole mesh's tags without adding the interfaces'.
TEST(PartAdaptation, SettlesAPartsBoundaryButItsInterfaces) {
  Mesh<3> mesh = generate_cube(6);
  mesh.build_topology();
  classify_vertices(mesh, 45);
  // Every other vertex inside the side z = 0 is 0.01 off it (a split that could not use its point
  // on the geometry leaves it so).
  std::set<Index> off;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec3& x = mesh.vertex(v);
    if (x[2] == 0 && x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1 && std::lround(6 * (x[0] + x[1])) % 2 == 1) {
      x[2] = 0.01;
      off.insert(v);
    }
  }
  std::vector<int> part_of;  // two halves across x = 0.5, whose interface crosses the side z = 0
  for (Index k = 0; k < mesh.element_count(); ++k) {
    double x = 0;
    for (Index v : mesh.element(k)) x += mesh.vertex(v)[0];
    part_of.push_back(x < 2 ? 0 : 1);
  }
  Index settled = 0;
  std::set<Index> frozen;  // (in both parts)
  for (MeshPart<3> part : split_mesh(mesh, part_of, 2)) {
    const std::size_t corners = part.mesh.corners().size();
    const Index lines = part.mesh.line_count();
    part.mesh.build_topology();
    const std::vector<char> on_interface = interface_vertex_flags(part.mesh);
    const BoundarySettling settling = settle_part_boundary<3>(part, unit_metrics(part.mesh), adapt_test::unit_box_sides<3>(), 45);
    EXPECT_EQ(settling.partly + settling.blocked, 0);
    settled += settling.settled;
    for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
      const Index whole = part.global_ids[v];
      if (!off.contains(whole)) continue;
      if (on_interface[v]) {
        frozen.insert(whole);
        EXPECT_EQ(part.mesh.vertex(v), mesh.vertex(whole)) << "interface vertex " << whole << " moved";
      } else {
        EXPECT_NEAR(part.mesh.vertex(v)[2], 0, 1e-12) << "vertex " << whole << " left off the side";
      }
    }
    EXPECT_EQ(part.mesh.corners().size(), corners) << "the interfaces' corners left";
    EXPECT_EQ(part.mesh.line_count(), lines) << "the interfaces' lines left";
    adapt_test::expect_closed_and_consistent(part.mesh);
  }
  EXPECT_FALSE(frozen.empty());
  EXPECT_EQ(settled + static_cast<Index>(frozen.size()), static_cast<Index>(off.size()));
}

// A facet between two materials on a part's interface shares its face with the interface facet,
// which the face links; the loop moves and replaces the elements on that face, and each facet must
// still name an element face that holds it after the loop (docs/distributed.md §Migration: the
// migration ships a facet with that element).
TEST(PartAdaptation, FacetsOnAnInterfaceFaceStayLinkedToIt) {
  Mesh<3> mesh = mesh_test::two_refs_across_an_interface<3>(4);
  std::vector<int> part_of;  // the two materials, whose facets are then the parts' interface
  for (Index k = 0; k < mesh.element_count(); ++k) part_of.push_back(mesh.element_ref(k) == 1 ? 0 : 1);
  Index shared_faces = 0;
  for (MeshPart<3> part : split_mesh(mesh, part_of, 2)) {
    part.mesh.build_topology();
    AdaptationSettings settings = part_settings({});
    settings.threads = 1;
    adapt_part_measured<3>(part, adapt_test::uniform_metric<3>(0.08), nullptr, settings);
    ASSERT_GT(part.mesh.element_count(), 4 * mesh.element_count() / 2);
    for (Index f = 0; f < part.mesh.facet_count(); ++f) {
      const Index k = part.mesh.facet_element_face(f) / 4;
      const int face = static_cast<int>(part.mesh.facet_element_face(f) % 4);
      EXPECT_TRUE(sorted_key<3>(mesh_test::element_face(part.mesh, k, face)) == sorted_key<3>(part.mesh.facet(f)))
          << "facet " << f << " (ref " << part.mesh.facet_ref(f) << ") names face " << face << " of element " << k
          << ", which does not hold it";
      shared_faces += part.mesh.facet_ref(f) == 9;
    }
  }
  EXPECT_GT(shared_faces, 0);  // the material facets went with one part, on its interface
}

// Where an interface meets a flat side of the domain in the metric's fine layer, a part cuts the
// side's edges at the interface vertices (docs/distributed.md §Interfaces refined first): left
// long, they kept the splits next to them cutting inner edges ever nearer the side, without end.
TEST(PartAdaptation, SplitsAFlatSidesEdgesAtItsInterfaceVertices) {
  Mesh<3> mesh = generate_cube(4);
  mesh.build_topology();
  classify_vertices(mesh, 45);
  std::vector<int> part_of;  // two halves across z = 0.5, the metric's finest plane
  for (Index k = 0; k < mesh.element_count(); ++k) {
    double z = 0;
    for (Index v : mesh.element(k)) z += mesh.vertex(v)[2];
    part_of.push_back(z < 2 ? 0 : 1);
  }
  AnalyticMetricSpec spec;
  spec.name = "linear";  // sizes along z from 0.02 at z = 0.5; the interface's own edges are not long
  spec.h_min = 0.02;
  spec.h_max = 0.5;
  const AdaptationMetric<3> metric(spec, {});
  for (MeshPart<3> part : split_mesh(mesh, part_of, 2)) {
    part.mesh.build_topology();
    AdaptationSettings settings = part_settings({});
    settings.threads = 1;
    adapt_part_measured<3>(part, metric, nullptr, settings);
    adapt_test::expect_closed_and_consistent(part.mesh);
    EXPECT_TRUE(adapt_test::every_element_positive(part.mesh));
    const std::vector<char> on_interface = interface_vertex_flags(part.mesh);
    double longest = 0;  // across z, of the sides' edges at an interface vertex
    Index edges = 0;
    for (Index f = 0; f < part.mesh.facet_count(); ++f) {
      if (part.mesh.facet_removed(f) || part.mesh.facet_ref(f) == kInterfaceRef) continue;
      const auto& facet = part.mesh.facet(f);
      for (int i = 0; i < 3; ++i) {
        const Index a = facet[i], b = facet[(i + 1) % 3];
        if (on_interface[a] == on_interface[b]) continue;
        longest = std::max(longest, std::abs(part.mesh.vertex(a)[2] - part.mesh.vertex(b)[2]));
        ++edges;
      }
    }
    EXPECT_GT(edges, 0);
    EXPECT_LT(longest, 0.1) << "a side's edge at an interface vertex left " << longest << " long across the fine layer (0.25 at the start)";
  }
}

}  // namespace
}  // namespace hocav
