// jerk/root.hpp: the bracketed root solver of the level searches (Newton with a slope where one
// is known, regula falsi otherwise); it must always answer the feasible side (g <= 0).

#include "jerk/root.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>

using ncsim::jerk::detail::solve_with_slope;

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// g(x) = x^2 - 2 (convex, increasing on [0, 2]); counts its evaluations.
struct Square {
  int calls = 0;
  bool with_slope = true;
  double slope_scale = 1.0;  // != 1: a wrong slope (the safeguard must still converge)
  double operator()(double x, double& slope) {
    ++calls;
    slope = with_slope ? slope_scale * 2.0 * x : kNan;
    return x * x - 2.0;
  }
};

}  // namespace

TEST_CASE("the root solver answers the feasible side of the root, in few steps with a slope") {
  const double tol = 1e-14;
  for (const bool with_slope : {true, false}) {
    CAPTURE(with_slope);
    Square g;
    g.with_slope = with_slope;
    const double x = solve_with_slope(0.0, 2.0, -2.0, 2.0, with_slope ? 0.0 : kNan,
                                      with_slope ? 4.0 : kNan, tol, std::ref(g));
    CHECK(x * x - 2.0 <= 0.0);
    CHECK(x == doctest::Approx(std::sqrt(2.0)).epsilon(1e-14));
    if (with_slope) CHECK(g.calls <= 6);
    CHECK(g.calls <= 12);
  }
}

TEST_CASE("a wrong slope only slows the root solver down: every step stays in the bracket") {
  for (const double scale : {1e-3, 0.5, 3.0, 1e3}) {
    CAPTURE(scale);
    Square g;
    g.slope_scale = scale;
    const double x = solve_with_slope(0.0, 2.0, -2.0, 2.0, 0.0, scale * 4.0, 1e-14, std::ref(g));
    CHECK(x * x - 2.0 <= 0.0);
    CHECK(x == doctest::Approx(std::sqrt(2.0)).epsilon(1e-13));
    CHECK(g.calls < 200);
  }
}

TEST_CASE("the root solver crosses a kink (a ramp reaching its limit) without losing the bracket") {
  // g = x - 1.5 below x = 1, 3 (x - 1) - 0.5 above: root 1 + 1/6; the slope jumps at the kink.
  int calls = 0;
  const auto g = [&](double x, double& slope) {
    ++calls;
    slope = x < 1.0 ? 1.0 : 3.0;
    return x < 1.0 ? x - 1.5 : 3.0 * (x - 1.0) - 0.5;
  };
  const double x = solve_with_slope(0.0, 3.0, -1.5, 5.5, 1.0, 3.0, 1e-14, g);
  CHECK(x == doctest::Approx(1.0 + 1.0 / 6.0).epsilon(1e-14));
  CHECK(3.0 * (x - 1.0) - 0.5 <= 0.0);
  CHECK(calls <= 8);
}

TEST_CASE("with the curvature, a quadratic's root is found by one step, on the feasible side") {
  // g = x^2 - 2 with slope and curvature: the quadratic model is g itself.
  using ncsim::jerk::detail::solve_with_curve;
  const double tol = 1e-14;
  int calls = 0;
  const auto g = [&](double x, double& slope, double& curve) {
    ++calls;
    slope = 2.0 * x;
    curve = 2.0;
    return x * x - 2.0;
  };
  const double x = solve_with_curve(0.0, 2.0, -2.0, 2.0, 0.0, 4.0, 2.0, 2.0, tol, g);
  CHECK(x * x - 2.0 <= 0.0);
  CHECK(x * x - 2.0 >= -tol);
  CHECK(calls == 1);
  // A wrong curvature only costs steps (the step stays in the bracket, Newton takes over).
  for (const double c : {-50.0, 0.0, 0.1, 40.0}) {
    CAPTURE(c);
    calls = 0;
    const auto g_wrong = [&](double x_, double& slope, double& curve) {
      ++calls;
      slope = 2.0 * x_;
      curve = c;
      return x_ * x_ - 2.0;
    };
    const double y = solve_with_curve(0.0, 2.0, -2.0, 2.0, 0.0, 4.0, c, c, tol, g_wrong);
    CHECK(y * y - 2.0 <= 0.0);
    CHECK(y == doctest::Approx(std::sqrt(2.0)).epsilon(1e-14));
    CHECK(calls < 200);
  }
}
