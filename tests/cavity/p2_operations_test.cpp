#include "cavity/p2_operations.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <optional>
#include <random>

#include "adapt/reinsertion_curving.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "cases/structured.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/consistency.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/metric_quality.hpp"

namespace hocav {
namespace {

enum class Kind { kSplit, kCollapse, kSwap, kMove };

// The unit square or cube, curved by reinsertion in a shear layer (radius 0.6 around the origin):
// a certified P2 mesh whose edges are bent, and the metric it was curved in.
template <int D>
struct CurvedCase {
  Mesh<D> mesh;
  std::unique_ptr<MetricField<D>> field;
  static Mesh<D> unit_mesh(int cells) {
    if constexpr (D == 2)
      return generate_square(cells);
    else
      return generate_cube(cells);
  }
  explicit CurvedCase(int cells) : mesh(unit_mesh(cells)) {
    AnalyticMetricSpec spec;
    spec.name = D == 2 ? "shear-circle" : "shear-sphere";
    spec.radius = 0.6;
    spec.width = 0.08;
    spec.h_min = 0.01;
    spec.h_max = 0.1;
    field = std::make_unique<MetricField<D>>(mesh, analytic_metric_at_vertices(spec, mesh));
    curve_by_reinsertion<D>(mesh, *field, nullptr);
  }
};

// Everything a refused operation must leave as it was, as bytes.
template <int D>
std::vector<unsigned char> mesh_bytes(const Mesh<D>& mesh) {
  std::vector<unsigned char> bytes;
  auto add = [&](const void* data, std::size_t size) {
    const auto* first = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), first, first + size);
  };
  auto add_span = [&](auto items) { add(items.data(), items.size_bytes()); };
  add_span(mesh.vertices());
  add_span(mesh.elements());
  add_span(mesh.element_refs());
  add_span(mesh.facets());
  add_span(mesh.edges());
  add_span(mesh.edge_nodes());
  add_span(mesh.element_edge_table());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const Index k = mesh.vertex_element(v);
    const bool removed = mesh.vertex_removed(v);
    add(&k, sizeof k);
    add(&removed, sizeof removed);
  }
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      const Index n = mesh.neighbor(k, face), f = mesh.element_face_facet(k, face);
      add(&n, sizeof n);
      add(&f, sizeof f);
    }
  return bytes;
}

template <int D>
bool every_element_certified(const Mesh<D>& mesh, double floor) {
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh, k), floor)) return false;
  return true;
}

// The last operation's new inner edges hold their optimum, found again here from their start (and
// the back element the operator started from: on a kink the walk's choice of element can lead to
// another local optimum), or a point between their start (the fallback) and that optimum.
template <int D>
void expect_inner_edges_optimal_or_corrected(const Mesh<D>& mesh, const MetricField<D>& field, const P2Operations<D>& operations) {
  for (const auto& edge : operations.cavity_operator().curved_edges()) {
    if (!edge.inner) continue;
    const Index id = mesh.find_edge(edge.a, edge.b);
    ASSERT_NE(id, kNoIndex);
    EXPECT_EQ(mesh.edge_node(id), edge.node());
    EXPECT_GE(edge.scale, 0.0);
    EXPECT_LE(edge.scale, 1.0);
    const auto again = optimize_edge_length(field, mesh.vertex(edge.a), mesh.vertex(edge.b), operations.log_metric(edge.a),
                                            operations.log_metric(edge.b), edge.fallback, edge.start_hint);
    EXPECT_LE(norm(again.node - edge.target), 1e-9 * norm(mesh.vertex(edge.b) - mesh.vertex(edge.a))) << "edge " << edge.a << "-" << edge.b;
  }
}

// An edge (a, b) of a random element, and a third vertex of it.
template <int D>
std::array<Index, 3> random_edge(const Mesh<D>& mesh, std::mt19937& random) {
  const auto& element = mesh.element(static_cast<Index>(random() % static_cast<unsigned>(mesh.element_count())));
  std::array<int, D + 1> order;
  for (int i = 0; i <= D; ++i) order[static_cast<std::size_t>(i)] = i;
  std::shuffle(order.begin(), order.end(), random);
  return {element[order[0]], element[order[1]], element[order[2]]};
}

