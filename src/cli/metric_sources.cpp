#include "cli/metric_sources.hpp"

#include "io/node_metrics.hpp"
#include "mesh/measure.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/hessian_recovery.hpp"
#include "metric/surface_metric.hpp"

namespace hocav {

template <int D>
std::vector<SymMat<D>> hessian_source_metrics(const Mesh<D>& mesh, const MeshFileContent& file, const HessianSource& source) {
  std::vector<SymMat<D>> hessians;
  if (is_analytic_field(source.field)) {
    const AnalyticFieldSpec shape = analytic_field_of(source);
    for (const auto& x : mesh.vertices()) hessians.push_back(analytic_field_hessian<D>(shape, x));
  } else {
    hessians = recover_hessians(mesh, read_scalar_for_mesh(source.field, file));
  }
  return lp_metric(mesh, hessians, lp_options_of(source, bounding_box_diagonal(mesh)));
}

template <int D>
std::vector<SymMat<D>> surface_source_metrics(const Mesh<D>& mesh, double normal, double tangential, std::optional<double> h_max) {
  return surface_metric_at_vertices(mesh, SurfaceSizes{normal, tangential, h_max.value_or(bounding_box_diagonal(mesh))});
}

template std::vector<SymMat<2>> hessian_source_metrics(const Mesh<2>&, const MeshFileContent&, const HessianSource&);
template std::vector<SymMat<3>> hessian_source_metrics(const Mesh<3>&, const MeshFileContent&, const HessianSource&);
template std::vector<SymMat<2>> surface_source_metrics(const Mesh<2>&, double, double, std::optional<double>);
template std::vector<SymMat<3>> surface_source_metrics(const Mesh<3>&, double, double, std::optional<double>);

}  // namespace hocav
