#include "adapt/hausdorff_metric.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "adapt/vertex_classes.hpp"
#include "geom/metric_intersection.hpp"
#include "geom/orthonormal_complement.hpp"
#include "geom/small_linear_system.hpp"
#include "geom/sym_eigen.hpp"
#include "mesh/measure.hpp"
#include "metric/gradation.hpp"

namespace hocav {
namespace {

// A boundary edge of the back mesh: its ends, a ref of its facets, whether it lies on a feature line
// (3D), and its sag: from the chord's middle to the geometry.
template <int D>
struct SaggingEdge {
  Index a = kNoIndex, b = kNoIndex;
  int ref = 0;
  bool on_line = false;
  Vec<D> sag{};
};

// 2D: the facets are the boundary edges, each on the curve of its ref.
std::vector<SaggingEdge<2>> sagging_edges(const Mesh<2>& mesh, const BoundaryGeometry<2>& geometry) {
  std::vector<SaggingEdge<2>> edges;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f)) continue;
    const auto [a, b] = mesh.facet(f);
    const Vec2 middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    edges.push_back({a, b, mesh.facet_ref(f), false, geometry.project(middle, {mesh.facet_ref(f)}).point - middle});
  }
  return edges;
}

// 3D: the facets' edges, each once; a feature line's edge sags to its curve (between the refs of
// its sides), any other to the surface of its ref.
std::vector<SaggingEdge<3>> sagging_edges(const Mesh<3>& mesh, const BoundaryGeometry<3>& geometry) {
  struct Side {
    std::uint64_t key;
    Index facet, a, b;
    bool operator<(const Side& other) const { return std::tie(key, facet) < std::tie(other.key, other.facet); }
  };
  std::vector<Side> sides;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (!mesh.facet_removed(f))
      for (int i = 0; i < 3; ++i) {
        const Index a = mesh.facet(f)[i], b = mesh.facet(f)[(i + 1) % 3];
        sides.push_back({Mesh<3>::edge_key(a, b), f, a, b});
      }
  std::sort(sides.begin(), sides.end());
  std::vector<std::uint64_t> lines;
  for (Index l = 0; l < mesh.line_count(); ++l)
    if (!mesh.line_removed(l)) lines.push_back(Mesh<3>::edge_key(mesh.line(l)[0], mesh.line(l)[1]));
  std::sort(lines.begin(), lines.end());
  std::vector<SaggingEdge<3>> edges;
  for (std::size_t first = 0, last = 0; first < sides.size(); first = last) {
    while (last < sides.size() && sides[last].key == sides[first].key) ++last;
    SaggingEdge<3> edge;
    edge.a = sides[first].a;
    edge.b = sides[first].b;
    edge.ref = mesh.facet_ref(sides[first].facet);
    edge.on_line = std::binary_search(lines.begin(), lines.end(), sides[first].key);
    const Vec3 middle = 0.5 * (mesh.vertex(edge.a) + mesh.vertex(edge.b));
    const Vec3 point = edge.on_line ? geometry.project_on_ridge(middle, edge.ref, mesh.facet_ref(sides[last - 1].facet))
                                    : geometry.project(middle, {edge.ref}).point;
    edge.sag = point - middle;
    edges.push_back(edge);
  }
  return edges;
}

// The curvature along an edge from its sag s and length L: a circle's chord of length L sags by
// L²κ/8 (docs/adaptation.md §The Hausdorff bound).
template <int D>
double sag_curvature(const Mesh<D>& mesh, const SaggingEdge<D>& edge, const Vec<D>& direction) {
  const Vec<D> chord = mesh.vertex(edge.b) - mesh.vertex(edge.a);
  return 8 * dot(edge.sag, direction) / dot(chord, chord);
}

// The metric eigenvalue that keeps a unit facet within hausd of a surface of curvature κ along the
// eigenvector: a regular unit triangle's centroid sags by (κ1/μ1 + κ2/μ2)/12, hausd with μ = |κ|/(6
// hausd) both ways. Along a curve (a 2D boundary, a 3D feature line), a unit chord sags by
// κ/(8μ).
double surface_eigenvalue(double curvature, double hausd) { return std::abs(curvature) / (6 * hausd); }
double curve_eigenvalue(double curvature, double hausd) { return std::abs(curvature) / (8 * hausd); }

template <int D>
SymMat<D> outer(const Vec<D>& u, double weight) {
  SymMat<D> m{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) = weight * u[i] * u[j];
  return m;
}

