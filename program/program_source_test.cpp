// The interpreter -> interpolator adapter: commands become Moves and Dwells in the
// interpolated-axis order with their modal settings; unsupported commands are NC6001 errors at
// their line; the machine lists become the documented limits.

#include "program/program_source.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "audit/time.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"

namespace {

using namespace ncsim;

struct Pulled {
  std::vector<ipo::Item> items;
  std::string error_id;
  std::uint32_t error_line = 0;
  std::string error_message;
};

Pulled pull(const std::string& text, const std::string& machine_name = "portal_3x") {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine(machine_name);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  Pulled p;
  ipo::Item item;
  while (src.next(item))
    p.items.push_back(item);
  CHECK_FALSE(src.next(item));  // the stream stays ended
  if (const core::Diagnostic* e = src.error()) {
    p.error_id = e->id;
    p.error_line = e->loc.line;
    p.error_message = e->message;
  }
  return p;
}

// Cycles of `text` on portal_3x at T = 1 ms, run to its end without an error.
std::uint64_t cycles_of(const std::string& text) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  const audit::TimeResult r = audit::machining_time(program::machine_config(m, 0.001), src);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE(src.error() == nullptr);
  return r.cycles;
}

}  // namespace

TEST_CASE("motion, feed, modal transition, contour and slope become the Move's fields") {
  const Pulled p = pull(
      "N10 G00 X10 Y5\n"
      "N20 #SLOPE [TYPE=TRAPEZ]\n"
      "N30 #CONTOUR MODE [DEV, PATH_DEV=0.5]\n"
      "N40 G261 G01 X20 F600\n"
      "N50 G09 G02 X30 Y15 I0 J10 E300\n"
      "N60 G04 X2\n"
      "N70 M30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.items.size() == 4);
  const auto& rapid = std::get<planner::Move>(p.items[0]);
  CHECK(rapid.rapid);
  CHECK(rapid.line == 1);
  CHECK(rapid.axis_count == 3);
  CHECK(rapid.path_axes == 0b111u);
  CHECK(rapid.end[0] == 10.0);
  CHECK(rapid.end[1] == 5.0);
  const auto& line = std::get<planner::Move>(p.items[1]);
  CHECK_FALSE(line.rapid);
  CHECK(line.feed == doctest::Approx(10.0));  // F600 mm/min
  CHECK(line.start[0] == 10.0);
  CHECK(line.contour == planner::Contour::tolerance);
  CHECK(line.path_dev == 0.5);
  CHECK(line.slope == planner::SlopeType::trapez);
  const auto& arc = std::get<planner::Move>(p.items[2]);
  REQUIRE(arc.arc.has_value());
  CHECK(arc.arc->clockwise);
  CHECK(arc.arc->axis_1 == 0);
  CHECK(arc.arc->axis_2 == 1);
  CHECK(arc.arc->centre_1 == doctest::Approx(20.0));
  CHECK(arc.arc->centre_2 == doctest::Approx(15.0));
  CHECK(arc.transition == planner::Transition::stop_at_end);
  REQUIRE(arc.end_feed.has_value());
  CHECK(*arc.end_feed == doctest::Approx(5.0));
  const auto& dwell = std::get<ipo::Dwell>(p.items[3]);
  CHECK(dwell.seconds == 2.0);
  CHECK(dwell.line == 6);
}

TEST_CASE("G60 and G93 block time reach the Move") {
  const Pulled p = pull("N10 G01 G60 X10 F600\nN20 G93 X20 F2\nN30 M30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.items.size() == 2);
  CHECK(std::get<planner::Move>(p.items[0]).exact_stop);
  const auto& timed = std::get<planner::Move>(p.items[1]);
  CHECK_FALSE(timed.exact_stop);
  CHECK(timed.block_time.has_value());
}

TEST_CASE("M00 / M01, M functions and messages pass without a stop") {
  const Pulled p = pull("N10 G01 X10 F600\nN20 M00\nN30 M01\nN40 M08\nN50 X20\nN60 M30\n");
  REQUIRE(p.error_id.empty());
  CHECK(p.items.size() == 2);
}

TEST_CASE("#FLUSH and #FLUSH WAIT stop the path at their line; #FLUSH CONTINUE passes") {
  // isg-language.md 5.1 [C] (PROG-207042443): #FLUSH empties the channel buffer, the path stops
  // at the end of the last motion block; #FLUSH WAIT lets decoding wait until interpolation has
  // caught up (the buffer runs empty: a stop too); #FLUSH CONTINUE does not stop when the next
  // motion block is already there, which it always is here (the decoder runs ahead of time).
  for (const char* kind : {"", " WAIT"}) {
    CAPTURE(kind);
    const Pulled p =
        pull(std::string("N10 G01 X10 F600\nN20 #FLUSH") + kind + "\nN30 X20\nN40 M30\n");
    REQUIRE(p.error_id.empty());
    REQUIRE(p.items.size() == 3);
    const auto* stop = std::get_if<ipo::ChannelWait>(&p.items[1]);
    REQUIRE(stop != nullptr);
    CHECK(stop->line == 2);
  }
  const Pulled cont = pull("N10 G01 X10 F600\nN20 #FLUSH CONTINUE\nN30 X20\nN40 M30\n");
  REQUIRE(cont.error_id.empty());
  CHECK(cont.items.size() == 2);
}

TEST_CASE("a plain #FLUSH between two collinear lines stops the path: twice the single time") {
  // portal_3x, STEP slope: 100 mm at 100 mm/s is 1 + 1/30 + 0.001 s -> 1035 cycles (the test
  // above). Through #FLUSH the path stops at X100 and starts again; without it, or with
  // #FLUSH CONTINUE, the two lines are one 200 mm run (2035 cycles).
  CHECK(cycles_of("N10 G01 X100 F6000\nN20 X200\nN30 M30\n") == 2035);
  CHECK(cycles_of("N10 G01 X100 F6000\nN15 #FLUSH CONTINUE\nN20 X200\nN30 M30\n") == 2035);
  CHECK(cycles_of("N10 G01 X100 F6000\nN15 #FLUSH\nN20 X200\nN30 M30\n") == 2 * 1035);
  CHECK(cycles_of("N10 G01 X100 F6000\nN15 #FLUSH WAIT\nN20 X200\nN30 M30\n") == 2 * 1035);
}

TEST_CASE("dynamics weightings lower the block's limits: G131 its acceleration, G128 its v_max") {
  // portal_3x, STEP: 100 mm at 100 mm/s takes 1 + v/A + T with A 3000 mm/s^2 (1035 cycles,
  // above). G131=50 halves A: 1 + 1/15 + 0.001 s; G128=10 caps X at 50 mm/s: 2 + 50/3000 +
  // 0.001 s; G129 weights G00 only, so a G01 block keeps its time.
  CHECK(cycles_of("N10 G131=50 G01 X100 F6000\nN30 M30\n") ==
        doctest::Approx(1000.0 + 1000.0 / 15.0 + 1.0).epsilon(0.002));
  CHECK(cycles_of("N5 G130 X50\nN10 G01 X100 F6000\nN30 M30\n") ==
        doctest::Approx(1000.0 + 1000.0 / 15.0 + 1.0).epsilon(0.002));
  CHECK(cycles_of("N10 G128=10 G01 X100 F6000\nN30 M30\n") ==
        doctest::Approx(2000.0 + 1000.0 / 60.0 + 1.0).epsilon(0.002));
  CHECK(cycles_of("N10 G129=10 G01 X100 F6000\nN30 M30\n") == 1035);
  CHECK(cycles_of("N5 G130 Y50\nN10 G01 X100 F6000\nN30 M30\n") == 1035);  // Y does not move
}

TEST_CASE("an unsupported command is NC6001 at its line, never skipped") {
  const Pulled set = pull("N10 G01 X10 F600\nN20 G92 X0\nN30 X5\nN40 M30\n");
  CHECK(set.items.size() == 1);
  CHECK(set.error_id == program::kNotSupportedId);
  CHECK(set.error_line == 2);
  CHECK(set.error_message.find("not supported: G92") == 0);
}

TEST_CASE("#CONTOUR MODE DIST reaches the Move with PRE_DIST and POST_DIST; DEV is unchanged") {
  // isg-language.md §5.3 (PROG-475180811): DIST with PRE_DIST, POST_DIST (1 mm each by default).
  const Pulled p = pull(
      "N10 G01 X10 F600\n"
      "N20 #CONTOUR MODE [DIST PRE_DIST=2 POST_DIST=0.5]\n"
      "N30 G261 X20\n"
      "N40 #CONTOUR MODE [DEV PATH_DEV=0.25]\n"
      "N50 Y10\n"
      "N60 M30\n");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.items.size() == 3);
  CHECK(std::get<planner::Move>(p.items[0]).contour == planner::Contour::none);
  const auto& dist = std::get<planner::Move>(p.items[1]);
  CHECK(dist.contour == planner::Contour::distance);
  CHECK(dist.pre_dist == 2.0);
  CHECK(dist.post_dist == 0.5);
  const auto& dev = std::get<planner::Move>(p.items[2]);
  CHECK(dev.contour == planner::Contour::tolerance);
  CHECK(dev.path_dev == 0.25);
}

TEST_CASE("#CONTOUR MODE DIST_SOFT, DIST_MASTER, POS and PTP stay NC6001 with their names") {
  for (const char* mode : {"DIST_SOFT", "DIST_MASTER", "POS", "PTP"}) {
    CAPTURE(mode);
    const Pulled p = pull(std::string("N10 G01 X10 F600\nN20 #CONTOUR MODE [") + mode +
                          "]\nN30 G261 X20\nN40 M30\n");
    CHECK(p.items.size() == 1);
    CHECK(p.error_id == program::kNotSupportedId);
    CHECK(p.error_line == 3);
    CHECK(p.error_message.find(std::string("#CONTOUR MODE ") + mode + " (only DEV and DIST") !=
          std::string::npos);
  }
}

TEST_CASE("#TRAFO ON / OFF: a 0 s dwell at each switch, the moves between are transformed") {
  const Pulled p = pull(
      "N10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X10 Y0 Z-750 F600\nN40 #TRAFO OFF\n"
      "N50 G01 X0 Y0 Z0\nN60 M30\n",
      "delta_picker");
  REQUIRE(p.error_id.empty());
  REQUIRE(p.items.size() == 4);
  const auto* on = std::get_if<ipo::Dwell>(&p.items[0]);
  REQUIRE(on != nullptr);
  CHECK(on->seconds == 0.0);
  CHECK(on->line == 2);
  const auto* tcp = std::get_if<planner::Move>(&p.items[1]);
  REQUIRE(tcp != nullptr);
  CHECK(tcp->transformed);
  CHECK(tcp->end[2] == -750.0);  // the TCP, not a drive angle
  const auto* off = std::get_if<ipo::Dwell>(&p.items[2]);
  REQUIRE(off != nullptr);
  CHECK(off->line == 4);
  const auto* axes = std::get_if<planner::Move>(&p.items[3]);
  REQUIRE(axes != nullptr);
  CHECK_FALSE(axes->transformed);
  CHECK(axes->end[2] == 0.0);
}

TEST_CASE("an interpreter error ends the stream with the interpreter's diagnostic") {
  const Pulled p = pull("N10 G01 X10 F600\nN20 X[1/0]\nN30 M30\n");
  CHECK(p.items.size() == 1);
  CHECK_FALSE(p.error_id.empty());
  CHECK(p.error_id != program::kNotSupportedId);
  CHECK(p.error_line == 2);
}

TEST_CASE("machine limits: portal_3x axis lists map to the documented keys") {
  const machines::Machine& m = interp::test::machine("portal_3x");
  const ipo::Config c = program::machine_config(m, 0.001);
  REQUIRE(c.axes.size() == 3);
  const machines::Dynamics& x = m.axes[0].dynamics;
  CHECK(c.axes[0].v_max == x.v_max);
  CHECK(c.axes[0].v_reference == x.v_max);
  CHECK(c.axes[0].v_rapid == x.v_rapid);
  CHECK(c.axes[0].a_max == std::min(x.acc_feed, x.acc_max));
  CHECK(c.axes[0].d_max == std::min(x.dec_feed, x.acc_max));
  CHECK(c.axes[0].j_max == x.jerk_feed());
  CHECK(c.axes[0].c0 == x.velo_jump_factor);
  CHECK(c.axes[0].a_rapid == std::min(x.acc_rapid, x.acc_max));  // P-AXIS-00004, 00008
  CHECK(c.axes[0].j_rapid == x.acc_rapid / x.ramp_rapid);        // P-AXIS-00004 / 00200
  REQUIRE(c.exact_stop.size() == 3);
  CHECK(c.exact_stop[0].window == m.axes[0].monitoring.exact_stop_window);
  CHECK(c.exact_stop[0].settle_time == m.axes[0].monitoring.settling_time.value_or(0.0));
  CHECK(c.window == static_cast<std::size_t>(m.channel.interpolator.look_ahead_blocks));
  CHECK(c.channel.t_cycle == 0.001);
}

TEST_CASE("a long line at F takes length / F + F / A + T, rounded up to the cycle") {
  // portal_3x: X A+ = A- = 3000 mm/s^2, STEP slope: 1000 mm at 100 mm/s is 10 s
  // cruise-equivalent, plus v / A = 1/30 s for the two ramps, plus A / J = T because the
  // planner gives STEP the jerk max(A+, A-) / T (docs/planner.md): 10.03433 s -> 10035 cycles.
  const core::SourceFile file("t.nc", "N10 G01 X1000 F6000\nN20 M30\n");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  const audit::TimeResult r = audit::machining_time(program::machine_config(m, 0.001), src);
  REQUIRE(r.status == ipo::Status::finished);
  const double exact = 1000.0 / 100.0 + 100.0 / 3000.0 + 0.001;
  CHECK(r.total >= exact - 1e-9);
  CHECK(r.total < exact + 0.001 + 1e-9);
  CHECK(r.cycles == 10035);
}

TEST_CASE("the blocks before a faulty one run to their end; then the error stands") {
  // 100 mm at 100 mm/s with A = 3000 mm/s^2 (STEP): 1 + 1/30 + 0.001 s -> 1035 cycles.
  const core::SourceFile file("t.nc", "N10 G01 X100 F6000\nN20 G92 X0\nN30 X5\nN40 M30\n");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  const audit::TimeResult r = audit::machining_time(program::machine_config(m, 0.001), src);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.cycles == 1035);
  CHECK(r.distance == doctest::Approx(100.0));
  REQUIRE(src.error() != nullptr);
  CHECK(src.error()->loc.line == 2);
}

