// Certified validity of P2 elements (src/bezier): time per check on the fast path (mildly curved
// elements, all coefficients above the floor) and on hard cases that need subdivision, plus the
// coefficients alone and the refined quality. Elements come from a structured mesh whose edge nodes
// are moved at random by a fraction of the edge length.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bezier/jacobian_bounds.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

constexpr double kFloor = 0.01;  // hocav's default validity floor on the normalized Jacobian

template <int D>
Mesh<D> structured_mesh() {
  if constexpr (D == 2)
    return generate_square(24);  // 1152 triangles
  else
    return generate_cube(6);  // 1296 tetrahedra
}

// The mesh's elements after moving every edge node by up to `amplitude` × edge length.
template <int D>
std::vector<P2Element<D>> curved_elements(double amplitude, unsigned seed) {
  Mesh<D> mesh = structured_mesh<D>();
  mesh.make_p2();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto& ends = mesh.edge_vertices(e);
    const double length = norm(mesh.vertex(ends[1]) - mesh.vertex(ends[0]));
    for (int r = 0; r < D; ++r) mesh.edge_node(e)[r] += amplitude * length * coordinate(random);
  }
  std::vector<P2Element<D>> elements;
  for (Index k = 0; k < mesh.element_count(); ++k) elements.push_back(gather_p2_element(mesh, k));
  return elements;
}

enum class Outcome { kFastPath, kCertifiedAfterSubdivision, kRejectedAfterSubdivision };

template <int D>
Outcome outcome(const P2Element<D>& element) {
  const JacobianCertificate certificate = certify_min_normalized_jacobian(element, kFloor);
  if (certificate.subdivisions == 0) return Outcome::kFastPath;
  return certificate.certified ? Outcome::kCertifiedAfterSubdivision : Outcome::kRejectedAfterSubdivision;
}

// Elements of one outcome, drawn from meshes curved by `amplitude`.
template <int D>
std::vector<P2Element<D>> elements_with(Outcome wanted, double amplitude) {
  std::vector<P2Element<D>> chosen;
  for (unsigned seed = 1; chosen.size() < 256 && seed < 200; ++seed)
    for (const P2Element<D>& element : curved_elements<D>(amplitude, seed))
      if (outcome(element) == wanted) chosen.push_back(element);
  return chosen;
}

template <int D>
void certify_benchmark(benchmark::State& state, Outcome wanted, double amplitude) {
  const std::vector<P2Element<D>> elements = elements_with<D>(wanted, amplitude);
  if (elements.empty()) {
    state.SkipWithError("no element of the wanted kind");
    return;
  }
  std::size_t next = 0;
  long subdivisions = 0;
  for (auto _ : state) {
    const JacobianCertificate certificate = certify_min_normalized_jacobian(elements[next], kFloor);
    benchmark::DoNotOptimize(certificate);
    subdivisions += certificate.subdivisions;
    next = next + 1 == elements.size() ? 0 : next + 1;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["splits_per_check"] = double(subdivisions) / double(state.iterations());
  state.counters["ns_per_check"] = benchmark::Counter(double(state.iterations()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_CertifyTetrahedron(benchmark::State& state, Outcome wanted, double amplitude) { certify_benchmark<3>(state, wanted, amplitude); }
void BM_CertifyTriangle(benchmark::State& state, Outcome wanted, double amplitude) { certify_benchmark<2>(state, wanted, amplitude); }
BENCHMARK_CAPTURE(BM_CertifyTetrahedron, mildly_curved_fast_path, Outcome::kFastPath, 0.1);
BENCHMARK_CAPTURE(BM_CertifyTetrahedron, certified_after_subdivision, Outcome::kCertifiedAfterSubdivision, 0.35);
BENCHMARK_CAPTURE(BM_CertifyTetrahedron, rejected_after_subdivision, Outcome::kRejectedAfterSubdivision, 0.35);
BENCHMARK_CAPTURE(BM_CertifyTriangle, mildly_curved_fast_path, Outcome::kFastPath, 0.1);
BENCHMARK_CAPTURE(BM_CertifyTriangle, certified_after_subdivision, Outcome::kCertifiedAfterSubdivision, 0.35);
BENCHMARK_CAPTURE(BM_CertifyTriangle, rejected_after_subdivision, Outcome::kRejectedAfterSubdivision, 0.35);

template <int D>
void BM_JacobianCoefficients(benchmark::State& state) {
  const std::vector<P2Element<D>> elements = curved_elements<D>(0.1, 1);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(jacobian_coefficients(elements[next]));
    next = next + 1 == elements.size() ? 0 : next + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_JacobianCoefficients<3>);
BENCHMARK(BM_JacobianCoefficients<2>);

// The refined quality (min normalized and scaled Jacobian to 1e-3) that `hocav stats` reports.
template <int D>
void BM_JacobianQuality(benchmark::State& state) {
  const std::vector<P2Element<D>> elements = curved_elements<D>(0.1, 1);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(jacobian_quality(elements[next]));
    next = next + 1 == elements.size() ? 0 : next + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_JacobianQuality<3>);
BENCHMARK(BM_JacobianQuality<2>);

}  // namespace
}  // namespace hocav