// The incident edges of each vertex, as positions in `edges`.
template <int D>
std::vector<std::vector<Index>> edges_at_vertices(const Mesh<D>& mesh, const std::vector<SaggingEdge<D>>& edges) {
  std::vector<std::vector<Index>> at(static_cast<std::size_t>(mesh.vertex_count()));
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at[static_cast<std::size_t>(edges[i].a)].push_back(static_cast<Index>(i));
    at[static_cast<std::size_t>(edges[i].b)].push_back(static_cast<Index>(i));
  }
  return at;
}

// A ridge or corner: the same size every way, from the most curved of its edges (those along a
// feature line by the line's curvature, the others by their surface's).
template <int D>
double isotropic_eigenvalue(const Mesh<D>& mesh, const std::vector<SaggingEdge<D>>& edges, const std::vector<Index>& around, double hausd) {
  double largest = 0;
  for (Index i : around) {
    const SaggingEdge<D>& edge = edges[static_cast<std::size_t>(i)];
    const Vec<D> chord = mesh.vertex(edge.b) - mesh.vertex(edge.a);
    const double curvature = 8 * norm(edge.sag) / dot(chord, chord);  // sag_curvature along the sag itself
    largest = std::max(largest, edge.on_line || D == 2 ? curve_eigenvalue(curvature, hausd) : surface_eigenvalue(curvature, hausd));
  }
  return largest;
}

// A vertex of a smooth surface (3D): the curvature tensor K in the tangent plane fitted by least
// squares to the normal curvatures of its edges, tᵀKt = κ along each edge's tangent t; its principal
// curvatures give the eigenvalues along the principal directions. nullopt when the edges do not
// determine K (fewer than three directions).
std::optional<SymMat<3>> smooth_surface_metric(const Mesh<3>& mesh, Index v, const Vec3& normal, const std::vector<SaggingEdge<3>>& edges,
                                               const std::vector<Index>& around, double hausd, double floor) {
  const auto [e1, e2] = orthonormal_complement<3>(normal);
  std::array<std::array<double, 3>, 3> normal_matrix{};
  std::array<double, 3> rhs{};
  double largest = 0;
  for (Index i : around) {
    const SaggingEdge<3>& edge = edges[static_cast<std::size_t>(i)];
    const Vec3 out = mesh.vertex(edge.a == v ? edge.b : edge.a) - mesh.vertex(v);
    const double c = dot(out, e1), s = dot(out, e2), length = std::hypot(c, s);
    if (!(length > 0)) continue;
    const std::array<double, 3> row{c * c / (length * length), 2 * c * s / (length * length), s * s / (length * length)};
    const double curvature = sag_curvature(mesh, edge, normal);
    largest = std::max(largest, std::abs(curvature));
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) normal_matrix[r][k] += row[r] * row[k];
      rhs[r] += row[r] * curvature;
    }
  }
  if (around.size() < 3 || !solve_small_system<3>(normal_matrix, rhs)) return std::nullopt;
  SymMat<2> tensor{};
  tensor(0, 0) = rhs[0];
  tensor(1, 0) = rhs[1];
  tensor(1, 1) = rhs[2];
  const SymEigen<2> principal = sym_eigen(tensor);
  std::array<double, 2> eigenvalues;
  SymMat<3> metric{};
  for (int j = 0; j < 2; ++j) {
    // No principal curvature beyond the largest measured: a fit of coarse edges may overshoot.
    eigenvalues[j] = std::max(surface_eigenvalue(std::min(std::abs(principal.values[j]), largest), hausd), floor);
    metric += outer<3>(principal.vectors(0, j) * e1 + principal.vectors(1, j) * e2, eigenvalues[j]);
  }
  // Across the surface, the larger of the two sizes: elements of the bound's sizes along the surface
  // keep their shape, and the gradation carries the bound inside.
  return metric + outer<3>(normal, std::min(eigenvalues[0], eigenvalues[1]));
}

// A vertex of a smooth curve (2D): the larger curvature of its two edges, the same size both ways
// (smooth_surface_metric's choice across the boundary).
SymMat<2> smooth_curve_metric(const Mesh<2>& mesh, const Vec2& normal, const std::vector<SaggingEdge<2>>& edges,
                              const std::vector<Index>& around, double hausd, double floor) {
  double largest = 0;
  for (Index i : around) largest = std::max(largest, std::abs(sag_curvature(mesh, edges[static_cast<std::size_t>(i)], normal)));
  return SymMat<2>::identity() * std::max(curve_eigenvalue(largest, hausd), floor);
}

