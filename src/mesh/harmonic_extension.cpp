#include "mesh/harmonic_extension.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "geom/barycentric.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// The conjugate gradients stop when the residual falls below this share of the right-hand side.
constexpr double kRelativeResidual = 1e-10;
constexpr int kMaxConjugateGradientSteps = 20000;

// Per vertex, the least over moving fixed vertices s of (path length from s − reach_factor × |move
// of s|): negative within the reach of some moving vertex (a multi-source Dijkstra from them, along
// the edges of the elements around each vertex reached).
template <int D>
std::vector<double> reach_labels(const Mesh<D>& mesh, const VertexElements& around, std::span<const char> fixed,
                                 std::span<const Vec<D>> moves, double reach_factor) {
  std::vector<double> label(static_cast<std::size_t>(mesh.vertex_count()), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (fixed[v] && norm(moves[v]) > 0) queue.push({label[v] = -reach_factor * norm(moves[v]), v});
  while (!queue.empty()) {
    const auto [at, v] = queue.top();
    queue.pop();
    if (at > label[v]) continue;  // reached shorter since
    for (Index k : around.of(v))
      for (Index w : mesh.element(k))
        if (const double to = at + norm(mesh.vertex(w) - mesh.vertex(v)); w != v && to < 0 && to < label[w]) queue.push({label[w] = to, w});
  }
  return label;
}

// The linear system of the free vertices: the P1 finite-element Laplacian, K_ij = Σ_k |k| ∇λ_i·∇λ_j
// over the elements k that hold both, row i: Σ_j K_ij u_j = 0, the moves of the vertices that are
// not free on the right-hand side.
template <int D>
struct FreeSystem {
  std::vector<Index> vertices;            // free vertex i is vertices[i]
  std::vector<Index> offsets, columns;    // row i's free neighbours: columns[offsets[i] .. offsets[i + 1])
  std::vector<double> entries, diagonal;  // K_ij of those neighbours; K_ii
  std::vector<Vec<D>> right_hand_side;    // −Σ_j K_ij u_j over the neighbours that are not free
};

// The stiffness matrix's rows at the free vertices, as entries parallel to graph.neighbors and a
// diagonal: assembled over the elements that hold a free vertex.
template <int D>
void assemble_stiffness(const Mesh<D>& mesh, const VertexGraph& graph, const std::vector<Index>& row, std::vector<double>& entries,
                        std::vector<double>& diagonal) {
  entries.assign(graph.neighbors.size(), 0);
  diagonal.assign(row.size(), 0);
  for (const auto& element : mesh.elements()) {
    if (std::none_of(element.begin(), element.end(), [&](Index v) { return row[v] != kNoIndex; })) continue;
    SimplexPoints<D> points;
    for (int i = 0; i <= D; ++i) points[i] = mesh.vertex(element[i]);
    const std::array<Vec<D>, D + 1> gradient = barycentric_gradients<D>(points);
    const double scale = std::abs(signed_measure<D>(points));
    for (int i = 0; i <= D; ++i) {
      if (row[element[i]] == kNoIndex) continue;
      diagonal[element[i]] += scale * dot(gradient[i], gradient[i]);
      const std::span<const Index> neighbors = graph.neighbors_of(element[i]);
      for (int j = 0; j <= D; ++j)
        if (j != i) {
          const auto at = std::lower_bound(neighbors.begin(), neighbors.end(), element[j]) - neighbors.begin();
          entries[static_cast<std::size_t>(graph.offsets[element[i]] + at)] += scale * dot(gradient[i], gradient[j]);
        }
    }
  }
}

template <int D>
FreeSystem<D> free_system(const Mesh<D>& mesh, const VertexGraph& graph, std::span<const char> fixed, std::span<const Vec<D>> moves,
                          const std::vector<double>& label) {
  FreeSystem<D> system;
  std::vector<Index> row(label.size(), kNoIndex);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!fixed[v] && label[v] < 0) {
      row[v] = static_cast<Index>(system.vertices.size());
      system.vertices.push_back(v);
    }
  std::vector<double> entries, diagonal;
  assemble_stiffness(mesh, graph, row, entries, diagonal);
  system.offsets.push_back(0);
  for (Index v : system.vertices) {
    Vec<D> known{};
    for (Index n = graph.offsets[v]; n < graph.offsets[v + 1]; ++n) {
      const Index w = graph.neighbors[n];
      if (row[w] != kNoIndex) {
        system.columns.push_back(row[w]);
        system.entries.push_back(entries[n]);
      } else if (fixed[w]) {
        known = known - entries[n] * moves[w];
      }
    }
    system.diagonal.push_back(diagonal[v]);
    system.right_hand_side.push_back(known);
    system.offsets.push_back(static_cast<Index>(system.columns.size()));
  }
  return system;
}

template <int D>
void multiply(const FreeSystem<D>& system, const std::vector<double>& x, std::vector<double>& y) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    double sum = system.diagonal[i] * x[i];
    for (Index n = system.offsets[i]; n < system.offsets[i + 1]; ++n) sum += system.entries[n] * x[system.columns[n]];
    y[i] = sum;
  }
}

double dot_product(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

// Jacobi-preconditioned conjugate gradients from x = 0; returns the iterations.
template <int D>
int conjugate_gradients(const FreeSystem<D>& system, const std::vector<double>& b, std::vector<double>& x) {
  const std::size_t n = b.size();
  x.assign(n, 0);
  std::vector<double> r = b, z(n), p(n), q(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = r[i] / system.diagonal[i];
  p = z;
  double rz = dot_product(r, z);
  const double stop = kRelativeResidual * std::sqrt(dot_product(b, b));
  int iteration = 0;
  while (iteration < kMaxConjugateGradientSteps && std::sqrt(dot_product(r, r)) > stop) {
    ++iteration;
    multiply(system, p, q);
    const double alpha = rz / dot_product(p, q);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      z[i] = r[i] / system.diagonal[i];
    }
    const double next = dot_product(r, z);
    for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + next / rz * p[i];
    rz = next;
  }
  return iteration;
}

}  // namespace

template <int D>
HarmonicExtension<D> harmonic_extension(const Mesh<D>& mesh, std::span<const char> fixed, std::span<const Vec<D>> moves,
                                        double reach_factor) {
  HarmonicExtension<D> out;
  out.moves.assign(static_cast<std::size_t>(mesh.vertex_count()), Vec<D>{});
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (fixed[v]) out.moves[v] = moves[v];
  const VertexElements around = vertex_elements(mesh);
  const std::vector<double> label = reach_labels(mesh, around, fixed, moves, reach_factor);
  std::vector<char> within(label.size());
  for (std::size_t v = 0; v < label.size(); ++v) within[v] = label[v] < 0;
  const FreeSystem<D> system = free_system(mesh, vertex_graph(mesh, around, within), fixed, moves, label);
  out.free_vertices = static_cast<Index>(system.vertices.size());
  std::vector<double> b(system.vertices.size()), x;
  for (int c = 0; c < D; ++c) {
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = system.right_hand_side[i][c];
    out.iterations += conjugate_gradients(system, b, x);
    for (std::size_t i = 0; i < x.size(); ++i) out.moves[system.vertices[i]][c] = x[i];
  }
  return out;
}

template HarmonicExtension<2> harmonic_extension(const Mesh<2>&, std::span<const char>, std::span<const Vec<2>>, double);
template HarmonicExtension<3> harmonic_extension(const Mesh<3>&, std::span<const char>, std::span<const Vec<3>>, double);

}  // namespace hocav
