// #CS frames and #SPLINE sections through the adapter and the interpolator: a square under a
// rotated and shifted #CS runs in MCS through the transformed programmed points; an arc under
// the rotation stays an arc in the rotated plane; Akima and B-spline sections become curve
// pieces (never lines) that run with the audit clean (limits and contour).

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"

namespace {

using namespace ncsim;

std::vector<planner::Move> moves(const std::string& text, std::string* error = nullptr) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  std::vector<planner::Move> out;
  ipo::Item item;
  while (src.next(item))
    if (const auto* mv = std::get_if<planner::Move>(&item)) out.push_back(*mv);
  if (error != nullptr && src.error() != nullptr)
    *error = src.error()->id + " " + src.error()->message;
  return out;
}

/// Runs the program with Detail::axes and the audit; the position of the last cycle of each
/// line, the final position and the verdict.
struct Run {
  audit::Verdict verdict;
  std::map<std::uint32_t, planner::AxisVec> last_of_line;
  planner::AxisVec final_x{};
  std::uint64_t cycles = 0;
  ipo::Status status = ipo::Status::running;
  std::string error;
};

struct Recorder final : ipo::Sink {
  audit::Audit audit;
  Run* run;
  Recorder(const ipo::Config& c, Run* r) : audit(c.axes, c.channel.t_cycle, c.start), run(r) {}
  void on_joint(const ipo::Joint& j) override { audit.on_joint(j); }
  void on_cycle(const ipo::Cycle& c) override {
    audit.on_cycle(c);
    if (c.activity == ipo::Activity::motion) run->last_of_line[c.line] = c.x;
    run->final_x = c.x;
  }
};

Run run(const std::string& text, double t_cycle = 0.001) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  const ipo::Config cfg = program::machine_config(m, t_cycle);
  Run r;
  Recorder rec(cfg, &r);
  ipo::PathInterpolator ipo(cfg, src, &rec);
  while ((r.status = ipo.step()) == ipo::Status::running)
    ++r.cycles;
  r.verdict = rec.audit.verdict();
  if (src.error() != nullptr) r.error = src.error()->id + " " + src.error()->message;
  if (r.status == ipo::Status::error) r.error += ipo.message();
  return r;
}

constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace

TEST_CASE("a square under #CS rotation and offset runs through the transformed points") {
  // #CS ON [v1, v2, v3, phi1, phi2, phi3], sequence ZYX (portal_3x): phi1 turns about Z.
  // PCS (x, y, z) -> MCS (10 + x cos30 - y sin30, 20 + x sin30 + y cos30, 5 + z).
  const std::string prog =
      "N10 G00 X0 Y0 Z0\n"
      "N20 #CS ON [1][10, 20, 5, 30, 0, 0]\n"
      "N30 G01 X0 Y0 Z0 F3000\n"
      "N40 G60 X40\n"
      "N50 G60 Y40\n"
      "N60 G60 X0\n"
      "N70 G60 Y0\n"
      "N80 #CS OFF\n"
      "N90 G01 X0 Y0 Z0\n"
      "N100 M30\n";
  const double c = std::cos(30 * kDeg), s = std::sin(30 * kDeg);
  const auto mcs = [&](double x, double y) {
    return std::array<double, 3>{10 + x * c - y * s, 20 + x * s + y * c, 5.0};
  };
  const std::map<std::uint32_t, std::array<double, 3>> expected = {
      {3, mcs(0, 0)}, {4, mcs(40, 0)}, {5, mcs(40, 40)}, {6, mcs(0, 40)}, {7, mcs(0, 0)}};
  std::string error;
  const std::vector<planner::Move> mv = moves(prog, &error);
  CHECK(error.empty());
  REQUIRE(mv.size() == 7);
  for (const planner::Move& m : mv) {
    if (!expected.contains(m.line)) continue;
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(m.end[i] == doctest::Approx(expected.at(m.line)[i]).epsilon(1e-12));
  }
  // Hand-checked corner: PCS (40, 0, 0) is MCS (44.641016, 40, 5).
  CHECK(mv[2].end[0] == doctest::Approx(44.6410161514).epsilon(1e-10));
  CHECK(mv[2].end[1] == doctest::Approx(40.0).epsilon(1e-12));
  // #CS OFF: the line back is in MCS again.
  CHECK(mv[6].end[0] == 0.0);
  CHECK(mv[6].end[1] == 0.0);
  CHECK(mv[6].start[0] == doctest::Approx(10.0));

  const Run r = run(prog);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.error.empty());
  CHECK(r.verdict.ok());
  CHECK(r.verdict.contour_max < 1e-9);
  // Each G60 block stops on its transformed end point.
  for (std::uint32_t line = 4; line <= 7; ++line) {
    REQUIRE(r.last_of_line.contains(line));
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(r.last_of_line.at(line)[i] == doctest::Approx(expected.at(line)[i]).epsilon(1e-12));
  }
  CHECK(r.final_x[0] == 0.0);
}

