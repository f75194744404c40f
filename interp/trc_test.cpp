#include "interp/trc.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "interp/interpreter.hpp"
#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

using trc::Element;
using trc::Vec2;

Element line(Vec2 a, Vec2 b) {
  Element e;
  e.start = a;
  e.end = b;
  return e;
}

Element arc(Vec2 a, Vec2 b, Vec2 c, bool ccw) {
  Element e = line(a, b);
  e.arc = true;
  e.centre = c;
  e.ccw = ccw;
  return e;
}

bool near(Vec2 a, Vec2 b, double tol = 1e-6) {
  return std::fabs(a.x - b.x) < tol && std::fabs(a.y - b.y) < tol;
}

double radius(const Element& e) {
  return std::hypot(e.start.x - e.centre.x, e.start.y - e.centre.y);
}

// Geometry

TEST_CASE("a line is offset to the left (G41, d > 0) and to the right (G42, d < 0)") {
  const Element l = line({0, 0}, {10, 0});
  const auto left = trc::offset(l, 2.0);
  const auto right = trc::offset(l, -2.0);
  REQUIRE(left);
  REQUIRE(right);
  CHECK(near(left->start, {0, 2}));
  CHECK(near(left->end, {10, 2}));
  CHECK(near(right->start, {0, -2}));
  CHECK(near(right->end, {10, -2}));
}

TEST_CASE("an arc keeps its centre; its radius shrinks on the inner side and grows outside") {
  // G03 about (0,0) from (10,0) to (0,10): the left side is the inside
  const Element ccw = arc({10, 0}, {0, 10}, {0, 0}, true);
  CHECK(radius(*trc::offset(ccw, 2.0)) == doctest::Approx(8.0));
  CHECK(radius(*trc::offset(ccw, -2.0)) == doctest::Approx(12.0));
  // G02 about (0,0) from (0,10) to (10,0): the left side is the outside
  const Element cw = arc({0, 10}, {10, 0}, {0, 0}, false);
  CHECK(radius(*trc::offset(cw, 2.0)) == doctest::Approx(12.0));
  CHECK(radius(*trc::offset(cw, -2.0)) == doctest::Approx(8.0));
  const auto o = trc::offset(cw, 2.0);
  CHECK(near(o->start, {0, 12}));
  CHECK(near(o->end, {12, 0}));
  CHECK(near(o->centre, {0, 0}));
}

TEST_CASE("a tool radius not below the inner arc radius has no offset arc [90017]") {
  CHECK_FALSE(trc::offset(arc({10, 0}, {0, 10}, {0, 0}, true), 10.0));
  CHECK_FALSE(trc::offset(arc({10, 0}, {0, 10}, {0, 0}, true), 12.0));
  CHECK(trc::offset(arc({10, 0}, {0, 10}, {0, 0}, true), -12.0));
}

TEST_CASE("an outer corner gets a circle about the corner with G26") {
  // X+ then Y-: a right turn, outer for a tool on the left
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 2.0);
  const auto b = *trc::offset(line({10, 0}, {10, -10}), 2.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 2.0, TrcCorner::circle, err);
  CHECK(err == trc::JoinError::none);
  CHECK(near(j.a_end, {10, 2}));
  CHECK(near(j.b_start, {12, 0}));
  REQUIRE(j.inserted.size() == 1);
  CHECK(j.inserted[0].arc);
  CHECK_FALSE(j.inserted[0].ccw);  // tool left of a right turn: bypassed clockwise
  CHECK(near(j.inserted[0].centre, {10, 0}));
  CHECK(radius(j.inserted[0]) == doctest::Approx(2.0));
}

TEST_CASE("G25 extends the offset lines to their intersection up to 90 degrees of turn") {
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 2.0);
  const auto b = *trc::offset(line({10, 0}, {10, -10}), 2.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 2.0, TrcCorner::linear, err);
  CHECK(near(j.a_end, {12, 2}));
  CHECK(near(j.b_start, {12, 2}));
  CHECK(j.inserted.empty());  // LIN-LIN 180..270 degrees: no block (TF5200 table)
}

