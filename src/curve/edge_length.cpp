#include "curve/edge_length.hpp"

#include <cmath>

#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

// The P2 Lagrange basis along the edge (docs/method.md §4).
struct EdgeBasis {
  double a, middle, b;
};
EdgeBasis edge_basis(double t) { return {(1 - t) * (1 - 2 * t), 4 * t * (1 - t), t * (2 * t - 1)}; }

}  // namespace

template <int D>
EdgeEndpoint<D> edge_endpoint(const Vec<D>& position, const SymMat<D>& log_metric) {
  return {position, log_metric, exp_sym(log_metric)};
}

template <int D>
EdgeLengthFunction<D>::EdgeLengthFunction(const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const QuadratureRule& rule)
    : a_(a), b_(b), rule_(rule) {}

template <int D>
const ExpSpectrum<D>& EdgeLengthFunction<D>::spectrum_at(std::size_t q, const SymMat<D>& log_node, bool at_same_point,
                                                         EdgeLengthScratch<D>& scratch, LazySlot<ExpSpectrum<D>>& uncached) const {
  if (at_same_point) return *scratch.spectrum[q];
  const EdgeBasis phi = edge_basis(rule_.nodes[q]);
  if (q < kCachedNodes) scratch.frechet[q].reset();
  LazySlot<ExpSpectrum<D>>& spectrum = q < kCachedNodes ? scratch.spectrum[q] : uncached;
  return spectrum.emplace(exp_spectrum(phi.a * a_.log_metric + phi.middle * log_node + phi.b * b_.log_metric));
}

template <int D>
const ExpFrechet<D>& EdgeLengthFunction<D>::frechet_at(std::size_t q, const ExpSpectrum<D>& spectrum, EdgeLengthScratch<D>& scratch,
                                                       LazySlot<ExpFrechet<D>>& uncached) const {
  LazySlot<ExpFrechet<D>>& frechet = q < kCachedNodes ? scratch.frechet[q] : uncached;
  if (!frechet) frechet.emplace(spectrum);  // spectrum_at resets the cached one when it decomposes anew
  return *frechet;
}

template <int D>
void EdgeLengthFunction<D>::remember(const SymMat<D>& log_node, EdgeLengthScratch<D>& scratch) const {
  scratch.log_node = log_node;
  scratch.owner = rule_.nodes.size() <= kCachedNodes ? this : nullptr;
}

template <int D>
EdgeLengthValue<D> EdgeLengthFunction<D>::evaluate(const Vec<D>& node, const SymMat<D>& log_node,
                                                   const std::array<SymMat<D>, D>& log_node_gradient, Order order,
                                                   EdgeLengthScratch<D>& scratch) const {
  // Accumulated in locals and returned whole: a zero-initialized result object in memory costs a block clear.
  double length = 0;
  Vec<D> gradient{}, node_gradient{};
  SymMat<D> hessian{}, log_node_gradient_part{};
  const bool at_same_point = same_point(scratch, log_node);
  for (std::size_t q = 0; q < rule_.nodes.size(); ++q) {
    const double t = rule_.nodes[q], w = rule_.weights[q];
    const EdgeBasis phi = edge_basis(t);
    const double du = 4 * (1 - 2 * t);  // ∂γ'(t)/∂X = du · I
    const Vec<D> u = (4 * t - 3) * a_.position + du * node + (4 * t - 1) * b_.position;

    // g = uᵀ E u; ∂_i g = 2 du (E u)_i + uᵀ ∂_iE u; ∂_ij g = 2 du² E_ij + 2 du ((∂_jE u)_i + (∂_iE u)_j) + uᵀ ∂_ijE u.
    double g;
    Vec<D> dg{}, dg_dnode{};     // ∂g/∂X, and its part at fixed T
    SymMat<D> d2g{}, dg_dlog{};  // ∂²g/∂X², ∂g/∂L^L
    if (phi.middle == 0) {
      const SymMat<D>& e = t == 0 ? a_.metric : b_.metric;  // φ_M = 0 only at the ends
      const Vec<D> eu = e * u;
      g = dot(u, eu);
      if (order != Order::kValue) dg = dg_dnode = (2 * du) * eu;
      if (order == Order::kHessian) d2g = (2 * du * du) * e;
    } else {
      LazySlot<ExpSpectrum<D>> uncached;
      const ExpSpectrum<D>& spectrum = spectrum_at(q, log_node, at_same_point, scratch, uncached);
      // In the eigenbasis: keeps g relatively accurate along the small eigenvalues (high anisotropy).
      g = exp_squared_length(spectrum, u);
      if (order != Order::kValue) {
        LazySlot<ExpFrechet<D>> frechet_uncached;
        const ExpFrechet<D>& exp_t = frechet_at(q, spectrum, scratch, frechet_uncached);
        // uᵀ Dexp[H] u = <Dexp[u uᵀ], H> (Dexp is self-adjoint): one derivative serves every direction.
        const SymMat<D> adjoint = exp_t.squared_length_gradient(u);
        std::array<SymMat<D>, D> directions;
        for (int i = 0; i < D; ++i) {
          directions[i] = phi.middle * log_node_gradient[i];
          dg[i] = frobenius_dot(adjoint, directions[i]);
        }
        dg_dlog = phi.middle * adjoint;
        // du = 0 at t = 1/2 (the middle node of the 3-point rules): the tangent does not depend on X there.
        if (du != 0) dg_dnode = (2 * du) * (exp_t.value() * u);
        dg += dg_dnode;
        if (order == Order::kHessian) {
          d2g = exp_t.squared_length_hessian(directions, u);
          if (du != 0) {
            std::array<Vec<D>, D> de_u;  // ∂_iE u
            for (int i = 0; i < D; ++i) de_u[i] = exp_t.derivative(directions[i]) * u;
            for (int i = 0; i < D; ++i)
              for (int j = 0; j <= i; ++j) d2g(i, j) += 2 * du * du * exp_t.value()(i, j) + 2 * du * (de_u[j][i] + de_u[i][j]);
          }
        }
      }
    }
    // ℓ = Σ w sqrt(g): ∂ℓ = w ∂g / (2√g), ∂²ℓ = w (∂²g / (2√g) − ∂g ∂gᵀ / (4 g^{3/2})).
    const double root = std::sqrt(g);
    length += w * root;
    if (order == Order::kValue || root == 0) continue;
    gradient += (w / (2 * root)) * dg;
    node_gradient += (w / (2 * root)) * dg_dnode;
    log_node_gradient_part += (w / (2 * root)) * dg_dlog;
    if (order == Order::kHessian)
      for (int i = 0; i < D; ++i)
        for (int j = 0; j <= i; ++j) hessian(i, j) += w * (d2g(i, j) / (2 * root) - dg[i] * dg[j] / (4 * g * root));
  }
  remember(log_node, scratch);
  return {length, gradient, hessian, node_gradient, log_node_gradient_part};
}

