// The metric's back mesh in shares (docs/distributed.md §The back mesh in shares), run by ctest under
// `mpirun -np N` (N = 2, 3, 4). Every process makes the same square and cube (bent, so that their
// elements differ) with two fields at their vertices; rank 0 scatters the back mesh to home shares
// by slabs of x, then each process gathers the share around a part of its own (the elements of a
// slab of y):
// 1. the homes hold every back element once, each with its vertices' points and log-metrics;
// 2. a share holds the back elements whose boxes meet the part's region, with their vertices' points
//    and log-metrics: every back element whose box meets one of the part's, and not the whole
//    mesh; an empty region gets nothing;
// 3. the metric remade on the share (ShareMetric) is the whole one's, a field's and an analytic
//    one's with a Hausdorff bound field, a fraction of the way from a start field, at points
//    inside the part's elements.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

#include "cases/structured.hpp"
#include "mesh/mesh_box.hpp"
#include "metric/implied_metric.hpp"
#include "mpi_test_main.hpp"
#include "parallel/back_mesh_share.hpp"
#include "parallel/communicator.hpp"
#include "parallel/share_metric.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "back-mesh share (rank " << process_rank() << "): " << what << '\n';
  return false;
}

int slab(double x) { return std::clamp(static_cast<int>(std::floor(x * process_count())), 0, process_count() - 1); }

template <int D>
Vec<D> centroid(const Mesh<D>& mesh, Index k) {
  Vec<D> sum{};
  for (Index v : mesh.element(k)) sum += mesh.vertex(v);
  return sum * (1.0 / (D + 1));
}

// An element as its sorted global vertex ids.
template <int D>
std::string key(const Mesh<D>& mesh, Index k, const std::vector<Index>& global_ids) {
  std::vector<Index> ids;
  for (Index v : mesh.element(k)) ids.push_back(global_ids.empty() ? v : global_ids[v]);
  std::sort(ids.begin(), ids.end());
  std::ostringstream out;
  for (Index id : ids) out << id << ' ';
  return out.str();
}

// The share's vertices are the whole mesh's with the same points and log-metrics.
template <int D>
bool vertices_match(const BackMeshShare<D>& share, const Mesh<D>& mesh, const std::vector<std::vector<SymMat<D>>>& fields,
                    const std::string& what) {
  if (share.global_ids.size() != static_cast<std::size_t>(share.mesh.vertex_count()) || share.log_metrics.size() != fields.size())
    return fail(what + ": arrays of the wrong size");
  if (!std::is_sorted(share.global_ids.begin(), share.global_ids.end())) return fail(what + ": global ids not increasing");
  for (Index v = 0; v < share.mesh.vertex_count(); ++v) {
    const Index id = share.global_ids[v];
    if (share.mesh.vertex(v) != mesh.vertex(id)) return fail(what + ": vertex " + std::to_string(id) + " moved");
    for (std::size_t f = 0; f < fields.size(); ++f)
      if (share.log_metrics[f][v] != fields[f][id]) return fail(what + ": vertex " + std::to_string(id) + " has another log-metric");
  }
  return true;
}

// The elements of `mesh` for which keep(k), as keys.
template <int D, typename Keep>
std::multiset<std::string> keys_of(const Mesh<D>& mesh, Keep&& keep) {
  std::multiset<std::string> keys;
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (keep(k)) keys.insert(key(mesh, k, {}));
  return keys;
}

template <int D>
std::multiset<std::string> keys_of(const BackMeshShare<D>& share) {
  std::multiset<std::string> keys;
  for (Index k = 0; k < share.mesh.element_count(); ++k) keys.insert(key(share.mesh, k, share.global_ids));
  return keys;
}

// The metric on the share against the whole one at the centroids of the part's elements and at
// points a third of the way to each corner; returns the largest relative difference.
template <int D>
double largest_difference(const Mesh<D>& part, const AdaptationMetric<D>& on_share, const AdaptationMetric<D>& whole) {
  double largest = 0;
  Index hint_share = kNoIndex, hint_whole = kNoIndex;
  for (Index k = 0; k < part.element_count(); ++k) {
    const Vec<D> c = centroid(part, k);
    for (int corner = -1; corner <= D; ++corner) {
      const Vec<D> x = corner < 0 ? c : c + (part.vertex(part.element(k)[corner]) - c) * (1.0 / 3);
      const SymMat<D> a = on_share.metric_at(x, hint_share), b = whole.metric_at(x, hint_whole);
      largest = std::max(largest, frobenius_norm(a - b) / frobenius_norm(b));
    }
  }
  return largest;
}