TEST_CASE("a #CS chain sits on the zero offset's X/Y/Z; G55 under the chain moves the chain") {
  // TF5200 "Definition of a machining coordinate system": a CS is defined relative to the
  // workpiece coordinate system, which the zero offset places in the MCS.
  const std::string prog =
      "V.G.NP[1].V.X = 100\n"
      "V.G.NP[1].V.Y = 50\n"
      "V.G.NP[2].V.X = 200\n"
      "N30 G54 G00 X0 Y0 Z0\n"
      "N40 #CS ON [0, 0, 0, 90, 0, 0]\n"
      "N50 G01 X10 Y0 F3000\n"
      "N60 G55\n"
      "N70 G01 X10 Y0\n"
      "N80 #CS OFF\n"
      "N90 G01 X0 Y0\n"
      "N100 M30\n";
  const std::map<std::uint32_t, std::array<double, 3>> expected = {
      {4, {100, 50, 0}}, {6, {100, 60, 0}}, {8, {200, 10, 0}}, {10, {200, 0, 0}}};
  std::string error;
  const std::vector<planner::Move> mv = moves(prog, &error);
  CHECK(error.empty());
  std::size_t seen = 0;
  for (const planner::Move& m : mv) {
    if (!expected.contains(m.line)) continue;
    ++seen;
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(m.end[i] == doctest::Approx(expected.at(m.line)[i]).epsilon(1e-12));
  }
  CHECK(seen == expected.size());
}

TEST_CASE("an arc under a rotated #CS is an arc in the rotated plane through the right points") {
  // Rotation about X by 90 deg (phi3 in ZYX): the PCS XY plane becomes the MCS XZ plane.
  const std::string prog =
      "N10 G00 X0 Y0 Z0\n"
      "N20 #CS ON [1][0, 0, 50, 0, 0, 90]\n"
      "N30 G01 X20 Y0 Z0 F3000\n"
      "N40 G03 X0 Y20 I-20 J0\n"
      "N50 G02 X-20 Y0 R20 Z10\n"
      "N60 #CS OFF\n"
      "N70 M30\n";
  const std::vector<planner::Move> mv = moves(prog);
  REQUIRE(mv.size() == 4);
  const planner::Move& arc = mv[2];
  REQUIRE(arc.arc.has_value());
  REQUIRE(arc.arc_plane.has_value());
  // PCS (0, 20, 0) -> MCS (0, 0, 70): y goes to z under Rx(90).
  CHECK(arc.end[0] == doctest::Approx(0.0).scale(1.0));
  CHECK(arc.end[1] == doctest::Approx(0.0).scale(1.0));
  CHECK(arc.end[2] == doctest::Approx(70.0));
  const planner::Segment seg = planner::Segment::from_move(arc);
  CHECK(seg.length() == doctest::Approx(20.0 * std::numbers::pi / 2.0));
  // Mid-arc: PCS (20 cos45, 20 sin45, 0) -> MCS (14.142, 0, 64.142).
  const planner::AxisVec mid = seg.point(seg.length() / 2.0);
  CHECK(mid[0] == doctest::Approx(20.0 * std::cos(45 * kDeg)));
  CHECK(mid[1] == doctest::Approx(0.0).scale(1.0));
  CHECK(mid[2] == doctest::Approx(50.0 + 20.0 * std::sin(45 * kDeg)));
  // The helix (PCS Z rise 10) rises along MCS -Y.
  const planner::Segment helix = planner::Segment::from_move(mv[3]);
  CHECK(helix.end()[1] == doctest::Approx(-10.0));
  CHECK(helix.end()[0] == doctest::Approx(-20.0));

  const Run r = run(prog);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.verdict.ok());
  CHECK(r.verdict.contour_max < 1e-6);
}

