// The CAD backend of the boundary geometry (docs/method.md §9, "the real CAD"): a STEP or BREP model read
// by gmsh's OpenCASCADE kernel, projected on with gmsh::model::getClosestPoint (its closest
// coordinates; the parametric coordinates it returns are wrong in gmsh 4.8.4, so normals use
// getParametrization). In 3D the facets lie on CAD surfaces, in 2D on CAD curves (z = 0).
//
// Refs. Each facet ref names one CAD boundary entity (a surface in 3D, a curve in 2D):
//   - by default the ref is the entity's tag, which is what gmsh writes for meshes it makes from the
//     same file (physical groups aside);
//   - built with a mesh, each ref of its facets goes to an entity that holds a sample of that ref's
//     vertices (in its bounding box, and the largest distance within 1e-3 of the model's size:
//     getClosestPoint projects on the untrimmed surface, so a narrow strip at the top of a thin
//     wall lies on the whole top plane), the one nearest to the facets' centroids among those (a
//     narrow face has all its vertices on its bounding curves, hence on its neighbours too), for meshes whose refs follow
//     another rule, such as the generated sphere shell (refs 1 inner, 2 outer, while its exported
//     BREP reads back with tags 1 outer, 2 inner). Error when no entity lies near a ref.
//
// gmsh keeps one global model and is not thread-safe: a CadBoundary holds gmsh (a GmshSession, the
// process-wide gmsh lock) for its whole life and serializes its own calls with a mutex, so its
// queries may come from several threads, one at a time. No other gmsh session can open meanwhile:
// in another thread it waits, in the same thread it is an Error.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include "cases/gmsh_model.hpp"
#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

template <int D>
class CadBoundary final : public BoundaryGeometry<D> {
 public:
  // Error when the file cannot be read or holds no entity of dimension D − 1.
  explicit CadBoundary(const std::string& path);
  CadBoundary(const std::string& path, const Mesh<D>& mesh);

  // The point of the queried entities (all of them when the query has no ref) closest to x; the
  // patch is the entity's tag. Error for a ref with no entity.
  BoundaryPoint<D> project(const Vec<D>& x, const ProjectionQuery& query = {}) const override;
  Vec<D> normal(const Vec<D>& x, const ProjectionQuery& query = {}) const override;
  // On the CAD curves the two refs' surfaces share (3D); the default when they share none.
  Vec<D> project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const override;

  // The tag of the CAD entity a ref names.
  int entity_of_ref(int ref) const;

 private:
  // A CAD entity and the ref its facets carry.
  struct Piece {
    int ref = 0;
    int tag = 0;
  };
  // Points of a ref's facets, to find its entity.
  struct RefSample {
    std::vector<Vec<D>> vertices, centroids;
  };
  BoundaryPoint<D> closest_unlocked(const Vec<D>& x, const ProjectionQuery& query) const;
  // The entity holding every sampled vertex (within tolerance) nearest to the centroids; size() if none.
  static std::size_t nearest_entity(const std::vector<Piece>& entities, const RefSample& sample, double tolerance);

  GmshSession session_;
  mutable std::mutex mutex_;
  std::vector<Piece> pieces_;
  std::vector<std::vector<int>> curves_of_piece_;  // 3D: each piece's bounding curves, sorted
};

extern template class CadBoundary<2>;
extern template class CadBoundary<3>;

}  // namespace hocav
