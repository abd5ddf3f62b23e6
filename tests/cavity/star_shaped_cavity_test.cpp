// The correction of Delaunay cavities (make_star_shaped): on a mesh that is not Delaunay, the
// cavity grown from an edge's shell around the edge's middle is made star-shaped from it, stays
// connected to the shell, and the cavity operator then accepts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "../mesh/inner_facet_meshes.hpp"
#include "base/small_set.hpp"
#include "cases/structured.hpp"
#include "cavity/cavity_operations.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

template <int D>
bool ball_positive(const Mesh<D>& mesh, Index v) {
  std::vector<Index> ball;
  collect_ball(mesh, v, ball);
  return std::all_of(ball.begin(), ball.end(), [&](Index k) { return element_measure(mesh, k) > 0; });
}

bool on_cube_boundary(const Vec<3>& x) {
  bool on_boundary = false;
  for (int i = 0; i < 3; ++i) on_boundary = on_boundary || x[i] < 1e-9 || x[i] > 1 - 1e-9;
  return on_boundary;
}

// A cube whose inner vertices moved at random (each move kept only if its ball stays positive):
// far from Delaunay, so grown cavities are often not star-shaped.
Mesh<3> jittered_cube(int cells, std::mt19937& random) {
  Mesh<3> mesh = generate_cube(cells);
  std::uniform_real_distribution<double> offset(-0.45 / cells, 0.45 / cells);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const Vec<3> start = mesh.vertex(v);
    if (on_cube_boundary(start)) continue;
    for (int i = 0; i < 3; ++i) mesh.vertex(v)[i] += offset(random);
    if (!ball_positive(mesh, v)) mesh.vertex(v) = start;
  }
  return mesh;
}

// Whether x sees every face of the cavity's boundary that belongs to an element past the first `kept`.
bool sees_every_face(const Mesh<3>& mesh, const std::vector<Index>& cavity, std::size_t kept, const Vec<3>& x) {
  for (std::size_t i = kept; i < cavity.size(); ++i)
    for (int face = 0; face <= 3; ++face) {
      const Index n = mesh.neighbor(cavity[i], face);
      if (n != kNoIndex && small_set_holds(cavity, n)) continue;
      std::array<Vec<3>, 4> points;
      for (int j = 0; j <= 3; ++j) points[j] = j == face ? x : mesh.vertex(mesh.element(cavity[i])[j]);
      if (!(signed_measure<3>(points) > 0)) return false;
    }
  return true;
}

bool connected_to_prefix(const Mesh<3>& mesh, const std::vector<Index>& cavity, std::size_t kept) {
  std::vector<Index> reached(cavity.begin(), cavity.begin() + static_cast<std::ptrdiff_t>(kept));
  for (std::size_t next = 0; next < reached.size(); ++next)
    for (int face = 0; face <= 3; ++face) {
      const Index n = mesh.neighbor(reached[next], face);
      if (n != kNoIndex && small_set_holds(cavity, n) && !small_set_holds(reached, n)) reached.push_back(n);
    }
  return reached.size() == cavity.size();
}

TEST(StarShapedCavity, DelaunayCavitiesOfEdgeMiddlesBecomeStarShapedAndAccepted) {
  std::mt19937 random(7);
  Mesh<3> mesh = jittered_cube(6, random);
  std::uniform_real_distribution<double> stretch(1.0, 30.0);
  CavityWorkspace<3> work;
  std::vector<Index> shell, cavity, read;
  int corrected = 0, accepted_raw = 0, accepted = 0, tried = 0;
  for (Index k = 0; k < mesh.element_count(); k += 3) {
    const Index a = mesh.element(k)[0], b = mesh.element(k)[1 + k % 3];
    if (on_cube_boundary(mesh.vertex(a)) || on_cube_boundary(mesh.vertex(b))) continue;  // the loop splits inner edges so
    collect_shell(mesh, a, b, shell);
    std::sort(shell.begin(), shell.end());
    const Vec<3> x = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    SymMat<3> metric = SymMat<3>::identity();
    metric(k % 3, k % 3) = stretch(random);
    cavity = shell;
    grow_delaunay_cavity(mesh, cavity, read, x, metric);
    const std::vector<Index> grown = cavity;
    const std::size_t read_before = read.size();
    make_star_shaped(mesh, cavity, shell.size(), read, x);
    ++tried;
    ASSERT_TRUE(std::equal(shell.begin(), shell.end(), cavity.begin())) << "the shell is kept, first";
    ASSERT_TRUE(sees_every_face(mesh, cavity, shell.size(), x)) << "edge " << a << "-" << b;
    ASSERT_TRUE(connected_to_prefix(mesh, cavity, shell.size())) << "edge " << a << "-" << b;
    ASSERT_EQ(cavity.size() + (read.size() - read_before), grown.size()) << "what is dropped is reported";
    corrected += cavity.size() < grown.size();
    const Index v = mesh.add_vertex(x);
    accepted_raw += work.cavity_operator.plan(mesh, grown, v, {}) == CavityStatus::kAccepted;
    accepted += work.cavity_operator.plan(mesh, cavity, v, {}) == CavityStatus::kAccepted;
    mesh.pop_vertex();
  }
  // The case must exercise the correction, and the correction must pay.
  EXPECT_GT(corrected, tried / 10) << tried << " cavities";
  EXPECT_LT(accepted_raw, tried - tried / 10);
  EXPECT_GE(accepted, tried - tried / 50) << "raw: " << accepted_raw << " of " << tried;
}

// The growth stops at a facet inside the domain from either of its sides, though the facet is
// linked from one side only: from every element on the interface, the middle of its interface face
// (inside both elements' circumspheres) grows no element across.
TEST(StarShapedCavity, TheGrowthStopsAtAnInterfaceFromBothSides) {
  const Mesh<3> mesh = mesh_test::two_refs_across_an_interface<3>(4);
  std::vector<Index> cavity, read;
  int linked_sides = 0, unlinked_sides = 0;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face < 4; ++face) {
      const Index across = mesh.neighbor(k, face);
      if (across == kNoIndex || mesh.element_ref(across) == mesh.element_ref(k)) continue;
      ASSERT_TRUE(mesh.face_has_facet(k, face)) << "element " << k << " face " << face;
      (mesh.element_face_facet(k, face) != kNoIndex ? linked_sides : unlinked_sides) += 1;
      Vec<3> x{};
      for (int i = 0; i < 3; ++i) x += mesh.vertex(mesh.element(k)[face_vertices<3>(face)[i]]) * (1.0 / 3);
      cavity = {k};
      grow_delaunay_cavity(mesh, cavity, read, x, SymMat<3>::identity());
      EXPECT_EQ(std::count(cavity.begin(), cavity.end(), across), 0) << "element " << k << " grew across its face " << face;
      EXPECT_TRUE(std::all_of(cavity.begin(), cavity.end(), [&](Index c) { return mesh.element_ref(c) == mesh.element_ref(k); }));
    }
  EXPECT_EQ(linked_sides, 32);  // the plane's 16 squares, two triangles each, seen from each side once
  EXPECT_EQ(unlinked_sides, 32);
}

}  // namespace
}  // namespace hocav