// A point near v: a random step of up to a fifth of its shortest edge.
template <int D>
Vec<D> nearby_point(const Mesh<D>& mesh, Index v, std::mt19937& random) {
  std::vector<Index> ball;
  collect_ball(mesh, v, ball);
  double shortest = 1e300;
  for (Index k : ball)
    for (Index w : mesh.element(k))
      if (w != v) shortest = std::min(shortest, norm(mesh.vertex(w) - mesh.vertex(v)));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Vec<D> x = mesh.vertex(v);
  for (int i = 0; i < D; ++i) x[i] += 0.2 * shortest * unit(random) / std::sqrt(double{D});
  return x;
}

// Applies one operation of `kind` on a random edge; true when accepted.
template <int D>
CavityStatus try_operation(P2Operations<D>& operations, Mesh<D>& mesh, Kind kind, std::mt19937& random) {
  const auto [a, b, c] = random_edge(mesh, random);
  switch (kind) {
    case Kind::kSplit: {
      const Vec<D> node = mesh.edge_node(mesh.find_edge(a, b));
      Index m = kNoIndex;
      const CavityStatus status = operations.split_edge(a, b, &m);
      if (status == CavityStatus::kAccepted) {
        EXPECT_EQ(mesh.vertex(m), node) << "the new vertex is the split edge's P2 node";
        EXPECT_EQ(mesh.find_edge(a, b), kNoIndex);
      }
      return status;
    }
    case Kind::kCollapse: {
      const CavityStatus status = operations.collapse_edge(a, b);
      if (status == CavityStatus::kAccepted) {
        EXPECT_TRUE(mesh.vertex_removed(a));
      }
      return status;
    }
    case Kind::kSwap: {
      const CavityStatus status = operations.swap_edge(a, b, c);
      if (status == CavityStatus::kAccepted) {
        EXPECT_EQ(mesh.find_edge(a, b), kNoIndex);
      }
      return status;
    }
    case Kind::kMove: {
      const Vec<D> x = nearby_point(mesh, a, random);
      const CavityStatus status = operations.move_vertex(a, x);
      if (status == CavityStatus::kAccepted) {
        EXPECT_EQ(mesh.vertex(a), x);
      }
      return status;
    }
  }
  return CavityStatus::kNotStarShaped;
}

// Random operations of one kind on the curved case: each accepted one leaves the mesh consistent,
// every element certified above the floor and its new inner edges at their optimum or pulled
// back toward their fallback; each refused one leaves the mesh byte for byte as it was.
template <int D>
void run_operations(Kind kind, int cells, int operations_count) {
  CurvedCase<D> curved(cells);
  Mesh<D>& mesh = curved.mesh;
  const P2CavityOptions options;
  ASSERT_TRUE(every_element_certified(mesh, options.jacobian_floor));
  P2Operations<D> operations(mesh, *curved.field, nullptr, options);
  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;
  consistency.require_boundary_facets = true;
  std::mt19937 random(static_cast<unsigned>(7 + static_cast<int>(kind)));
  int accepted = 0, refused_interior = 0;
  for (int i = 0; i < operations_count; ++i) {
    const auto before = mesh_bytes(mesh);
    const CavityStatus status = try_operation(operations, mesh, kind, random);
    if (status != CavityStatus::kAccepted) {
      ASSERT_EQ(mesh_bytes(mesh), before) << "operation " << i << " was refused (" << to_string(status) << ") and changed the mesh";
      refused_interior += status != CavityStatus::kCrossesBoundary;
      continue;
    }
    ++accepted;
    ASSERT_EQ(check_consistency(mesh, consistency), std::vector<std::string>{}) << "after operation " << i;
    ASSERT_TRUE(every_element_certified(mesh, options.jacobian_floor)) << "after operation " << i;
    expect_inner_edges_optimal_or_corrected(mesh, *curved.field, operations);
    if (::testing::Test::HasFailure()) return;
  }
  const P2CavityCounters& counters = operations.cavity_operator().counters();
  std::printf("%dD operation %d: %d of %d accepted; inside the domain refused by topology %lld, by curving %lld; %lld corrections\n", D,
              static_cast<int>(kind), accepted, operations_count, counters.rejected_topology, counters.rejected_curving,
              counters.corrections);
  EXPECT_GT(accepted, operations_count / 10) << "refused inside the domain: " << refused_interior;
  EXPECT_GT(counters.edges_optimized, 0);
}