TEST_CASE("G25 beyond 90 degrees of turn extends both lines by the radius and inserts one line") {
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 2.0);
  const auto b = *trc::offset(line({10, 0}, {0, -1}), 2.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 2.0, TrcCorner::linear, err);
  CHECK(near(j.a_end, {12, 2}));
  REQUIRE(j.inserted.size() == 1);  // LIN-LIN 270..360 degrees: 1 LIN
  CHECK_FALSE(j.inserted[0].arc);
  CHECK(near(j.inserted[0].start, {12, 2}));
  CHECK(near(j.inserted[0].end, j.b_start));
}

TEST_CASE("G25 at a line-arc outer corner inserts the line along the arc's tangent") {
  // X+ then a G02 quarter circle turning right, for a tool on the left: outer
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 1.0);
  const auto b = *trc::offset(arc({10, 0}, {0, -10}, {0, 0}, false), 1.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 1.0, TrcCorner::linear, err);
  REQUIRE(j.inserted.size() == 1);  // LIN-CIR 180..270: 1 LIN
  CHECK(near(j.inserted[0].end, b.start));
  CHECK(near(j.a_end, j.inserted[0].start));
}

TEST_CASE("an inner corner ends both offset elements at their intersection") {
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 2.0);
  const auto b = *trc::offset(line({10, 0}, {10, 10}), 2.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 2.0, TrcCorner::circle, err);
  CHECK(err == trc::JoinError::none);
  CHECK(near(j.a_end, {8, 2}));
  CHECK(near(j.b_start, {8, 2}));
  CHECK(j.inserted.empty());
}

TEST_CASE("an inner corner of a line and an arc meets at the intersection nearest the corner") {
  // X+ then G03 about (10,10): a left turn that keeps turning; tool left = inside
  const auto a = *trc::offset(line({0, 0}, {10, 0}), 1.0);
  const auto b = *trc::offset(arc({10, 0}, {20, 10}, {10, 10}, true), 1.0);
  trc::JoinError err{};
  const trc::Join j = trc::join(a, b, {10, 0}, 1.0, TrcCorner::linear, err);
  // tangent at the corner: the offset points coincide
  CHECK(near(j.a_end, {10, 1}));
  CHECK(near(j.b_start, {10, 1}));
}

TEST_CASE("a trimmed element that runs backwards is a contour violation") {
  const Element l = line({7, 0}, {7, 10});
  CHECK(trc::keeps_direction(l, {7, 3}, {7, 5}));
  CHECK_FALSE(trc::keeps_direction(l, {7, 3}, {7, -1}));
  const Element a = arc({10, 0}, {0, 10}, {0, 0}, true);
  CHECK(trc::keeps_direction(a, {10, 0}, {0, 10}));
  const double s = std::sqrt(50.0);
  CHECK(trc::keeps_direction(a, {s, s}, {0, 10}));
  CHECK_FALSE(trc::keeps_direction(a, {0, 10}, {s, s}));
}

// The filter in the interpreter

struct Path {
  std::vector<Command> motions;
  std::string error_id;
  std::uint32_t error_line = 0;
  std::string error_message;
};

Path path(const std::string& program, const std::string& machine = "portal_3x_tools") {
  const core::SourceFile file("test.nc", program);
  Interpreter interp(file, test::machine(machine));
  Path p;
  while (auto c = interp.next_decode_only()) {
    if (std::holds_alternative<Motion>(c->body)) p.motions.push_back(*c);
  }
  if (const auto* e = interp.error()) {
    p.error_id = e->id;
    p.error_line = e->loc.line;
    p.error_message = e->message;
  }
  return p;
}

const Motion& mo(const Path& p, std::size_t i) {
  REQUIRE(i < p.motions.size());
  return std::get<Motion>(p.motions[i].body);
}

bool from_to(const Motion& m, Vec2 a, Vec2 b) {
  return near({m.start[0], m.start[1]}, a, 1e-4) && near({m.end[0], m.end[1]}, b, 1e-4);
}