// The distance bound at a boundary vertex whose given metric is `given`.
template <int D>
double bound_at(const HausdorffBound& bound, const SymMat<D>& given) {
  if (!(bound.relative_to_size > 0)) return bound.hausd;
  const double largest_eigenvalue = sym_eigen(given).values[D - 1];  // (ascending)
  return std::min(bound.hausd, bound.relative_to_size / std::sqrt(largest_eigenvalue));
}

template <int D>
SymMat<D> isotropic(double eigenvalue) {
  return SymMat<D>::identity() * eigenvalue;
}

}  // namespace

template <int D>
std::vector<SymMat<D>> hausdorff_metrics(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, const HausdorffBound& bound,
                                         std::span<const SymMat<D>> given) {
  // Ridges and corners as the loop classifies them (from the facets alone), on a copy: classifying
  // tags the mesh.
  Mesh<D> classified = mesh;
  const std::vector<VertexClass> classes = classify_vertices(classified, bound.feature_angle_degrees);
  const std::vector<SaggingEdge<D>> edges = sagging_edges(classified, geometry);
  const std::vector<std::vector<Index>> at = edges_at_vertices(classified, edges);
  const double diagonal = bounding_box_diagonal(mesh);
  const double floor = 1 / (diagonal * diagonal);
  std::vector<SymMat<D>> metrics(static_cast<std::size_t>(mesh.vertex_count()), unbounded_metric<D>(diagonal));
  bool finer = false;  // than `given` somewhere
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const std::vector<Index>& around = at[static_cast<std::size_t>(v)];
    if (around.empty()) continue;
    const double hausd = bound_at(bound, given[static_cast<std::size_t>(v)]);
    std::optional<SymMat<D>> metric;
    if (classes[static_cast<std::size_t>(v)] == VertexClass::kSurface) {
      const Vec<D> normal = geometry.normal(mesh.vertex(v), {edges[static_cast<std::size_t>(around.front())].ref});
      if constexpr (D == 3)
        metric = smooth_surface_metric(mesh, v, normal, edges, around, hausd, floor);
      else
        metric = smooth_curve_metric(mesh, normal, edges, around, hausd, floor);
    }
    if (!metric) metric = isotropic<D>(std::max(isotropic_eigenvalue(mesh, edges, around, hausd), floor));
    if (within_bound(given[static_cast<std::size_t>(v)], *metric) == given[static_cast<std::size_t>(v)]) continue;
    metrics[static_cast<std::size_t>(v)] = *metric;
    finer = true;
  }
  if (finer) grade_metrics(mesh, metrics, {kHausdorffGradation});  // (a whole-mesh sweep: 1 s at a million elements)
  return metrics;
}

template <int D>
SymMat<D> unbounded_metric(double diagonal) {
  return isotropic<D>(1 / (diagonal * diagonal));
}

template <int D>
SymMat<D> within_bound(const SymMat<D>& metric, const SymMat<D>& bound) {
  return sym_eigen(metric - bound).values[0] >= 0 ? metric : intersect_metrics(metric, bound);
}

template <int D>
Index bound_metrics_by_hausdorff(const Mesh<D>& mesh, std::vector<SymMat<D>>& metrics, const BoundaryGeometry<D>& geometry,
                                 const HausdorffBound& bound) {
  const std::vector<SymMat<D>> bounds = hausdorff_metrics<D>(mesh, geometry, bound, metrics);
  Index changed = 0;
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    const SymMat<D> bounded = within_bound(metrics[v], bounds[v]);
    changed += bounded != metrics[v];
    metrics[v] = bounded;
  }
  return changed;
}

template std::vector<SymMat<2>> hausdorff_metrics(const Mesh<2>&, const BoundaryGeometry<2>&, const HausdorffBound&,
                                                  std::span<const SymMat<2>>);
template std::vector<SymMat<3>> hausdorff_metrics(const Mesh<3>&, const BoundaryGeometry<3>&, const HausdorffBound&,
                                                  std::span<const SymMat<3>>);
template SymMat<2> within_bound(const SymMat<2>&, const SymMat<2>&);
template SymMat<3> within_bound(const SymMat<3>&, const SymMat<3>&);
template Index bound_metrics_by_hausdorff(const Mesh<2>&, std::vector<SymMat<2>>&, const BoundaryGeometry<2>&, const HausdorffBound&);
template Index bound_metrics_by_hausdorff(const Mesh<3>&, std::vector<SymMat<3>>&, const BoundaryGeometry<3>&, const HausdorffBound&);

template SymMat<2> unbounded_metric(double);
template SymMat<3> unbounded_metric(double);

}  // namespace hocav
