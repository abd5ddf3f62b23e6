// Vertex normals per smooth side (docs/method.md §9).
#include "surface/vertex_normals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>

#include "surface/feature_lines.hpp"
#include "surface/quadric_fit.hpp"
#include "surface/section_circle_fit.hpp"

namespace hocav {
namespace {

// A fitted normal that turns further than this from the weighted one is a failed fit.
const double kMaxFitTurn = 30 * std::numbers::pi / 180;
// Rings of facets around a side for its quadric fit, and for its section fit (a side at a corner
// may have a single facet; the section fit has four unknowns).
constexpr int kQuadricRings = 1, kSectionRings = 2;
// A fit over one ref's points replaces the fit over the whole neighbourhood when its residual is
// below this share of the whole one's. A side whose own facets span refs (merged at a junction)
// would give up some of them: it needs a large gain, which a smooth surface split by refs stays well
// above (0.47 at least on the split sphere). A side within one ref only borrows its neighbours'
// points: on one smooth surface they keep the residual (0.68 at least on the split sphere), across
// a jump in curvature (a fillet meeting its floor) they double it or more (docs/surface.md).
constexpr double kMergedRefFitGain = 0.1, kSingleRefFitGain = 0.5;
// Sides along a feature line whose section-fitted normals differ by less than this are merged: the
// fits are exact on cylinders and planes, so a tangent junction lands well below it and the
// part's shallowest crease (20°, docs/cases.md) well above.
const double kSectionSmoothAngle = 5 * std::numbers::pi / 180;

// Union-find over facet corners (corner = D * facet + local vertex), path halving.
class CornerSets {
 public:
  explicit CornerSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), Index{0}); }
  Index find(Index c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index> parent_;
};

// The contribution of facet f to the normal at its local vertex i.
template <int D>
Vec<D> weighted_facet_normal(const Mesh<D>& mesh, Index f, int i, NormalWeights weights) {
  const Vec<D> area_normal = facet_area_normal(mesh, f);
  const double measure = norm(area_normal);
  if (measure == 0 || weights == NormalWeights::kArea) return area_normal;
  const auto& facet = mesh.facet(f);
  if constexpr (D == 2) {
    return weights == NormalWeights::kMax ? area_normal * (1 / (measure * measure)) : area_normal * (1 / measure);
  } else {
    const Vec3 e1 = mesh.vertex(facet[(i + 1) % 3]) - mesh.vertex(facet[i]);
    const Vec3 e2 = mesh.vertex(facet[(i + 2) % 3]) - mesh.vertex(facet[i]);
    if (weights == NormalWeights::kMax) return area_normal * (1 / (dot(e1, e1) * dot(e2, e2)));
    const double angle = std::atan2(measure, dot(e1, e2));  // |e1 × e2| = measure
    return area_normal * (angle / measure);
  }
}

// Groups the corners by the root of their set and gives each group the unit weighted mean of its
// facets' normals (or, when they cancel out in a degenerate fold, its first facet's own normal).
template <int D>
VertexNormals<D> weighted_side_normals(const Mesh<D>& mesh, CornerSets& sets, NormalWeights weights) {
  const Index corner_count = D * mesh.facet_count();
  VertexNormals<D> result;
  result.corner_sides.resize(mesh.facet_count());
  std::vector<Index> side_of_root(static_cast<std::size_t>(corner_count), kNoIndex);
  std::vector<Index> first_facet;
  for (Index c = 0; c < corner_count; ++c) {
    const Index root = sets.find(c);
    if (side_of_root[root] == kNoIndex) {
      side_of_root[root] = static_cast<Index>(result.normals.size());
      result.normals.emplace_back();
      first_facet.push_back(c / D);
    }
    const Index side = side_of_root[root];
    result.corner_sides[c / D][c % D] = side;
    result.normals[side] += weighted_facet_normal(mesh, c / D, c % D, weights);
  }
  for (std::size_t side = 0; side < result.normals.size(); ++side) {
    Vec<D>& normal = result.normals[side];
    if (norm(normal) == 0) normal = facet_area_normal(mesh, first_facet[side]);
    normal *= 1 / norm(normal);
  }
  return result;
}

