// What the elements around a moved P2 node must keep (docs/curving.md, "Boundary edges no cavity
// reaches"): a certificate above the Jacobian floor and, with a metric, most of their curved quality
// (at least max(0.7 q, min(q, 0.1)), q the quality before the move, as the boundary settling asks).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

template <int D>
class ElementGuard {
 public:
  // Takes the qualities of `elements` as they are now.
  ElementGuard(const Mesh<D>& mesh, std::vector<Index> elements, double jacobian_floor, const MetricField<D>* field);

  // Whether every element passes as the mesh is now; counts the elements certified.
  bool holds(long long& elements_certified) const;

  const std::vector<Index>& elements() const { return elements_; }

 private:
  double quality(Index k) const;

  const Mesh<D>& mesh_;
  std::vector<Index> elements_;
  double jacobian_floor_;
  const MetricField<D>* field_;
  std::vector<double> bars_;  // per element, with a metric
};

extern template class ElementGuard<2>;
extern template class ElementGuard<3>;

}  // namespace hocav
