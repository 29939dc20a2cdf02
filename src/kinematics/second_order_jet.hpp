// Second-order forward-mode automatic differentiation: a value with its gradient and Hessian
// with respect to N local parameters. Connector kinematics evaluates the angle measures on jets
// to get B_i and H_i exactly (connection-types.md §3.7) without hand-written second derivatives.
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace clinch {

template <int N>
struct Jet {
  using Gradient = Eigen::Matrix<double, N, 1>;
  using Hessian = Eigen::Matrix<double, N, N>;

  double v = 0;
  Gradient g = Gradient::Zero();
  Hessian h = Hessian::Zero();

  static Jet constant(double value) {
    Jet jet;
    jet.v = value;
    return jet;
  }
};

inline double value_of(double x) { return x; }
template <int N>
double value_of(const Jet<N>& x) {
  return x.v;
}

// f(x) from f, f′ and f″ at x.v (chain rule to second order).
template <int N>
Jet<N> chain(const Jet<N>& x, double f, double f1, double f2) {
  Jet<N> r;
  r.v = f;
  r.g = f1 * x.g;
  r.h = f1 * x.h + f2 * x.g * x.g.transpose();
  return r;
}

// f(x, y) from its value and partial derivatives up to second order.
template <int N>
Jet<N> chain(const Jet<N>& x, const Jet<N>& y, double f, double fx, double fy, double fxx,
             double fxy, double fyy) {
  Jet<N> r;
  r.v = f;
  r.g = fx * x.g + fy * y.g;
  const Eigen::Matrix<double, N, N> cross = x.g * y.g.transpose();
  r.h = fx * x.h + fy * y.h + fxx * x.g * x.g.transpose() + fxy * (cross + cross.transpose()) +
        fyy * y.g * y.g.transpose();
  return r;
}

template <int N>
Jet<N> operator+(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  r.h = a.h + b.h;
  return r;
}
template <int N>
Jet<N> operator-(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  r.h = a.h - b.h;
  return r;
}
template <int N>
Jet<N> operator-(const Jet<N>& a) {
  Jet<N> r;
  r.v = -a.v;
  r.g = -a.g;
  r.h = -a.h;
  return r;
}
template <int N>
Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  const Eigen::Matrix<double, N, N> cross = a.g * b.g.transpose();
  r.h = a.v * b.h + b.v * a.h + cross + cross.transpose();
  return r;
}
template <int N>
Jet<N> operator*(const Jet<N>& a, double s) {
  Jet<N> r;
  r.v = a.v * s;
  r.g = a.g * s;
  r.h = a.h * s;
  return r;
}
template <int N>
Jet<N> operator*(double s, const Jet<N>& a) {
  return a * s;
}
template <int N>
Jet<N> operator+(const Jet<N>& a, double s) {
  Jet<N> r = a;
  r.v += s;
  return r;
}
template <int N>
Jet<N> operator+(double s, const Jet<N>& a) {
  return a + s;
}
template <int N>
Jet<N> operator-(const Jet<N>& a, double s) {
  return a + (-s);
}
template <int N>
Jet<N> operator-(double s, const Jet<N>& a) {
  return (-a) + s;
}
template <int N>
Jet<N> operator/(double s, const Jet<N>& a) {
  const double inv = 1.0 / a.v;
  return chain(a, s * inv, -s * inv * inv, 2.0 * s * inv * inv * inv);
}
template <int N>
Jet<N> operator/(const Jet<N>& a, const Jet<N>& b) {
  return a * (1.0 / b);
}
template <int N>
Jet<N> operator/(const Jet<N>& a, double s) {
  return a * (1.0 / s);
}

template <int N>
Jet<N> sqrt(const Jet<N>& x) {
  const double s = std::sqrt(x.v);
  return chain(x, s, 0.5 / s, -0.25 / (s * x.v));
}
template <int N>
Jet<N> sin(const Jet<N>& x) {
  const double s = std::sin(x.v);
  return chain(x, s, std::cos(x.v), -s);
}
template <int N>
Jet<N> cos(const Jet<N>& x) {
  const double c = std::cos(x.v);
  return chain(x, c, -std::sin(x.v), -c);
}
template <int N>
Jet<N> asin(const Jet<N>& x) {
  const double q = 1.0 - x.v * x.v;
  const double inv = 1.0 / std::sqrt(q);
  return chain(x, std::asin(x.v), inv, x.v * inv / q);
}
template <int N>
Jet<N> acos(const Jet<N>& x) {
  const double q = 1.0 - x.v * x.v;
  const double inv = 1.0 / std::sqrt(q);
  return chain(x, std::acos(x.v), -inv, -x.v * inv / q);
}
template <int N>
Jet<N> atan2(const Jet<N>& y, const Jet<N>& x) {
  const double r2 = x.v * x.v + y.v * y.v;
  const double r4 = r2 * r2;
  return chain(x, y, std::atan2(y.v, x.v), -y.v / r2, x.v / r2, 2.0 * x.v * y.v / r4,
               (y.v * y.v - x.v * x.v) / r4, -2.0 * x.v * y.v / r4);
}

}  // namespace clinch
