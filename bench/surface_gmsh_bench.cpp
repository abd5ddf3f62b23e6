// The P3 surrogate of the sphere shell's boundary (src/surface, docs/method.md §9): building it, the
// projections the cavity operators ask for (points near the boundary, without and with a hint
// patch), and the proposals for every boundary edge.
#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <vector>

#include "cases/concentric_shell.hpp"
#include "surface/boundary_proposals.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

// The shell (r_in = 0.5, r_out = 1) at size h, generated once per size.
const Mesh<3>& shell(double h) {
  static std::map<double, Mesh<3>> meshes;
  auto found = meshes.find(h);
  if (found == meshes.end()) found = meshes.emplace(h, generate_sphere_shell({0.5, 1.0, h})).first;
  return found->second;
}

double size_of(const benchmark::State& state) { return 1.0 / double(state.range(0)); }

// Points near the boundary as the cavity sees them: on a random facet, moved off it by up to a
// tenth of its size, each with that facet as its hint.
struct NearPoint {
  Vec3 point;
  Index facet;
};

std::vector<NearPoint> points_near(const Mesh<3>& mesh, int count) {
  std::mt19937 random(1);
  std::uniform_int_distribution<Index> any_facet(0, mesh.facet_count() - 1);
  std::uniform_real_distribution<double> unit(0, 1), offset(-0.1, 0.1);
  std::vector<NearPoint> points;
  for (int k = 0; k < count; ++k) {
    const Index f = any_facet(random);
    const auto& facet = mesh.facet(f);
    double u = unit(random), v = unit(random);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 a = mesh.vertex(facet[0]), b = mesh.vertex(facet[1]), c = mesh.vertex(facet[2]);
    const double size = norm(b - a);
    const Vec3 normal = cross(b - a, c - a) * (1 / norm(cross(b - a, c - a)));
    const Vec3 tangent = (b - a) * (1 / size);
    points.push_back({a + u * (b - a) + v * (c - a) + size * (offset(random) * normal + offset(random) * tangent), f});
  }
  return points;
}

void BM_SurrogateBuild(benchmark::State& state) {
  const Mesh<3>& mesh = shell(size_of(state));
  for (auto _ : state) benchmark::DoNotOptimize(P3Surrogate<3>(mesh));
  state.SetItemsProcessed(state.iterations() * mesh.facet_count());
  state.counters["facets"] = mesh.facet_count();
}
BENCHMARK(BM_SurrogateBuild)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

void project_benchmark(benchmark::State& state, bool with_hint) {
  const Mesh<3>& mesh = shell(size_of(state));
  const P3Surrogate<3> surrogate(mesh);
  const std::vector<NearPoint> points = points_near(mesh, 4096);
  std::size_t next = 0;
  for (auto _ : state) {
    const NearPoint& near = points[next];
    benchmark::DoNotOptimize(surrogate.project(near.point, {.hint = with_hint ? near.facet : kNoIndex}));
    next = next + 1 == points.size() ? 0 : next + 1;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["facets"] = mesh.facet_count();
}

void BM_ProjectCold(benchmark::State& state) { project_benchmark(state, false); }
void BM_ProjectWithHint(benchmark::State& state) { project_benchmark(state, true); }
BENCHMARK(BM_ProjectCold)->Arg(8)->Arg(16)->Arg(32);
BENCHMARK(BM_ProjectWithHint)->Arg(8)->Arg(16)->Arg(32);

void BM_Proposals(benchmark::State& state) {
  const Mesh<3>& mesh = shell(size_of(state));
  const P3Surrogate<3> surrogate(mesh);
  std::size_t edges = 0;
  for (auto _ : state) {
    BoundaryProposals<3> proposals(mesh, surrogate);
    edges = proposals.size();
    benchmark::DoNotOptimize(proposals);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(edges));
  state.counters["edges"] = double(edges);
}
BENCHMARK(BM_Proposals)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hocav
