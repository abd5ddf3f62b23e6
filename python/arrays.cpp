#include <numeric>

#include "base/error.hpp"
#include "binding.hpp"

namespace hocav::python {

PyMesh with_writer_numbering(AnyMesh mesh) {
  PyMesh content{std::move(mesh), {}, {}, 0};
  std::visit(
      [&content](const auto& m) {
        content.vertex_file_ids.resize(static_cast<std::size_t>(m.vertex_count()));
        std::iota(content.vertex_file_ids.begin(), content.vertex_file_ids.end(), Index{0});
        if (m.is_p2()) {
          content.edge_node_file_ids.resize(static_cast<std::size_t>(m.edge_count()));
          std::iota(content.edge_node_file_ids.begin(), content.edge_node_file_ids.end(), m.vertex_count());
        }
        content.file_node_count = m.vertex_count() + (m.is_p2() ? m.edge_count() : 0);
      },
      content.mesh);
  return content;
}

template <int D>
py::array_t<double> array_of_metrics(std::vector<SymMat<D>>&& metrics) {
  static_assert(sizeof(SymMat<D>) == SymMat<D>::kEntryCount * sizeof(double));
  auto* owned = new std::vector<SymMat<D>>(std::move(metrics));
  py::capsule owner(owned, [](void* vector) { delete static_cast<std::vector<SymMat<D>>*>(vector); });
  const auto rows = static_cast<py::ssize_t>(owned->size());
  return py::array_t<double>({rows, static_cast<py::ssize_t>(SymMat<D>::kEntryCount)}, reinterpret_cast<const double*>(owned->data()),
                             owner);
}

template <int D>
std::vector<SymMat<D>> metrics_of_array(const DoubleArray& array, Index rows, const std::string& what) {
  constexpr auto kEntries = static_cast<py::ssize_t>(SymMat<D>::kEntryCount);
  if (array.ndim() != 2 || array.shape(0) != rows || array.shape(1) != kEntries) {
    std::string shape;
    for (py::ssize_t i = 0; i < array.ndim(); ++i) shape.append(i ? ", " : "").append(std::to_string(array.shape(i)));
    throw Error(what + ": an array of shape (" + std::to_string(rows) + ", " + std::to_string(kEntries) +
                ") expected (one symmetric matrix per vertex, its lower triangle row by row), not (" + shape + ")");
  }
  std::vector<SymMat<D>> metrics(static_cast<std::size_t>(rows));
  const double* values = array.data();
  for (auto& metric : metrics)
    for (auto& entry : metric.entries) entry = *values++;
  return metrics;
}

template py::array_t<double> array_of_metrics(std::vector<SymMat<2>>&&);
template py::array_t<double> array_of_metrics(std::vector<SymMat<3>>&&);
template std::vector<SymMat<2>> metrics_of_array(const DoubleArray&, Index, const std::string&);
template std::vector<SymMat<3>> metrics_of_array(const DoubleArray&, Index, const std::string&);

}  // namespace hocav::python
