// Small linear algebra of metrics (docs/method.md §1, §6): nanoseconds per eigen-decomposition with each solver,
// exp of a log-metric, exp with its Fréchet derivative in D directions (what one edge-length gradient needs per
// quadrature point), log of a metric, and metric intersection.
#include <benchmark/benchmark.h>

#include <random>
#include <utility>
#include <vector>

#include "geom/metric_intersection.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

constexpr int kPoolSize = 1024;  // cycled through so that no single input is learnt by the branch predictor

// Log-metrics with entries in ±9 (sizes spread over about 1e4) and the metrics they are the logarithms of.
template <int D>
std::vector<SymMat<D>> log_metric_pool() {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> entry(-9.0, 9.0);
  std::vector<SymMat<D>> pool(kPoolSize);
  for (SymMat<D>& t : pool)
    for (double& x : t.entries) x = entry(rng);
  return pool;
}

template <int D>
std::vector<SymMat<D>> metric_pool() {
  std::vector<SymMat<D>> pool = log_metric_pool<D>();
  for (SymMat<D>& m : pool) m = exp_sym(m);
  return pool;
}

template <int D, class Kernel>
void run_over_pool(benchmark::State& state, const std::vector<SymMat<D>>& pool, Kernel kernel) {
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kernel(pool[next]));
    next = (next + 1) % pool.size();
  }
}

template <int D>
void BM_SymEigenFastOnLogMetrics(benchmark::State& state) {
  run_over_pool<D>(state, log_metric_pool<D>(), [](const SymMat<D>& t) { return sym_eigen(t); });
}
BENCHMARK_TEMPLATE(BM_SymEigenFastOnLogMetrics, 2);
BENCHMARK_TEMPLATE(BM_SymEigenFastOnLogMetrics, 3);

template <int D>
void BM_SpdEigenJacobiOnMetrics(benchmark::State& state) {
  run_over_pool<D>(state, metric_pool<D>(), [](const SymMat<D>& m) { return spd_eigen(m); });
}
BENCHMARK_TEMPLATE(BM_SpdEigenJacobiOnMetrics, 2);
BENCHMARK_TEMPLATE(BM_SpdEigenJacobiOnMetrics, 3);

template <int D>
void BM_ExpSym(benchmark::State& state) {
  run_over_pool<D>(state, log_metric_pool<D>(), [](const SymMat<D>& t) { return exp_sym(t); });
}
BENCHMARK_TEMPLATE(BM_ExpSym, 2);
BENCHMARK_TEMPLATE(BM_ExpSym, 3);

// exp(T) and Dexp(T)[H_i] for D directions H_i sharing one eigendecomposition.
template <int D>
void BM_ExpAndDerivativesInDDirections(benchmark::State& state) {
  std::vector<SymMat<D>> directions = log_metric_pool<D>();
  run_over_pool<D>(state, log_metric_pool<D>(), [&](const SymMat<D>& t) {
    ExpFrechet<D> at_t(t);
    SymMat<D> sum = at_t.value();
    for (int i = 0; i < D; ++i) sum += at_t.derivative(directions[i]);
    return sum;
  });
}
BENCHMARK_TEMPLATE(BM_ExpAndDerivativesInDDirections, 2);
BENCHMARK_TEMPLATE(BM_ExpAndDerivativesInDDirections, 3);

// What an edge-length gradient needs at one quadrature point: uᵀexp(T)u and its derivatives along D directions,
// from one squared_length_gradient (see ExpFrechet).
template <int D>
void BM_ExpAndLengthGradientInDDirections(benchmark::State& state) {
  std::vector<SymMat<D>> directions = log_metric_pool<D>();
  Vec<D> u;
  for (int i = 0; i < D; ++i) u[i] = 1.0 / (i + 1);
  run_over_pool<D>(state, log_metric_pool<D>(), [&](const SymMat<D>& t) {
    ExpFrechet<D> at_t(t);
    SymMat<D> gradient = at_t.squared_length_gradient(u);
    Vec<D> along = {};
    for (int i = 0; i < D; ++i) along[i] = frobenius_dot(gradient, directions[i]);
    return std::pair{at_t.squared_length(u), along};
  });
}
BENCHMARK_TEMPLATE(BM_ExpAndLengthGradientInDDirections, 2);
BENCHMARK_TEMPLATE(BM_ExpAndLengthGradientInDDirections, 3);

template <int D>
void BM_ExpSecondDerivative(benchmark::State& state) {
  std::vector<SymMat<D>> directions = log_metric_pool<D>();
  run_over_pool<D>(state, log_metric_pool<D>(), [&](const SymMat<D>& t) { return d2exp(t, directions[0], directions[1]); });
}
BENCHMARK_TEMPLATE(BM_ExpSecondDerivative, 2);
BENCHMARK_TEMPLATE(BM_ExpSecondDerivative, 3);

template <int D>
void BM_LogSpd(benchmark::State& state) {
  run_over_pool<D>(state, metric_pool<D>(), [](const SymMat<D>& m) { return log_spd(m); });
}
BENCHMARK_TEMPLATE(BM_LogSpd, 2);
BENCHMARK_TEMPLATE(BM_LogSpd, 3);

template <int D>
void BM_IntersectMetrics(benchmark::State& state) {
  std::vector<SymMat<D>> others = metric_pool<D>();
  std::size_t next = 0;
  run_over_pool<D>(state, metric_pool<D>(), [&](const SymMat<D>& m) {
    next = (next + 7) % others.size();
    return intersect_metrics(m, others[next]);
  });
}
BENCHMARK_TEMPLATE(BM_IntersectMetrics, 2);
BENCHMARK_TEMPLATE(BM_IntersectMetrics, 3);

}  // namespace
}  // namespace hocav