TEST_CASE("an Akima section becomes curve pieces that pass through its points; audit clean") {
  const std::string prog =
      "N10 G00 X0 Y0 Z0\n"
      "N20 #SPLINE ON\n"
      "N30 G01 X10 Y5 F3000\n"
      "N40 X20 Y0\n"
      "N50 X30 Y-5\n"
      "N60 X40 Y0\n"
      "N70 #SPLINE OFF\n"
      "N80 G01 X50 Y0\n"
      "N90 M30\n";
  std::string error;
  const std::vector<planner::Move> mv = moves(prog, &error);
  CHECK(error.empty());
  REQUIRE(mv.size() == 6);  // G00, four pieces, the line after
  const double pts[4][2] = {{10, 5}, {20, 0}, {30, -5}, {40, 0}};
  for (std::size_t k = 0; k < 4; ++k) {
    const planner::Move& piece = mv[1 + k];
    CHECK(piece.spline != nullptr);
    CHECK(piece.line == 3 + k);
    CHECK(piece.feed == doctest::Approx(50.0));
    CHECK(piece.end[0] == doctest::Approx(pts[k][0]));
    CHECK(piece.end[1] == doctest::Approx(pts[k][1]));
    const planner::Segment seg = planner::Segment::from_move(piece);
    CHECK(seg.kind() == planner::SegmentKind::spline);
    // A curve, not a chord: longer than the straight line between its ends.
    CHECK(seg.length() > std::hypot(piece.end[0] - piece.start[0], piece.end[1] - piece.start[1]));
  }
  const Run r = run(prog);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.error.empty());
  CHECK(r.verdict.ok());
  CHECK(r.verdict.contour_max < 1e-6);
  CHECK(r.final_x[0] == 50.0);
}

TEST_CASE("a B-spline section under #CS runs with the audit clean, 0.5 to 2 ms cycles") {
  const std::string prog =
      "N10 G00 X0 Y0 Z0\n"
      "N20 #CS ON [1][5, 5, 0, 20, 0, 0]\n"
      "N25 G01 X0 Y0 F2400\n"
      "N30 #SPLINE TYPE BSPLINE\n"
      "N40 #SPLINE ON\n"
      "N50 G01 X10 Y10\n"
      "N60 X20 Y-10\n"
      "N70 X30 Y10\n"
      "N80 X40 Y0 F1200\n"
      "N90 #SPLINE OFF\n"
      "N100 #CS OFF\n"
      "N110 M30\n";
  std::string error;
  const std::vector<planner::Move> mv = moves(prog, &error);
  CHECK(error.empty());
  std::size_t pieces = 0;
  for (const planner::Move& m : mv)
    pieces += m.spline ? 1 : 0;
  CHECK(pieces == 2);  // 5 control points: n - 3 spans
  // Clamped: the curve ends on the last control point, PCS (40, 0) rotated by 20 deg, shifted.
  const planner::Move& last = mv.back();
  CHECK(last.end[0] == doctest::Approx(5.0 + 40.0 * std::cos(20 * kDeg)));
  CHECK(last.end[1] == doctest::Approx(5.0 + 40.0 * std::sin(20 * kDeg)));
  for (const double t : {0.0005, 0.001, 0.002}) {
    const Run r = run(prog, t);
    CHECK(r.status == ipo::Status::finished);
    CHECK(r.verdict.ok());
    CHECK(r.verdict.contour_max < 1e-6);
  }
}

TEST_CASE("the bundled cs_rotated_pocket and spline_akima_contour run with the audit clean") {
  for (const std::string name : {"cs_rotated_pocket", "spline_akima_contour"}) {
    CAPTURE(name);
    std::ifstream in(std::string(NCSIM_SOURCE_ROOT) + "/programs/" + name + "/" + name + ".nc");
    REQUIRE(in.good());
    std::ostringstream text;
    text << in.rdbuf();
    const Run r = run(text.str());
    CHECK(r.status == ipo::Status::finished);
    CHECK(r.error.empty());
    CHECK(r.verdict.ok());
    CHECK(r.verdict.contour_max < 1e-9);
    const double z_end = name == "spline_akima_contour" ? 5.0 : 20.0;  // the last G00
    CHECK(r.final_x[2] == z_end);
  }
}

