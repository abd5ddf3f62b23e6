#include "parallel/spatial_cut.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

#include "mesh/mesh_box.hpp"
#include "mesh/spatial_order.hpp"

namespace hocav {

template <int D>
std::vector<int> spatial_cut(const Mesh<D>& mesh, std::span<const double> loads, int parts) {
  const Box<D> box = vertex_box(mesh);
  std::vector<std::pair<std::uint64_t, Index>> order;
  order.reserve(static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) {
    Vec<D> centroid{};
    for (Index v : mesh.element(k)) centroid += (1.0 / (D + 1)) * mesh.vertex(v);
    order.emplace_back(morton_code<D>(centroid, box.lower, box.upper - box.lower), k);
  }
  std::sort(order.begin(), order.end());
  const double total = std::accumulate(loads.begin(), loads.end(), 0.0);
  std::vector<int> part_of(order.size(), 0);
  double before = 0;  // the load of the elements before, in the order
  for (const auto& [code, k] : order) {
    const double middle = before + 0.5 * loads[k];
    part_of[k] = total > 0 ? std::min(parts - 1, static_cast<int>(middle / total * parts)) : 0;
    before += loads[k];
  }
  return part_of;
}

template std::vector<int> spatial_cut(const Mesh<2>&, std::span<const double>, int);
template std::vector<int> spatial_cut(const Mesh<3>&, std::span<const double>, int);

}  // namespace hocav