TEST(P2Operations, SplitsKeepTheTriangleMeshCurvedAndCertified) { run_operations<2>(Kind::kSplit, 10, 150); }
TEST(P2Operations, SplitsKeepTheTetrahedralMeshCurvedAndCertified) { run_operations<3>(Kind::kSplit, 6, 150); }
TEST(P2Operations, CollapsesKeepTheTriangleMeshCurvedAndCertified) { run_operations<2>(Kind::kCollapse, 10, 150); }
TEST(P2Operations, CollapsesKeepTheTetrahedralMeshCurvedAndCertified) { run_operations<3>(Kind::kCollapse, 6, 150); }
TEST(P2Operations, SwapsKeepTheTriangleMeshCurvedAndCertified) { run_operations<2>(Kind::kSwap, 10, 150); }
TEST(P2Operations, SwapsKeepTheTetrahedralMeshCurvedAndCertified) { run_operations<3>(Kind::kSwap, 6, 150); }
TEST(P2Operations, MovesKeepTheTriangleMeshCurvedAndCertified) { run_operations<2>(Kind::kMove, 10, 150); }
TEST(P2Operations, MovesKeepTheTetrahedralMeshCurvedAndCertified) { run_operations<3>(Kind::kMove, 6, 150); }

// A floor no element reaches: every operation inside the domain is refused by the curving step,
// after its vertex was added or moved, and each leaves the mesh byte for byte as it was.
template <int D>
void expect_refusals_leave_no_trace(int cells) {
  CurvedCase<D> curved(cells);
  Mesh<D>& mesh = curved.mesh;
  P2CavityOptions options;
  options.jacobian_floor = 1.5;
  P2Operations<D> operations(mesh, *curved.field, nullptr, options);
  std::mt19937 random(3);
  const auto before = mesh_bytes(mesh);
  for (Kind kind : {Kind::kSplit, Kind::kCollapse, Kind::kSwap, Kind::kMove})
    for (int i = 0; i < 20; ++i) {
      const CavityStatus status = try_operation(operations, mesh, kind, random);
      ASSERT_NE(status, CavityStatus::kAccepted);
      ASSERT_EQ(mesh_bytes(mesh), before) << "refused (" << to_string(status) << ") operation kind " << static_cast<int>(kind);
    }
  EXPECT_GT(operations.cavity_operator().counters().rejected_curving, 20);
}

TEST(P2Operations, RefusedTriangleOperationsLeaveTheMeshByteIdentical) { expect_refusals_leave_no_trace<2>(8); }
TEST(P2Operations, RefusedTetrahedralOperationsLeaveTheMeshByteIdentical) { expect_refusals_leave_no_trace<3>(4); }

template <int D>
double worst_quality_of(const P2Operations<D>& operations, const std::vector<Index>& elements) {
  double worst = 1e300;
  for (Index k : elements) worst = std::min(worst, operations.quality(k));
  return worst;
}

