#include "mesh/spatial_order.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "base/error.hpp"
#include "mesh/mesh_box.hpp"

namespace hocav {

template <int D>
std::uint64_t morton_code(const Vec<D>& x, const Vec<D>& low, const Vec<D>& extent) {
  constexpr int kBits = 63 / D;
  constexpr double kCells = static_cast<double>((std::uint64_t{1} << kBits) - 1);
  std::array<std::uint64_t, D> cell;
  for (int d = 0; d < D; ++d) {
    const double t = extent[d] > 0 ? (x[d] - low[d]) / extent[d] : 0;
    cell[d] = static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * kCells);
  }
  std::uint64_t code = 0;
  for (int bit = kBits - 1; bit >= 0; --bit)
    for (int d = 0; d < D; ++d) code = (code << 1) | ((cell[d] >> bit) & 1);
  return code;
}

namespace {

// Each vertex's position in the Morton order of the vertices (ties by id).
template <int D>
std::vector<Index> vertices_in_morton_order(const Mesh<D>& mesh) {
  const Box<D> box = vertex_box(mesh);
  std::vector<std::pair<std::uint64_t, Index>> keyed(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    keyed[static_cast<std::size_t>(v)] = {morton_code<D>(mesh.vertex(v), box.lower, box.upper - box.lower), v};
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> new_id(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) new_id[static_cast<std::size_t>(keyed[i].second)] = static_cast<Index>(i);
  return new_id;
}

// Each element's position when the elements are ordered by their smallest new vertex id (a
// counting sort: equals keep their order).
template <int D>
std::vector<Index> elements_by_first_vertex(const Mesh<D>& mesh, const std::vector<Index>& new_vertex_id) {
  const auto smallest = [&](Index k) {
    Index first = std::numeric_limits<Index>::max();
    for (Index v : mesh.element(k)) first = std::min(first, new_vertex_id[static_cast<std::size_t>(v)]);
    return static_cast<std::size_t>(first);
  };
  std::vector<Index> start(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for (Index k = 0; k < mesh.element_count(); ++k) ++start[smallest(k) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Index> new_id(static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) new_id[static_cast<std::size_t>(k)] = start[smallest(k)]++;
  return new_id;
}

}  // namespace

template <int D>
void sort_spatially(Mesh<D>& mesh) {
  if (!mesh.is_compact()) throw Error("sort_spatially: the mesh has removed entities; compact it first");
  const std::vector<Index> new_vertex_id = vertices_in_morton_order(mesh);
  mesh.renumber(new_vertex_id, elements_by_first_vertex(mesh, new_vertex_id));
}

template std::uint64_t morton_code(const Vec<2>&, const Vec<2>&, const Vec<2>&);
template std::uint64_t morton_code(const Vec<3>&, const Vec<3>&, const Vec<3>&);
template void sort_spatially(Mesh<2>&);
template void sort_spatially(Mesh<3>&);

}  // namespace hocav
