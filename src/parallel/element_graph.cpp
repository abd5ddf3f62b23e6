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

// The smaller of two labels, kNoLabel counting as none.
int smaller_label(int a, int b) { return a == kNoLabel ? b : b == kNoLabel ? a : std::min(a, b); }

}  // namespace

std::vector<std::int64_t> integer_loads(std::span<const double> loads, double total) {
  const double scale = total > 0 ? std::min(1000.0, 1e9 / total) : 0;
  std::vector<std::int64_t> weights(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) weights[k] = 1 + std::llround(loads[k] * scale);
  return weights;
}

template <int D>
WeightedGraph element_graph(const Mesh<D>& mesh, std::span<const double> loads, std::span<const char> kept_inside) {
  WeightedGraph graph;
  graph.vertex_weights = integer_loads(loads, sum_of(loads));
  graph.offsets.push_back(0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const bool near_kept_inside = touches<D>(mesh.element(k), kept_inside);
    for (int face = 0; face <= D; ++face) {
      const Index other = mesh.neighbor(k, face);
      if (other == kNoIndex) continue;
      graph.neighbours.push_back(other);
      const bool heavy = near_kept_inside && touches<D>(mesh.element(other), kept_inside);
      graph.edge_weights.push_back(heavy ? kKeptInsideFaceWeight : 1);
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
  std::vector<int> labels(marked.size(), kNoLabel);
  for (std::size_t v = 0; v < marked.size(); ++v)
    if (marked[v]) labels[v] = 0;
  std::vector<char> near;
  for (int label : nearest_labels(mesh, std::move(labels), rings)) near.push_back(label != kNoLabel);
  return near;
}

template <int D>
std::vector<int> nearest_labels(const Mesh<D>& mesh, std::vector<int> labels, int rings) {
  std::vector<int> nearest(static_cast<std::size_t>(mesh.element_count()), kNoLabel);
  for (int ring = 1; ring <= rings; ++ring) {
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (nearest[k] == kNoLabel)
        for (Index v : mesh.element(k)) nearest[k] = smaller_label(nearest[k], labels[v]);
    std::vector<int> grown = labels;  // (this ring's elements label the next ring's vertices)
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (nearest[k] != kNoLabel)
        for (Index v : mesh.element(k))
          if (labels[v] == kNoLabel) grown[v] = smaller_label(grown[v], nearest[k]);
    labels = std::move(grown);
  }
  return nearest;
}

template WeightedGraph member_graph(const Mesh<2>&, std::span<const char>, std::span<const double>, std::vector<Index>&);
template WeightedGraph member_graph(const Mesh<3>&, std::span<const char>, std::span<const double>, std::vector<Index>&);
template std::vector<char> elements_near(const Mesh<2>&, std::vector<char>, int);
template std::vector<char> elements_near(const Mesh<3>&, std::vector<char>, int);
template std::vector<int> nearest_labels(const Mesh<2>&, std::vector<int>, int);
template std::vector<int> nearest_labels(const Mesh<3>&, std::vector<int>, int);
template WeightedGraph element_graph(const Mesh<2>&, std::span<const double>, std::span<const char>);
template WeightedGraph element_graph(const Mesh<3>&, std::span<const double>, std::span<const char>);

}  // namespace hocav