// Operations asked to beat a quality: with a bar no element reaches (the mean ratio is at most 1)
// each swap, move, split and collapse is refused, byte for byte; with the ball's own worst quality
// as the bar, each accepted move leaves a ball whose worst is above it.
template <int D>
void expect_quality_bar_kept(int cells) {
  CurvedCase<D> curved(cells);
  Mesh<D>& mesh = curved.mesh;
  P2Operations<D> operations(mesh, *curved.field, nullptr, {});
  std::mt19937 random(5);
  const auto before = mesh_bytes(mesh);
  for (int i = 0; i < 20; ++i) {
    const auto [a, b, c] = random_edge(mesh, random);
    for (CavityStatus status : {operations.swap_edge(a, b, c, {1.0}), operations.move_vertex(a, nearby_point(mesh, a, random), {1.0}),
                                operations.split_edge(a, b, nullptr, {1.0}), operations.collapse_edge(a, b, {1.0})}) {
      ASSERT_NE(status, CavityStatus::kAccepted);
      ASSERT_EQ(mesh_bytes(mesh), before) << to_string(status);
    }
  }
  EXPECT_GT(operations.cavity_operator().counters().rejected_quality, 10);
  int accepted = 0;
  std::vector<Index> ball;
  for (int i = 0; i < 40; ++i) {
    const Index v = random_edge(mesh, random)[0];
    collect_ball(mesh, v, ball);
    const double bar = worst_quality_of(operations, ball);
    if (operations.move_vertex(v, nearby_point(mesh, v, random), {bar}) != CavityStatus::kAccepted) continue;
    ++accepted;
    collect_ball(mesh, v, ball);
    EXPECT_GT(worst_quality_of(operations, ball), bar);
  }
  EXPECT_GT(accepted, 0);
}

TEST(P2Operations, TriangleOperationsKeepTheirQualityBar) { expect_quality_bar_kept<2>(8); }
TEST(P2Operations, TetrahedralOperationsKeepTheirQualityBar) { expect_quality_bar_kept<3>(4); }

// A swap given a list of apexes is the swap from the first apex of the list that the operator
// accepts: on two copies of the mesh, the list at once and its apexes one by one give the same
// verdicts and the same bytes.
template <int D>
void expect_apex_list_is_the_first_accepted(int cells) {
  CurvedCase<D> curved(cells);
  Mesh<D> copy = curved.mesh;
  P2Operations<D> at_once(curved.mesh, *curved.field, nullptr, {}), one_by_one(copy, *curved.field, nullptr, {});
  std::mt19937 random(11);
  std::vector<Index> shell, ring;
  int accepted = 0;
  for (int i = 0; i < 40; ++i) {
    const auto [a, b, c] = random_edge(curved.mesh, random);
    collect_shell(curved.mesh, a, b, shell);
    other_vertices<D>(curved.mesh, shell, a, b, ring);
    std::reverse(ring.begin(), ring.end());  // not the order the shell lists them in
    const CavityStatus status = at_once.swap_edge(a, b, ring);
    CavityStatus expected = CavityStatus::kNotStarShaped;
    for (std::size_t k = 0; k < ring.size() && expected != CavityStatus::kAccepted && expected != CavityStatus::kCrossesBoundary; ++k)
      expected = one_by_one.swap_edge(a, b, ring[k]);
    ASSERT_EQ(status, expected) << "swap " << i;
    ASSERT_EQ(mesh_bytes(curved.mesh), mesh_bytes(copy)) << "swap " << i;
    accepted += status == CavityStatus::kAccepted;
  }
  EXPECT_GT(accepted, 0);
}

TEST(P2Operations, TriangleSwapFromTheFirstAcceptedApex) { expect_apex_list_is_the_first_accepted<2>(8); }
TEST(P2Operations, TetrahedralSwapFromTheFirstAcceptedApex) { expect_apex_list_is_the_first_accepted<3>(4); }

// The P2 map of element k at barycentrics λ: Σ λ_i(2λ_i − 1) x_i + Σ_edges 4 λ_i λ_j x_ij.
template <int D>
Vec<D> p2_map(const Mesh<D>& mesh, Index k, const std::array<double, D + 1>& lambda) {
  const P2Element<D> element = gather_p2_element(mesh, k);
  Vec<D> x{};
  for (int i = 0; i <= D; ++i) x += lambda[i] * (2 * lambda[i] - 1) * element.vertex(i);
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    const auto ends = edge_vertices<D>(e);
    x += 4 * lambda[ends[0]] * lambda[ends[1]] * element.edge_node(e);
  }
  return x;
}

