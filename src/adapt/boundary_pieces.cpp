#include "adapt/boundary_pieces.hpp"

#include <algorithm>
#include <cstdint>

#include "base/small_set.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {

template <int D>
void facets_through(const Mesh<D>& mesh, std::span<const Index> elements, std::span<const Index> through, std::vector<Index>& out) {
  out.clear();
  for (Index k : elements)
    for (int face = 0; face <= D; ++face) {
      const Index f = mesh.element_face_facet(k, face);
      if (f == kNoIndex) continue;
      const auto& vertices = mesh.facet(f);
      if (std::all_of(through.begin(), through.end(),
                      [&](Index v) { return std::find(vertices.begin(), vertices.end(), v) != vertices.end(); }) &&
          std::find(out.begin(), out.end(), f) == out.end())
        out.push_back(f);
    }
}

template <int D>
bool holds_required_facet(const Mesh<D>& mesh, std::span<const Index> facets) {
  const std::vector<Index>& required = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  return std::any_of(facets.begin(), facets.end(),
                     [&](Index f) { return std::find(required.begin(), required.end(), f) != required.end(); });
}

void lines_through(const Mesh<3>& mesh, Index v, std::vector<Index>& out) {
  out.clear();
  for (Index l = 0; l < mesh.line_count(); ++l)
    if (!mesh.line_removed(l) && (mesh.line(l)[0] == v || mesh.line(l)[1] == v)) out.push_back(l);
}

void lines_along(const Mesh<3>& mesh, Index a, Index b, std::vector<Index>& out) {
  out.clear();
  const std::uint64_t key = Mesh<3>::edge_key(a, b);
  for (Index l = 0; l < mesh.line_count(); ++l)
    if (!mesh.line_removed(l) && Mesh<3>::edge_key(mesh.line(l)[0], mesh.line(l)[1]) == key) out.push_back(l);
}

namespace {

template <int D>
Vec<D> facet_centroid(const Mesh<D>& mesh, const typename Mesh<D>::Facet& facet) {
  Vec<D> sum{};
  for (Index v : facet) sum = sum + mesh.vertex(v);
  return (1.0 / D) * sum;
}

// A facet with these vertices and ref, replacing one of normal `old_normal`: turned by less than the
// feature angle, and (with a geometry, hausd > 0) its centroid within hausd of the geometry.
template <int D>
bool facet_close(const AdaptationMesh<D>& adaptation, const typename Mesh<D>::Facet& vertices, int ref, const Vec<D>& old_normal,
                 double cos_feature_angle, double hausd) {
  const Mesh<D>& mesh = adaptation.mesh();
  if (!turns_less<D>(mesh, vertices, old_normal, cos_feature_angle)) return false;
  if (!adaptation.geometry() || hausd <= 0) return true;
  // The search starts from a vertex's last projection, when one has been made.
  Index hint = kNoIndex;
  for (Index v : vertices)
    if (hint == kNoIndex) hint = adaptation.surface_hint(v);
  return adaptation.geometry()->project(facet_centroid<D>(mesh, vertices), {ref, hint}).distance <= hausd;
}

}  // namespace

template <int D>
Vec<D> area_normal(const Mesh<D>& mesh, const typename Mesh<D>::Facet& f) {
  if constexpr (D == 2) {
    const Vec2 e = mesh.vertex(f[1]) - mesh.vertex(f[0]);
    return Vec2{e[1], -e[0]};
  } else {
    return cross(mesh.vertex(f[1]) - mesh.vertex(f[0]), mesh.vertex(f[2]) - mesh.vertex(f[0]));
  }
}

template <int D>
bool turns_less(const Mesh<D>& mesh, const typename Mesh<D>::Facet& vertices, const Vec<D>& old_normal, double cos_feature_angle) {
  const Vec<D> normal = area_normal<D>(mesh, vertices);
  return dot(normal, old_normal) > cos_feature_angle * norm(normal) * norm(old_normal);
}

template <int D>
bool new_facets_turn_less(const Mesh<D>& mesh, const CavityOperator<D>& plan, double cos_feature_angle) {
  return std::all_of(plan.new_facets().begin(), plan.new_facets().end(), [&](const auto& facet) {
    return turns_less<D>(mesh, facet.vertices, area_normal<D>(mesh, mesh.facet(facet.replaced)), cos_feature_angle);
  });
}