// #CAXTRACK at the adapter (docs/caxtrack.md)
TEST_CASE("#CAXTRACK: C follows the tangent + OFFSET; a corner above ANGLIMIT stops and turns C") {
  const Pulled p = pull(
      "N10 G00 X0 Y0 C0\n"
      "N20 #CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 10]\n"
      "N30 G01 X10 F600\n"
      "N40 X20 Y0.1\n"
      "N50 Y10\n"
      "N60 #CAXTRACK OFF\n"
      "N70 X0\n"
      "N80 M30\n",
      "static_saw");
  REQUIRE(p.error_id.empty());
  // G00, [stop, turn to 10], X10 at 10, X20 turning within ANGLIMIT, [stop, turn], Y10, X0
  REQUIRE(p.items.size() == 9);
  const auto move = [&](std::size_t i) { return std::get<planner::Move>(p.items.at(i)); };
  constexpr std::size_t kC = 3;
  CHECK(std::get<ipo::Dwell>(p.items[1]).seconds == 0.0);
  CHECK(move(2).rapid);
  CHECK(move(2).end[kC] == doctest::Approx(10.0));
  CHECK(move(3).start[kC] == doctest::Approx(10.0));
  CHECK(move(3).end[kC] == doctest::Approx(10.0));
  const double small = std::atan2(0.1, 10.0) * 180.0 / 3.14159265358979;
  CHECK(move(4).start[kC] == doctest::Approx(10.0));  // turned through within the block
  CHECK(move(4).end[kC] == doctest::Approx(10.0 + small));
  CHECK(std::holds_alternative<ipo::Dwell>(p.items[5]));
  CHECK(move(6).end[kC] == doctest::Approx(100.0));  // +Y: 90 + OFFSET
  CHECK(move(7).end[kC] == doctest::Approx(100.0));
  CHECK(move(8).start[kC] == doctest::Approx(100.0));  // after OFF C stays where it was left
  CHECK(move(8).end[kC] == doctest::Approx(100.0));
}

