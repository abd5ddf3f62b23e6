// The jobs of the command line as functions (docs/python.md): read and write every format, adapt,
// curve, stats. Each calls the library's driver that the command calls, with the command's options
// as keyword arguments and its defaults; reports come back as the dicts of the commands' --report
// JSON. The GIL is released while the library works; hocav's errors raise hocav.Error with the
// command's message, and its warnings are Python warnings.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <sstream>

#include "adapt/adaptation_driver.hpp"
#include "base/error.hpp"
#include "base/memory_budget.hpp"
#include "base/thread_pool.hpp"
#include "binding.hpp"
#include "io/node_metrics.hpp"
#include "mesh/input_check.hpp"
#include "report/curved_vtu.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav::python {
namespace {

py::object parsed_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

void warn(const std::string& message) {
  if (!message.empty() && PyErr_WarnEx(PyExc_UserWarning, ("hocav: " + message).c_str(), 1) != 0) throw py::error_already_set();
}

// Paths: str or any os.PathLike.
using Path = std::filesystem::path;

PyMesh read(const Path& path) {
  py::gil_scoped_release release;
  return read_mesh_file(path.string());
}

// Rows of a metric for `mesh`: one per vertex, or one per vertex and P2 node (the writers' node order).
template <int D>
SolutionField metric_rows(const Mesh<D>& mesh, const DoubleArray& metric) {
  const bool per_node = metric.ndim() == 2 && mesh.is_p2() && metric.shape(0) == mesh.vertex_count() + mesh.edge_count();
  const Index rows = per_node ? mesh.vertex_count() + mesh.edge_count() : mesh.vertex_count();
  return rows_of_metrics(metrics_of_array<D>(metric, rows, "metric"));
}

void write(const Path& file, const PyMesh& mesh, const std::optional<DoubleArray>& metric, int meshb_version) {
  const std::string path = file.string();
  visit_mesh(mesh, [&](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    std::optional<SolutionField> rows;
    if (metric) rows = metric_rows(m, *metric);
    py::gil_scoped_release release;
    check_writable_mesh_format(path);
    if (file_extension(path) != ".vtu") {
      if (rows) throw Error(path + ": a metric goes into a .vtu, or into a .sol/.solb by write_metric");
      write_mesh_file(path, m, {meshb_version});
      return;
    }
    VtuData data;  // as `hocav convert`: the metric at the nodes, the Jacobian figures per element
    if (rows) {
      if (m.is_p2() && rows->count() == m.vertex_count()) throw Error(path + ": a P2 mesh's .vtu needs the metric at its P2 nodes too");
      data.point_fields.push_back(metric_tensor_field<D>(*rows));
    }
    data.cell_fields = jacobian_cell_fields(m);
    write_vtu(path, m, data);
  });
}

py::array_t<double> read_metric(const Path& path, const PyMesh& mesh, bool edge_nodes) {
  return visit_mesh(mesh, [&](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    std::vector<SymMat<D>> metrics;
    {
      py::gil_scoped_release release;
      metrics = metrics_of_rows<D>(read_metric_for_mesh(path.string(), mesh, edge_nodes && m.is_p2()));
    }
    return array_of_metrics(std::move(metrics));
  });
}

void write_metric(const Path& file, const PyMesh& mesh, const DoubleArray& metric, int meshb_version) {
  const std::string path = file.string();
  visit_mesh(mesh, [&](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    const SolutionField rows = metric_rows(m, metric);
    py::gil_scoped_release release;
    const std::string extension = file_extension(path);
    if (extension != ".sol" && extension != ".solb") throw Error(path + ": a metric is written as .sol or .solb, not '" + extension + "'");
    write_solution_file(path, {D, rows.count(), {rows}}, meshb_version);
  });
}

py::array_t<double> read_field(const Path& path, const PyMesh& mesh) {
  std::vector<double> values;
  {
    py::gil_scoped_release release;
    values = read_scalar_for_mesh(path.string(), mesh);
  }
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::tuple curve(const PyMesh& input_mesh, const DoubleArray& metric, const std::string& surface, double jacobian_floor,
                const std::string& quadrature, int passes, std::optional<int> threads) {
  return visit_mesh(input_mesh, [&](const auto& input) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(input)>>;
    const std::vector<SymMat<D>> metrics = metrics_of_array<D>(metric, input.vertex_count(), "metric");
    CurvingOptions options;
    options.quadrature = quadrature_rule_named(quadrature);
    options.jacobian_floor = jacobian_floor;
    options.passes = passes;
    options.threads = threads.value_or(every_core());
    const GeometryMaker<D> make_geometry = geometry_maker<D>(surface);
    Mesh<D> mesh = input;  // a Mesh never changes: the result is a new one
    prepare_input_mesh(mesh, "mesh", warn);
    warn(check_input_mesh(mesh, "mesh"));
    std::ostringstream report;
    {
      py::gil_scoped_release release;
      check_memory_fits("curving the mesh", mesh.element_count(), kCurvingBytesPerElement);
      const MetricField<D> field(mesh, metrics);
      const auto geometry = make_geometry(mesh);
      write_curving_report_json(report, curve_in_metric(mesh, field, geometry.get(), options));
    }
    return py::make_tuple(with_writer_numbering(std::move(mesh)), parsed_json(report.str()));
  });
}

// The options of `hocav adapt` (docs/usage.md), as the keyword arguments give them.
struct AdaptArguments {
  std::optional<DoubleArray> metric;
  std::optional<std::string> analytic;
  int order;
  std::optional<double> h_min, h_max, gradation, hausd;
  std::optional<double> hausd_relative;
  double angle;
  std::string surface;
  double jacobian_floor;
  int iterations;
  std::optional<int> threads;
  bool curved;
};

// The keyword arguments as the library's job.
template <int D>
AdaptationJob<D> adaptation_job(const AdaptArguments& a) {
  AdaptationJob<D> job;
  if (a.analytic) {
    job.analytic.emplace();
    job.analytic->name = *a.analytic;
  }
  job.bounds = {a.h_min.value_or(0), a.h_max.value_or(1e300)};
  job.gradation = a.gradation;
  job.hausd = a.hausd;
  job.hausd_relative = a.hausd_relative;
  job.angle = a.angle;
  job.iterations = a.iterations;
  job.threads = a.threads.value_or(every_core());
  job.metric_name = a.analytic ? "analytic " + *a.analytic : "metric";
  if (a.order == 2) {
    job.curving.emplace();
    job.curving->jacobian_floor = a.jacobian_floor;
    job.curving->threads = a.threads.value_or(every_core());
    job.curved = a.curved;
  }
  job.geometry = geometry_maker<D>(a.surface);
  return job;
}

py::tuple adapt(const PyMesh& mesh, const AdaptArguments& a) {
  if (a.metric.has_value() == a.analytic.has_value()) throw Error("give exactly one metric source: metric or analytic");
  if (a.order != 1 && a.order != 2) throw Error("order: 1 or 2, not " + std::to_string(a.order));
  if (a.curved && a.order == 1) throw Error("curved adapts the curved mesh: it needs order 2");
  if (a.h_min && a.h_max && *a.h_min > *a.h_max) throw Error("hmin must not exceed hmax");
  if (a.hausd_relative && !(*a.hausd_relative >= 0 && std::isfinite(*a.hausd_relative)))
    throw Error("hausd_relative: a finite number >= 0 (0: none)");
  if (a.gradation && a.analytic)
    throw Error("hgrad grades a metric given on a mesh: make one with grade_metric(mesh, analytic_metric(...), BETA)");
  return visit_mesh(mesh, [&](const auto& input) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(input)>>;
    std::vector<SymMat<D>> metrics;
    if (a.metric) metrics = metrics_of_array<D>(*a.metric, input.vertex_count(), "metric");
    Mesh<D> output = input;
    prepare_boundary<D>(output, "mesh", warn);  // as the command does, before the check
    warn(check_input_mesh(output, "mesh"));
    AdaptationJob<D> job = adaptation_job<D>(a);
    std::vector<std::string> warnings;  // given to Python once it holds the GIL again
    job.warn = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    std::ostringstream report;
    {
      py::gil_scoped_release release;
      const AdaptedMesh<D> result = run_adaptation_job(output, std::move(metrics), job, "the mesh");
      write_adaptation_report_json(report, result.report);
      warnings.push_back(non_convergence_summary(result.report));
    }
    for (const std::string& warning : warnings) warn(warning);
    return py::make_tuple(with_writer_numbering(std::move(output)), parsed_json(report.str()));
  });
}