TEST_CASE("a closed square compensated outside with G26 grows by r with rounded corners") {
  const Path p = path(
      "%t\nG00 X-20 Y-20\nG26 G42 D1\nG01 X0 Y0 F1000\nX100\nY100\nX0\nY0\n"
      "G40 G01 X-20 Y-20\nM30\n");
  REQUIRE(p.error_id.empty());
  const double k = 3.0 * (std::sqrt(2.0) - 1.0);  // the inner corner of the approach
  REQUIRE(p.motions.size() == 10);
  CHECK(from_to(mo(p, 0), {0, 0}, {-20, -20}));   // G00
  CHECK(from_to(mo(p, 1), {-20, -20}, {k, -3}));  // selection (line 4)
  CHECK(from_to(mo(p, 2), {k, -3}, {100, -3}));   // bottom
  CHECK(from_to(mo(p, 3), {100, -3}, {103, 0}));  // corner circle
  CHECK(mo(p, 3).kind == MotionKind::arc_ccw);
  CHECK(mo(p, 3).arc->radius == doctest::Approx(3.0));
  CHECK(mo(p, 3).arc->centre_1 == doctest::Approx(100.0));
  CHECK(p.motions[3].line == 6);  // the transition belongs to the block it leads into
  CHECK(from_to(mo(p, 4), {103, 0}, {103, 100}));
  CHECK(from_to(mo(p, 5), {103, 100}, {100, 103}));
  CHECK(from_to(mo(p, 6), {100, 103}, {0, 103}));
  CHECK(from_to(mo(p, 7), {0, 103}, {-3, 100}));
  CHECK(from_to(mo(p, 8), {-3, 100}, {-3, k}));
  CHECK(from_to(mo(p, 9), {-3, k}, {-20, -20}));  // deselection (line 9)
  CHECK(p.motions[9].line == 9);
}

