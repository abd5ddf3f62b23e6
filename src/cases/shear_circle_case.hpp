// The mesh for the paper's Fig. 1: the shear-circle metric (metric/analytic_metric.hpp) has a thin
// circular layer of radius r0 where sizes across the circle are small; the straight edges of a mesh
// adapted to it are chords of that circle, and bending them along it shortens them in the metric —
// the metric's intrinsic curvature, recovered by curving alone.
//
// The mesh is a polar annulus (polar_annulus.hpp) around the layer that is a unit mesh of the
// metric: its layers make the radial size h_r(r) unit (equal steps of ∫ dr / h_r), its sectors the
// tangential size h_t at r0 (m = ceil(2π r0 / h_t)). At the layer the cells are h_t by h_min, and
// a chord's sagitta h_t² / (8 r0) is of the order of the layer thickness (1.7 h_min with the
// defaults): curving is both rewarding and constrained by validity there.
#pragma once

#include "mesh/mesh.hpp"
#include "metric/analytic_metric.hpp"

namespace hocav {

// `metric` must be shear-circle centred at the origin. Facet refs 1 inner circle, 2 outer circle.
// Throws Error for bad radii, another metric, or an origin off the annulus' centre.
Mesh<2> generate_shear_circle_annulus(double inner_radius, double outer_radius, const AnalyticMetricSpec& metric);

}  // namespace hocav
