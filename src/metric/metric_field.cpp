#include "metric/metric_field.hpp"

#include <algorithm>
#include <string>

#include "base/error.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

template <int D>
void check_positive_elements(const Mesh<D>& back) {
  for (Index k = 0; k < back.element_count(); ++k)
    if (!(element_measure(back, k) > 0))
      throw Error("back mesh: element " + one_based(k) +
                  " has non-positive straight (P1) measure; the metric's back mesh must be a valid P1 mesh");
}

template <int D>
std::unique_ptr<Mesh<D>> straight_copy(const Mesh<D>& mesh) {
  auto back = std::make_unique<Mesh<D>>();
  for (Index v = 0; v < mesh.vertex_count(); ++v) back->add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
  for (Index k = 0; k < mesh.element_count(); ++k) back->add_element(mesh.element(k), mesh.element_ref(k));
  check_positive_elements(*back);
  for (Index f = 0; f < mesh.facet_count(); ++f) back->add_facet(mesh.facet(f), mesh.facet_ref(f));
  back->build_topology();
  return back;
}

}  // namespace

template <int D>
MetricField<D>::MetricField(std::shared_ptr<const Mesh<D>> back_mesh, std::shared_ptr<const PointLocator<D>> locator,
                            std::vector<SymMat<D>> log_metrics)
    : back_mesh_(std::move(back_mesh)), locator_(std::move(locator)), log_metrics_(std::move(log_metrics)) {
  if (log_metrics_.size() != static_cast<std::size_t>(back_mesh_->vertex_count()))
    throw Error("metric field: " + std::to_string(log_metrics_.size()) + " metrics for " + std::to_string(back_mesh_->vertex_count()) +
                " vertices");
}

template <int D>
MetricField<D>::MetricField(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics)
    : MetricField(MetricField::from_log_metrics(mesh, logarithms(metrics))) {}

template <int D>
MetricField<D> MetricField<D>::from_log_metrics(const Mesh<D>& mesh, std::vector<SymMat<D>> log_metrics) {
  std::shared_ptr<const Mesh<D>> back = straight_copy(mesh);
  auto locator = std::make_shared<const PointLocator<D>>(*back);
  return MetricField(std::move(back), std::move(locator), std::move(log_metrics));
}

template <int D>
MetricField<D> MetricField<D>::on_back_mesh(std::shared_ptr<const Mesh<D>> back_mesh, std::vector<SymMat<D>> log_metrics) {
  if (!back_mesh->has_topology() && back_mesh->element_count() > 0) throw Error("a metric field's shared back mesh has no topology");
  check_positive_elements(*back_mesh);
  auto locator = std::make_shared<const PointLocator<D>>(*back_mesh);
  return MetricField(std::move(back_mesh), std::move(locator), std::move(log_metrics));
}

template <int D>
std::vector<SymMat<D>> MetricField<D>::logarithms(const std::vector<SymMat<D>>& metrics) {
  std::vector<SymMat<D>> logs(metrics.size());
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    if (!is_spd(metrics[v])) throw Error("metric at vertex " + one_based(v) + " is not positive definite");
    logs[v] = log_spd(metrics[v]);
  }
  return logs;
}

template <int D>
bool MetricField<D>::is_on(const Mesh<D>& mesh) const {
  const auto same = [](auto a, auto b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); };
  return same(back_mesh_->vertices(), mesh.vertices()) && same(back_mesh_->elements(), mesh.elements());
}

template <int D>
MetricField<D> MetricField<D>::with_log_metrics(std::vector<SymMat<D>> log_metrics) const {
  return MetricField(back_mesh_, locator_, std::move(log_metrics));
}

template <int D>
SymMat<D> MetricField<D>::interpolate(Index back_element, const Barycentrics<D>& lambda) const {
  const auto& element = back_mesh_->element(back_element);
  SymMat<D> result{};
  for (int i = 0; i <= D; ++i) result += lambda[i] * log_metrics_[element[i]];
  return result;
}

template <int D>
typename MetricField<D>::Sample MetricField<D>::sample(const Vec<D>& x, Index hint, LocatorScratch& scratch) const {
  Sample result{locator_->localize(x, hint, scratch), {}};
  result.log_metric = interpolate(result.where.element, result.where.barycentrics);
  return result;
}

template <int D>
typename MetricField<D>::Sample MetricField<D>::sample_within(const Vec<D>& x, Index hint, LocatorScratch& scratch) const {
  Sample result{locator_->localize(x, hint, scratch), {}};
  Barycentrics<D> lambda = result.where.barycentrics;
  const double centroid = 1.0 / (D + 1), lowest = *std::min_element(lambda.begin(), lambda.end());
  if (lowest < -kMostExtension) {  // toward the centroid until the lowest is −kMostExtension
    const double shrink = (centroid + kMostExtension) / (centroid - lowest);
    for (double& l : lambda) l = centroid + shrink * (l - centroid);
  }
  result.log_metric = interpolate(result.where.element, lambda);
  return result;
}

template <int D>
typename MetricField<D>::Sample MetricField<D>::sample(const Vec<D>& x, const ElementFrame& frame, LocatorScratch& scratch) const {
  const Barycentrics<D> lambda = barycentric_coordinates<D>(frame.barycentric_gradients, frame.origin, x);
  if (!PointLocator<D>::contains(lambda)) return sample(x, frame.element, scratch);
  return {{frame.element, lambda, true}, interpolate(frame.element, lambda)};
}

template <int D>
std::array<SymMat<D>, D> MetricField<D>::log_metric_gradient(Index back_element,
                                                             const std::array<Vec<D>, D + 1>& barycentric_gradients) const {
  const auto& element = back_mesh_->element(back_element);
  std::array<SymMat<D>, D> result{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= D; ++j) result[i] += barycentric_gradients[j][i] * log_metrics_[element[j]];
  return result;
}

template <int D>
std::array<SymMat<D>, D> MetricField<D>::log_metric_gradient(Index back_element) const {
  return log_metric_gradient(back_element, barycentric_gradients<D>(locator_->element_points(back_element)));
}

template <int D>
typename MetricField<D>::ElementFrame MetricField<D>::element_frame(Index back_element) const {
  const SimplexPoints<D> points = locator_->element_points(back_element);
  const std::array<Vec<D>, D + 1> gradients = barycentric_gradients<D>(points);
  // Made whole, not cleared and then filled.
  return {back_element, points[0], gradients, log_metric_gradient(back_element, gradients)};
}

template <int D>
std::vector<SymMat<D>> metrics_at(const MetricField<D>& field, std::span<const Vec<D>> points, Index& hint) {
  LocatorScratch scratch;
  std::vector<SymMat<D>> metrics;
  metrics.reserve(points.size());
  for (const Vec<D>& x : points) {
    const typename MetricField<D>::Sample sample = field.sample_within(x, hint, scratch);
    hint = sample.where.element;
    metrics.push_back(exp_sym(sample.log_metric));
  }
  return metrics;
}

template std::vector<SymMat<2>> metrics_at(const MetricField<2>&, std::span<const Vec<2>>, Index&);
template std::vector<SymMat<3>> metrics_at(const MetricField<3>&, std::span<const Vec<3>>, Index&);
template class MetricField<2>;
template class MetricField<3>;

}  // namespace hocav
