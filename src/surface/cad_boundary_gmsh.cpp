// Projection onto a STEP/BREP model through gmsh and OpenCASCADE (docs/method.md §9).
#include "surface/cad_boundary_gmsh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <system_error>

#include "base/quiet_stdout.hpp"

namespace hocav {
namespace {

// Vertices sampled per ref to find its CAD entity, and how far (relative to the model's size)
// they may lie from it.
constexpr Index kRefSamples = 16;
constexpr double kRefTolerance = 1e-3;
// Newton steps from a point of a CAD curve onto the intersection of its two surfaces, and the
// sine between their normals below which (nearly tangent surfaces) the curve's point stays.
constexpr int kIntersectionSteps = 3;
constexpr double kMinCrossingSine = 1e-3;

template <int D>
std::vector<double> gmsh_coordinates(const Vec<D>& x) {
  return {x[0], x[1], D == 3 ? x[2] : 0.0};
}

template <int D>
BoundaryPoint<D> closest_on_entity(int dimension, int tag, const Vec<D>& x) {
  std::vector<double> closest, parametric;
  gmsh::model::getClosestPoint(dimension, tag, gmsh_coordinates(x), closest, parametric);
  BoundaryPoint<D> found;
  for (int i = 0; i < D; ++i) found.point[i] = closest[i];
  found.distance = norm(found.point - x);
  found.patch = tag;
  return found;
}

std::string entity_name(int dimension) { return dimension == 2 ? "surface" : "curve"; }

// The unit normal of the entity of dimension D − 1 at a point on it.
template <int D>
Vec<D> entity_normal(const BoundaryPoint<D>& on_entity) {
  std::vector<double> parameters, values;
  gmsh::model::getParametrization(D - 1, on_entity.patch, gmsh_coordinates(on_entity.point), parameters);
  Vec<D> normal;
  if constexpr (D == 3) {
    gmsh::model::getNormal(on_entity.patch, parameters, values);
    normal = Vec3{{values[0], values[1], values[2]}};
  } else {
    gmsh::model::getDerivative(1, on_entity.patch, parameters, values);
    normal = Vec2{{values[1], -values[0]}};
  }
  return normal * (1 / norm(normal));
}

// From a point of the CAD curve that surfaces a and b share onto both surfaces. OpenCASCADE stores
// the curve where two fillets meet as a B-spline within its tolerance of them (1.9e-8 on the
// machined part with a thin wall, docs/surface.md): Newton on the two surfaces' equations (each
// step to the point nearest x on both tangent planes) lands on their intersection to rounding.
// Keeps the point closest to both surfaces.
Vec3 onto_both_surfaces(const Vec3& on_curve, int surface_a, int surface_b) {
  Vec3 x = on_curve, best = on_curve;
  double best_gap = std::numeric_limits<double>::infinity();
  for (int step = 0;; ++step) {
    const BoundaryPoint<3> on_a = closest_on_entity<3>(2, surface_a, x), on_b = closest_on_entity<3>(2, surface_b, x);
    const double gap = std::max(on_a.distance, on_b.distance);
    if (gap < best_gap) {
      best_gap = gap;
      best = x;
    }
    if (step == kIntersectionSteps || gap == 0) return best;
    const Vec3 normal_a = entity_normal(on_a), normal_b = entity_normal(on_b);
    const double cosine = dot(normal_a, normal_b), sine2 = 1 - cosine * cosine;
    if (!(sine2 > kMinCrossingSine * kMinCrossingSine)) return best;
    const double offset_a = dot(normal_a, on_a.point - x), offset_b = dot(normal_b, on_b.point - x);
    x += ((offset_a - cosine * offset_b) / sine2) * normal_a + ((offset_b - cosine * offset_a) / sine2) * normal_b;
  }
}

}  // namespace

template <int D>
CadBoundary<D>::CadBoundary(const std::string& path) : session_("cad") {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": cannot read the CAD file");
  call_gmsh([&] {
    gmsh::vectorpair imported, entities;
    {
      QuietStdout quiet;  // OpenCASCADE's STEP reader prints its statistics
      gmsh::model::occ::importShapes(path, imported);
    }
    gmsh::model::occ::synchronize();
    gmsh::model::getEntities(entities, D - 1);
    for (const auto& [dimension, tag] : entities) {
      pieces_.push_back({tag, tag});
      if constexpr (D == 3) {
        gmsh::vectorpair curves;
        gmsh::model::getBoundary({{dimension, tag}}, curves, /*combined=*/false, /*oriented=*/false);
        std::vector<int> tags;
        for (const auto& curve : curves) tags.push_back(std::abs(curve.second));
        std::sort(tags.begin(), tags.end());
        curves_of_piece_.push_back(tags);
      }
    }
  });
  if (pieces_.empty()) throw Error(path + ": the CAD model has no " + entity_name(D - 1));
}

