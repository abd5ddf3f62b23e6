// Regular subdivision of a Bernstein polynomial over a simplex by blossoming (math.md §8).
#include "bezier/bernstein_subdivision.hpp"

namespace hocav {
namespace {

template <int D>
using SubdivisionMatrices =
    std::array<std::array<std::array<double, kJacobianCoefficientCount<D>>, kJacobianCoefficientCount<D>>,
               kSubdivisionChildCount<D>>;

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
constexpr auto kSubdivisionMatrices = make_subdivision_matrices<D>();

}  // namespace

template <int D>
void subdivide_bernstein(const JacobianCoefficients<D>& parent, SubdivisionChildren<D>& children) {
  for (int child = 0; child < kSubdivisionChildCount<D>; ++child)
    for (int beta = 0; beta < kJacobianCoefficientCount<D>; ++beta) {
      const auto& row = kSubdivisionMatrices<D>[child][beta];
      double sum = 0.0;
      for (int alpha = 0; alpha < kJacobianCoefficientCount<D>; ++alpha) sum += row[alpha] * parent[alpha];
      children[child][beta] = sum;
    }
}

template void subdivide_bernstein(const JacobianCoefficients<2>&, SubdivisionChildren<2>&);
template void subdivide_bernstein(const JacobianCoefficients<3>&, SubdivisionChildren<3>&);

}  // namespace hocav
