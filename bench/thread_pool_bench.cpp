// What handing a batch to the pool's threads costs (docs/adaptation.md §Threads, "Sharing a
// batch"): an empty batch (the wake and the wait), and a batch of small items as the loop's swap
// judgements are (a few hundred microseconds in all), at one and two threads.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "base/thread_pool.hpp"

namespace {

// A quarter of a microsecond of arithmetic: a swap judgement costs about twice that.
double small_item(std::size_t i) {
  double x = static_cast<double>(i) + 1;
  for (int k = 0; k < 60; ++k) x = std::sqrt(x + k);
  return x;
}

void BM_EmptyBatch(benchmark::State& state) {
  hocav::ThreadPool pool(static_cast<int>(state.range(0)));
  for (auto _ : state) hocav::run_in_blocks(pool, 2, 1, [](std::size_t, std::size_t) {});
}
BENCHMARK(BM_EmptyBatch)->Arg(1)->Arg(2)->UseRealTime();

void BM_BatchOfSmallItems(benchmark::State& state) {
  hocav::ThreadPool pool(static_cast<int>(state.range(0)));
  std::vector<double> out(static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) {
    hocav::run_in_blocks(pool, out.size(), 1, [&](std::size_t, std::size_t i) { out[i] = small_item(i); });
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(1));
}
BENCHMARK(BM_BatchOfSmallItems)->Args({1, 300})->Args({2, 300})->Args({1, 3000})->Args({2, 3000})->UseRealTime();

}  // namespace
