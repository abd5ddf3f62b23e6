#include "metric/surface_metric.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace hocav {
namespace {

// The normal of a facet, as long as the facet is large (length or area), either way round.
template <int D>
Vec<D> facet_normal(const Mesh<D>& mesh, const typename Mesh<D>::Facet& facet) {
  if constexpr (D == 2) {
    Vec2 t = mesh.vertex(facet[1]) - mesh.vertex(facet[0]);
    return Vec2{{t[1], -t[0]}};
  } else {
    const Vec3& a = mesh.vertex(facet[0]);
    return 0.5 * cross(mesh.vertex(facet[1]) - a, mesh.vertex(facet[2]) - a);
  }
}

}  // namespace

template <int D>
std::vector<Vec<D>> boundary_vertex_normals(const Mesh<D>& mesh) {
  if (!mesh.has_topology() && mesh.facet_count() > 0) throw Error("boundary normals: the mesh has no topology (build_topology)");
  std::vector<Vec<D>> sums(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<double> magnitudes(sums.size(), 0.0);
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& facet = mesh.facet(f);
    Vec<D> normal = facet_normal(mesh, facet);
    // Outward whatever the facet's vertex order: away from the element vertex opposite the facet.
    Index element_face = mesh.facet_element_face(f);
    Index opposite = mesh.element(element_face / (D + 1))[element_face % (D + 1)];
    if (dot(normal, mesh.vertex(facet[0]) - mesh.vertex(opposite)) < 0) normal = -normal;
    for (Index v : facet) {
      sums[static_cast<std::size_t>(v)] += normal;
      magnitudes[static_cast<std::size_t>(v)] += norm(normal);
    }
  }
  for (std::size_t v = 0; v < sums.size(); ++v) {
    double length = norm(sums[v]);
    // Facets whose normals (nearly) cancel leave no direction worth trusting.
    sums[v] = length > 1e-12 * magnitudes[v] ? (1 / length) * sums[v] : Vec<D>{};
  }
  return sums;
}

template <int D>
std::vector<SymMat<D>> surface_metric_at_vertices(const Mesh<D>& mesh, const SurfaceSizes& sizes) {
  for (double h : {sizes.normal, sizes.tangential, sizes.interior})
    if (!(h > 0) || !std::isfinite(h)) throw Error("surface metric: sizes must be positive, not " + std::to_string(h));
  const double normal = 1 / (sizes.normal * sizes.normal), tangential = 1 / (sizes.tangential * sizes.tangential);
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto& facet : mesh.facets())
    for (Index v : facet) on_boundary[static_cast<std::size_t>(v)] = true;
  std::vector<Vec<D>> normals = boundary_vertex_normals(mesh);
  std::vector<SymMat<D>> metrics(normals.size());
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    if (!on_boundary[v])
      metrics[v] = (1 / (sizes.interior * sizes.interior)) * SymMat<D>::identity();
    else if (normals[v] == Vec<D>{})
      metrics[v] = normal * SymMat<D>::identity();
    else
      metrics[v] = tangential * SymMat<D>::identity() + (normal - tangential) * outer(normals[v]);
  }
  return metrics;
}

template std::vector<Vec<2>> boundary_vertex_normals(const Mesh<2>&);
template std::vector<Vec<3>> boundary_vertex_normals(const Mesh<3>&);
template std::vector<SymMat<2>> surface_metric_at_vertices(const Mesh<2>&, const SurfaceSizes&);
template std::vector<SymMat<3>> surface_metric_at_vertices(const Mesh<3>&, const SurfaceSizes&);

}  // namespace hocav
