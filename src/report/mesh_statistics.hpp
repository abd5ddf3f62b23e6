// The figures `hocav stats` reports about a mesh (and optionally the metric that goes with it),
// its validity verdict, and their two renderings: an aligned table for people and one JSON object
// for scripts.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_defects.hpp"

namespace hocav {

struct RefCount {
  int ref = 0;
  Index count = 0;
};

// Edge lengths in the metric, binned at these bounds; the bin [1/sqrt(2), sqrt(2)] of unit edges
// is closed at both ends, so its share is the "unit edges" figure of the literature. Its ends are
// compared with a relative slack of kUnitBinSlack: a quadrature rounds, and the diagonals of a unit
// mesh are sqrt(2) exactly.
inline const std::array<double, 6> kEdgeLengthBinBounds{0.3, 0.5, 1 / std::sqrt(2.0), std::sqrt(2.0), 2.0, 3.0};
inline constexpr std::size_t kUnitEdgeBin = 3;
inline constexpr double kUnitBinSlack = 1e-12;

// The mean-ratio quality of the elements in the metric (src/metric/metric_quality.hpp), binned at
// these bounds: (−inf, 0.1), [0.1, 0.3), …, [0.9, 1], each closed on the left (an inverted element,
// below 0, goes to the first). Below kLowQuality, the first bound, an element counts as poor.
inline constexpr std::array<double, 5> kQualityBinBounds{0.1, 0.3, 0.5, 0.7, 0.9};
inline constexpr double kLowQuality = kQualityBinBounds[0];

// The metric figures: edge lengths in the metric, element qualities in it and the largest anisotropy.
struct MetricStatistics {
  Index edge_count = 0;
  double min = 0, mean = 0, max = 0;  // edge lengths
  std::array<Index, kEdgeLengthBinBounds.size() + 1> histogram{};
  double unit_share = 0;  // share of edges with length in [1/sqrt(2), sqrt(2)]
  // Per element, with the metric at its centroid (the log-Euclidean mean of its vertices' metrics).
  double quality_min = 0, quality_mean = 0;
  std::array<Index, kQualityBinBounds.size() + 1> quality_histogram{};
  double low_quality_share = 0;  // share of elements with quality below kLowQuality
  // max over the vertices of sqrt(λmax/λmin): the ratio of the largest to the smallest size.
  double max_anisotropy = 0;
};

// The sums the metric figures follow from, in the order the values are added (the figures are then
// the same for any thread count). The tallies of a distributed mesh's parts, each edge in one of
// them, add up to the whole mesh's (docs/distributed.md §The end in the parts).
struct MetricTally {
  Index edges = 0;
  double length_min = std::numeric_limits<double>::infinity(), length_max = -length_min, length_sum = 0;
  std::array<Index, kEdgeLengthBinBounds.size() + 1> length_histogram{};
  Index elements = 0;
  double quality_min = std::numeric_limits<double>::infinity(), quality_sum = 0;
  std::array<Index, kQualityBinBounds.size() + 1> quality_histogram{};
  double max_anisotropy = 0;