template <int D>
double EdgeLengthFunction<D>::length(const Vec<D>& node, const SymMat<D>& log_node, EdgeLengthScratch<D>& scratch) const {
  return evaluate(node, log_node, {}, Order::kValue, scratch).length;
}

template <int D>
double EdgeLengthFunction<D>::curvature(const Vec<D>& node, const SymMat<D>& log_node, const Vec<D>& d,
                                        const SymMat<D>& log_node_derivative, EdgeLengthScratch<D>& scratch) const {
  // Along the line, g(s) = u(s)ᵀ E(s) u(s) with u' = du·d and E' = Dexp[φ_M δ]:
  //   g' = 2 du dᵀE u + uᵀ Dexp[φ_M δ] u,  g'' = 2 du² dᵀE d + 4 du dᵀ Dexp[φ_M δ] u + uᵀ D²exp[φ_M δ, φ_M δ] u.
  const bool at_same_point = same_point(scratch, log_node);
  double result = 0;
  for (std::size_t q = 0; q < rule_.nodes.size(); ++q) {
    const double t = rule_.nodes[q], w = rule_.weights[q];
    const EdgeBasis phi = edge_basis(t);
    const double du = 4 * (1 - 2 * t);
    const Vec<D> u = (4 * t - 3) * a_.position + du * node + (4 * t - 1) * b_.position;
    double g, dg, d2g;
    if (phi.middle == 0) {
      const SymMat<D>& e = t == 0 ? a_.metric : b_.metric;
      const Vec<D> eu = e * u;
      g = dot(u, eu);
      dg = 2 * du * dot(d, eu);
      d2g = 2 * du * du * dot(d, e * d);
    } else {
      LazySlot<ExpSpectrum<D>> uncached;
      LazySlot<ExpFrechet<D>> frechet_uncached;
      const ExpFrechet<D>& exp_t = frechet_at(q, spectrum_at(q, log_node, at_same_point, scratch, uncached), scratch, frechet_uncached);
      const SymMat<D> direction = phi.middle * log_node_derivative;
      const auto along = exp_t.squared_length_derivatives(direction, u);
      g = exp_t.squared_length(u);
      dg = along.first;
      d2g = along.second;
      if (du != 0) {
        dg += 2 * du * dot(d, exp_t.value() * u);
        d2g += 2 * du * du * dot(d, exp_t.value() * d) + 4 * du * dot(d, exp_t.derivative(direction) * u);
      }
    }
    const double root = std::sqrt(g);
    if (root == 0) continue;
    result += w * (d2g / (2 * root) - dg * dg / (4 * g * root));
  }
  remember(log_node, scratch);
  return result;
}

template EdgeEndpoint<2> edge_endpoint(const Vec<2>&, const SymMat<2>&);
template EdgeEndpoint<3> edge_endpoint(const Vec<3>&, const SymMat<3>&);
template class EdgeLengthFunction<2>;
template class EdgeLengthFunction<3>;

}  // namespace hocav
