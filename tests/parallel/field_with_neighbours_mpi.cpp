// The metric field of a part with a ring of its neighbours' elements (src/parallel/field_with_neighbours.hpp),
// run by ctest under `mpirun -np N` (N = 2, 3, 4). Every process makes the same Kuhn cube and square
// of kCells cells a side, a shear-layer metric at their vertices, and keeps its part of them: slabs
// of x on 2 and 3 processes, quadrants of x and y on 4 (four parts meet along a line). Then:
// - the field's back mesh has the part's vertices first, in their order, with their log-metrics,
//   then exactly the other parts' elements with a vertex on this part (by the whole mesh);
// - a point in each such element, past the part's border, is inside the field and sampled there as
//   in the whole mesh's field, where the part's own field finds it outside.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <unordered_set>

#include "cases/structured.hpp"
#include "geom/sym_functions.hpp"
#include "metric/analytic_metric.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/field_with_neighbours.hpp"
#include "parallel/mesh_parts.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

constexpr int kCells = 8;

bool fail(const std::string& what) {
  std::cerr << "field with neighbours (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// The part of an element by its centroid's x and y.
int part_at(double x, double y) {
  if (process_count() != 4) return std::clamp(static_cast<int>(std::floor(x * process_count())), 0, process_count() - 1);
  return (x < 0.5 ? 0 : 1) + (y < 0.5 ? 0 : 2);
}

template <int D>
std::vector<SymMat<D>> shear_log_metrics(const Mesh<D>& mesh) {
  AnalyticMetricSpec spec;
  spec.name = D == 2 ? "shear-circle" : "shear-sphere";
  spec.radius = 0.6;
  spec.width = 0.1;
  spec.h_min = 0.02;
  spec.h_max = 0.2;
  std::vector<SymMat<D>> logs;
  for (const SymMat<D>& metric : analytic_metric_at_vertices(spec, mesh)) logs.push_back(log_spd(metric));
  return logs;
}

template <int D>
bool check(Mesh<D> mesh) {
  const std::string name = std::to_string(D) + "D";
  mesh.build_topology();
  const std::vector<SymMat<D>> whole_logs = shear_log_metrics(mesh);
  const MetricField<D> whole = MetricField<D>::from_log_metrics(mesh, whole_logs);
  std::vector<int> part_of;
  for (Index k = 0; k < mesh.element_count(); ++k) part_of.push_back(part_at(centroid(mesh, k)[0], centroid(mesh, k)[1]));
  MeshPart<D> part = std::move(split_mesh(mesh, part_of, process_count()).at(static_cast<std::size_t>(process_rank())));
  std::vector<SymMat<D>> logs;
  for (Index g : part.global_ids) logs.push_back(whole_logs[g]);
  long long bytes = 0;
  const MetricField<D> field = field_with_neighbours(part, logs, bytes);
  const MetricField<D> own = MetricField<D>::from_log_metrics(part.mesh, logs);
  const Mesh<D>& back = field.back_mesh();
  bool ok = true;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (!(back.vertex(v) == part.mesh.vertex(v)) || !(field.vertex_log_metric(v).entries == logs[v].entries))
      return fail(name + ": back vertex " + std::to_string(v) + " is not the part's");
  // The ring by the whole mesh: the other parts' elements with a vertex of this part.
  const std::unordered_set<Index> held(part.global_ids.begin(), part.global_ids.end());
  std::vector<Index> ring;
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (part_of[k] != process_rank() &&
        std::any_of(mesh.element(k).begin(), mesh.element(k).end(), [&](Index v) { return held.contains(v); }))
      ring.push_back(k);
  if (back.element_count() != part.mesh.element_count() + static_cast<Index>(ring.size()))
    ok = fail(name + ": " + std::to_string(back.element_count() - part.mesh.element_count()) + " elements of the neighbours, " +
              std::to_string(ring.size()) + " expected");
  if (ring.empty()) ok = fail(name + ": no neighbour");
  if (bytes <= 0) ok = fail(name + ": nothing sent");
  std::set<std::vector<double>> back_points;  // the back mesh's element corners, as points
  for (Index k = 0; k < back.element_count(); ++k) {
    std::vector<double> corners;
    for (Index v : back.element(k))
      for (int i = 0; i < D; ++i) corners.push_back(back.vertex(v)[i]);
    back_points.insert(corners);
  }
  Index outside_own = 0;
  for (Index k : ring) {
    std::vector<double> corners;
    for (Index v : mesh.element(k))
      for (int i = 0; i < D; ++i) corners.push_back(mesh.vertex(v)[i]);
    if (!back_points.contains(corners)) ok = fail(name + ": element " + std::to_string(k) + " of the ring is not in the back mesh");
    const Vec<D> point = centroid(mesh, k);
    const auto sample = field.sample(point), expected = whole.sample(point);
    if (!sample.where.inside) ok = fail(name + ": the centroid of element " + std::to_string(k) + " is outside");
    for (std::size_t i = 0; i < sample.log_metric.entries.size(); ++i)
      if (std::abs(sample.log_metric.entries[i] - expected.log_metric.entries[i]) > 1e-12)
        ok = fail(name + ": element " + std::to_string(k) + "'s centroid sampled off the whole field");
    outside_own += !own.sample(point).where.inside;
  }
  if (outside_own != static_cast<Index>(ring.size())) ok = fail(name + ": the part's own field finds the ring inside");
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "field with neighbours", [] {
    return hocav::check<3>(hocav::generate_cube(hocav::kCells)) & hocav::check<2>(hocav::generate_square(hocav::kCells));
  });
}
