// Small fixed-size vectors of doubles (points and directions in 2D and 3D).
#pragma once

#include <array>
#include <cmath>

namespace hocav {

template <int D>
struct Vec {
  std::array<double, D> c{};

  constexpr double& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  constexpr double operator[](int i) const { return c[static_cast<std::size_t>(i)]; }

  constexpr Vec& operator+=(const Vec& o) {
    for (int i = 0; i < D; ++i) (*this)[i] += o[i];
    return *this;
  }
  constexpr Vec& operator-=(const Vec& o) {
    for (int i = 0; i < D; ++i) (*this)[i] -= o[i];
    return *this;
  }
  constexpr Vec& operator*=(double s) {
    for (int i = 0; i < D; ++i) (*this)[i] *= s;
    return *this;
  }
  friend constexpr Vec operator+(Vec a, const Vec& b) { return a += b; }
  friend constexpr Vec operator-(Vec a, const Vec& b) { return a -= b; }
  friend constexpr Vec operator*(Vec a, double s) { return a *= s; }
  friend constexpr Vec operator*(double s, Vec a) { return a *= s; }
  friend constexpr Vec operator-(Vec a) { return a *= -1.0; }
  friend constexpr bool operator==(const Vec&, const Vec&) = default;
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

template <int D>
constexpr double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

template <int D>
inline double norm(const Vec<D>& a) {
  return std::sqrt(dot(a, a));
}

constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

constexpr double determinant(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
constexpr double determinant(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

template <int D>
inline bool is_finite(const Vec<D>& a) {
  for (int i = 0; i < D; ++i)
    if (!std::isfinite(a[i])) return false;
  return true;
}

}  // namespace hocav