// The neighbourhood of a side: the vertices of the side's facets and of the facets reached from them
// in `rings` steps across sides that are not ridges there (the two facets share a normal at a
// vertex of that side), each with the ref of the facet it came from.
struct RefVertex {
  int ref;
  Index vertex;
  auto operator<=>(const RefVertex&) const = default;
};

template <int D>
void gather_neighbourhood(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, const VertexNormals<D>& normals,
                          std::span<const Index> side_corners, int rings, std::vector<Index>& facets, std::vector<RefVertex>& gathered) {
  facets.clear();
  for (Index corner : side_corners) facets.push_back(corner / D);
  std::size_t layer_begin = 0;
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t layer_end = facets.size();
    for (std::size_t k = layer_begin; k < layer_end; ++k) {
      const Index f = facets[k];
      for (int s = 0; s < D; ++s) {
        const Index g = topology.neighbors[f][s];
        if (g == kNoIndex || std::find(facets.begin(), facets.end(), g) != facets.end()) continue;
        const int i = (s + 1) % D;  // a vertex of side s
        if (normals.corner_sides[f][i] == normals.corner_sides[g][facet_local_vertex(mesh, g, mesh.facet(f)[i])]) facets.push_back(g);
      }
    }
    layer_begin = layer_end;
  }
  const Index vertex = mesh.facet(side_corners.front() / D)[side_corners.front() % D];
  gathered.clear();
  for (Index f : facets)
    for (Index v : mesh.facet(f))
      if (v != vertex) gathered.push_back({mesh.facet_ref(f), v});
  std::sort(gathered.begin(), gathered.end());
  gathered.erase(std::unique(gathered.begin(), gathered.end()), gathered.end());
}

// The points of the neighbourhood from facets of one ref (all refs when ref is empty), each vertex once.
template <int D>
void neighbourhood_points(const Mesh<D>& mesh, const std::vector<RefVertex>& gathered, std::optional<int> ref, std::vector<Index>& vertices,
                          std::vector<Vec<D>>& points) {
  vertices.clear();
  for (const RefVertex& item : gathered)
    if (!ref || item.ref == *ref) vertices.push_back(item.vertex);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  points.clear();
  for (Index v : vertices) points.push_back(mesh.vertex(v));
}

// The facet corners of each side, in compressed rows.
struct SideCorners {
  std::vector<Index> offsets, corners;
  std::span<const Index> of(std::size_t side) const { return {corners.data() + offsets[side], corners.data() + offsets[side + 1]}; }
};

template <int D>
SideCorners side_corners_of(const Mesh<D>& mesh, const VertexNormals<D>& normals) {
  const std::size_t side_count = normals.normals.size();
  SideCorners rows{std::vector<Index>(side_count + 1, 0), std::vector<Index>(static_cast<std::size_t>(D) * mesh.facet_count())};
  for (const auto& sides : normals.corner_sides)
    for (Index side : sides) ++rows.offsets[side + 1];
  for (std::size_t side = 0; side < side_count; ++side) rows.offsets[side + 1] += rows.offsets[side];
  std::vector<Index> fill(rows.offsets.begin(), rows.offsets.end() - 1);
  for (Index c = 0; c < static_cast<Index>(rows.corners.size()); ++c) rows.corners[fill[normals.corner_sides[c / D][c % D]]++] = c;
  return rows;
}

