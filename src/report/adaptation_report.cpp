#include "report/adaptation_report.hpp"

#include <cstdio>
#include <ostream>
#include <sstream>

#include "report/json_writer.hpp"

namespace hocav {

namespace {

// {"done": N, "refused": {"classes": N, ...}}
void write_operation(JsonWriter& json, const char* name, const OperationCount& count) {
  json.key(name).begin_object().member("done", count.done);
  json.key("refused").begin_object();
  for (int reason = 0; reason < kRefusalKinds; ++reason)
    json.member(to_string(static_cast<Refusal>(reason)), count.refused[static_cast<std::size_t>(reason)]);
  json.end_object().end_object();
}

}  // namespace

void write_curved_operation(JsonWriter& json, const char* name, const CurvedOperationCount& count) {
  json.key(name).begin_object().member("done", count.done).member("boundary_done", count.boundary_done);
  json.member("on_boundary", count.on_boundary);
  json.member("too_long", count.too_long).member("no_gain", count.no_gain).member("flat", count.flat);
  json.member("refused", count.refused).end_object();
}

void write_curved_passes(JsonWriter& json, const CurvedAdaptationRun& run) {
  json.key("curved_passes").begin_object();
  json.member("converged", run.converged).member("seconds", run.seconds);
  json.member("corrections", run.counters.corrections).member("rejected_by_curving", run.counters.rejected_curving);
  json.member("rejected_by_quality", run.counters.rejected_quality);
  json.member("rejected_by_straight_quality", run.counters.rejected_straight_quality);
  json.member("rejected_by_boundary_geometry", run.counters.rejected_boundary);
  json.key("passes").begin_array();
  for (const CurvedPass& pass : run.passes) {
    json.begin_object();
    write_curved_operation(json, "collapses", pass.collapses);
    write_curved_operation(json, "splits", pass.splits);
    write_curved_operation(json, "swaps", pass.swaps);
    write_curved_operation(json, "moves", pass.moves);
    json.member("vertices", pass.vertices).member("elements", pass.elements).member("seconds", pass.seconds);
    json.end_object();
  }
  json.end_array().end_object();
}

void write_curved_measures(JsonWriter& json, const CurvedMeasures& m) {
  json.key("curved_measures").begin_object();
  json.member("edges", m.edge_count).member("length_min", m.length_min).member("length_mean", m.length_mean);
  json.member("length_max", m.length_max).member("unit_share", m.unit_share);
  json.member("quality_min", m.quality_min).member("quality_mean", m.quality_mean).end_object();
}

// The loop stops at its cap of passes at the latest; when it stops there the metric may ask for what the
// mesh cannot give (sizes below what corners, required entities or the geometry allow, or a field too
// rough for its back mesh), and the user hears it.
std::string non_convergence_summary(const AdaptationReport& report) {
  if (report.run.converged || report.run.passes.empty()) return "";
  const AdaptationPass& last = report.run.passes.back();
  std::ostringstream text;
  text << "not converged after " << report.run.passes.size() << " passes (the last split " << last.splits.done << " and collapsed "
       << last.collapses.done << " edges";
  if (report.measures.edge_count > 0) text << "; " << static_cast<int>(1000 * report.measures.unit_share) / 10.0 << "% of edges unit";
  text << ")";
  if (changed_little(last))  // then only the settling kept the loop going
    text << ": few enough to stop, but the boundary's settling was still getting further (" << last.settled
         << " vertices put on the geometry, " << last.partly_settled << " left part of the way); raise --iterations to let it finish";
  else
    text << "; raise --iterations, or check that the metric asks for sizes the geometry allows";
  return text.str();
}

namespace {

template <typename T>
void write_per_rank(JsonWriter& json, std::string_view name, const std::vector<T>& values) {
  json.key(name).begin_array();
  for (const T& value : values) json.value(value);
  json.end_array();
}

void write_distributed_iterations(JsonWriter& json, const std::vector<DistributedIteration>& iterations) {
  json.key("distributed_iterations").begin_array();
  for (const DistributedIteration& it : iterations) {
    json.begin_object().member("iteration", it.iteration).member("metric_fraction", it.metric_fraction);
    json.member("vertices", it.vertices).member("elements", it.elements);
    json.member("interface_vertices", it.interface_vertices).member("interface_faces", it.interface_faces);
    json.member("interface_edges_split", it.interface_edges_split).member("interface_faces_turned", it.interface_faces_turned);
    json.member("unsettled_vertices", it.unsettled_vertices).member("region_elements", it.region_elements);
    json.member("bytes_sent", it.bytes_sent)
        .member("back_mesh_bytes", it.back_mesh_bytes)
        .member("seconds", it.seconds)
        .member("seconds_partition", it.seconds_partition);
    write_per_rank(json, "part_seconds", it.part_seconds);
    write_per_rank(json, "peak_memory_bytes", it.peak_memory_bytes);
    json.end_object();
  }
  json.end_array();
}

void write_settling(JsonWriter& json, const BoundarySettling& s) {
  json.key("boundary_settling").begin_object();
  json.member("off_geometry", s.off_geometry).member("largest_distance", s.largest_distance);
  json.member("settled", s.settled).member("partly", s.partly).member("blocked", s.blocked);
  json.member("largest_distance_left", s.largest_distance_left).member("inner_vertices_moved", s.inner_vertices_moved);
  json.member("solver_iterations", s.solver_iterations).member("rounds", s.rounds).member("seconds", s.seconds);
  json.end_object();
}

// "boundary onto the geometry: N vertices off it ..." when some were.
void write_settling_line(std::ostream& out, const std::optional<BoundarySettling>& settling) {
  if (!settling || settling->off_geometry == 0) return;
  const BoundarySettling& b = *settling;
  char line[512];
  std::snprintf(line, sizeof line,
                "boundary onto the geometry: %d vertices off it (up to %.3g): %d moved onto it, %d part of the way, %d kept (up to %.3g "
                "left); %d inner vertices moved along, %.2f s\n",
                b.off_geometry, b.largest_distance, b.settled, b.partly, b.blocked, b.largest_distance_left, b.inner_vertices_moved,
                b.seconds);
  out << line;
}

}  // namespace

void write_adaptation_report_json(std::ostream& out, const AdaptationReport& report) {
  JsonWriter json(out);
  json.begin_object();
  json.member("dimension", report.dimension);
  json.member("input_vertices", report.input_vertices).member("input_elements", report.input_elements);
  json.member("output_vertices", report.output_vertices).member("output_elements", report.output_elements);
  json.member("hausdorff_bounded_vertices", report.hausdorff_bounded_vertices);
  json.member("converged", report.run.converged);
  json.member("stopped_with_window_open", report.run.stopped_with_window_open);
  json.member("caps_removed", report.run.caps_removed);
  json.key("passes").begin_array();
  for (const AdaptationPass& pass : report.run.passes) {
    json.begin_object();
    write_operation(json, "collapses", pass.collapses);
    write_operation(json, "splits", pass.splits);
    write_operation(json, "swaps", pass.swaps);
    write_operation(json, "moves", pass.moves);
    json.member("vertices", pass.vertices).member("elements", pass.elements).member("seconds", pass.seconds);
    json.key("seconds_per_operator").begin_object();
    json.member("collapse", pass.seconds_collapse).member("swap", pass.seconds_swap).member("split", pass.seconds_split);
    json.member("smooth", pass.seconds_smooth).member("compact", pass.seconds_compact).member("settle", pass.seconds_settle).end_object();
    json.member("settled", pass.settled).member("partly_settled", pass.partly_settled);
    json.member("window_open", pass.window_open).member("collapse_length_bound", pass.collapse_length_bound);
    json.member("coarse_phase", pass.coarse_phase);
    json.end_object();
  }
  json.end_array();
  if (report.settling) write_settling(json, *report.settling);
  const MetricStatistics& m = report.measures;
  json.key("edge_length").begin_object();
  json.member("edges", m.edge_count).member("min", m.min).member("mean", m.mean);
  json.member("max", m.max).member("unit_share", m.unit_share).end_object();
  json.key("quality").begin_object();
  json.member("min", m.quality_min).member("mean", m.quality_mean);
  json.member("share_below_0_1", m.low_quality_share).end_object();
  json.key("seconds").begin_object().member("adapt", report.seconds_adapt).member("curve", report.seconds_curve).end_object();
  json.member("peak_memory_bytes", report.peak_memory_bytes);
  if (report.curving) {
    json.key("curving");
    write_curving_report_object(json, *report.curving);
  }
  if (report.curved_passes) write_curved_passes(json, *report.curved_passes);
  if (report.curved_measures) write_curved_measures(json, *report.curved_measures);
  if (!report.distributed_iterations.empty()) {
    write_distributed_iterations(json, report.distributed_iterations);
    json.member("input_read_in_pieces", report.input_read_in_pieces);
  }
  json.end_object();
  out << '\n';
}

void write_adaptation_report_table(std::ostream& out, const AdaptationReport& report) {
  out << "pass  collapses  splits   swaps   moves  settled  vertices  elements  seconds  window\n";
  for (std::size_t i = 0; i < report.run.passes.size(); ++i) {
    const AdaptationPass& p = report.run.passes[i];
    char line[160];
    std::snprintf(line, sizeof line, "%4zu %10d %7d %7d %7d %8d %9d %9d %8.2f  %s\n", i + 1, p.collapses.done, p.splits.done, p.swaps.done,
                  p.moves.done, p.settled + p.partly_settled, p.vertices, p.elements, p.seconds, p.window_open ? "open" : "closed");
    out << line;
  }
  char summary[512];
  std::snprintf(summary, sizeof summary,
                "%s after %zu passes: %d -> %d elements; edges unit %.1f%% (length %.3f/%.3f/%.3f min/mean/max); "
                "quality min %.3f mean %.3f (%.2f%% below 0.1); adapt %.2f s, curve %.2f s, peak %.0f MiB\n",
                report.run.converged ? "converged" : "stopped at the cap", report.run.passes.size(), report.input_elements,
                report.output_elements, 100 * report.measures.unit_share, report.measures.min, report.measures.mean, report.measures.max,
                report.measures.quality_min, report.measures.quality_mean, 100 * report.measures.low_quality_share, report.seconds_adapt,
                report.seconds_curve, static_cast<double>(report.peak_memory_bytes) / (1 << 20));
  out << summary;
  write_settling_line(out, report.settling);
  if (report.curved_passes) {
    const CurvedAdaptationRun& run = *report.curved_passes;
    for (std::size_t i = 0; i < run.passes.size(); ++i) {
      const CurvedPass& p = run.passes[i];
      std::snprintf(summary, sizeof summary,
                    "curved pass %zu: %d collapses (refused: %d on the boundary, %d too long, %d other), %d splits (refused: %d on "
                    "the boundary, %d other), %d swaps and %d moves (refused: %d and %d no gain, %d and %d other), %d elements, %.2f s\n",
                    i + 1, p.collapses.done, p.collapses.on_boundary, p.collapses.too_long, p.collapses.refused, p.splits.done,
                    p.splits.on_boundary, p.splits.refused, p.swaps.done, p.moves.done, p.swaps.no_gain, p.moves.no_gain,
                    p.swaps.refused + p.swaps.on_boundary, p.moves.refused + p.moves.on_boundary, p.elements, p.seconds);
      out << summary;
    }
  }
  if (report.curved_measures) {
    const CurvedMeasures& m = *report.curved_measures;
    std::snprintf(summary, sizeof summary,
                  "curved: edges unit %.1f%% (length %.3f/%.3f/%.3f min/mean/max); curved quality min %.3f mean %.3f\n", 100 * m.unit_share,
                  m.length_min, m.length_mean, m.length_max, m.quality_min, m.quality_mean);
    out << summary;
  }
}

}  // namespace hocav