// The elements of `mesh` for which keep(k), as a mesh of their own (the vertices they use).
template <int D, typename Keep>
Mesh<D> submesh(const Mesh<D>& mesh, Keep&& keep) {
  Mesh<D> part;
  std::vector<Index> id(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    if (!keep(k)) continue;
    typename Mesh<D>::Element element = mesh.element(k);
    for (Index& v : element) {
      if (id[v] == kNoIndex) id[v] = part.add_vertex(mesh.vertex(v));
      v = id[v];
    }
    part.add_element(element);
  }
  return part;
}

template <int D>
bool run(Mesh<D> mesh) {
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec<D>& x = mesh.vertex(v);
    x[0] += 0.03 * std::sin(4 * x[D - 1]);
  }
  mesh.build_topology();
  AnalyticMetricSpec spec;
  spec.name = "linear";
  spec.h_min = 0.01;
  const MetricField<D> start(mesh, implied_metric_at_vertices(mesh));
  const MetricField<D> target(mesh, analytic_metric_at_vertices(spec, mesh));
  const AdaptationMetric<D> whole_field(target, {0.02, 0.5});
  const AdaptationMetric<D> whole_analytic(spec, {0, 1e300}, &target);  // (the target as a Hausdorff bound: the same fields)
  const std::vector<std::vector<SymMat<D>>> fields = share_log_metrics(whole_field, start);
  if (fields.size() != 2 || share_log_metrics(whole_analytic, start) != fields) return fail("share_log_metrics lists other fields");
  std::vector<int> part_of;
  for (Index k = 0; k < mesh.element_count(); ++k) part_of.push_back(slab(centroid(mesh, k)[0]));
  const bool root = process_rank() == 0;
  long long scattered = 0;
  const BackMeshShare<D> home = scatter_back_mesh(root ? mesh : Mesh<D>{}, root ? std::span<const int>(part_of) : std::span<const int>(),
                                                  root ? fields : std::vector<std::vector<SymMat<D>>>{}, &scattered);
  bool ok = vertices_match(home, mesh, fields, "home");
  if (keys_of(home) != keys_of(mesh, [&](Index k) { return part_of[k] == process_rank(); })) ok = fail("the home share is not its slab");
  if ((scattered > 0) != (root && process_count() > 1)) ok = fail("the scatter's bytes are not rank 0's");
  // Each process's part: the elements of a slab of y, shifted so that it cuts the mesh's rows.
  const double lowest = (process_rank() + 0.37) / process_count() - 0.2;
  const Mesh<D> part = submesh(mesh, [&](Index k) { return std::abs(centroid(mesh, k)[1] - lowest - 0.15) < 0.15; });
  const ShareRegion<D> region = share_region(part);
  const BackMeshShare<D> share = share_around(home, region);
  ok &= vertices_match(share, mesh, fields, "share");
  const std::multiset<std::string> shared = keys_of(share);
  if (shared != keys_of(mesh, [&](Index k) { return region.meets(element_box(mesh, k)); }))
    ok = fail("the share is not the elements whose boxes meet the region");
  std::vector<Box<D>> part_boxes;
  for (Index k = 0; k < part.element_count(); ++k) part_boxes.push_back(element_box(part, k));
  for (const std::string& near : keys_of(mesh, [&](Index k) {
         return std::any_of(part_boxes.begin(), part_boxes.end(), [&](const Box<D>& box) { return box.overlaps(element_box(mesh, k)); });
       }))
    if (!shared.contains(near)) ok = fail("the share lacks element " + near + ", whose box meets a part element's");
  if (D == 3 && shared.size() >= static_cast<std::size_t>(mesh.element_count())) ok = fail("the share is the whole mesh");
  if (share_around(home, ShareRegion<D>{}).mesh.element_count() != 0) ok = fail("an empty region got elements");
  const ShareMetric<D> field_metric(share, recipe_of(whole_field)), analytic_metric(share, recipe_of(whole_analytic));
  for (double fraction : {1.0, 0.4}) {
    const double field_gap = largest_difference(part, field_metric.partway(fraction), whole_field.partway_from(start, fraction));
    const double analytic_gap = largest_difference(part, analytic_metric.partway(fraction), whole_analytic.partway_from(start, fraction));
    if (field_gap > 1e-12 || analytic_gap > 1e-12)
      ok = fail("the metric on the share differs from the whole one's by " + std::to_string(std::max(field_gap, analytic_gap)));
  }
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "back-mesh share", [] {
    return hocav::run(hocav::generate_square(12)) & hocav::run(hocav::generate_cube(6));  // every process runs both
  });
}