// Replaces each side's normal by a quadric fitted to its neighbourhood. Where that spans several
// refs (a fillet meeting a plane, tangent to it: the sides merge there), one quadric cannot follow
// the jump in curvature; the fit over the points of one ref of the side's own facets is kept
// instead when it explains them better (kMergedRefFitGain, kSingleRefFitGain): on a plane, exactly.
template <int D>
void fit_quadric_normals(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, VertexNormals<D>& normals) {
  const SideCorners rows = side_corners_of(mesh, normals);
  std::vector<RefVertex> gathered;
  std::vector<Index> facets, vertices;
  std::vector<Vec<D>> points;
  std::vector<int> own_refs;
  for (std::size_t side = 0; side < normals.normals.size(); ++side) {
    const std::span<const Index> side_corners = rows.of(side);
    const Vec<D> point = mesh.vertex(mesh.facet(side_corners.front() / D)[side_corners.front() % D]);
    const Vec<D> initial = normals.normals[side];
    gather_neighbourhood(mesh, topology, normals, side_corners, kQuadricRings, facets, gathered);
    neighbourhood_points(mesh, gathered, std::nullopt, vertices, points);
    QuadricNormal<D> best = quadric_fitted_normal<D>(point, points, initial, kMaxFitTurn);
    const bool several_refs = !gathered.empty() && gathered.front().ref != gathered.back().ref;
    if (several_refs) {
      own_refs.clear();
      for (Index corner : side_corners) own_refs.push_back(mesh.facet_ref(corner / D));
      std::sort(own_refs.begin(), own_refs.end());
      own_refs.erase(std::unique(own_refs.begin(), own_refs.end()), own_refs.end());
      const double gain = own_refs.size() == 1 ? kSingleRefFitGain : kMergedRefFitGain;
      const double union_residual = best.residual;
      for (int ref : own_refs) {
        neighbourhood_points(mesh, gathered, ref, vertices, points);
        QuadricNormal<D> fit = quadric_fitted_normal<D>(point, points, initial, kMaxFitTurn);
        if (std::isinf(fit.residual)) fit = plane_fitted_normal<D>(point, points, initial, kMaxFitTurn);
        if (fit.residual < gain * union_residual && fit.residual < best.residual) best = fit;
      }
    }
    normals.normals[side] = best.normal;
  }
}

// The normals of the unmerged sides along the feature lines, fitted in the line's normal plane
// (section_circle_fit.hpp), that decide which sides merge.
class SectionFits {
 public:
  SectionFits(const Mesh<3>& mesh, const SurfaceTopology<3>& topology, const VertexNormals<3>& separate)
      : mesh_(mesh), topology_(topology), separate_(separate), rows_(side_corners_of(mesh, separate)) {
    VertexNormals<3> adjusted = separate;
    lines_ = find_feature_lines(mesh, topology, adjusted, LineTangents::kCircle);  // the weighted normals lean
  }

  // The normals of sides a and b at vertex v across their ridge edge (v, w): in the normal plane of
  // the line through v, or at a corner of the branch toward w. None off the feature lines, or where
  // a side has too few points for the fit.
  std::optional<std::array<Vec3, 2>> across(Index side_a, Index side_b, Index v, Index w) {
    Vec3 tangent = lines_.tangents[v];
    if (!(norm(tangent) > 0)) {
      const auto& neighbours = lines_.neighbours[v];
      if (std::find(neighbours.begin(), neighbours.end(), w) == neighbours.end()) return std::nullopt;
      tangent = branch_tangent(mesh_, lines_, v, w);
      if (!(norm(tangent) > 0)) return std::nullopt;
    }
    const std::optional<Vec3> normal_a = fit(side_a, v, tangent), normal_b = fit(side_b, v, tangent);
    if (!normal_a || !normal_b) return std::nullopt;
    return std::array<Vec3, 2>{*normal_a, *normal_b};
  }

 private:
  std::optional<Vec3> fit(Index side, Index v, const Vec3& tangent) {
    gather_neighbourhood(mesh_, topology_, separate_, rows_.of(static_cast<std::size_t>(side)), kSectionRings, facets_, gathered_);
    neighbourhood_points(mesh_, gathered_, std::nullopt, vertices_, points_);
    return section_circle_normal(mesh_.vertex(v), tangent, points_, separate_.normals[side]);
  }

  const Mesh<3>& mesh_;
  const SurfaceTopology<3>& topology_;
  const VertexNormals<3>& separate_;
  SideCorners rows_;
  FeatureLines<3> lines_;
  std::vector<RefVertex> gathered_;
  std::vector<Index> facets_, vertices_;
  std::vector<Vec3> points_;
};

}  // namespace

