// The metric sources of `hocav metric` (docs/metrics.md), each a function of a mesh returning one
// metric per vertex as an (n, 3) or (n, 6) array (the lower triangle row by row, the .sol order).
#include <pybind11/stl.h>

#include <optional>

#include "base/error.hpp"
#include "binding.hpp"
#include "mesh/measure.hpp"
#include "metric/analytic_field.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/gradation.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/hessian_recovery.hpp"
#include "metric/implied_metric.hpp"
#include "metric/metric_field.hpp"
#include "metric/surface_metric.hpp"

namespace hocav::python {
namespace {

using Origin = std::optional<std::vector<double>>;

// Runs f() without the GIL (f touches no Python object) and returns its metrics as an array.
template <class F>
py::array_t<double> metric_array(F&& f) {
  auto metrics = [&f] {
    py::gil_scoped_release release;
    return f();
  }();
  return array_of_metrics(std::move(metrics));
}

template <int D>
std::array<double, 3> origin_of(const Origin& origin) {
  std::array<double, 3> point{0, 0, 0};
  if (!origin) return point;
  if (origin->size() != static_cast<std::size_t>(D))
    throw Error("origin needs " + std::to_string(D) + " coordinates for a " + std::to_string(D) + "D mesh");
  std::copy(origin->begin(), origin->end(), point.begin());
  return point;
}

py::array_t<double> analytic(const PyMesh& mesh, const std::string& name, std::optional<double> h, std::optional<double> h_min,
                             std::optional<double> h_max, std::optional<std::string> axis, std::optional<double> center,
                             std::optional<double> radius, std::optional<double> width, const Origin& origin) {
  AnalyticMetricSpec spec;
  spec.name = name;
  spec.h = h.value_or(spec.h);
  spec.h_min = h_min.value_or(spec.h_min);
  spec.h_max = h_max.value_or(spec.h_max);
  if (axis) {
    if (axis->size() != 1 || (*axis)[0] < 'x' || (*axis)[0] > 'z') throw Error("axis: x, y or z, not '" + *axis + "'");
    spec.axis = (*axis)[0] - 'x';
  }
  spec.center = center.value_or(spec.center);
  spec.radius = radius.value_or(spec.radius);
  spec.width = width.value_or(spec.width);
  return visit_mesh(mesh, [&spec, &origin](const auto& m) {
    spec.origin = origin_of<kDimensionOf<std::decay_t<decltype(m)>>>(origin);
    return metric_array([&spec, &m] { return analytic_metric_at_vertices(spec, m); });
  });
}

py::array_t<double> implied(const PyMesh& mesh) {
  return visit_mesh(mesh, [](const auto& m) { return metric_array([&m] { return implied_metric_at_vertices(m); }); });
}

py::array_t<double> surface(const PyMesh& mesh, double h_normal, double h_tangent, double gradation, std::optional<double> h_max) {
  return visit_mesh(mesh, [&](const auto& m) {
    return metric_array([&] {
      auto metrics = surface_metric_at_vertices(m, SurfaceSizes{h_normal, h_tangent, h_max.value_or(bounding_box_diagonal(m))});
      grade_metrics(m, metrics, GradationOptions{gradation});
      return metrics;
    });
  });
}

// The Hessians of a field given at the vertices (an array) or analytic (its name).
template <int D>
std::vector<SymMat<D>> hessians_of(const Mesh<D>& mesh, const std::variant<DoubleArray, std::string>& field, const Origin& origin,
                                   std::optional<double> radius, std::optional<double> width) {
  if (const auto* name = std::get_if<std::string>(&field)) {
    AnalyticFieldSpec spec;
    spec.name = *name;
    spec.radius = radius.value_or(spec.radius);
    spec.width = width.value_or(spec.width);
    spec.origin = origin_of<D>(origin);
    std::vector<SymMat<D>> hessians;
    for (const auto& x : mesh.vertices()) hessians.push_back(analytic_field_hessian<D>(spec, x));
    return hessians;
  }
  const DoubleArray& values = std::get<DoubleArray>(field);
  if (values.ndim() != 1 || values.shape(0) != mesh.vertex_count())
    throw Error("hessian_metric: field: one value per vertex expected (" + std::to_string(mesh.vertex_count()) + ")");
  return recover_hessians(mesh, std::span<const double>(values.data(), static_cast<std::size_t>(values.shape(0))));
}

py::array_t<double> hessian(const PyMesh& mesh, const std::variant<DoubleArray, std::string>& field, double complexity,
                            std::optional<double> norm, std::optional<double> h_min, std::optional<double> h_max, const Origin& origin,
                            std::optional<double> radius, std::optional<double> width) {
  return visit_mesh(mesh, [&](const auto& m) {
    const auto hessians = hessians_of(m, field, origin, radius, width);  // with the GIL: reads the array
    return metric_array([&] {
      LpMetricOptions lp;
      lp.complexity = complexity;
      lp.norm = norm.value_or(lp.norm);
      lp.h_max = h_max.value_or(bounding_box_diagonal(m));
      lp.h_min = h_min.value_or(kHessianSizeRange * lp.h_max);
      return lp_metric(m, hessians, lp);
    });
  });
}

// The back mesh's metric interpolated log-Euclidean at the vertices of `mesh` (`hocav metric --from`).
py::array_t<double> interpolated(const PyMesh& mesh, const PyMesh& back, const DoubleArray& back_metric) {
  if (dimension_of(mesh.mesh) != dimension_of(back.mesh)) throw Error("interpolate_metric: the back mesh is not as the mesh 2D or 3D");
  return visit_mesh(mesh, [&](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    const Mesh<D>& back_mesh = std::get<Mesh<D>>(back.mesh);
    const std::vector<SymMat<D>> back_metrics = metrics_of_array<D>(back_metric, back_mesh.vertex_count(), "back_metric");
    return metric_array([&] {
      const MetricField<D> field(back_mesh, back_metrics);
      Index hint = kNoIndex;
      return metrics_at(field, m.vertices(), hint);
    });
  });
}

py::array_t<double> graded(const PyMesh& mesh, const DoubleArray& metric, double gradation) {
  return visit_mesh(mesh, [&](const auto& m) {
    auto metrics = metrics_of_array<kDimensionOf<std::decay_t<decltype(m)>>>(metric, m.vertex_count(), "metric");
    return metric_array([&] {
      grade_metrics(m, metrics, GradationOptions{gradation});
      return std::move(metrics);
    });
  });
}

double complexity(const PyMesh& mesh, const DoubleArray& metric) {
  return visit_mesh(mesh, [&metric](const auto& m) {
    return metric_complexity(m, metrics_of_array<kDimensionOf<std::decay_t<decltype(m)>>>(metric, m.vertex_count(), "metric"));
  });
}

}  // namespace

void bind_metrics(py::module_& module) {
  module.def("analytic_metric", &analytic, py::arg("mesh"), py::arg("name"), py::kw_only(), py::arg("h") = py::none(),
             py::arg("h_min") = py::none(), py::arg("h_max") = py::none(), py::arg("axis") = py::none(), py::arg("center") = py::none(),
             py::arg("radius") = py::none(), py::arg("width") = py::none(), py::arg("origin") = py::none(),
             R"(An analytic metric at the vertices (`hocav metric --analytic NAME`).

name: one of analytic_metric_names(). h (uniform; default 0.1), h_min, h_max (linear, shear-*;
defaults 0.001, 0.1), axis ('x', 'y', 'z'; linear), center (linear; 0.5), radius, width, origin
(shear-*; 0.75, 0.05, the origin). Returns an (n, 3) (2D) or (n, 6) (3D) array.)");
  module.def("implied_metric", &implied, py::arg("mesh"), "The metric in which the mesh is a unit mesh (`hocav metric --implied`).");
  module.def("surface_metric", &surface, py::arg("mesh"), py::arg("h_normal"), py::arg("h_tangent"), py::kw_only(), py::arg("gradation"),
             py::arg("h_max") = py::none(),
             R"(Size h_normal along the boundary normals and h_tangent along the boundary, carried into the
volume by gradation (> 1); interior vertices start at h_max (default the bounding box's diagonal)
(`hocav metric --surface HN,HT --gradation BETA`).)");
  module.def("hessian_metric", &hessian, py::arg("mesh"), py::arg("field"), py::kw_only(), py::arg("complexity"),
             py::arg("norm") = py::none(), py::arg("h_min") = py::none(), py::arg("h_max") = py::none(), py::arg("origin") = py::none(),
             py::arg("radius") = py::none(), py::arg("width") = py::none(),
             R"(The Lp metric of the Hessian of a field, at a target complexity (about the vertex count)
(`hocav metric --hessian`).

field: one value per vertex (a numpy array; its Hessians are recovered), or the name of an analytic
field (analytic_field_names(), with origin, radius, width). norm: the p of the Lp norm (default 2).
h_max: bound on |H| (default the bounding box's diagonal), h_min (default 1e-6 h_max).)");
  module.def("interpolate_metric", &interpolated, py::arg("mesh"), py::arg("back_mesh"), py::arg("back_metric"),
             R"(The metric of back_mesh (one per vertex) interpolated log-Euclidean at the vertices of mesh
(`hocav metric --from BACK --from-metric SOL`): to measure a remesher's output in its input metric.)");
  module.def("grade_metric", &graded, py::arg("mesh"), py::arg("metric"), py::arg("gradation"),
             "The metric graded: sizes grow by at most gradation (> 1) per unit length (`--gradation`).");
  module.def("metric_complexity", &complexity, py::arg("mesh"), py::arg("metric"),
             "The complexity of a metric on a mesh: the integral of sqrt(det M), about its unit mesh's vertex count.");
  module.def("analytic_metric_names", &analytic_metric_names, "The names analytic_metric takes.");
  module.def("analytic_field_names", &analytic_field_names, "The analytic fields hessian_metric takes by name.");
}

}  // namespace hocav::python