// A split falls back on the exact subdivision of its shell: each new edge's fallback node is the old
// shell's P2 map at the edge's reference midpoint (the new vertex at the middle of a and b), so the
// new elements with their fallback nodes are the old ones' geometry, cut in two.
template <int D>
void expect_split_fallback_is_the_old_geometry(int cells) {
  CurvedCase<D> curved(cells);
  Mesh<D>& mesh = curved.mesh;
  P2Operations<D> operations(mesh, *curved.field, nullptr, P2CavityOptions{});
  std::mt19937 random(5);
  std::vector<Index> shell;
  int accepted = 0;
  for (int i = 0; i < 40; ++i) {
    const auto [a, b, third] = random_edge(mesh, random);
    const Mesh<D> old = mesh;
    collect_shell(old, a, b, shell);
    Index m = kNoIndex;
    if (operations.split_edge(a, b, &m) != CavityStatus::kAccepted) continue;
    ++accepted;
    for (const auto& edge : operations.cavity_operator().curved_edges()) {
      const Index c = edge.a == m ? edge.b : edge.a;
      ASSERT_TRUE(edge.inner && (edge.a == m || edge.b == m));
      // Barycentrics of the edge's midpoint in an old shell element holding c: m is (a + b)/2.
      const auto holds_c = std::find_if(shell.begin(), shell.end(), [&](Index k) { return local_vertex(old, k, c) >= 0; });
      ASSERT_NE(holds_c, shell.end());
      std::array<double, D + 1> lambda{};
      lambda[local_vertex(old, *holds_c, a)] += 0.25;
      lambda[local_vertex(old, *holds_c, b)] += 0.25;
      lambda[local_vertex(old, *holds_c, c)] += 0.5;
      const Vec<D> expected = p2_map(old, *holds_c, lambda);
      EXPECT_LE(norm(edge.fallback - expected), 1e-12 * norm(old.vertex(b) - old.vertex(a))) << "new edge to " << c;
    }
  }
  EXPECT_GT(accepted, 10);
}

TEST(P2Operations, TriangleSplitsFallBackOnTheExactSubdivision) { expect_split_fallback_is_the_old_geometry<2>(8); }
TEST(P2Operations, TetrahedralSplitsFallBackOnTheExactSubdivision) { expect_split_fallback_is_the_old_geometry<3>(4); }

// Boundary nodes proposed by a "geometry" that bulges each boundary edge outward by 2% of its
// length; a proposal applied in full is consumed and remembered.
template <int D>
class BulgingBoundary : public BoundaryNodeSource<D> {
 public:
  explicit BulgingBoundary(const Mesh<D>& mesh) {
    Vec<D> center;
    for (int i = 0; i < D; ++i) center[i] = 0.5;
    for (const auto& facet : mesh.facets())
      for (int i = 0; i < D; ++i) {
        const Index a = facet[i], b = facet[(i + 1) % D];
        const Vec<D> middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
        const Vec<D> outward = middle - center;
        waiting_[Mesh<D>::edge_key(a, b)] = middle + 0.02 * norm(mesh.vertex(b) - mesh.vertex(a)) / norm(outward) * outward;
      }
  }
  std::optional<Vec<D>> proposal(Index a, Index b) const override {
    const auto found = waiting_.find(Mesh<D>::edge_key(a, b));
    return found == waiting_.end() ? std::nullopt : std::optional<Vec<D>>(found->second);
  }
  void consume(Index a, Index b) override {
    const auto key = Mesh<D>::edge_key(a, b);
    placed_[key] = waiting_.at(key);
    waiting_.erase(key);
  }
  const std::map<std::uint64_t, Vec<D>>& placed() const { return placed_; }

 private:
  std::map<std::uint64_t, Vec<D>> waiting_, placed_;
};

// Interior operations next to the boundary give its edges their proposed nodes (on the geometry)
// as the reinsertion does, certified with the rest.
template <int D>
void expect_boundary_nodes_on_the_geometry(int cells) {
  Mesh<D> mesh = CurvedCase<D>::unit_mesh(cells);
  MetricField<D> field(mesh, std::vector<SymMat<D>>(static_cast<std::size_t>(mesh.vertex_count()), SymMat<D>::identity() * 100.0));
  mesh.make_p2();
  BulgingBoundary<D> boundary(mesh);
  const P2CavityOptions options;
  P2Operations<D> operations(mesh, field, &boundary, options);
  std::mt19937 random(11);
  for (int i = 0; i < 100; ++i)
    for (Kind kind : {Kind::kSplit, Kind::kMove}) try_operation(operations, mesh, kind, random);
  EXPECT_GT(boundary.placed().size(), 10u);
  for (const auto& [key, node] : boundary.placed()) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    EXPECT_EQ(mesh.edge_node(mesh.find_edge(a, b)), node);
  }
  EXPECT_TRUE(every_element_certified(mesh, options.jacobian_floor));
}

