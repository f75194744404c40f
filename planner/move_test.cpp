// Boundary checks of the planner's inputs: misuse throws and names the field and value.

#include "planner/move.hpp"

#include <doctest/doctest.h>

#include <array>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using namespace ncsim::planner;

std::string message_of(const Move& move) {
  try {
    validate(move);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

Move good_move() {
  Move m;
  m.end[0] = 10.0;
  m.feed = 20.0;
  m.line = 7;
  return m;
}

}  // namespace

TEST_CASE("a well-formed move passes") {
  CHECK(message_of(good_move()).empty());
}

TEST_CASE("a feed move without a positive feed is misuse naming the line and field") {
  Move m = good_move();
  m.feed = 0.0;
  const std::string msg = message_of(m);
  CHECK(msg.find("line 7") != std::string::npos);
  CHECK(msg.find("feed") != std::string::npos);
  m.rapid = true;  // G00 needs no feed
  CHECK(message_of(m).empty());
}

TEST_CASE("arc plane axes must be distinct axes in use, the radius positive") {
  Move m = good_move();
  m.arc = Arc{0, 0, 0.0, 0.0, false, false};
  CHECK(message_of(m).find("plane axes") != std::string::npos);
  m.arc = Arc{0, 5, 0.0, 0.0, false, false};
  CHECK(message_of(m).find("plane axes") != std::string::npos);
  m.arc = Arc{0, 1, 0.0, 0.0, false, false};  // start at the centre
  CHECK(message_of(m).find("radius") != std::string::npos);
}

TEST_CASE("non-finite positions, negative E and PATH_DEV <= 0 are rejected") {
  Move m = good_move();
  m.end[1] = std::numeric_limits<double>::quiet_NaN();
  CHECK(message_of(m).find("end[1]") != std::string::npos);
  m = good_move();
  m.end_feed = -1.0;
  CHECK(message_of(m).find("end_feed") != std::string::npos);
  m = good_move();
  m.contour = Contour::tolerance;
  m.path_dev = 0.0;
  CHECK(message_of(m).find("PATH_DEV") != std::string::npos);
}

TEST_CASE("DIST distances must be positive; the contour bound is the larger of them") {
  Move m = good_move();
  m.contour = Contour::distance;
  m.pre_dist = 2.0;
  m.post_dist = 0.5;
  CHECK_NOTHROW(validate(m));
  CHECK(contoured(m));
  CHECK(contour_bound(m) == 2.0);
  m.post_dist = 0.0;
  CHECK(message_of(m).find("POST_DIST") != std::string::npos);
  m.post_dist = 0.5;
  m.pre_dist = -1.0;
  CHECK(message_of(m).find("PRE_DIST") != std::string::npos);
  m.contour = Contour::tolerance;  // DEV reads only PATH_DEV
  CHECK_NOTHROW(validate(m));
  CHECK(contour_bound(m) == m.path_dev);
  m.contour = Contour::none;
  CHECK_FALSE(contoured(m));
  CHECK(contour_bound(m) == 0.0);
}

TEST_CASE("axis limits must be positive; the VELOJUMP factor may be 0") {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 100.0;
  ax.a_max = ax.d_max = 1000.0;
  ax.j_max = 1e5;
  ax.c0 = 0.0;
  std::array<AxisLimits, 2> limits = {ax, ax};
  CHECK_NOTHROW(validate(limits));
  limits[1].j_max = -1.0;
  CHECK_THROWS_WITH_AS(validate(limits), doctest::Contains("axis 1 j_max"), std::invalid_argument);
  CHECK_THROWS_AS(validate(std::span<const AxisLimits>{}), std::invalid_argument);
}
