#include "picture/planar_cut.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "base/error.hpp"

namespace hocav {
namespace {

constexpr int kMaxSubdivisions = 64;

// The P2 map of a triangle (D = 2) or tetrahedron (D = 3) in 3D at barycentric coordinates λ:
// Σ λ_i (2 λ_i − 1) P_i + Σ_edges 4 λ_a λ_b M_ab.
template <int D>
Vec3 p2_point(const std::array<Vec3, kP2NodeCount<D>>& nodes, const std::array<double, D + 1>& lambda) {
  Vec3 point{};
  for (int i = 0; i <= D; ++i) point += lambda[i] * (2 * lambda[i] - 1) * nodes[i];
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    point += 4 * lambda[ends[0]] * lambda[ends[1]] * nodes[D + 1 + edge];
  }
  return point;
}

struct Sample {
  std::uint64_t key = 0;  // the lattice node
  Vec3 position;
  double distance = 0;
};

// Marching triangles over lattice sub-triangles, then chaining of the crossing segments.
class CrossingTracer {
 public:
  void add_triangle(const Sample& a, const Sample& b, const Sample& c) {
    const Sample* corners[3] = {&a, &b, &c};
    std::uint64_t ends[2];
    int found = 0;
    for (int i = 0; i < 3; ++i) {
      const Sample &p = *corners[i], &q = *corners[(i + 1) % 3];
      if ((p.distance >= 0) != (q.distance >= 0)) ends[found++] = crossing(p, q);
    }
    if (found == 2) segments_.push_back({ends[0], ends[1]});
  }

  std::vector<CutCurve> curves() const {
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> at_point;
    for (std::size_t s = 0; s < segments_.size(); ++s)
      for (std::uint64_t end : segments_[s]) at_point[end].push_back(s);
    std::vector<bool> used(segments_.size(), false);
    // Follows unused segments from `end` and appends the points reached; true when back at `stop`.
    auto walk = [&](std::uint64_t end, std::uint64_t stop, std::vector<std::uint64_t>& keys) {
      for (;;) {
        auto next = std::find_if(at_point.at(end).begin(), at_point.at(end).end(), [&](std::size_t s) { return !used[s]; });
        if (next == at_point.at(end).end()) return false;
        used[*next] = true;
        end = segments_[*next][0] == end ? segments_[*next][1] : segments_[*next][0];
        if (end == stop) return true;
        keys.push_back(end);
      }
    };
    std::vector<CutCurve> curves;
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      if (used[s]) continue;
      used[s] = true;
      std::vector<std::uint64_t> forward{segments_[s][0], segments_[s][1]}, backward;
      CutCurve curve;
      curve.closed = walk(segments_[s][1], segments_[s][0], forward);
      if (!curve.closed) walk(segments_[s][0], segments_[s][1], backward);
      for (auto key = backward.rbegin(); key != backward.rend(); ++key) curve.points.push_back(points_.at(*key));
      for (std::uint64_t key : forward) curve.points.push_back(points_.at(key));
      curves.push_back(std::move(curve));
    }
    return curves;
  }

 private:
  // The crossing on lattice edge pq, computed from its ends in key order so both sub-triangles
  // sharing the edge get the same point.
  std::uint64_t crossing(const Sample& p, const Sample& q) {
    const Sample &first = p.key < q.key ? p : q, &second = p.key < q.key ? q : p;
    const std::uint64_t key = (first.key << 32) | second.key;
    const double t = first.distance / (first.distance - second.distance);
    points_.try_emplace(key, first.position + t * (second.position - first.position));
    return key;
  }

  std::vector<std::array<std::uint64_t, 2>> segments_;
  std::unordered_map<std::uint64_t, Vec3> points_;
};

// Samples the face with local vertices `face` of a P2 simplex on the lattice of `n` subdivisions
// and marches over its sub-triangles. Lattice nodes are named by their integer barycentric
// coordinates in the whole simplex, so faces sharing an edge share its samples.
template <int D>
void trace_face(const std::array<Vec3, kP2NodeCount<D>>& nodes, const std::array<int, 3>& face, int n, const CutPlane& plane,
                CrossingTracer& tracer) {
  auto sample = [&](int i, int j) {
    std::array<int, D + 1> counts{};
    counts[face[0]] = n - i - j;
    counts[face[1]] = i;
    counts[face[2]] = j;
    Sample result;
    std::array<double, D + 1> lambda{};
    for (int k = 0; k <= D; ++k) {
      result.key = result.key * static_cast<std::uint64_t>(n + 1) + static_cast<std::uint64_t>(counts[k]);
      lambda[k] = static_cast<double>(counts[k]) / n;
    }
    result.position = p2_point<D>(nodes, lambda);
    result.distance = plane.signed_distance(result.position);
    return result;
  };
  std::vector<Sample> row(static_cast<std::size_t>(n + 1)), next_row(static_cast<std::size_t>(n + 1));
  for (int j = 0; j <= n; ++j) row[j] = sample(0, j);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= n - i - 1; ++j) next_row[j] = sample(i + 1, j);
    for (int j = 0; j < n - i; ++j) {
      tracer.add_triangle(row[j], next_row[j], row[j + 1]);
      if (j + 1 < n - i) tracer.add_triangle(next_row[j], next_row[j + 1], row[j + 1]);
    }
    std::swap(row, next_row);
  }
}

void check_subdivisions(int subdivisions) {
  if (subdivisions < 1 || subdivisions > kMaxSubdivisions)
    throw Error("internal error: a planar cut with " + std::to_string(subdivisions) + " subdivisions (1 to 64)");
}

}  // namespace

std::vector<CutCurve> cut_p2_triangle(const std::array<Vec3, 6>& nodes, const CutPlane& plane, int subdivisions) {
  check_subdivisions(subdivisions);
  CrossingTracer tracer;
  trace_face<2>(nodes, {0, 1, 2}, subdivisions, plane, tracer);
  return tracer.curves();
}

std::vector<CutCurve> cut_p2_tetrahedron(const P2Element<3>& element, const CutPlane& plane, int subdivisions) {
  check_subdivisions(subdivisions);
  CrossingTracer tracer;
  for (int face = 0; face < Simplex<3>::kFaces; ++face) {
    const auto& vertices = face_vertices<3>(face);
    trace_face<3>(element.nodes, {vertices[0], vertices[1], vertices[2]}, subdivisions, plane, tracer);
  }
  return tracer.curves();
}

std::vector<CutCell> cut_p2_mesh(const Mesh<3>& mesh, const CutPlane& plane, int subdivisions) {
  std::vector<CutCell> cells;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const P2Element<3> element = gather_p2_element(mesh, k);
    // The element lies in the convex hull of its Bézier control net: when the net is on one side,
    // so is the element.
    const BezierControlNet<3> net = control_net(element);
    const auto on_positive_side = [&](const Vec3& node) { return plane.signed_distance(node) >= 0; };
    const auto positive = std::count_if(net.nodes.begin(), net.nodes.end(), on_positive_side);
    if (positive == 0 || positive == static_cast<std::ptrdiff_t>(net.nodes.size())) continue;
    // The boundary of a tetrahedron is closed: its curves are too.
    for (const CutCurve& curve : cut_p2_tetrahedron(element, plane, subdivisions)) {
      CutCell cell{k, {}};
      for (const Vec3& point : curve.points) cell.outline.push_back(plane.coordinates(point));
      cells.push_back(std::move(cell));
    }
  }
  return cells;
}

}  // namespace hocav