TEST(P2Operations, TriangleOperationsPutBoundaryNodesOnTheGeometry) { expect_boundary_nodes_on_the_geometry<2>(6); }
TEST(P2Operations, TetrahedralOperationsPutBoundaryNodesOnTheGeometry) { expect_boundary_nodes_on_the_geometry<3>(3); }

// A point at `height` times v's distance from the centroid of `face` (vertices), on v's side.
template <int D>
Vec<D> toward_face(const Mesh<D>& mesh, Index v, const std::vector<Index>& face, double height) {
  Vec<D> centroid{};
  for (Index w : face) centroid += (1.0 / D) * mesh.vertex(w);
  return centroid + height * (mesh.vertex(v) - centroid);
}

template <int D>
double worst_straight_quality_of_ball(const Mesh<D>& mesh, const P2Operations<D>& operations, Index v) {
  std::vector<Index> ball;
  collect_ball(mesh, v, ball);
  double worst = 1e300;
  for (Index k : ball) worst = std::min(worst, operations.straight_quality(k));
  return worst;
}

// A move of v near the plane of a face of its ball, which makes nearly flat straight simplices
// (valid curved elements: the mesh is straight), is refused under the straight quality floor and
// accepted without it; from there, the floor is the cavity's own worst: a move that flattens them
// further is refused, one that raises them accepted.
template <int D>
void expect_near_flat_straight_elements_refused(int cells) {
  Mesh<D> mesh = CurvedCase<D>::unit_mesh(cells);
  SymMat<D> metric;
  for (int i = 0; i < D; ++i) metric(i, i) = cells * cells;
  const MetricField<D> field(mesh, std::vector<SymMat<D>>(static_cast<std::size_t>(mesh.vertex_count()), metric));
  mesh.make_p2();
  P2CavityOptions floored;
  floored.positive_straight_elements = true;
  floored.straight_quality_floor = 0.1;
  P2CavityOptions unfloored = floored;
  unfloored.straight_quality_floor = 0;
  const Index v = volume_vertices(mesh).front();
  std::vector<Index> ball, face;
  collect_ball(mesh, v, ball);
  for (Index w : mesh.element(ball.front()))
    if (w != v) face.push_back(w);
  const Vec<D> near_flat = toward_face(mesh, v, face, 0.005);
  {
    P2Operations<D> operations(mesh, field, nullptr, floored);
    const auto before = mesh_bytes(mesh);
    EXPECT_EQ(operations.move_vertex(v, near_flat), CavityStatus::kFlatStraightElement);
    EXPECT_EQ(mesh_bytes(mesh), before);
    EXPECT_EQ(operations.cavity_operator().counters().rejected_straight_quality, 1);
  }
  P2Operations<D> operations(mesh, field, nullptr, unfloored);
  ASSERT_EQ(operations.move_vertex(v, near_flat), CavityStatus::kAccepted);
  const double made = worst_straight_quality_of_ball(mesh, operations, v);
  EXPECT_GT(made, 0);
  EXPECT_LT(made, 0.05);
  EXPECT_TRUE(every_element_certified(mesh, floored.jacobian_floor));
  P2Operations<D> from_flat(mesh, field, nullptr, floored);
  EXPECT_EQ(from_flat.move_vertex(v, toward_face(mesh, v, face, 0.5)), CavityStatus::kFlatStraightElement);
  ASSERT_EQ(from_flat.move_vertex(v, toward_face(mesh, v, face, 2.0)), CavityStatus::kAccepted);
  EXPECT_GT(worst_straight_quality_of_ball(mesh, from_flat, v), made);
}

TEST(P2Operations, TriangleOperationsRefuseNearFlatStraightElements) { expect_near_flat_straight_elements_refused<2>(4); }
TEST(P2Operations, TetrahedralOperationsRefuseNearFlatStraightElements) { expect_near_flat_straight_elements_refused<3>(3); }

