#include "metric/surface_metric.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "mesh/baffle_orientation.hpp"

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

// Per vertex, the sum of the outward normals `outward(f)` of its facets, normalized; zero on no
// facet and where they (nearly) cancel, which leaves no direction worth trusting.
template <int D, typename Outward>
std::vector<Vec<D>> normals_of_facets(const Mesh<D>& mesh, Outward outward) {
  std::vector<Vec<D>> sums(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<double> magnitudes(sums.size(), 0.0);
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const Vec<D> normal = outward(f);
    for (Index v : mesh.facet(f)) {
      sums[static_cast<std::size_t>(v)] += normal;
      magnitudes[static_cast<std::size_t>(v)] += norm(normal);
    }
  }
  for (std::size_t v = 0; v < sums.size(); ++v) {
    double length = norm(sums[v]);
    sums[v] = length > 1e-12 * magnitudes[v] ? (1 / length) * sums[v] : Vec<D>{};
  }
  return sums;
}

// The metric at each vertex of `mesh` from its vertex normal (`normals`), boundary or not.
template <int D>
std::vector<SymMat<D>> metrics_of_normals(const Mesh<D>& mesh, const std::vector<Vec<D>>& normals, const SurfaceSizes& sizes) {
  for (double h : {sizes.normal, sizes.tangential, sizes.interior})
    if (!(h > 0) || !std::isfinite(h)) throw Error("surface metric: sizes must be positive, not " + std::to_string(h));
  const double normal = 1 / (sizes.normal * sizes.normal), tangential = 1 / (sizes.tangential * sizes.tangential);
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto& facet : mesh.facets())
    for (Index v : facet) on_boundary[static_cast<std::size_t>(v)] = true;
  std::vector<SymMat<D>> metrics(normals.size());
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    if (!on_boundary[v])
      metrics[v] = surface_interior_metric<D>(sizes);
    else if (normals[v] == Vec<D>{})
      metrics[v] = normal * SymMat<D>::identity();
    else
      metrics[v] = tangential * SymMat<D>::identity() + (normal - tangential) * outer(normals[v]);
  }
  return metrics;
}

}  // namespace

template <int D>
std::vector<Vec<D>> boundary_vertex_normals(const Mesh<D>& mesh) {
  if (!mesh.has_topology() && mesh.facet_count() > 0) throw Error("boundary normals: the mesh has no topology (build_topology)");
  const std::vector<Index> turned = baffle_facets_to_turn(mesh);  // (ascending)
  return normals_of_facets(mesh, [&](Index f) {
    const auto& facet = mesh.facet(f);
    const Vec<D> normal = facet_normal(mesh, facet);
    // Whatever the facet's vertex order, as Mesh::orient_boundary_facets_outward would orient it:
    // away from its element on the domain's boundary, from the side of the smaller ref on an
    // interface; a baffle like its patch's first facet.
    const Index k = mesh.outward_element(f);
    if (k == kNoIndex) return std::binary_search(turned.begin(), turned.end(), f) ? -normal : normal;
    const auto& element = mesh.element(k);
    const Index opposite = *std::find_if(element.begin(), element.end(),
                                         [&](Index v) { return std::find(facet.begin(), facet.end(), v) == facet.end(); });
    return dot(normal, mesh.vertex(facet[0]) - mesh.vertex(opposite)) < 0 ? -normal : normal;
  });
}

template <int D>
std::vector<SymMat<D>> surface_metric_at_vertices(const Mesh<D>& mesh, const SurfaceSizes& sizes) {
  return metrics_of_normals(mesh, boundary_vertex_normals(mesh), sizes);
}

template <int D>
std::vector<SymMat<D>> surface_metric_at_boundary(const Mesh<D>& boundary, const SurfaceSizes& sizes) {
  return metrics_of_normals(boundary,
                            normals_of_facets(boundary, [&boundary](Index f) { return facet_normal(boundary, boundary.facet(f)); }), sizes);
}

template std::vector<Vec<2>> boundary_vertex_normals(const Mesh<2>&);
template std::vector<Vec<3>> boundary_vertex_normals(const Mesh<3>&);
template std::vector<SymMat<2>> surface_metric_at_vertices(const Mesh<2>&, const SurfaceSizes&);
template std::vector<SymMat<3>> surface_metric_at_vertices(const Mesh<3>&, const SurfaceSizes&);
template std::vector<SymMat<2>> surface_metric_at_boundary(const Mesh<2>&, const SurfaceSizes&);
template std::vector<SymMat<3>> surface_metric_at_boundary(const Mesh<3>&, const SurfaceSizes&);

}  // namespace hocav