namespace {

/// A seeded random program in a random #CS (rotation about all three axes and a shift): lines,
/// G17 and G18 arcs and helices given by R, Akima and B-spline sections; half of the programs
/// with TRAPEZ slopes, a third with tolerance balls. Returns the text and the last PCS point.
std::string random_program(std::mt19937_64& rng, std::array<double, 3>& last) {
  std::uniform_real_distribution<double> pos(-100.0, 100.0);
  std::uniform_real_distribution<double> zpos(-40.0, 40.0);
  std::uniform_real_distribution<double> angle(-60.0, 60.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::ostringstream p;
  p.setf(std::ios::fixed);
  p.precision(6);
  int n = 10;
  const auto block = [&]() -> std::ostringstream& {
    p << 'N' << n << ' ';
    n += 10;
    return p;
  };
  block() << "G00 X400 Y300 Z0\n";
  if (unit(rng) < 0.5) block() << "#SLOPE [TYPE=TRAPEZ]\n";
  const bool contouring = unit(rng) < 0.33;
  if (contouring) {
    block() << "#CONTOUR MODE [DEV, PATH_DEV=0.05]\n";
    block() << "G261\n";
  }
  block() << "#CS ON [1][400, 300, 0, " << angle(rng) << ", " << angle(rng) << ", " << angle(rng)
          << "]\n";
  std::array<double, 3> at{0.0, 0.0, 0.0};
  block() << "G01 X0 Y0 Z0 F" << 600.0 + 5400.0 * unit(rng) << '\n';
  for (int k = 0; k < 10; ++k) {
    const double pick = unit(rng);
    if (pick < 0.35) {
      at = {pos(rng), pos(rng), zpos(rng)};
      block() << "G01 X" << at[0] << " Y" << at[1] << " Z" << at[2] << '\n';
    } else if (pick < 0.75) {
      const bool g18 = pick > 0.65;
      std::array<double, 3> to{pos(rng), pos(rng), zpos(rng)};
      // Chord in the plane (G17: X, Y; G18: Z, X) at least 5 mm; R 1.05..3 times its half.
      const double d =
          g18 ? std::hypot(to[2] - at[2], to[0] - at[0]) : std::hypot(to[0] - at[0], to[1] - at[1]);
      if (d < 5.0) continue;
      const double r = d / 2.0 * (1.05 + 1.95 * unit(rng));
      block() << (g18 ? "G18 " : "G17 ") << (unit(rng) < 0.5 ? "G02" : "G03") << " X" << to[0]
              << " Y" << to[1] << " Z" << to[2] << " R" << r << '\n';
      at = to;
    } else if (!contouring) {  // a spline with G261 is 120255 (the interpreter's rule)
      block() << (unit(rng) < 0.5 ? "#SPLINE TYPE AKIMA\n" : "#SPLINE TYPE BSPLINE\n");
      block() << "#SPLINE ON\n";
      const int points = 4 + static_cast<int>(unit(rng) * 3);
      for (int i = 0; i < points; ++i) {
        at = {at[0] + 0.5 * pos(rng), at[1] + 0.5 * pos(rng), at[2] + 0.25 * zpos(rng)};
        for (double& c : at)
          c = std::clamp(c, -100.0, 100.0);
        block() << "G01 X" << at[0] << " Y" << at[1] << " Z" << at[2] << '\n';
      }
      block() << "#SPLINE OFF\n";
    }
  }
  block() << "G17\n";
  block() << "#CS OFF\n";
  block() << "M30\n";
  last = at;
  return p.str();
}

}  // namespace

TEST_CASE("property: random programs in random #CS frames keep every limit and the contour") {
  std::mt19937_64 rng(1212);
  for (int trial = 0; trial < 24; ++trial) {
    std::array<double, 3> last{};
    const std::string text = random_program(rng, last);
    CAPTURE(text);
    const Run r = run(text, trial % 3 == 0 ? 0.0005 : 0.001);
    CHECK(r.status == ipo::Status::finished);
    CHECK_MESSAGE(r.error.empty(), r.error);
    CHECK(r.verdict.ok());
    if (!r.verdict.ok() && !r.verdict.violations.empty()) {
      const audit::Violation& v = r.verdict.violations.front();
      MESSAGE("first violation: quantity "
              << static_cast<int>(v.quantity) << " method " << static_cast<int>(v.method)
              << " axis " << static_cast<int>(v.axis) << " line " << v.line << " value " << v.value
              << " limit " << v.limit);
    }
    // The program ends on the last point; #CS OFF does not move the tool.
    std::string error;
    const std::vector<planner::Move> mv = moves(text, &error);
    REQUIRE_FALSE(mv.empty());
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(r.final_x[i] == doctest::Approx(mv.back().end[i]).epsilon(1e-9).scale(100.0));
  }
}
