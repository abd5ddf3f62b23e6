// The curved boundary of the generated sphere shell (docs/benchmarks.md, boundary accuracy): P2
// mid nodes proposed by the P3 surrogate of its own facets (no knowledge of the spheres).
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/concentric_shell.hpp"
#include "gmsh_requirement.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/boundary_distance.hpp"
#include "surface/boundary_proposals.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

double curved_distance(const Mesh<3>& mesh, const BoundaryGeometry<3>& proposer, const BoundaryGeometry<3>& spheres) {
  Mesh<3> curved = mesh;
  BoundaryProposals<3> proposals(mesh, proposer);
  EXPECT_GT(apply_boundary_proposals(curved, proposals), 0);
  return max_boundary_distance(curved, spheres);
}

TEST(SurfaceAccuracy, SphereShellSurrogateIsWithinTwiceTheExactNodes) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const Mesh<3> mesh = generate_sphere_shell({0.5, 1.0, 0.125});
  const AnalyticBoundary<3> spheres = concentric_shell_boundary<3>(0.5, 1.0);
  const double straight = max_boundary_distance(mesh, spheres);
  const double surrogate = curved_distance(mesh, P3Surrogate<3>(mesh), spheres);
  const double exact = curved_distance(mesh, spheres, spheres);  // nodes on the spheres, like gmsh's
  std::printf("sphere shell h = 0.125: P1 %.3e, P2 on the surrogate %.3e (%.0fx smaller), exact nodes %.3e (%.2fx)\n", straight, surrogate,
              straight / surrogate, exact, surrogate / exact);
  EXPECT_GT(straight / surrogate, 100);
  EXPECT_LT(surrogate / exact, 2);
}

}  // namespace
}  // namespace hocav
