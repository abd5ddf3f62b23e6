// Caps (docs/adaptation.md §Operators, "Caps"): a tetrahedron with two facets on one smooth surface
// sits on the boundary like a roof over the edge its facets share. Nothing else mends a poor one:
// swaps keep boundary faces, smoothing keeps its vertices on their surface, and a cut through its
// inner edge leaves halves as flat as the cap. Removing it makes its two inner faces the boundary:
// the facets' shared edge flips to the cap's inner edge, and the domain gives up the cap's volume.
#include <algorithm>
#include <array>
#include <tuple>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

struct ListedCap {
  double quality;
  std::array<Index, 4> vertices;
  bool operator<(const ListedCap& other) const { return std::tie(quality, vertices) < std::tie(other.quality, other.vertices); }
};

// The elements below kBoundaryOnlyQuality with two faces on the domain's boundary, worst first.
std::vector<ListedCap> poor_caps(const AdaptationMesh<3>& am) {
  const Mesh<3>& mesh = am.mesh();
  std::vector<ListedCap> listed;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    if (!(am.quality(k) < kBoundaryOnlyQuality)) continue;
    int facets = 0;
    for (int face = 0; face < 4; ++face) facets += mesh.element_face_facet(k, face) != kNoIndex;
    if (facets == 2) listed.push_back({am.quality(k), mesh.element(k)});
  }
  std::sort(listed.begin(), listed.end());
  return listed;
}

// The element with these vertices now (earlier removals renumber elements), or kNoIndex.
Index element_with(const Mesh<3>& mesh, std::array<Index, 4> vertices, std::vector<Index>& ball) {
  collect_ball(mesh, vertices[0], ball);
  std::sort(vertices.begin(), vertices.end());
  for (Index k : ball) {
    auto element = mesh.element(k);
    std::sort(element.begin(), element.end());
    if (element == vertices) return k;
  }
  return kNoIndex;
}

struct CapScratch {
  std::vector<Index> ball, lines, cavity;
};

// Removes cap k when its facets are one smooth surface's, its inner edge is inside the domain, and
// the boundary it leaves passes the test of splits and collapses.
Refusal remove_cap(AdaptationMesh<3>& am, Index k, const AdaptationLimits& limits, CapScratch& scratch) {
  Mesh<3>& mesh = am.mesh();
  std::array<Index, 2> facets{}, apexes{};  // each facet, and the cap's vertex opposite it
  int found = 0;
  for (int face = 0; face < 4; ++face)
    if (const Index f = mesh.element_face_facet(k, face); f != kNoIndex && found < 2) {
      if (mesh.neighbor(k, face) != kNoIndex) return Refusal::kClasses;  // an inner interface
      facets[static_cast<std::size_t>(found)] = f;
      apexes[static_cast<std::size_t>(found++)] = mesh.element(k)[face];
    }
  if (found != 2 || mesh.facet_ref(facets[0]) != mesh.facet_ref(facets[1]) || holds_required_facet<3>(mesh, facets))
    return Refusal::kClasses;
  std::array<Index, 2> ridge{};  // the facets' shared edge
  int ends = 0;
  for (Index v : mesh.element(k))
    if (v != apexes[0] && v != apexes[1]) ridge[static_cast<std::size_t>(ends++)] = v;
  lines_along(mesh, ridge[0], ridge[1], scratch.lines);
  if (!scratch.lines.empty()) return Refusal::kClasses;
  CavityOptions options;
  options.removed_facets = facets;
  options.exposes_faces = true;
  scratch.cavity.assign({k});
  CavityOperator<3>& plan = am.workspace().cavity_operator;
  if (plan.plan(mesh, scratch.cavity, apexes[0], options) != CavityStatus::kAccepted) return Refusal::kTopology;
  if (!boundary_change_acceptable(am, plan, limits.cos_feature_angle, limits.hausd)) return Refusal::kGeometry;
  const std::array<Index, 4> vertices = mesh.element(k);
  am.commit(plan);
  for (Index v : vertices) am.mark_changed(v);  // no new element marks them
  return Refusal::kNone;
}

}  // namespace

template <int D>
OperationCount remove_boundary_caps(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  OperationCount count;
  if constexpr (D == 3) {
    CapScratch scratch;
    for (const ListedCap& cap : poor_caps(am))
      if (const Index k = element_with(am.mesh(), cap.vertices, scratch.ball); k != kNoIndex) count.add(remove_cap(am, k, limits, scratch));
  }
  return count;
}

template OperationCount remove_boundary_caps(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount remove_boundary_caps(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
