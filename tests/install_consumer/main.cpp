// hocav_consumer IN OUT: adapts the mesh IN to a uniform metric of half its size h with the
// installed library, curved boundary points on the P3 surrogate of IN's boundary, writes OUT, and
// exits 1 unless the result is consistent, covers the same domain and is finer than IN.
#include <hocav/adapt/adaptation_loop.hpp>
#include <hocav/io/mesh_file.hpp>
#include <hocav/mesh/consistency.hpp>
#include <hocav/mesh/measure.hpp>
#include <hocav/metric/analytic_metric.hpp>
#include <hocav/surface/p3_surrogate.hpp>

#include <cmath>
#include <iostream>
#include <variant>

namespace {

template <int D>
int adapt_and_check(hocav::Mesh<D>& mesh, const std::string& output) {
  const hocav::Mesh<D> input = mesh;
  hocav::AnalyticMetricSpec uniform;
  uniform.h = 0.05;
  const hocav::MetricField<D> field(input, hocav::analytic_metric_at_vertices(uniform, input));
  const hocav::AdaptationMetric<D> metric(field, hocav::SizeBounds{});
  const hocav::P3Surrogate<D> boundary(input);
  hocav::adapt_to_metric(mesh, metric, &boundary, hocav::AdaptationSettings{});
  hocav::write_mesh_file(output, mesh);

  bool ok = true;
  for (const std::string& problem : hocav::check_consistency(mesh)) {
    std::cerr << "inconsistent: " << problem << '\n';
    ok = false;
  }
  const double before = hocav::total_measure(input), after = hocav::total_measure(mesh);
  if (std::abs(after - before) > 0.01 * before) {
    std::cerr << "the domain changed: measure " << before << " -> " << after << '\n';
    ok = false;
  }
  if (mesh.vertex_count() < 2 * input.vertex_count()) {
    std::cerr << "not refined: " << input.vertex_count() << " -> " << mesh.vertex_count() << " vertices\n";
    ok = false;
  }
  std::cout << input.vertex_count() << " -> " << mesh.vertex_count() << " vertices\n";
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: hocav_consumer IN OUT\n";
    return 2;
  }
  try {
    hocav::MeshFileContent file = hocav::read_mesh_file(argv[1]);
    return std::visit([&](auto& mesh) { return adapt_and_check(mesh, argv[2]); }, file.mesh);
  } catch (const std::exception& error) {
    std::cerr << "hocav_consumer: " << error.what() << '\n';
    return 2;
  }
}
