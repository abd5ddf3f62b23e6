#include "parallel/share_metric.hpp"

#include <memory>

#include "base/error.hpp"

namespace hocav {
namespace {

// Takes the share's log-metrics of one field (none for an empty share: a process whose part is empty).
template <int D>
std::vector<SymMat<D>> take_field(BackMeshShare<D>& share, std::size_t field) {
  if (share.global_ids.empty()) return {};
  if (field >= share.log_metrics.size()) throw Error("a back-mesh share lacks a field of its metric");
  return std::move(share.log_metrics[field]);
}

// The share's mesh as the fields' back mesh, its topology built.
template <int D>
std::shared_ptr<const Mesh<D>> back_mesh_of(BackMeshShare<D>& share) {
  share.mesh.build_topology();
  return std::make_shared<const Mesh<D>>(std::move(share.mesh));
}

}  // namespace

template <int D>
MetricRecipe recipe_of(const AdaptationMetric<D>& metric) {
  return {metric.analytic(), metric.bounds(), metric.analytic() && metric.field() != nullptr};
}

template <int D>
std::vector<std::vector<SymMat<D>>> share_log_metrics(const AdaptationMetric<D>& metric, const MetricField<D>& input_metric) {
  std::vector<std::vector<SymMat<D>>> fields(1);
  const Index count = input_metric.back_mesh().vertex_count();
  for (Index v = 0; v < count; ++v) fields[0].push_back(input_metric.vertex_log_metric(v));
  if (const MetricField<D>* field = metric.field()) {
    if (field->back_mesh().vertex_count() != count) throw Error("a metric's field is not on the input's vertices");
    fields.emplace_back();
    for (Index v = 0; v < count; ++v) fields[1].push_back(field->vertex_log_metric(v));
  }
  return fields;
}

template <int D>
ShareMetric<D>::ShareMetric(BackMeshShare<D> share, MetricRecipe recipe)
    : recipe_(std::move(recipe)), start_(MetricField<D>::on_back_mesh(back_mesh_of(share), take_field(share, 0))) {
  if (!recipe_.analytic || recipe_.hausdorff) field_.emplace(start_.with_log_metrics(take_field(share, 1)));
}

template <int D>
AdaptationMetric<D> ShareMetric<D>::partway(double fraction) const {
  const AdaptationMetric<D> target = recipe_.analytic ? AdaptationMetric<D>(*recipe_.analytic, recipe_.bounds, field_ ? &*field_ : nullptr)
                                                      : AdaptationMetric<D>(*field_, recipe_.bounds);
  return target.partway_from(start_, fraction);
}

template MetricRecipe recipe_of(const AdaptationMetric<2>&);
template MetricRecipe recipe_of(const AdaptationMetric<3>&);
template std::vector<std::vector<SymMat<2>>> share_log_metrics(const AdaptationMetric<2>&, const MetricField<2>&);
template std::vector<std::vector<SymMat<3>>> share_log_metrics(const AdaptationMetric<3>&, const MetricField<3>&);
template class ShareMetric<2>;
template class ShareMetric<3>;

}  // namespace hocav
