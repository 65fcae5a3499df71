#pragma once
// Brent's method for a one-dimensional minimum (Brent 1973, "Algorithms for
// minimization without derivatives", ch. 5): golden-section steps, replaced
// by parabolic interpolation where the parabola is trusted.

#include <cmath>

namespace tessella::growth {

template <typename F>
double brentMinimize(F&& f, double a, double b, double tol, int max_iterations) {
  constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt 5) / 2
  if (a > b) std::swap(a, b);
  double x = a + kGolden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    const double m = 0.5 * (a + b);
    const double tol1 = 0.5 * tol + 1e-15 * std::abs(x), tol2 = 2.0 * tol1;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;  // bracket narrower than tol
    bool golden = true;
    if (std::abs(e) > tol1) {
      // Parabola through (v, fv), (w, fw), (x, fx).
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double e_prev = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * e_prev) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < m ? tol1 : -tol1;
        golden = false;
      }
    }
    if (golden) {
      e = (x < m ? b : a) - x;
      d = kGolden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + (d > 0 ? tol1 : -tol1);
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w; fv = fw;
      w = x; fw = fx;
      x = u; fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w; fv = fw;
        w = u; fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u; fv = fu;
      }
    }
  }
  return x;
}

}  // namespace tessella::growth