TEST_CASE("#CAXTRACK without AX= on a machine without P-CHAN-00095 has no tracking axis: NC9103") {
  const Pulled p = pull("N10 #CAXTRACK ON\nN20 G01 X1 F600\nM30\n", "portal_3x");
  CHECK(p.error_id == "NC9103");
  CHECK(p.error_line == 1);
}

TEST_CASE("x_virtual: a dwell, #FLUSH or a corner while synchronised would stop the path: NC9101") {
  // static_saw: P-CHAN-00364 x_virtual = 1; the contour runs against the conveying direction.
  const Pulled dwell = pull(
      "N10 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000]\n"
      "N20 G01 X0 Y0 F100\n"  // the catch-up
      "N30 G04 0.5\n"
      "M30\n",
      "static_saw");
  CHECK(dwell.error_id == "NC9101");
  CHECK(dwell.error_line == 3);
  const Pulled flush = pull(
      "N10 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000]\n"
      "N20 G01 X0 Y0 F100\n"  // the catch-up
      "N30 G01 X-10 Y0\n"
      "N40 #FLUSH\n"  // stops the path (isg-language.md 5.1)
      "N50 G01 X-20 Y0\n"
      "M30\n",
      "static_saw");
  CHECK(flush.error_id == "NC9101");
  CHECK(flush.error_line == 4);
  CHECK(flush.error_message.find("#FLUSH") != std::string::npos);
  const Pulled corner = pull(
      "N10 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000]\n"
      "N20 G01 X0 Y0 F100\n"  // the catch-up
      "N30 G01 X-10 Y0\n"
      "N40 G01 X-20 Y10\n"  // a 45 deg corner between unblended lines
      "M30\n",
      "static_saw");
  CHECK(corner.error_id == "NC9101");
  CHECK(corner.error_line == 4);
}

