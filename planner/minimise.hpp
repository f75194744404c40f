#pragma once
// planner/minimise: a one-dimensional minimum by golden-section search, for the near-cusp
// searches of curves (planner/spline.cpp, planner/path_bezier.cpp).
//
// Inputs: a function f on [lo, hi] with one minimum there. Output: the midpoint of the final
// bracket, after at most `iterations` steps or once the bracket is below kParameterWidth.

#include "core/tolerance.hpp"

namespace ncsim::planner {

template <typename F>
double golden_section_minimum(const F& f, double lo, double hi, int iterations) {
  constexpr double kGolden = 0.6180339887498949;  // (sqrt(5) - 1) / 2
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < iterations && hi - lo > kParameterWidth; ++it) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace ncsim::planner
