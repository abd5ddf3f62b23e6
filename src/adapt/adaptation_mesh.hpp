// The mesh an adaptation run changes, with what its operators read at every vertex: the metric
// (clamped, from the run's AdaptationMetric), the vertex's geometric class, a back-mesh hint for the
// next metric evaluation near it, and the pass that last changed its ball. All four are vertex
// attributes of the mesh, so they follow every insertion, removal and compaction
// (docs/mesh-model.md).
#pragma once

#include <array>

#include "adapt/adaptation_metric.hpp"
#include "adapt/metric_measures.hpp"
#include "cavity/cavity_operations.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

// What a vertex may do (mmg's order: a vertex collapses only onto one of its class or higher).
enum class VertexClass : int {
  kInterior = 0,  // moves and vanishes freely
  kSurface = 1,   // on a boundary surface (3D) or curve (2D): stays on it
  kRidge = 2,     // 3D: on a feature line, between exactly two of its edges: stays on it
  kCorner = 3,    // never moves or vanishes
};

template <int D>
class AdaptationMesh {
 public:
  using Element = typename Mesh<D>::Element;

  // Takes a mesh with its topology and compacts it; classifies its vertices (feature_angle:
  // boundary sides whose facets' normals differ by more, or whose refs differ, are ridges; 3D ones
  // become feature lines) and evaluates the metric at every vertex.
  AdaptationMesh(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                 double feature_angle_degrees);

  Mesh<D>& mesh() { return mesh_; }
  const Mesh<D>& mesh() const { return mesh_; }
  const BoundaryGeometry<D>* geometry() const { return geometry_; }
  CavityWorkspace<D>& workspace() { return work_; }

  SymMat<D> metric(Index v) const;
  VertexClass vertex_class(Index v) const { return static_cast<VertexClass>(mesh_.vertex_attribute(class_attribute_, v)[0]); }
  // A new vertex at x with the metric there (evaluated from near vertex `near`).
  Index add_vertex(const Vec<D>& x, VertexClass vertex_class, Index near);
  // Moves v to x and evaluates its metric there.
  void move_vertex(Index v, const Vec<D>& x);
  // Puts v back where it was, with the metric it had there (a refused move).
  void restore_vertex(Index v, const Vec<D>& x, const SymMat<D>& metric) {
    mesh_.vertex(v) = x;
    set_metric(v, metric);
  }

  // The active set: a pass tries only what changed since the start of the previous pass (the first
  // pass tries everything), so that late passes cost what they change, not the mesh's size.
  void start_pass() { ++pass_; }
  // Commits a plan of the cavity operator and marks the vertices of its new elements changed.
  void commit(CavityOperator<D>& plan);
  // Marks a vertex changed (a move marks its ball's vertices).
  void mark_changed(Index v) { mesh_.vertex_attribute(stamp_attribute_, v)[0] = pass_; }
  bool changed_recently(Index v) const { return mesh_.vertex_attribute(stamp_attribute_, v)[0] >= pass_ - 1; }
  // Swaps, the most tried operation, retry only around what this pass changed (every element in
  // the first pass): a swap refused once stays refused until its cavity changes.
  bool changed_this_pass(Index v) const { return pass_ == 1 || mesh_.vertex_attribute(stamp_attribute_, v)[0] >= pass_; }

  double edge_length(Index a, Index b) const {
    return metric_edge_length<D>(mesh_.vertex(a), mesh_.vertex(b), metric(a), metric(b));
  }
  double quality(const Element& element) const;
  double quality(Index k) const { return quality(mesh_.element(k)); }

 private:
  void set_metric(Index v, const SymMat<D>& metric);
  void evaluate_metric(Index v, Index near);

  Mesh<D>& mesh_;
  const AdaptationMetric<D>& metric_;
  const BoundaryGeometry<D>* geometry_;
  int metric_attribute_, class_attribute_, hint_attribute_, stamp_attribute_;
  int pass_ = 0;
  CavityWorkspace<D> work_;
};

extern template class AdaptationMesh<2>;
extern template class AdaptationMesh<3>;

}  // namespace hocav