TEST_CASE("#CAXTRACK: a main axis is 120626; ROTMODE 2 and OPTALIGN are not supported") {
  CHECK(pull("N10 #CAXTRACK ON [AX=Y]\nN20 G01 X1 F600\nM30\n", "static_saw").error_id == "120626");
  const Pulled r = pull("N10 #CAXTRACK ON [AX=C, ROTMODE=2]\nN20 G01 X1 F600\nM30\n", "static_saw");
  CHECK(r.error_id == program::kNotSupportedId);
  CHECK(r.error_message.find("ROTMODE=2") != std::string::npos);
  CHECK(pull("N10 #CAXTRACK ON [AX=C, OPTALIGN=5]\nM30\n", "static_saw").error_id ==
        program::kNotSupportedId);
}

TEST_CASE("a target beyond the soft limits is check's NC4601 before it moves, when refused") {
  // issue 34 item 22: `check` said NC4601, `time` moved 48 s and stopped with NC5502
  const machines::Machine& m = interp::test::machine("portal_3x");
  const core::SourceFile file("far.nc", "%t\nG01 X100 F6000\nG00 X10000000\nM30\n");
  for (const bool refuse : {true, false}) {
    CAPTURE(refuse);
    interp::Interpreter in(file, m);
    program::ProgramSource src(in, m, program::SourceConfig{.refuse_soft_limits = refuse});
    std::vector<std::uint32_t> lines;
    ipo::Item item;
    while (src.next(item))
      if (const auto* mv = std::get_if<planner::Move>(&item)) lines.push_back(mv->line);
    if (refuse) {
      CHECK(lines == std::vector<std::uint32_t>{2});  // the block before it, not the far one
      REQUIRE(src.error() != nullptr);
      CHECK(src.error()->id == "NC4601");
      CHECK(src.error()->loc.line == 3);
    } else {
      CHECK(lines == std::vector<std::uint32_t>{2, 3});  // the per-cycle monitor's matter
      CHECK(src.error() == nullptr);
    }
  }
}