py::object stats(const PyMesh& mesh, const std::optional<DoubleArray>& metric) {
  return visit_mesh(mesh, [&](const auto& input) {
    std::vector<double> node_metrics;
    if (metric) node_metrics = metric_rows(input, *metric).values;
    std::ostringstream json;
    {
      py::gil_scoped_release release;
      auto copy = input;  // the statistics build an edge table
      write_statistics_json(json, compute_mesh_statistics(copy, node_metrics, every_core()), "mesh", metric ? "metric" : "");
    }
    return parsed_json(json.str());
  });
}

}  // namespace

void bind_jobs(py::module_& module) {
  module.def("read", &read, py::arg("path"),
             "Reads a .mesh, .meshb or .msh file (2D or 3D, P1 or P2) into a Mesh (`hocav convert`'s reader).");
  module.def("write", &write, py::arg("path"), py::arg("mesh"), py::kw_only(), py::arg("metric") = py::none(), py::arg("meshb_version") = 0,
             R"(Writes a mesh as .mesh, .meshb, .msh or .vtu, by the extension (replaced whole or not at all).

A .vtu carries, as `hocav convert` writes it, the Jacobian figures of every element and, given a
metric (one row per vertex, and per P2 node for a P2 mesh), the metric as a tensor per node.
meshb_version: 1-4 for binary Gamma files (0: 3, or 4 when counts need it).)");
  module.def("read_metric", &read_metric, py::arg("path"), py::arg("mesh"), py::kw_only(), py::arg("edge_nodes") = false,
             R"(Reads the .sol/.solb metric of a mesh (one symmetric matrix per node of its file), checked as
the commands check it, as an (n, 3) or (n, 6) array in the mesh's vertex order (then its P2 nodes'
when edge_nodes).)");
  module.def("write_metric", &write_metric, py::arg("path"), py::arg("mesh"), py::arg("metric"), py::kw_only(),
             py::arg("meshb_version") = 0, "Writes a metric of a mesh (one row per vertex) as .sol or .solb.");
  module.def("read_field", &read_field, py::arg("path"), py::arg("mesh"),
             "Reads the first scalar field of a .sol/.solb given with a mesh: one value per vertex.");
  module.def("curve", &curve, py::arg("mesh"), py::arg("metric"), py::kw_only(), py::arg("surface") = "p3",
             py::arg("jacobian_floor") = 0.01, py::arg("quadrature") = "simpson", py::arg("passes") = 1, py::arg("threads") = py::none(),
             R"(Curves a mesh in its metric (`hocav curve`): the P2 mesh and the report (a dict, as --report writes it).

metric: one matrix per vertex ((n, 3) in 2D, (n, 6) in 3D). surface: 'p3' (a cubic surrogate of the
boundary), 'cad:FILE' or 'none'. jacobian_floor: every element the operator creates keeps its min
normalized Jacobian above it. quadrature: 'simpson', 'trapezoid' or 'gauss-N'. passes: reinsertion
passes. threads: default every core (the output does not depend on it).)");
  module.def(
      "adapt",
      [](const PyMesh& mesh, std::optional<DoubleArray> metric, std::optional<std::string> analytic, int order, std::optional<double> hmin,
         std::optional<double> hmax, std::optional<double> hgrad, std::optional<double> hausd, std::optional<double> hausd_relative,
         double angle, std::string surface, double jacobian_floor, int iterations, std::optional<int> threads, bool curved) {
        return adapt(mesh, {std::move(metric), std::move(analytic), order, hmin, hmax, hgrad, hausd, hausd_relative, angle,
                            std::move(surface), jacobian_floor, iterations, threads, curved});
      },
      py::arg("mesh"), py::arg("metric") = py::none(), py::kw_only(), py::arg("analytic") = py::none(), py::arg("order") = 2,
      py::arg("hmin") = py::none(), py::arg("hmax") = py::none(), py::arg("hgrad") = py::none(), py::arg("hausd") = py::none(),
      py::arg("hausd_relative") = py::none(), py::arg("angle") = 45.0, py::arg("surface") = "p3", py::arg("jacobian_floor") = 0.01,
      py::arg("iterations") = 20, py::arg("threads") = py::none(), py::arg("curved") = false,
      R"(Adapts a mesh to a metric, then curves it (`hocav adapt`): the new mesh and the report (a dict).

metric: one matrix per vertex of mesh (its back mesh), or analytic: a name of analytic_metric_names()
evaluated exactly. order: 2 curves the adapted mesh, 1 stops after the P1 adaptation. hmin, hmax:
clamp the sizes; hgrad: grade the metric first; hausd: largest distance of a new boundary facet from
the geometry (default 0.01 of the bounding box's diagonal); hausd_relative: when > 0, that distance
also at most this times the smallest size the metric asks at each boundary vertex (default 1 with
order 2, which the curving needs on a boundary layer; none with order 1); angle: ridges above this dihedral angle;
surface: 'p3', 'cad:FILE' or 'none'; iterations: at most this many passes (a warning when the loop
stops there); threads: of the swaps, smoothing, collapse tests and curving, default every core;
curved: then curved passes on the curved mesh (`adapt --curved`: split and collapse by curved
length, swaps and moves by curved quality, every P2 operation certified; needs order 2; the report
gains curved_passes). Sizes below 1e-6 of the input's diagonal are clamped there, with a warning.)");
  module.def("stats", &stats, py::arg("mesh"), py::arg("metric") = py::none(),
             R"(The figures of `hocav stats --json` as a dict: counts, refs, measures, consistency, Jacobian
figures, memory; with a metric (one row per vertex, or per node), edge lengths and qualities in it.)");
}

}  // namespace hocav::python