template <int D>
VertexNormals<D> compute_vertex_normals(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, const VertexNormalOptions<D>& options) {
  const Index facet_count = mesh.facet_count();
  const Index corner_count = checked_index(static_cast<std::size_t>(facet_count) * D, "facet corners");
  CornerSets sets(static_cast<std::size_t>(corner_count));
  // Calls visit(corner of f, corner of g) for the corners of the vertices that side s of facet f shares with g.
  auto for_shared_corners = [&mesh](Index f, int s, Index g, auto&& visit) {
    for (int i = 0; i < D; ++i)
      if (i != s) visit(D * f + i, D * g + facet_local_vertex(mesh, g, mesh.facet(f)[i]));
  };
  for (Index f = 0; f < facet_count; ++f)
    for (int s = 0; s < D; ++s)
      if (const Index g = topology.neighbors[f][s]; g != kNoIndex && !topology.ridges[f][s])
        for_shared_corners(f, s, g, [&sets](Index a, Index b) { sets.unite(a, b); });

  // Sides that meet at a ridge with nearly the same normal (a ref boundary or a tagged ridge across
  // a smooth part) share one normal, computed over both, as on any smooth part.
  // Along the feature lines the sides are compared by their section-fitted normals, which tell a
  // fillet's tangent junction from a shallow crease (kSectionSmoothAngle); elsewhere by their
  // weighted normals (the smooth-ridge angle).
  const VertexNormals<D> separate = weighted_side_normals(mesh, sets, options.weights);
  const double cos_smooth_angle = std::cos(options.smooth_ridge_angle_degrees * std::numbers::pi / 180);
  const double cos_section_angle = std::cos(kSectionSmoothAngle);
  std::optional<SectionFits> section_fits;
  if constexpr (D == 3)
    if (options.quadric_fit) section_fits.emplace(mesh, topology, separate);
  for (Index f = 0; f < facet_count; ++f)
    for (int s = 0; s < D; ++s)
      if (const Index g = topology.neighbors[f][s]; g != kNoIndex && topology.ridges[f][s])
        for_shared_corners(f, s, g, [&](Index a, Index b) {
          const Index side_a = separate.corner_sides[a / D][a % D], side_b = separate.corner_sides[b / D][b % D];
          if (side_a == side_b) return;
          if constexpr (D == 3)
            if (section_fits) {
              const Index v = mesh.facet(f)[a % D], w = mesh.facet(f)[3 - s - a % D];
              if (const auto fitted = section_fits->across(side_a, side_b, v, w)) {
                if (dot((*fitted)[0], (*fitted)[1]) >= cos_section_angle) sets.unite(a, b);
                return;
              }
            }
          if (dot(separate.normals[side_a], separate.normals[side_b]) >= cos_smooth_angle) sets.unite(a, b);
        });
  VertexNormals<D> result = weighted_side_normals(mesh, sets, options.weights);
  if (options.quadric_fit) fit_quadric_normals(mesh, topology, result);

  if (options.normal_source != nullptr) {
    const double cos_feature_angle = std::cos(options.feature_angle_degrees * std::numbers::pi / 180);
    std::vector<bool> done(result.normals.size(), false);
    for (Index c = 0; c < corner_count; ++c) {
      const Index f = c / D, side = result.corner_sides[f][c % D];
      if (done[side]) continue;
      done[side] = true;
      Vec<D>& normal = result.normals[side];
      Vec<D> given = options.normal_source->normal(mesh.vertex(mesh.facet(f)[c % D]), {.ref = mesh.facet_ref(f)});
      if (dot(given, normal) < 0) given = -given;
      if (dot(given, normal) >= cos_feature_angle * norm(given)) normal = given * (1 / norm(given));
    }
  }
  return result;
}

template VertexNormals<2> compute_vertex_normals(const Mesh<2>&, const SurfaceTopology<2>&, const VertexNormalOptions<2>&);
template VertexNormals<3> compute_vertex_normals(const Mesh<3>&, const SurfaceTopology<3>&, const VertexNormalOptions<3>&);

}  // namespace hocav