// The decision figures: in a constant metric, a straight edge's curved length is its metric length
// and a straight element's curved quality its metric mean ratio; bending the edge lengthens it.
TEST(P2Operations, CurvedLengthAndQualityAreTheP1FiguresOnStraightElements) {
  Mesh<2> mesh = generate_square(4);
  SymMat<2> metric;
  metric(0, 0) = 9;
  metric(0, 1) = 2;
  metric(1, 1) = 4;
  MetricField<2> field(mesh, std::vector<SymMat<2>>(static_cast<std::size_t>(mesh.vertex_count()), metric));
  mesh.make_p2();
  P2Operations<2> operations(mesh, field, nullptr, P2CavityOptions{});
  const auto [a, b] = mesh.edge_vertices(7);
  const Vec2 edge = mesh.vertex(b) - mesh.vertex(a);
  EXPECT_NEAR(operations.edge_length(a, b), std::sqrt(quadratic_form(metric, edge)), 1e-12);
  SimplexPoints<2> points;
  for (int i = 0; i < 3; ++i) points[i] = mesh.vertex(mesh.element(3)[i]);
  EXPECT_NEAR(operations.quality(3), metric_mean_ratio<2>(points, metric), 1e-12);
  mesh.edge_node(7) += 0.1 * Vec2{{-edge[1], edge[0]}};
  EXPECT_GT(operations.edge_length(a, b), std::sqrt(quadratic_form(metric, edge)) * 1.001);
}

// Two copies of a curved mesh under the same operations, one with a memo: after each accepted
// operation, and after a node alone is moved (as a correction moves one), every edge length,
// straight length and curved quality the memo gives is bit for bit what the copy without it
// computes. A digest that left out an input would return a stale value.
template <int D>
void expect_memo_returns_what_is_computed(int cells) {
  CurvedCase<D> remembering(cells), computing(cells);
  DigestMemo memo;
  P2Operations<D> with_memo(remembering.mesh, *remembering.field, nullptr, {}, &memo);
  P2Operations<D> without(computing.mesh, *computing.field, nullptr, {});
  std::mt19937 random_a(11), random_b(11), nudge(13);
  int accepted = 0;
  for (int i = 0; i < 60; ++i) {
    const Kind kind = std::array{Kind::kMove, Kind::kSplit, Kind::kSwap, Kind::kCollapse}[i % 4];
    const CavityStatus status = try_operation(with_memo, remembering.mesh, kind, random_a);
    ASSERT_EQ(try_operation(without, computing.mesh, kind, random_b), status);
    if (status != CavityStatus::kAccepted) continue;
    ++accepted;
    const auto [a, b, c] = random_edge(remembering.mesh, nudge);
    for (Mesh<D>* copy : {&remembering.mesh, &computing.mesh}) {
      const Index e = copy->find_edge(a, b);
      copy->edge_node(e) += 0.01 * (copy->vertex(c) - copy->edge_node(e));
    }
    const Mesh<D>& mesh = remembering.mesh;
    for (Index e = 0; e < mesh.edge_count(); ++e) {
      const auto& ends = mesh.edge_vertices(e);
      if (ends[0] == kNoIndex) continue;
      ASSERT_EQ(with_memo.edge_length(ends[0], ends[1]), without.edge_length(ends[0], ends[1])) << "operation " << i << ", edge " << e;
      ASSERT_EQ(with_memo.straight_length(ends[1], ends[0]), without.straight_length(ends[1], ends[0])) << "operation " << i;
    }
    for (Index k = 0; k < mesh.element_count(); ++k) ASSERT_EQ(with_memo.quality(k), without.quality(k)) << "operation " << i;
  }
  EXPECT_GT(accepted, 10);
}

TEST(P2Operations, TriangleMeasuresFromTheMemoAreTheComputedOnes) { expect_memo_returns_what_is_computed<2>(8); }
TEST(P2Operations, TetrahedralMeasuresFromTheMemoAreTheComputedOnes) { expect_memo_returns_what_is_computed<3>(4); }

}  // namespace
}  // namespace hocav
