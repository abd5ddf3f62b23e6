#include <algorithm>
#include <cmath>

#include "parallel/element_partition.hpp"

namespace hocav {
namespace {

double sum_of(std::span<const double> loads) {
  double total = 0;
  for (double load : loads) total += load;
  return total;
}

}  // namespace

std::vector<std::int64_t> integer_loads(std::span<const double> loads, double total) {
  const double scale = total > 0 ? std::min(1000.0, 1e9 / total) : 0;
  std::vector<std::int64_t> weights(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) weights[k] = 1 + std::llround(loads[k] * scale);
  return weights;
}

template <int D>
WeightedGraph element_graph(const Mesh<D>& mesh, std::span<const double> loads, std::span<const char> old_interface) {
  WeightedGraph graph;
  graph.vertex_weights = integer_loads(loads, sum_of(loads));
  graph.offsets.push_back(0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const bool near_old_interface = touches<D>(mesh.element(k), old_interface);
    for (int face = 0; face <= D; ++face) {
      const Index other = mesh.neighbor(k, face);
      if (other == kNoIndex) continue;
      graph.neighbours.push_back(other);
      const bool heavy = near_old_interface && touches<D>(mesh.element(other), old_interface);
      graph.edge_weights.push_back(heavy ? kOldInterfaceFaceWeight : 1);
    }
    graph.offsets.push_back(static_cast<std::int64_t>(graph.neighbours.size()));
  }
  return graph;
}

template <int D>
WeightedGraph member_graph(const Mesh<D>& mesh, std::span<const char> members, std::span<const double> loads,
                           std::vector<Index>& elements) {
  elements.clear();
  std::vector<Index> vertex_of(static_cast<std::size_t>(mesh.element_count()), kNoIndex);
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (members[k]) {
      vertex_of[k] = static_cast<Index>(elements.size());
      elements.push_back(k);
    }
  WeightedGraph graph;
  if (loads.empty()) {
    graph.vertex_weights.assign(elements.size(), 1);
  } else {
    std::vector<double> member_loads;
    for (Index k : elements) member_loads.push_back(loads[k]);
    graph.vertex_weights = integer_loads(member_loads, sum_of(member_loads));
  }
  graph.offsets.push_back(0);
  for (Index k : elements) {
    for (int face = 0; face <= D; ++face)
      if (const Index other = mesh.neighbor(k, face); other != kNoIndex && vertex_of[other] != kNoIndex) {
        graph.neighbours.push_back(vertex_of[other]);
        graph.edge_weights.push_back(1);
      }
    graph.offsets.push_back(static_cast<std::int64_t>(graph.neighbours.size()));
  }
  return graph;
}

template <int D>
std::vector<char> elements_near(const Mesh<D>& mesh, std::vector<char> marked, int rings) {
  std::vector<char> near(static_cast<std::size_t>(mesh.element_count()), 0);
  for (int ring = 1; ring <= rings; ++ring) {
    for (Index k = 0; k < mesh.element_count(); ++k)
      for (Index v : mesh.element(k)) near[k] = near[k] || marked[v];
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (near[k])
        for (Index v : mesh.element(k)) marked[v] = 1;
  }
  return near;
}

template WeightedGraph member_graph(const Mesh<2>&, std::span<const char>, std::span<const double>, std::vector<Index>&);
template WeightedGraph member_graph(const Mesh<3>&, std::span<const char>, std::span<const double>, std::vector<Index>&);
template std::vector<char> elements_near(const Mesh<2>&, std::vector<char>, int);
template std::vector<char> elements_near(const Mesh<3>&, std::vector<char>, int);
template WeightedGraph element_graph(const Mesh<2>&, std::span<const double>, std::span<const char>);
template WeightedGraph element_graph(const Mesh<3>&, std::span<const double>, std::span<const char>);

}  // namespace hocav
