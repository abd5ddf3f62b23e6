// The figures of a curving run in the columns of the paper's Table 1 (docs/method.md §11),
// measured on the output mesh, plus the operator's counters.
#pragma once

#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "adapt/proposal_completion.hpp"
#include "adapt/reinsertion_curving.hpp"
#include "bezier/mesh_quality.hpp"
#include "report/json_writer.hpp"

namespace hocav {

struct CurvingReport {
  int dimension = 3;
  Index elements = 0;
  Index points_before = 0;                 // P1 points of the input
  Index points_after = 0;                  // P1 points + P2 nodes of the output
  double max_anisotropy = 0;               // largest ratio of largest to smallest metric size at a vertex
  double seconds = 0;                      // curving time, no I/O
  double edges_optimized_per_second = 0;   // over the whole curving time
  ValueSummary normalized_jacobian;        // per element: min of J / |J_straight|
  ValueSummary scaled_jacobian;            // per element: min J / max J (gmsh's measure)
  double average_gain = 0, max_gain = 0;   // over volume edges: 1 − ℓ(curved) / ℓ(straight), 16-point Gauss
  Index boundary_proposals_left = 0;       // proposals neither a cavity nor the last pass consumed
  ProposalCompletion boundary_completion;  // the last pass over the proposals the cavities left
  P2CavityCounters counters;
  int threads = 1;
};

// 1 − ℓ(curved) / ℓ(straight) of edge e (0 for a straight one), lengths in the metric by 16-point
// Gauss, and whether the field's search found its node and its straight middle inside the back
// mesh (a distributed part hands the others on: parallel/part_measures.hpp).
struct EdgeGain {
  double value = 0;
  bool sampled_inside = true;
};
template <int D>
EdgeGain edge_gain(const Mesh<D>& mesh, const MetricField<D>& field, Index e);

// 1 − ℓ(curved) / ℓ(straight) of every volume edge (not both ends on the boundary), in edge order,
// lengths in the metric by 16-point Gauss: the gains the report averages. The measures below run
// on `threads` threads and give the same figures for any count.
template <int D>
std::vector<double> volume_edge_gains(const Mesh<D>& mesh, const MetricField<D>& field, int threads = 1);

// Measures `mesh` into the report's output figures: element and point counts, Jacobians, gains.
template <int D>
void measure_curved_output(CurvingReport& report, const Mesh<D>& mesh, const MetricField<D>& field, int threads);

// The output figures from measures taken elsewhere (the parts of a distributed curving): each
// element's Jacobians and each volume edge's gain, every one once.
template <int D>
void summarize_curved_output(CurvingReport& report, const Mesh<D>& mesh, std::span<const JacobianQuality> elements,
                             std::span<const double> gains);

// The run's figures (times, counters, the metric's anisotropy), without the output's.
template <int D>
CurvingReport curving_run_report(const MetricField<D>& field, Index points_before, const ReinsertionResult& result,
                                 Index boundary_proposals_left);
// The same with the metric's largest anisotropy given (a distributed curving's, over its parts).
template <int D>
CurvingReport curving_run_report(double max_anisotropy, Index points_before, const ReinsertionResult& result,
                                 Index boundary_proposals_left);

// The ratio of the largest to the smallest size of a metric, from its logarithm.
template <int D>
double anisotropy_of(const SymMat<D>& log_metric);

// Measures the output (Jacobians, gains) and gathers the run's figures.
template <int D>
CurvingReport make_curving_report(const Mesh<D>& mesh, const MetricField<D>& field, Index points_before, const ReinsertionResult& result,
                                  Index boundary_proposals_left, int threads);

void write_curving_report_json(std::ostream& out, const CurvingReport& report);
// The same object, as a value inside a larger report.
void write_curving_report_object(JsonWriter& json, const CurvingReport& report);
// A short aligned table for the terminal.
void write_curving_report_table(std::ostream& out, const CurvingReport& report);

}  // namespace hocav
