// MetricField<D>: the metric known on a back mesh (docs/method.md §2). The back mesh is a P1 copy of the
// input mesh, never modified, with the log-metric R_i = log M_i at each of its vertices; the metric
// anywhere is M(X) = exp(Σ λ_i(X) R_i) in the back element that contains X (log-Euclidean
// interpolation, eq 2), so repeated interpolation never dissipates anisotropy.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "geom/sym_mat.hpp"
#include "metric/point_locator.hpp"

namespace hocav {

template <int D>
class MetricField {
 public:
  // Copies the corners, elements and boundary facets of `mesh` as the back mesh and takes one
  // metric per vertex. Throws Error naming the vertex for a metric that is not SPD, and the
  // element for a back element of non-positive P1 measure.
  MetricField(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics);
  // The same from log-metrics (any symmetric matrices), e.g. from an analytic field.
  static MetricField from_log_metrics(const Mesh<D>& mesh, std::vector<SymMat<D>> log_metrics);
  // The same on a mesh shared with its owner (with its topology, never modified while the field
  // lives): no copy.
  static MetricField on_back_mesh(std::shared_ptr<const Mesh<D>> back_mesh, std::vector<SymMat<D>> log_metrics);
  // Another field on this one's back mesh, sharing the mesh and its locator (no copy): one log-metric
  // per back vertex.
  MetricField with_log_metrics(std::vector<SymMat<D>> log_metrics) const;
  // The same from metrics (SPD; throws Error naming the vertex otherwise).
  MetricField with_metrics(const std::vector<SymMat<D>>& metrics) const { return with_log_metrics(logarithms(metrics)); }
  // Whether the back mesh has the vertices and elements of `mesh`, in its order (a field made from it).
  bool is_on(const Mesh<D>& mesh) const;

  const Mesh<D>& back_mesh() const { return *back_mesh_; }
  const PointLocator<D>& locator() const { return *locator_; }
  const SymMat<D>& vertex_log_metric(Index back_vertex) const { return log_metrics_[back_vertex]; }

  struct Sample {
    Localization<D> where;
    SymMat<D> log_metric;  // Σ λ_i R_i (affine extension just outside the back mesh)
  };
  // Thread-safe. `hint`: a back element near x, e.g. where the previous sample of an edge fell;
  // `scratch`: the caller's, reused from one sample to the next (point_locator.hpp).
  Sample sample(const Vec<D>& x, Index hint, LocatorScratch& scratch) const;
  Sample sample(const Vec<D>& x, Index hint = kNoIndex) const {
    LocatorScratch scratch;
    return sample(x, hint, scratch);
  }
  SymMat<D> log_metric_at(const Vec<D>& x, Index hint = kNoIndex) const { return sample(x, hint).log_metric; }
  // The same, but the affine extension outside the back mesh goes no farther than kMostExtension of
  // the element's height beyond a face (barycentrics pulled toward the centroid until none is below
  // −kMostExtension): it suits points just outside the mesh, but a vertex placed on a curved
  // boundary can lie farther out than a thin element is high, where the extension runs away (a
  // boundary-layer mesh's implied metric gave 1e7 times its largest eigenvalue; docs/adaptation.md
  // §Metric).
  static constexpr double kMostExtension = 0.25;
  Sample sample_within(const Vec<D>& x, Index hint, LocatorScratch& scratch) const;
  Sample sample_within(const Vec<D>& x, Index hint = kNoIndex) const {
    LocatorScratch scratch;
    return sample_within(x, hint, scratch);
  }

  // ∂(log M)/∂x_i = Σ_j (∂λ_j/∂x_i) R_j in back element k (constant inside it, docs/method.md §6).
  std::array<SymMat<D>, D> log_metric_gradient(Index back_element) const;

  // One back element prepared for many samples near it (an optimizer's iterates): its barycentric
  // gradients and the log-metric gradient. sample(x, frame) equals sample(x, frame.element) bit for bit,
  // without the walk's recomputation of the gradients when x is in the element.
  struct ElementFrame {
    Index element = kNoIndex;
    Vec<D> origin{};  // the element's first corner
    std::array<Vec<D>, D + 1> barycentric_gradients{};
    std::array<SymMat<D>, D> log_metric_gradient{};
  };
  ElementFrame element_frame(Index back_element) const;
  Sample sample(const Vec<D>& x, const ElementFrame& frame, LocatorScratch& scratch) const;

 private:
  static std::vector<SymMat<D>> logarithms(const std::vector<SymMat<D>>& metrics);
  MetricField(std::shared_ptr<const Mesh<D>> back_mesh, std::shared_ptr<const PointLocator<D>> locator, std::vector<SymMat<D>> log_metrics);
  // Σ_i λ_i R_i over the corners of a back element.
  SymMat<D> interpolate(Index back_element, const Barycentrics<D>& lambda) const;
  std::array<SymMat<D>, D> log_metric_gradient(Index back_element, const std::array<Vec<D>, D + 1>& barycentric_gradients) const;

  // Behind pointers: the locator refers to the mesh across moves, and fields on one back mesh share both.
  std::shared_ptr<const Mesh<D>> back_mesh_;
  std::shared_ptr<const PointLocator<D>> locator_;
  std::vector<SymMat<D>> log_metrics_;
};

// The metric (not its log) at each point (sample_within), each localization starting where the
// previous point fell (`hint`, updated): points in a mesh's order are mostly near their predecessor.
template <int D>
std::vector<SymMat<D>> metrics_at(const MetricField<D>& field, std::span<const Vec<D>> points, Index& hint);

extern template class MetricField<2>;
extern template class MetricField<3>;

}  // namespace hocav
