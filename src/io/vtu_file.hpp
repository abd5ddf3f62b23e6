// VTK XML unstructured grids (.vtu) for ParaView: quadratic cells for P2 meshes, with point data
// (e.g. the metric as a tensor) and cell data (refs; later per-element quality).
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct VtuField {
  std::string name;
  int components = 1;          // 1 scalar, 3 vector, 9 tensor (ParaView's tensor layout)
  std::vector<double> values;  // one row of `components` per file node (point data) or element
};

struct VtuData {
  std::vector<VtuField> point_fields;  // rows in file node order: vertices, then P2 edge nodes
  std::vector<VtuField> cell_fields;   // rows in element order; "ref" is always written
};

template <int D>
void write_vtu(const std::string& path, const Mesh<D>& mesh, const VtuData& data = {});

}  // namespace hocav
