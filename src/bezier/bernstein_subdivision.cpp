// Regular subdivision of a Bernstein polynomial over a simplex by blossoming (docs/method.md §8).
#include "bezier/bernstein_subdivision.hpp"

namespace hocav {
namespace {

template <int D>
using SubdivisionMatrices =
    std::array<std::array<std::array<double, kJacobianCoefficientCount<D>>, kJacobianCoefficientCount<D>>, kSubdivisionChildCount<D>>;

// matrices[child][β][α]: weight of parent coefficient α in child coefficient β. The blossom of B_α
// at the points (u_1, …, u_D) is Σ Π_m u_m[i_m] over the index sequences (i_1, …, i_D) whose
// counts are α; the points are the child's vertices, vertex v repeated β_v times.
template <int D>
constexpr SubdivisionMatrices<D> make_subdivision_matrices() {
  SubdivisionMatrices<D> matrices{};
  constexpr int kSequences = D == 2 ? 9 : 64;  // (D + 1)^D index sequences, sequence digit m is i_m
  std::array<int, kSequences> alpha_position{};
  for (int sequence = 0; sequence < kSequences; ++sequence) {
    BernsteinMultiIndex<D> alpha{};
    for (int m = 0, rest = sequence; m < D; ++m, rest /= D + 1) ++alpha[rest % (D + 1)];
    alpha_position[sequence] = jacobian_coefficient_index<D>(alpha);
  }
  for (int child = 0; child < kSubdivisionChildCount<D>; ++child)
    for (int beta = 0; beta < kJacobianCoefficientCount<D>; ++beta) {
      std::array<Barycentrics<D>, D> points{};
      int next = 0;
      for (int vertex = 0; vertex <= D; ++vertex)
        for (int repeat = 0; repeat < kJacobianMultiIndices<D>[beta][vertex]; ++repeat)
          points[next++] = subdivision_child_vertex<D>(child, vertex);
      for (int sequence = 0; sequence < kSequences; ++sequence) {
        double weight = 1.0;
        for (int m = 0, rest = sequence; m < D; ++m, rest /= D + 1) weight *= points[m][rest % (D + 1)];
        matrices[child][beta][alpha_position[sequence]] += weight;
      }
    }
  return matrices;
}

template <int D>
constexpr int count_nonzero_weights() {
  constexpr auto kMatrices = make_subdivision_matrices<D>();
  int count = 0;
  for (const auto& matrix : kMatrices)
    for (const auto& row : matrix)
      for (double weight : row) count += weight != 0.0 ? 1 : 0;
  return count;
}

// The same weights without the zeros (three quarters of them in 3D), row after row.
template <int D>
struct SparseSubdivision {
  struct Weight {
    int parent;  // α
    double value;
  };
  std::array<int, kSubdivisionChildCount<D> * kJacobianCoefficientCount<D> + 1> row_start{};
  std::array<Weight, count_nonzero_weights<D>()> weights{};
};

template <int D>
constexpr SparseSubdivision<D> make_sparse_subdivision() {
  constexpr auto kMatrices = make_subdivision_matrices<D>();
  SparseSubdivision<D> sparse{};
  int row = 0, next = 0;
  for (const auto& matrix : kMatrices)
    for (const auto& dense_row : matrix) {
      sparse.row_start[row++] = next;
      for (int alpha = 0; alpha < kJacobianCoefficientCount<D>; ++alpha)
        if (dense_row[alpha] != 0.0) sparse.weights[next++] = {alpha, dense_row[alpha]};
    }
  sparse.row_start[row] = next;
  return sparse;
}

template <int D>
constexpr auto kSubdivision = make_sparse_subdivision<D>();

}  // namespace

template <int D>
void subdivide_bernstein(const JacobianCoefficients<D>& parent, SubdivisionChildren<D>& children) {
  const auto& subdivision = kSubdivision<D>;
  int row = 0;
  for (int child = 0; child < kSubdivisionChildCount<D>; ++child)
    for (int beta = 0; beta < kJacobianCoefficientCount<D>; ++beta, ++row) {
      double sum = 0.0;
      for (int entry = subdivision.row_start[row]; entry < subdivision.row_start[row + 1]; ++entry)
        sum += subdivision.weights[entry].value * parent[subdivision.weights[entry].parent];
      children[child][beta] = sum;
    }
}

template void subdivide_bernstein(const JacobianCoefficients<2>&, SubdivisionChildren<2>&);
template void subdivide_bernstein(const JacobianCoefficients<3>&, SubdivisionChildren<3>&);

}  // namespace hocav
