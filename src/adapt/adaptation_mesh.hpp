// The mesh an adaptation run changes, with what its operators read at every vertex: the metric
// (clamped, from the run's AdaptationMetric), the vertex's geometric class, a back-mesh hint for the
// next metric evaluation near it, a geometry hint for the next projection near it, when its ball
// last changed, when a smoothing move of it was last refused, and whether parts of the mesh meet
// there without a face (a non-manifold place). All seven are vertex attributes of
// the mesh, so they follow every insertion, removal and compaction (docs/mesh-model.md); each
// element's quality is an element attribute.
#pragma once

#include <array>
#include <span>

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
  AdaptationMesh(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry, double feature_angle_degrees);

  Mesh<D>& mesh() { return mesh_; }
  const Mesh<D>& mesh() const { return mesh_; }
  const BoundaryGeometry<D>* geometry() const { return geometry_; }
  CavityWorkspace<D>& workspace() { return work_; }

  // (Inline: every length and quality reads it.)
  SymMat<D> metric(Index v) const {
    SymMat<D> m;
    const auto row = mesh_.vertex_attribute(metric_attribute_, v);
    for (std::size_t i = 0; i < m.entries.size(); ++i) m.entries[i] = row[i];
    return m;
  }
  VertexClass vertex_class(Index v) const { return static_cast<VertexClass>(mesh_.vertex_attribute(class_attribute_, v)[0]); }
  // Whether parts of the input meet at v without a face (non_manifold_places: a pinched vertex, or
  // an end of an edge with more than two boundary faces): a corner, whose ball and shells a walk
  // sees on one side only.
  bool non_manifold(Index v) const { return mesh_.vertex_attribute(non_manifold_attribute_, v)[0] != 0; }
  // The geometry's patch of the last projection at or near a boundary vertex (kNoIndex: none yet):
  // the next projection near it starts there (ProjectionQuery::hint).
  Index surface_hint(Index v) const { return static_cast<Index>(mesh_.vertex_attribute(surface_hint_attribute_, v)[0]); }
  void set_surface_hint(Index v, Index patch) { mesh_.vertex_attribute(surface_hint_attribute_, v)[0] = patch; }
  // The metric at a point, with the back-mesh element that held it (a vertex there keeps it as its
  // hint).
  struct PointMetric {
    SymMat<D> metric;
    Index hint;
  };
  // The metric at x, found from vertex `near`'s back-mesh hint; changes nothing, so it may run on
  // threads (move_vertex to x from near = v, or add_vertex at x near `near`, evaluates the same).
  PointMetric metric_at_point(const Vec<D>& x, Index near) const;
  SymMat<D> metric_near(const Vec<D>& x, Index near) const { return metric_at_point(x, near).metric; }
  // A new vertex at x with the metric there (evaluated from near vertex `near`, or given).
  Index add_vertex(const Vec<D>& x, VertexClass vertex_class, Index near) { return add_vertex(x, vertex_class, metric_at_point(x, near)); }
  Index add_vertex(const Vec<D>& x, VertexClass vertex_class, const PointMetric& metric);
  // Moves v to x and evaluates its metric there; `ball` is v's ball, whose qualities follow.
  void move_vertex(Index v, const Vec<D>& x, std::span<const Index> ball);
  // Puts v back where it was, with the metric it had there (a refused move).
  void restore_vertex(Index v, const Vec<D>& x, const SymMat<D>& metric, std::span<const Index> ball) {
    mesh_.vertex(v) = x;
    set_metric(v, metric);
    update_qualities(ball);
  }

  // The active set: a pass tries only what changed since the start of the previous pass (the first
  // pass tries everything), so that late passes cost what they change, not the mesh's size. Changes
  // are stamped with a clock that ticks at every pass and sweep.
  // Starts a pass; returns the clock at its start.
  int start_pass() {
    previous_pass_start_ = pass_start_;
    return pass_start_ = tick();
  }
  // Advances the clock (a sweep that later ones compare against); returns its new value.
  int tick() { return ++clock_; }
  // Starts a swap sweep (docs/adaptation.md §The loop, the swap rule): returns the clock at the start
  // of the previous sweep (0 before the first: everything changed then), so that the sweep counts
  // every change since, whatever passes and operators came between; remembers this sweep's start.
  int start_sweep() {
    const int since = sweep_start_;
    sweep_start_ = tick();
    return since;
  }
  // Commits a plan of the cavity operator and marks the vertices of its new elements changed.
  void commit(CavityOperator<D>& plan);
  // Marks a vertex changed (a move marks its ball's vertices).
  void mark_changed(Index v) { mesh_.vertex_attribute(stamp_attribute_, v)[0] = clock_; }
  // Marks the vertices outside `region` (per vertex) unchanged since before clock 0: the first pass
  // tries only the region (AdaptationSettings::first_pass_vertices).
  void settle_outside(std::span<const char> region) {
    for (Index v = 0; v < mesh_.vertex_count(); ++v)
      if (!region[static_cast<std::size_t>(v)]) mesh_.vertex_attribute(stamp_attribute_, v)[0] = -1;
  }
  // After vertices moved by something other than the operators (the boundary settling): each moved
  // vertex takes the metric at its new point, the elements of their balls renew their qualities, and
  // their vertices are marked changed.
  void vertices_moved(std::span<const Index> moved);
  bool changed_recently(Index v) const { return changed_since(v, previous_pass_start_); }
  // Whether v's ball changed at or after `clock` (everything did since clock 0).
  bool changed_since(Index v, int clock) const { return mesh_.vertex_attribute(stamp_attribute_, v)[0] >= clock; }
  // Smoothing's memory: a vertex whose move was refused, and whose ball has not changed since, would
  // be refused again (a refusal depends on the ball alone).
  void note_smoothing_refused(Index v) { mesh_.vertex_attribute(smoothing_refused_attribute_, v)[0] = clock_; }
  bool smoothing_refused_as_is(Index v) const {
    return mesh_.vertex_attribute(stamp_attribute_, v)[0] < mesh_.vertex_attribute(smoothing_refused_attribute_, v)[0];
  }
  // Whether element k was made, or one of its vertices moved, at or after `clock`.
  bool element_changed_since(Index k, int clock) const { return mesh_.element_attribute(element_stamp_attribute_, k) >= clock; }

  double edge_length(Index a, Index b) const { return metric_edge_length<D>(mesh_.vertex(a), mesh_.vertex(b), metric(a), metric(b)); }
  // The loop's quality (metric_measures.hpp) of any element, and of mesh element k: kept per
  // element (the most read figure of the loop), renewed by every commit and move.
  double quality(const Element& element) const { return quality(element, kNoIndex, {}, {}); }
  // The same with vertex `moved` at x with metric `metric_x` (a trial move; kNoIndex: none).
  double quality(const Element& element, Index moved, const Vec<D>& x, const SymMat<D>& metric_x) const;
  double quality(Index k) const { return mesh_.element_attribute(quality_attribute_, k); }

 private:
  // A vertex new to the run: no projection made near it, no move refused.
  void forget_history(Index v);
  void set_metric(Index v, const SymMat<D>& metric);
  void set_point_metric(Index v, const PointMetric& metric);
  // Renews the qualities of these elements and stamps them changed.
  void update_qualities(std::span<const Index> elements);

  Mesh<D>& mesh_;
  const AdaptationMetric<D>& metric_;
  const BoundaryGeometry<D>* geometry_;
  int metric_attribute_, class_attribute_, hint_attribute_, surface_hint_attribute_, stamp_attribute_, smoothing_refused_attribute_,
      non_manifold_attribute_, quality_attribute_, element_stamp_attribute_;
  int clock_ = 0, pass_start_ = 0, previous_pass_start_ = 0, sweep_start_ = 0;
  CavityWorkspace<D> work_;
};

extern template class AdaptationMesh<2>;
extern template class AdaptationMesh<3>;

}  // namespace hocav
