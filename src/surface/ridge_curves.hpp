// The P3 surrogate's ridge curves (docs/surface.md, "Ridge curves"): the cubic edge curves that the
// two patches of a feature edge share (its facets' refs differ, or they are on different sides: a
// dihedral ridge), each with the refs on its two sides, and the closest point on those that separate
// two given parts. A new vertex on a split ridge edge goes there (BoundaryGeometry::project_on_ridge),
// on the same curve as the mid nodes the surrogate proposes, where alternating projections onto the
// two parts would converge slowly and a ridge inside one part has no second part to alternate with.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "surface/patch_tree.hpp"

namespace hocav {

// The control points of a cubic Bézier curve: P_i, b_ij, b_ji, P_j.
using CubicCurve = std::array<Vec3, 4>;

Vec3 evaluate_curve(const CubicCurve& curve, double t);

// The closest point to x on the curve (t ∈ [0, 1]): the best of a few samples, polished by Newton.
Vec3 closest_point_on_curve(const CubicCurve& curve, const Vec3& x);

class RidgeCurves {
 public:
  RidgeCurves() = default;
  // curves[c] separates the parts with refs refs[c] (equal for a ridge inside one part).
  RidgeCurves(std::vector<CubicCurve> curves, std::vector<std::array<int, 2>> refs);

  // The closest point to x on the curves between the parts ref_a and ref_b (in either order);
  // none when no curve separates them.
  std::optional<Vec3> closest(const Vec3& x, int ref_a, int ref_b) const;
  Index size() const { return static_cast<Index>(curves_.size()); }

 private:
  std::vector<CubicCurve> curves_;
  std::vector<std::array<int, 2>> refs_;  // sorted pairs
  std::vector<Box<3>> boxes_;
  PatchTree<3> tree_;
};

}  // namespace hocav
