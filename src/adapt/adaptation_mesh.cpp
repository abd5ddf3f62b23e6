#include "adapt/adaptation_mesh.hpp"

#include <algorithm>

#include "adapt/vertex_classes.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/mesh_defects.hpp"

namespace hocav {

template <int D>
AdaptationMesh<D>::AdaptationMesh(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                  double feature_angle_degrees)
    : mesh_(mesh), metric_(metric), geometry_(geometry) {
  mesh_.compact();
  mesh_.orient_boundary_facets_outward();  // as the cavity operator makes them: its boundary tests compare the two
  metric_attribute_ = mesh_.add_vertex_attribute(SymMat<D>::kEntryCount);
  class_attribute_ = mesh_.add_vertex_attribute(1);
  hint_attribute_ = mesh_.add_vertex_attribute(1);
  surface_hint_attribute_ = mesh_.add_vertex_attribute(1);
  stamp_attribute_ = mesh_.add_vertex_attribute(1);  // the clock when the vertex's ball last changed
  smoothing_refused_attribute_ = mesh_.add_vertex_attribute(1);
  non_manifold_attribute_ = mesh_.add_vertex_attribute(1);
  const NonManifoldPlaces places = non_manifold_places(mesh_);
  for (Index v : places.every_vertex()) mesh_.vertex_attribute(non_manifold_attribute_, v)[0] = 1;
  const std::vector<VertexClass> classes = classify_vertices(mesh_, feature_angle_degrees, places);
  for (Index v = 0; v < mesh_.vertex_count(); ++v) {
    mesh_.vertex_attribute(class_attribute_, v)[0] = static_cast<double>(classes[v]);
    mesh_.vertex_attribute(hint_attribute_, v)[0] = kNoIndex;
    forget_history(v);
    set_point_metric(v, metric_at_point(mesh_.vertex(v), v));
  }
  quality_attribute_ = mesh_.add_element_attribute(0);
  element_stamp_attribute_ = mesh_.add_element_attribute(0);  // every element changed at clock 0
  for (Index k = 0; k < mesh_.element_count(); ++k) mesh_.set_element_attribute(quality_attribute_, k, quality(mesh_.element(k)));
}

template <int D>
void AdaptationMesh<D>::commit(CavityOperator<D>& plan) {
  plan.commit(mesh_);
  for (const auto& element : plan.new_elements())
    for (Index v : element) mark_changed(v);
  update_qualities(plan.committed_element_ids());
}

template <int D>
void AdaptationMesh<D>::update_qualities(std::span<const Index> elements) {
  for (Index k : elements) {
    mesh_.set_element_attribute(quality_attribute_, k, quality(mesh_.element(k)));
    mesh_.set_element_attribute(element_stamp_attribute_, k, clock_);
  }
}

template <int D>
void AdaptationMesh<D>::forget_history(Index v) {
  set_surface_hint(v, kNoIndex);
  mesh_.vertex_attribute(smoothing_refused_attribute_, v)[0] = -1;  // never refused
}

template <int D>
void AdaptationMesh<D>::set_metric(Index v, const SymMat<D>& metric) {
  std::copy(metric.entries.begin(), metric.entries.end(), mesh_.vertex_attribute(metric_attribute_, v).begin());
}

template <int D>
typename AdaptationMesh<D>::PointMetric AdaptationMesh<D>::metric_at_point(const Vec<D>& x, Index near) const {
  PointMetric found;
  found.hint = static_cast<Index>(mesh_.vertex_attribute(hint_attribute_, near)[0]);
  found.metric = metric_.metric_at(x, found.hint);
  return found;
}

template <int D>
void AdaptationMesh<D>::set_point_metric(Index v, const PointMetric& metric) {
  set_metric(v, metric.metric);
  mesh_.vertex_attribute(hint_attribute_, v)[0] = metric.hint;
}

template <int D>
Index AdaptationMesh<D>::add_vertex(const Vec<D>& x, VertexClass vertex_class, const PointMetric& metric) {
  const Index v = mesh_.add_vertex(x);
  mesh_.vertex_attribute(class_attribute_, v)[0] = static_cast<double>(vertex_class);
  forget_history(v);
  set_point_metric(v, metric);
  return v;
}

template <int D>
void AdaptationMesh<D>::move_vertex(Index v, const Vec<D>& x, std::span<const Index> ball) {
  mesh_.vertex(v) = x;
  set_point_metric(v, metric_at_point(x, v));
  update_qualities(ball);
}

template <int D>
void AdaptationMesh<D>::vertices_moved(std::span<const Index> moved) {
  if (moved.empty()) return;
  std::vector<char> is_moved(static_cast<std::size_t>(mesh_.vertex_count()), 0);
  for (Index v : moved) {
    set_point_metric(v, metric_at_point(mesh_.vertex(v), v));
    is_moved[v] = 1;
  }
  // Every element with a moved vertex, found by a scan: a walk around each vertex would miss the
  // far side of a vertex where two parts of the mesh touch.
  std::vector<Index> elements;
  for (Index k = 0; k < mesh_.element_count(); ++k) {
    const Element& element = mesh_.element(k);
    if (std::none_of(element.begin(), element.end(), [&](Index v) { return is_moved[v] != 0; })) continue;
    elements.push_back(k);
    for (Index v : element) mark_changed(v);
  }
  update_qualities(elements);
}

template <int D>
double AdaptationMesh<D>::quality(const Element& element, Index moved, const Vec<D>& x, const SymMat<D>& metric_x) const {
  SimplexPoints<D> points;
  std::array<SymMat<D>, D + 1> metrics;
  for (int i = 0; i <= D; ++i) {
    points[i] = element[i] == moved ? x : mesh_.vertex(element[i]);
    metrics[i] = element[i] == moved ? metric_x : metric(element[i]);
  }
  return mean_metric_ratio<D>(points, metrics);
}

template class AdaptationMesh<2>;
template class AdaptationMesh<3>;

}  // namespace hocav