template <int D>
CadBoundary<D>::CadBoundary(const std::string& path, const Mesh<D>& mesh) : CadBoundary(path) {
  // A sample of each ref's facets: every stride-th facet's first vertex and centroid.
  std::map<int, Index> facet_counts;
  for (Index f = 0; f < mesh.facet_count(); ++f) ++facet_counts[mesh.facet_ref(f)];
  std::map<int, RefSample> samples;
  std::map<int, Index> seen;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const int ref = mesh.facet_ref(f);
    if (seen[ref]++ % std::max<Index>(1, facet_counts[ref] / kRefSamples) != 0) continue;
    Vec<D> centroid{};
    for (Index v : mesh.facet(f)) centroid += mesh.vertex(v) * (1.0 / D);
    samples[ref].vertices.push_back(mesh.vertex(mesh.facet(f)[0]));
    samples[ref].centroids.push_back(centroid);
  }
  double x_min, y_min, z_min, x_max, y_max, z_max;
  call_gmsh([&] { gmsh::model::getBoundingBox(-1, -1, x_min, y_min, z_min, x_max, y_max, z_max); });
  const double tolerance = kRefTolerance * std::hypot(x_max - x_min, y_max - y_min, z_max - z_min);

  std::vector<Piece> entities = pieces_;
  std::vector<std::vector<int>> entity_curves = curves_of_piece_;
  pieces_.clear();
  curves_of_piece_.clear();
  for (const auto& [ref, sample] : samples) {
    const std::size_t best = nearest_entity(entities, sample, tolerance);
    if (best == entities.size())
      throw Error(path + ": no CAD " + entity_name(D - 1) + " lies near the facets of ref " + std::to_string(ref));
    pieces_.push_back({ref, entities[best].tag});
    if constexpr (D == 3) curves_of_piece_.push_back(entity_curves[best]);
  }
  if (pieces_.empty()) throw Error("a CAD boundary needs a mesh with boundary facets");
}

template <int D>
std::size_t CadBoundary<D>::nearest_entity(const std::vector<Piece>& entities, const RefSample& sample, double tolerance) {
  auto farthest = [](int tag, const std::vector<Vec<D>>& points) {
    double distance = 0;
    for (const Vec<D>& point : points)
      distance = std::max(distance, call_gmsh([&] { return closest_on_entity<D>(D - 1, tag, point).distance; }));
    return distance;
  };
  // getClosestPoint projects on the untrimmed surface (a whole plane): a face must also hold the
  // vertices in its bounding box.
  auto in_box = [tolerance](int tag, const std::vector<Vec<D>>& points) {
    double low[3], high[3];
    call_gmsh([&] { gmsh::model::getBoundingBox(D - 1, tag, low[0], low[1], low[2], high[0], high[1], high[2]); });
    return std::all_of(points.begin(), points.end(), [&](const Vec<D>& point) {
      for (int i = 0; i < D; ++i)
        if (point[i] < low[i] - tolerance || point[i] > high[i] + tolerance) return false;
      return true;
    });
  };
  std::size_t best = entities.size();
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < entities.size(); ++e) {
    if (!in_box(entities[e].tag, sample.vertices) || !(farthest(entities[e].tag, sample.vertices) <= tolerance)) continue;
    const double distance = farthest(entities[e].tag, sample.centroids);
    if (distance < best_distance) {
      best_distance = distance;
      best = e;
    }
  }
  return best;
}

template <int D>
int CadBoundary<D>::entity_of_ref(int ref) const {
  for (const Piece& piece : pieces_)
    if (piece.ref == ref) return piece.tag;
  throw Error("the CAD model has no " + entity_name(D - 1) + " for ref " + std::to_string(ref));
}

template <int D>
BoundaryPoint<D> CadBoundary<D>::closest_unlocked(const Vec<D>& x, const ProjectionQuery& query) const {
  BoundaryPoint<D> best;
  best.distance = std::numeric_limits<double>::infinity();
  if (query.ref) entity_of_ref(*query.ref);  // Error for an unknown ref
  for (const Piece& piece : pieces_) {
    if (query.ref && piece.ref != *query.ref) continue;
    BoundaryPoint<D> found = call_gmsh([&] { return closest_on_entity<D>(D - 1, piece.tag, x); });
    if (found.distance < best.distance) {
      best = found;
      best.ref = piece.ref;
    }
  }
  return best;
}

template <int D>
BoundaryPoint<D> CadBoundary<D>::project(const Vec<D>& x, const ProjectionQuery& query) const {
  std::lock_guard lock(mutex_);
  return closest_unlocked(x, query);
}

template <int D>
Vec<D> CadBoundary<D>::normal(const Vec<D>& x, const ProjectionQuery& query) const {
  std::lock_guard lock(mutex_);
  const BoundaryPoint<D> on_entity = closest_unlocked(x, query);
  return call_gmsh([&] { return entity_normal<D>(on_entity); });
}

template <int D>
Vec<D> CadBoundary<D>::project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const {
  if constexpr (D == 3) {
    std::unique_lock lock(mutex_);
    auto piece_of = [this](int ref) {
      for (std::size_t p = 0; p < pieces_.size(); ++p)
        if (pieces_[p].ref == ref) return p;
      throw Error("the CAD model has no surface for ref " + std::to_string(ref));
    };
    const std::size_t piece_a = piece_of(ref_a), piece_b = piece_of(ref_b);
    const std::vector<int>& curves_a = curves_of_piece_[piece_a];
    const std::vector<int>& curves_b = curves_of_piece_[piece_b];
    std::vector<int> shared;
    std::set_intersection(curves_a.begin(), curves_a.end(), curves_b.begin(), curves_b.end(), std::back_inserter(shared));
    if (!shared.empty()) {
      BoundaryPoint<3> best;
      best.distance = std::numeric_limits<double>::infinity();
      for (int curve : shared) {
        const BoundaryPoint<3> found = call_gmsh([&] { return closest_on_entity<3>(1, curve, x); });
        if (found.distance < best.distance) best = found;
      }
      return call_gmsh([&] { return onto_both_surfaces(best.point, pieces_[piece_a].tag, pieces_[piece_b].tag); });
    }
  }
  return BoundaryGeometry<D>::project_on_intersection(x, ref_a, ref_b);
}

template class CadBoundary<2>;
template class CadBoundary<3>;

}  // namespace hocav