template <int D>
bool collapse_folds_surface(const Mesh<D>& mesh, const CavityOperator<D>& plan, Index removed, Index kept,
                            std::span<const Index> removed_facets, std::vector<Index>& ball, std::vector<Index>& kept_facets) {
  collect_ball(mesh, kept, ball);
  const Index center[1] = {kept};
  facets_through(mesh, std::span<const Index>(ball), center, kept_facets);
  const auto kept_neighbor = [&](Index v) {
    return std::any_of(kept_facets.begin(), kept_facets.end(), [&](Index f) { return small_set_holds(mesh.facet(f), v); });
  };
  for (Index f : removed_facets) {
    if (small_set_holds(mesh.facet(f), kept)) continue;  // its far vertex is the edge's: shared, as it should be
    for (Index v : mesh.facet(f))
      if (v != removed && kept_neighbor(v) && std::none_of(removed_facets.begin(), removed_facets.end(), [&](Index g) {
            return small_set_holds(mesh.facet(g), kept) && small_set_holds(mesh.facet(g), v);
          }))
        return true;
  }
  const auto sorted = [](auto vertices) {
    std::sort(vertices.begin(), vertices.end());
    return vertices;
  };
  return std::any_of(plan.new_facets().begin(), plan.new_facets().end(), [&](const auto& created) {
    const auto created_vertices = sorted(created.vertices);
    return std::any_of(kept_facets.begin(), kept_facets.end(), [&](Index f) { return sorted(mesh.facet(f)) == created_vertices; });
  });
}

template <int D>
bool boundary_change_acceptable(const AdaptationMesh<D>& adaptation, const CavityOperator<D>& plan, double cos_feature_angle,
                                double hausd) {
  const Mesh<D>& mesh = adaptation.mesh();
  return std::all_of(plan.new_facets().begin(), plan.new_facets().end(), [&](const auto& facet) {
    return facet_close<D>(adaptation, facet.vertices, facet.ref, area_normal<D>(mesh, mesh.facet(facet.replaced)), cos_feature_angle,
                          hausd);
  });
}

template <int D>
bool facet_stays_close(const AdaptationMesh<D>& adaptation, Index facet, const Vec<D>& old_area_normal, double cos_feature_angle,
                       double hausd) {
  const Mesh<D>& mesh = adaptation.mesh();
  return facet_close<D>(adaptation, mesh.facet(facet), mesh.facet_ref(facet), old_area_normal, cos_feature_angle, hausd);
}

template bool holds_required_facet(const Mesh<2>&, std::span<const Index>);
template bool holds_required_facet(const Mesh<3>&, std::span<const Index>);
template void facets_through(const Mesh<2>&, std::span<const Index>, std::span<const Index>, std::vector<Index>&);
template void facets_through(const Mesh<3>&, std::span<const Index>, std::span<const Index>, std::vector<Index>&);
template bool facet_stays_close(const AdaptationMesh<2>&, Index, const Vec2&, double, double);
template bool facet_stays_close(const AdaptationMesh<3>&, Index, const Vec3&, double, double);
template bool turns_less<2>(const Mesh<2>&, const Mesh<2>::Facet&, const Vec2&, double);
template bool turns_less<3>(const Mesh<3>&, const Mesh<3>::Facet&, const Vec3&, double);
template bool new_facets_turn_less(const Mesh<2>&, const CavityOperator<2>&, double);
template bool new_facets_turn_less(const Mesh<3>&, const CavityOperator<3>&, double);
template bool collapse_folds_surface(const Mesh<2>&, const CavityOperator<2>&, Index, Index, std::span<const Index>, std::vector<Index>&,
                                     std::vector<Index>&);
template bool collapse_folds_surface(const Mesh<3>&, const CavityOperator<3>&, Index, Index, std::span<const Index>, std::vector<Index>&,
                                     std::vector<Index>&);
template Vec2 area_normal(const Mesh<2>&, const Mesh<2>::Facet&);
template Vec3 area_normal(const Mesh<3>&, const Mesh<3>::Facet&);
template bool boundary_change_acceptable(const AdaptationMesh<2>&, const CavityOperator<2>&, double, double);
template bool boundary_change_acceptable(const AdaptationMesh<3>&, const CavityOperator<3>&, double, double);

}  // namespace hocav