  void add_length(double length);
  void add_quality(double quality);
  void add(const MetricTally& other);
  // The figures: zeros for no edges or no elements.
  MetricStatistics statistics() const;
};

// The metric values of a mesh (see compute_mesh_statistics): per vertex its anisotropy (the ratio of
// its largest size to its smallest), per element its quality, per edge its ends and its length.
struct MetricValues {
  std::vector<double> anisotropies, qualities;
  std::vector<std::array<Index, 2>> edges;  // the edge table's in its order, else each pair an element joins once
  std::vector<double> lengths;
};

// The per-element Jacobian figures (certified bounds, src/bezier/), binned at these bounds: bins
// (−inf, 0] (invalid), (0, 0.01] (below the default floor of `hocav curve`), (0.01, 0.1], …,
// (0.9, 1], (1, inf), all closed on the right. The bound 1 is compared with a relative slack of
// kJacobianBinSlack: a straight element is 1 up to rounding, and belongs to (0.9, 1].
inline constexpr std::array<double, 8> kJacobianBinBounds{0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0};
inline constexpr double kJacobianBinSlack = 1e-12;
using JacobianHistogram = std::array<Index, kJacobianBinBounds.size() + 1>;

struct JacobianFigures {
  double min = 0, average = 0, max = 0;  // over the elements, the average unweighted
  JacobianHistogram histogram{};
};

struct JacobianStatistics {
  // Per element, the refined lower bound of min J / |J_straight| (1 for a straight element; ≤ 0:
  // not proven positive) and gmsh's scaled Jacobian min J / max J.
  JacobianFigures min_normalized, scaled;
  // Elements whose certified lower bound of min J is ≤ 0: J ≤ 0 somewhere, or J so close to 0
  // (within 1e-6 of max |J|) that it cannot be proven positive. For a P1 mesh: inverted or flat.
  Index invalid = 0;
  Index first_invalid_element = kNoIndex;
  bool straight = false;  // a P1 mesh: every figure is 1, or −1 for an inverted element
};

struct MeshStatistics {
  int dimension = 2;
  int order = 1;
  Index vertices = 0, elements = 0, boundary_facets = 0, lines = 0, edges = 0, p2_nodes = 0;
  Index corners = 0, ridges = 0, required_vertices = 0;
  std::vector<RefCount> element_refs, facet_refs;  // by increasing ref
  // Signed P1 measures (area or volume of the straight elements).
  double min_measure = 0, max_measure = 0, total_measure = 0;
  Index non_positive_elements = 0;
  // Element faces on the domain boundary without a boundary facet (allowed, but worth knowing).
  Index open_boundary_faces = 0;
  // Those and the other defects of a consistent mesh: non-manifold vertices and edges, overlaps.
  MeshDefects defects;
  // The consistency checker's verdict (P1 orientation is required of P1 meshes only).
  std::vector<std::string> consistency_problems;
  JacobianStatistics jacobian;
  std::size_t memory_bytes = 0;
  std::optional<MetricStatistics> metric;

  // Valid: consistent, and every element certified with a positive Jacobian.
  bool valid() const { return consistency_problems.empty() && jacobian.invalid == 0; }
};

// Computes the statistics; builds the mesh's edge table when it has none (so memory_bytes is taken
// first). `node_metrics`, when not empty, holds symmetric matrices in .sol order (D (D + 1) / 2
// values each): one per vertex, then, for a P2 mesh, optionally one per edge node.
// The length of an edge is its Riemannian length as a P2 edge (docs/method.md §5, eq 12) with the 16-point
// Gauss rule: log M varies along it as the P2 interpolation of the log-metrics at its ends and at its
// node. A P1 edge is straight, its node the midpoint with log M the mean of its ends' (so log M is
// linear along it); a P2 edge has its node, with the metric given there or else that mean.
// The quality of an element is that of its straight (P1) simplex. The metric figures are computed
// on `threads` threads (the same figures for any count).
template <int D>
MeshStatistics compute_mesh_statistics(Mesh<D>& mesh, std::span<const double> node_metrics = {}, int threads = 1);

// The metric figures alone (edge lengths and qualities as above), without the checks and Jacobian
// figures of compute_mesh_statistics: what `hocav adapt` reports on its output. A P1 mesh needs no
// edge table: its edges are found from its elements.
template <int D>
MetricStatistics compute_metric_statistics(const Mesh<D>& mesh, std::span<const double> node_metrics, int threads = 1);

// The values the metric figures are made of, on `threads` threads (the same for any count).
template <int D>
MetricValues compute_metric_values(const Mesh<D>& mesh, std::span<const double> node_metrics, int threads = 1);

// The bin of an edge length (index into MetricStatistics::histogram).
std::size_t edge_length_bin(double length);

// The bin of an element quality (index into MetricStatistics::quality_histogram); NaN goes to the first.
std::size_t quality_bin(double quality);

// The bin of a Jacobian figure (index into JacobianFigures::histogram); NaN goes to the first.
std::size_t jacobian_bin(double value);

// Why a mesh is not valid, in one line: "2 invalid elements (first: element 7), consistency: 3
// problems (first: ...)"; empty for a valid mesh.
std::string invalidity_summary(const MeshStatistics& statistics);

// The mesh and metric file names head the report; metric_name is empty when there is no metric.
void write_statistics_table(std::ostream& out, const MeshStatistics& statistics, const std::string& mesh_name,
                            const std::string& metric_name);
void write_statistics_json(std::ostream& out, const MeshStatistics& statistics, const std::string& mesh_name,
                           const std::string& metric_name);

}  // namespace hocav