TEST_CASE("a closed square pocket compensated inside shrinks by r with sharp inner corners") {
  const Path p = path(
      "%t\nG00 X50 Y50\nG41 D1\nG01 X50 Y0 F1000\nX100\nY100\nX0\nY0\nX50\n"
      "G40 X50 Y50\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 8);
  CHECK(from_to(mo(p, 1), {50, 50}, {53, 3}));  // selection: indirect, to the inner corner
  CHECK(from_to(mo(p, 2), {53, 3}, {97, 3}));
  CHECK(from_to(mo(p, 3), {97, 3}, {97, 97}));
  CHECK(from_to(mo(p, 4), {97, 97}, {3, 97}));
  CHECK(from_to(mo(p, 5), {3, 97}, {3, 3}));
  CHECK(from_to(mo(p, 6), {3, 3}, {47, 3}));
  CHECK(from_to(mo(p, 7), {47, 3}, {50, 50}));  // deselection
}

TEST_CASE("G138 selects directly onto the perpendicular point and deselects from it") {
  const Path p =
      path("%t\nG00 X-20 Y-20\nG138 G41 D1\nG01 X0 Y0 F1000\nX100\nG40 X120 Y-20\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 4);
  CHECK(from_to(mo(p, 1), {-20, -20}, {0, 3}));
  CHECK(from_to(mo(p, 2), {0, 3}, {100, 3}));
  CHECK(from_to(mo(p, 3), {100, 3}, {120, -20}));
}

TEST_CASE("offset arcs: G02 and G03 with G41 and G42 change the radius by r") {
  // a semicircle bump on a line: X+ to (10,0), G03 about (20,0) to (30,0)? G02 over the top
  const Path left = path(
      "%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX10\nG02 X30 Y0 I10 J0\nG01 X40\nG40 X40 Y-10\n"
      "M30\n");
  REQUIRE(left.error_id.empty());
  const auto arc_of = [](const Path& p) -> const Motion* {
    for (const Command& c : p.motions) {
      if (std::get<Motion>(c.body).arc && c.line == 6) return &std::get<Motion>(c.body);
    }
    return nullptr;
  };
  REQUIRE(arc_of(left) != nullptr);
  CHECK(arc_of(left)->arc->radius == doctest::Approx(13.0));  // G02, tool left: outside
  CHECK(arc_of(left)->kind == MotionKind::arc_cw);
  const Path right = path(
      "%t\nG00 X0 Y10\nG42 D1\nG01 X0 Y0 F1000\nX10\nG02 X30 Y0 I10 J0\nG01 X40\nG40 X40 Y10\n"
      "M30\n");
  REQUIRE(right.error_id.empty());
  REQUIRE(arc_of(right) != nullptr);
  CHECK(arc_of(right)->arc->radius == doctest::Approx(7.0));  // G02, tool right: inside
  const Path ccw = path(
      "%t\nG00 X0 Y10\nG42 D1\nG01 X0 Y0 F1000\nX10\nG03 X30 Y0 I10 J0\nG01 X40\nG40 X40 Y10\n"
      "M30\n");
  REQUIRE(ccw.error_id.empty());
  CHECK(arc_of(ccw)->arc->radius == doctest::Approx(13.0));  // G03, tool right: outside
}

TEST_CASE("a motion out of the plane and M functions between contour blocks keep their place") {
  const Path p =
      path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nZ-1\nM08\nX10\nG40 X10 Y-10\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 5);
  CHECK(from_to(mo(p, 1), {0, -10}, {-3, 3}));      // G25: extended to the tangent intersection
  CHECK(from_to(mo(p, 2), {-3, 3}, {-3, 3}));       // Z-1 where the compensated path is
  CHECK(mo(p, 2).end[2] == doctest::Approx(59.0));  // -1 + D1's length 60
  CHECK(p.motions[2].line == 5);
}

TEST_CASE("radius too large for an arc is 90017 at the arc's line") {
  const Path p = path(
      "%t\nG00 X0 Y-10\nG41 D2\nG01 X0 Y0 F1000\nX10\nG03 X14 Y4 I0 J4\nG40 G01 X20 Y4\nM30\n");
  CHECK(p.error_id == "90017");
  CHECK(p.error_line == 6);
}

TEST_CASE("a slot narrower than the tool reverses the compensated element [NC4701]") {
  const Path p = path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX10\nY2\nX0\nG40 X0 Y10\nM30\n");
  CHECK(p.error_id == "NC4701");
  CHECK(p.error_line == 6);
}

TEST_CASE("selection in a circular block is 90008; G40 before a circle is NC4703") {
  CHECK(path("%t\nG41 D1\nG02 X10 Y0 I5 J0 F1000\nM30\n").error_id == "90008");
  const Path p = path("%t\nG41 D1\nG01 X10 Y0 F1000\nG40 G02 X20 Y0 I5\nM30\n");
  CHECK(p.error_id == "NC4703");
  CHECK(p.error_line == 4);
}

TEST_CASE("a plane change while TRC is active is 20133; G41 with G42 in one block 20114") {
  const Path p = path("%t\nG41 D1\nG01 X10 Y0 F1000\nG19\nM30\n");
  CHECK(p.error_id == "20133");
  CHECK(p.error_line == 4);
  CHECK(path("%t\nG41 G42 D1 X10\nM30\n").error_id == "20114");
}

TEST_CASE("D needs a valid tool of the machine's tool list when TRC uses it [NC4706]") {
  CHECK(path("%t\nG41 D9\nM30\n").error_id == "NC4706");  // not in the list
  CHECK(path("%t\nG41 D4\nM30\n").error_id == "NC4706");  // wz[4].gueltig 0
  const Path none = path("%t\nG41 D1\nM30\n", "portal_3x");
  CHECK(none.error_id == "NC4706");
  CHECK(none.error_message.find("no tool list") != std::string::npos);
  // D without TRC passes through on any machine, D0 is radius 0
  CHECK(path("%t\nT1 D1\nG01 X1 F100\nM30\n", "portal_3x").error_id.empty());
  CHECK(path("%t\nG41 D0\nG01 X1 F100\nG40\nM30\n", "portal_3x").error_id.empty());
}

TEST_CASE("#CS or a V.E. read while an element is held is not supported [NC4705]") {
  const Path p = path("%t\nG41 D1\nG01 X10 Y0 F1000\n#CS ON[0,0,0,0,0,0]\nM30\n");
  CHECK(p.error_id == "NC4705");
  CHECK(p.error_line == 4);
}

const Motion* motion_at(const Path& p, std::uint32_t line, bool arc) {
  for (const Command& c : p.motions) {
    if (c.line == line && std::get<Motion>(c.body).arc.has_value() == arc)
      return &std::get<Motion>(c.body);
  }
  return nullptr;
}

TEST_CASE("G11 runs F on the contour of compensated arcs, above #TANGFEED RMIN [PROG-206473227]") {
  // F600 = 10 mm/s; the G02 of radius 10 is compensated outside (13, tool left) or inside (7)
  const auto arc_feed = [](const std::string& head, const std::string& side) {
    const Path p = path("%t\n" + head + "G00 X0 Y" + (side == "G41" ? "-10" : "10") + "\n" + side +
                        " D1\nG01 X0 Y0 F600\nX10\nG02 X30 Y0 I10 J0\nG01 X40\nG40 X50\nM30\n");
    REQUIRE(p.error_id.empty());
    const auto shift = static_cast<std::uint32_t>(std::count(head.begin(), head.end(), '\n'));
    const Motion* arc = motion_at(p, 6 + shift, true);
    const Motion* line = motion_at(p, 5 + shift, false);
    REQUIRE(arc != nullptr);
    REQUIRE(line != nullptr);
    CHECK(line->feed == doctest::Approx(10.0));  // lines keep F
    return arc->feed;
  };
  CHECK(arc_feed("", "G41") == doctest::Approx(10.0));           // G10, the initial state
  CHECK(arc_feed("G11\n", "G41") == doctest::Approx(13.0));      // outside: faster
  CHECK(arc_feed("G11\n", "G42") == doctest::Approx(7.0));       // inside: slower
  CHECK(arc_feed("G11 G10\n", "G41") == doctest::Approx(10.0));  // G10 ends it
  CHECK(arc_feed("G11\n#TANGFEED [RMIN=12]\n", "G41") == doctest::Approx(10.0));  // 10 < 12
  CHECK(arc_feed("G11\n#TANGFEED [RMIN=10]\n", "G41") == doctest::Approx(13.0));  // 10 >= 10
  CHECK(arc_feed("G11\n#SET TANGFEED RMIN [5]\n", "G41") == doctest::Approx(13.0));
  CHECK(path("%t\n#TANGFEED [RMIN=-1]\nM30\n").error_id == "NC4030");
}

TEST_CASE("G237 enters and leaves square to the contour, an arc may come first") {
  // N60 G03 about (10,60) r 50, tool right (outside): r 53; then a tangent line up
  const Path p =
      path("%t\nG00 X10 Y10\nG237 G42 D1\nG03 X60 Y60 J50 F1000\nG01 Y100\nG40\nG00 X0 Y0\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 6);
  CHECK(from_to(mo(p, 1), {10, 10}, {10, 7}));  // square onto the offset start
  CHECK(p.motions[1].line == 4);
  CHECK(from_to(mo(p, 2), {10, 7}, {63, 60}));
  CHECK(mo(p, 2).arc->radius == doctest::Approx(53.0));
  CHECK(from_to(mo(p, 3), {63, 60}, {63, 100}));
  CHECK(from_to(mo(p, 4), {63, 100}, {60, 100}));  // square back to the contour
  CHECK(from_to(mo(p, 5), {60, 100}, {0, 0}));     // the next block as programmed
  CHECK(mo(p, 5).kind == MotionKind::rapid);
}

TEST_CASE("G239 selects as G138 and deselects at the last offset point; a circle after is NC4703") {
  const Path p =
      path("%t\nG00 X0 Y0\nG239 G41 D1\nG01 X30 Y20 F1000\nX60\nX90\nG40\nG00 X150 Y0\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 5);
  CHECK(from_to(mo(p, 1), {0, 0}, {30, 23}));
  CHECK(from_to(mo(p, 2), {30, 23}, {60, 23}));
  CHECK(from_to(mo(p, 3), {60, 23}, {90, 23}));
  CHECK(from_to(mo(p, 4), {90, 23}, {150, 0}));
  const Path arc = path("%t\nG239 G41 D1\nG01 X30 Y20 F1000\nX60\nG40\nG02 X70 Y20 I5\nM30\n");
  CHECK(arc.error_id == "NC4703");
  CHECK(arc.error_line == 6);
}

TEST_CASE("G41 -> G42 without G40 leaves one side and takes the other in a linear block") {
  const Path p =
      path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX20\nX40 G42\nX60\nG40 X60 Y10\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 6);
  CHECK(from_to(mo(p, 2), {-3, 3}, {20, 3}));   // left of X0..X20
  CHECK(from_to(mo(p, 3), {20, 3}, {40, -3}));  // the change block crosses over
  CHECK(p.motions[3].line == 6);
  CHECK(from_to(mo(p, 4), {40, -3}, {63, -3}));  // right of X40..X60
  const Path arc = path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX20\nG42 G02 X40 Y0 I10\nM30\n");
  CHECK(arc.error_id == "NC4704");
  CHECK(arc.error_line == 6);
}

TEST_CASE("a new D while TRC is active takes its radius in the next linear block") {
  const Path p =
      path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX20\nD2 X40\nX60\nG40 X60 Y-10\nM30\n");
  REQUIRE(p.error_id.empty());
  CHECK(from_to(mo(p, 3), {20, 3}, {40, 5}));
  CHECK(from_to(mo(p, 4), {40, 5}, {65, 5}));
  const Path arc = path("%t\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX20\nD2 G02 X40 Y0 I10\nM30\n");
  CHECK(arc.error_id == "NC4704");
}

TEST_CASE(
    "D's tool length (P-TOOL-00003) lifts the tool axis from its next absolute value (P-CHAN-00100 "
    "= 0); D0 ends it") {
  // portal_3x_tools: D1 60 mm, D2 75 mm
  const Path p =
      path("%t\nG01 Z10 F600\nD1\nG01 X5\nG91 Z0\nG90 Z10\nD2 Z10\nD0 Z10\nG18 D1 Y20 Z10\nM30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.motions.size() == 7);
  CHECK(mo(p, 0).end[2] == doctest::Approx(10.0));
  CHECK(mo(p, 1).end[2] == doctest::Approx(10.0));  // X5: Z not programmed, no move
  CHECK(mo(p, 2).end[2] == doctest::Approx(10.0));  // G91 Z0: incremental, no move
  CHECK(mo(p, 3).end[2] == doctest::Approx(70.0));  // absolute: 10 + 60
  CHECK(mo(p, 4).end[2] == doctest::Approx(85.0));  // D2: 10 + 75
  CHECK(mo(p, 5).end[2] == doctest::Approx(10.0));  // D0
  CHECK(mo(p, 6).end[1] == doctest::Approx(80.0));  // G18: the tool axis is Y
  CHECK(mo(p, 6).end[2] == doctest::Approx(10.0));
  // without a tool list D is a plain function; with one it must name a released tool
  CHECK(mo(path("%t\nD1\nG01 Z10 F600\nM30\n", "portal_3x"), 0).end[2] == doctest::Approx(10.0));
  const Path bad = path("%t\nD9\nM30\n");
  CHECK(bad.error_id == "NC4706");
  CHECK(bad.error_line == 2);
}

TEST_CASE("check reports a compensation that cannot be built at its file:line:col") {
  const core::SourceFile file("bad.nc", "%t\nG41 D1\nG01 X10 Y0 F1000\nY2\nX0\nG40 X0 Y10\nM30\n");
  const core::DiagnosticList d = check_semantics(file, test::machine("portal_3x_tools"), {});
  REQUIRE(d.has_errors());
  const core::Diagnostic& e = d.items().back();
  CHECK(e.id == "NC4701");
  CHECK(e.file == "bad.nc");
  CHECK(e.loc == core::SourceLoc{4, 1});
}

}  // namespace
}  // namespace ncsim::interp
