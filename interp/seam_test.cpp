// The seam: every motion names its frame and carries start, end and centre in it; the position
// is re-based at #CS, #TRAFO, #SYNC IN/OUT, G74 and INDP moves; barriers stop the stream before
// blocks that need run-time state and resume() feeds it in.
#include <doctest/doctest.h>

#include <stdexcept>

#include "interp/test_support.hpp"
#include "machines/kinematics.hpp"

namespace ncsim::interp {
namespace {

using test::run;

/// Every command of `text` on `machine`, barriers answered by `answer` (decode-only if empty).
struct Stream {
  std::vector<Command> commands;
  std::vector<std::string> lines;
  std::string error_id;
};

template <typename Answer>
Stream stream(const std::string& text, const machines::Machine& m, Answer answer,
              Options options = {}) {
  core::SourceFile file("test.nc", text);
  Interpreter interp(file, m, std::move(options));
  Stream s;
  while (auto c = interp.next()) {
    s.lines.push_back(to_trace_line(*c, m));
    s.commands.push_back(*c);
    if (const auto* b = std::get_if<Barrier>(&c->body)) {
      RunState state = interp.decode_only_state(*b);
      answer(*b, state);
      interp.resume(state);
    }
  }
  if (interp.error() != nullptr) s.error_id = interp.error()->id;
  return s;
}

Stream stream(const std::string& text, const std::string& machine_name = "portal_3x") {
  return stream(text, test::machine(machine_name), [](const Barrier&, RunState&) {});
}

const Motion* motion_at(const Stream& s, std::uint32_t line) {
  for (const auto& c : s.commands) {
    if (c.line == line) {
      if (const auto* m = std::get_if<Motion>(&c.body)) return m;
    }
  }
  return nullptr;
}

std::string line_at(const Stream& s, std::uint32_t line, std::string_view kind) {
  for (const auto& l : s.lines) {
    if (l.starts_with(std::to_string(line) + ": " + std::string(kind))) return l;
  }
  return "";
}

TEST_CASE("#CS ON re-bases the position: an arc after it starts and turns in the PCS") {
  // MCS (10, 0, 0) is PCS (0, 0, 0) under a shift of 10 in X: the circle closes on its start.
  auto s = stream("%t\nG00 X10 Y0 Z0\n#CS ON [10, 0, 0, 0, 0, 0]\nG02 X0 Y0 I5 J0 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 4, "G02") ==
        "4: G02 X=0.0000 Y=0.0000 Z=0.0000 F=10.0000 centre X=5.0000 Y=0.0000 R=5.0000 FULL CS "
        "frame=PCS/CS1 start X=0.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("#CS ON with a rotation re-bases through the rotation; #CS OFF returns to the MCS") {
  // Shift (10, 20, 0), 90 degrees about Z (ZYX): MCS (10, 0, 0) -> PCS R^-1 (0, -20, 0) =
  // (-20, 0, 0). After #CS OFF the PCS end (-20, 10, 0) is MCS (10 - 10, 20 - 20, 0) = (0, 0, 0).
  auto s = stream(
      "%t\nG00 X10 Y0 Z0\n#CS ON [10, 20, 0, 90, 0, 0]\nG01 X-20 Y10 F600\n#CS OFF\n"
      "G01 X5 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  const Motion* in_cs = motion_at(s, 4);
  REQUIRE(in_cs != nullptr);
  CHECK(in_cs->frame == CoordFrame{Space::pcs, 1, false});
  CHECK(in_cs->start[0] == doctest::Approx(-20.0));
  CHECK(in_cs->start[1] == doctest::Approx(0.0).epsilon(1e-12));
  const Motion* after = motion_at(s, 6);
  REQUIRE(after != nullptr);
  CHECK(after->frame == CoordFrame{Space::mcs, 0, false});
  CHECK(after->start[0] == doctest::Approx(0.0).epsilon(1e-12));
  CHECK(after->start[1] == doctest::Approx(0.0).epsilon(1e-12));
  CHECK(after->end[0] == doctest::Approx(5.0));
}

TEST_CASE("pick_and_place line 19: after #TRAFO ON the start is Cartesian, not joint angles") {
  const machines::Machine& m = test::machine("delta_picker");
  core::SourceFile file =
      core::SourceFile::load(test::source_root() / "programs/pick_and_place/pick_and_place.nc");
  Interpreter interp(file, m);
  const Motion* found = nullptr;
  std::vector<Command> keep;
  for (int k = 0; k < 40 && found == nullptr; ++k) {
    auto c = interp.next_decode_only();
    REQUIRE(c.has_value());
    keep.push_back(*c);
    if (c->line == 19) found = std::get_if<Motion>(&keep.back().body);
  }
  REQUIRE(found != nullptr);
  CHECK(found->frame == CoordFrame{Space::mcs, 0, true});
  // The joint angles of line 12 (34.9485, -18.0290, 34.0535) through the delta's forward
  // transform: the same point, now in the frame of the end (-100, 0, -700).
  const auto& trafo = m.channel.trafos.front();
  auto kin = machines::make_kinematics(trafo.id, trafo.param);
  REQUIRE(kin.kinematics != nullptr);
  auto tcp = kin.kinematics->forward(Eigen::Vector3d(34.9485, -18.0290, 34.0535));
  REQUIRE(tcp.ok());
  CHECK(found->start[0] == doctest::Approx(tcp.value[0]));
  CHECK(found->start[1] == doctest::Approx(tcp.value[1]));
  CHECK(found->start[2] == doctest::Approx(tcp.value[2]));
  CHECK(found->start[2] < -500.0);  // a TCP height, not the joint angle 34.05
  CHECK(found->end[0] == -100.0);
  CHECK(found->end[2] == -700.0);
}

TEST_CASE("#TRAFO OFF re-bases back to the joint angles") {
  auto s = stream("%t\n#KIN ID[37]\nG00 X30 Y30 Z30\n#TRAFO ON\n#TRAFO OFF\nG01 X31 F600\nM30\n",
                  "delta_picker");
  REQUIRE(s.error_id.empty());
  const Motion* m = motion_at(s, 6);
  REQUIRE(m != nullptr);
  CHECK(m->frame == CoordFrame{Space::mcs, 0, false});
  CHECK(m->start[0] == doctest::Approx(30.0));
  CHECK(m->start[1] == doctest::Approx(30.0));
  CHECK(m->start[2] == doctest::Approx(30.0));
}

const char* kSync =
    "%t\nG00 X100 Y50 Z10\nS1[MC_TouchProbe Channel=1]\n#SYNC IN [CONVEYOR=S1, CONV_VEL=18000]\n"
    "G01 X10 Y0 Z0 F600\n#SYNC OUT\nG01 X200 F600\nM30\n";

TEST_CASE("the catch-up after #SYNC IN starts and ends in PCS1 (decode-only: T0, travel 0)") {
  machines::Machine m = test::machine("laser_portal");
  REQUIRE(m.channel.conveyor.has_value());
  m.channel.conveyor->t0_shift = Eigen::Vector3d(30.0, 5.0, 0.0);  // PCS0 origin at MCS (30, 5, 0)
  auto s = stream(kSync, m, [](const Barrier&, RunState&) {});
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 4, "BARRIER") == "4: BARRIER PROBE_LATCH S");
  CHECK(line_at(s, 5, "BARRIER") == "5: BARRIER POSITION frame=PCS1 X Y Z");
  const Motion* catch_up = motion_at(s, 5);
  REQUIRE(catch_up != nullptr);
  CHECK(catch_up->frame == CoordFrame{Space::pcs1, 0, false});
  CHECK(catch_up->start[0] == doctest::Approx(70.0));  // MCS 100 - T0 30
  CHECK(catch_up->start[1] == doctest::Approx(45.0));  // MCS 50 - T0 5
  CHECK(catch_up->start[2] == doctest::Approx(10.0));
  // after #SYNC OUT: back in the MCS, from the PCS1 end (10, 0, 0) + T0
  const Motion* out = motion_at(s, 7);
  REQUIRE(out != nullptr);
  CHECK(out->frame == CoordFrame{Space::mcs, 0, false});
  CHECK(out->start[0] == doctest::Approx(40.0));
  CHECK(out->start[1] == doctest::Approx(5.0));
}

TEST_CASE("resume() gives the catch-up the actual PCS1 position and SyncIn the latch") {
  const machines::Machine& m = test::machine("laser_portal");
  auto s = stream(kSync, m, [](const Barrier& b, RunState& state) {
    if (b.wants(BarrierNeed::probe_latch)) state.latch = 1234.5;
    if (b.wants(BarrierNeed::position) && b.frame.space == Space::pcs1) {
      state.position[0] = -250.0;  // the workpiece came 350 mm on since the latch
      state.position[1] = 50.0;
      state.position[2] = 10.0;
    }
  });
  REQUIRE(s.error_id.empty());
  const Motion* catch_up = motion_at(s, 5);
  REQUIRE(catch_up != nullptr);
  CHECK(catch_up->start[0] == -250.0);
  CHECK(catch_up->end[0] == 10.0);
  for (const auto& c : s.commands) {
    if (const auto* in = std::get_if<SyncIn>(&c.body)) CHECK(in->latch == 1234.5);
  }
}

TEST_CASE("after G74 the homed axes' position comes through a barrier") {
  auto s = stream("%t\nG00 X10 Y20\nG74 X1 Y2\nP1 = 3\nG01 X5 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  // No barrier before the assignment: it does not use the position.
  CHECK(line_at(s, 4, "BARRIER").empty());
  CHECK(line_at(s, 5, "BARRIER") == "5: BARRIER POSITION frame=MCS X Y");
  core::SourceFile file("test.nc", "%t\nG00 X10 Y20\nG74 X1 Y2\nG01 X5 F600\nM30\n");
  Interpreter interp(file, test::machine());
  const Motion* m = nullptr;
  std::vector<Command> keep;
  while (auto c = interp.next()) {
    keep.push_back(*c);
    if (const auto* b = std::get_if<Barrier>(&c->body)) {
      RunState st = interp.decode_only_state(*b);
      st.position[0] = 0.0;  // homed to the reference points
      st.position[1] = -5.0;
      interp.resume(st);
    }
  }
  for (const auto& c : keep) {
    if (c.line == 4) m = std::get_if<Motion>(&c.body);
  }
  REQUIRE(m != nullptr);
  CHECK(m->start[0] == 0.0);
  CHECK(m->start[1] == -5.0);
}

TEST_CASE("after INDP_ASYN the axis position is run-time state; INDP_SYN is not") {
  auto s = stream(
      "%t\nG00 X0 Y0 Z0\nX[INDP_SYN POS10 FEED600]\nG01 Y5 F600\nX[INDP_ASYN POS20 FEED600]\n"
      "G01 Y6 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 4, "BARRIER").empty());
  // A block that does not program X does not ask for it (P-CHAN-00451).
  CHECK(line_at(s, 6, "BARRIER").empty());
  const Motion* m = motion_at(s, 6);
  REQUIRE(m != nullptr);
  CHECK(m->start[0] == 20.0);  // the decoder carries the target; the INDP layer owns X
  CHECK(line_at(s, 5, "INDP_ASYN").ends_with(" frame=MCS"));
}

// isg-language.md 6.1, INDP_ASYN "is synchronised by #WAIT INDP or by programming
// the axis again as a path axis" (P-CHAN-00451, docs/ipo.md "Position barriers").
TEST_CASE("after INDP_ASYN only a block that programs the axis asks for it, with implicit sync") {
  auto s = stream("%t\nX[INDP_ASYN POS20 FEED600]\nG01 Y6 F600\nG91 X2\nG90 G01 Y7\nY8 X30\nM30\n");
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 3, "BARRIER").empty());  // Y only: X runs on beside it
  CHECK(line_at(s, 4, "BARRIER") == "4: BARRIER POSITION frame=MCS X");
  const Motion* m = motion_at(s, 4);
  REQUIRE(m != nullptr);
  CHECK(m->start[0] == 20.0);  // decode-only answer: the target
  CHECK(m->end[0] == 22.0);
  CHECK(line_at(s, 5, "BARRIER").empty());  // known again
  CHECK(line_at(s, 6, "BARRIER").empty());
}

TEST_CASE("after INDP_ASYN an arc asks for every unknown axis: its plane may hold it") {
  auto s = stream("%t\nG00 X0 Y0\nX[INDP_ASYN POS20 FEED600]\nG02 Y6 I0 J3 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 4, "BARRIER") == "4: BARRIER POSITION frame=MCS X");
}

TEST_CASE("a V.E. read between motions: the barrier stands before the block that reads it") {
  const char* text = "%t\nG01 X1 F600\nP1 = V.E.PART * 10\nG01 X[P1] F600\nM30\n";
  Options options;
  options.external["PART"] = 3.0;  // --ve PART=3: the decode-only value
  auto s = stream(
      text, test::machine(), [](const Barrier&, RunState&) {}, options);
  REQUIRE(s.error_id.empty());
  REQUIRE(s.lines.size() >= 3);
  CHECK(s.lines[0].starts_with("2: G01 X=1.0000"));
  CHECK(s.lines[1] == "3: BARRIER FLUSH V.E.READ V.E.PART");
  CHECK(s.lines[2].starts_with("4: G01 X=30.0000"));
  // Without a value anywhere, the read is NC4011 as before.
  CHECK(stream(text).error_id == "NC4011");

  // Two run-time values through resume give two different motions.
  std::vector<double> ends;
  for (double part : {2.0, 7.0}) {
    auto r = stream(text, test::machine(), [&](const Barrier& b, RunState& st) {
      REQUIRE(b.external == std::vector<std::string>{"PART"});
      st.external["PART"] = part;
    });
    const Motion* m = motion_at(r, 4);
    REQUIRE(m != nullptr);
    ends.push_back(m->end[0]);
  }
  CHECK(ends == std::vector<double>{20.0, 70.0});
}

TEST_CASE("a V.E. read in $IF gets its barrier on the $IF line; a V.E. write none") {
  Options options;
  options.external["READY"] = 1.0;
  auto s = stream(
      "%t\nV.E.OUT = 1\n$IF V.E.READY == 1\nG00 X1\n$ENDIF\nM30\n", test::machine(),
      [](const Barrier&, RunState&) {}, options);
  REQUIRE(s.error_id.empty());
  REQUIRE(!s.lines.empty());
  CHECK(s.lines[0] == "3: BARRIER FLUSH V.E.READ V.E.READY");
}

TEST_CASE("a V.E. read inside a string macro gets its barrier too") {
  Options options;
  options.external["GAP"] = 4.0;
  auto s = stream(
      "%t\n\"SHIFT\" = \"V.E.GAP * 2\"\nG00 X[\"SHIFT\"]\nM30\n", test::machine(),
      [](const Barrier&, RunState&) {}, options);
  REQUIRE(s.error_id.empty());
  REQUIRE(s.lines.size() >= 2);
  CHECK(s.lines[0] == "3: BARRIER FLUSH V.E.READ V.E.GAP");
  CHECK(s.lines[1].starts_with("3: G00 X=8.0000"));
}

TEST_CASE("a loop that waits for a V.E. value is not 'cannot end': each pass is a barrier") {
  // Run time: the outside world sets READY on the fifth answer and the loop ends.
  const std::string text = "%t\n$WHILE V.E.READY == 0\n$ENDWHILE\nG00 X5\nM30\n";
  int answers = 0;
  auto s = stream(text, test::machine(), [&](const Barrier&, RunState& st) {
    st.external["READY"] = ++answers >= 5 ? 1.0 : 0.0;
  });
  CHECK(s.error_id.empty());
  CHECK(answers == 5);
  REQUIRE(motion_at(s, 4) != nullptr);
  // Decode-only (check, trace): READY stays 0, so the program waits forever: a program that
  // runs endlessly (NC4904 in check), never NC4901.
  core::SourceFile file("test.nc", text);
  Options options;
  options.external["READY"] = 0.0;  // --ve READY=0
  Interpreter interp(file, test::machine(), options);
  for (int i = 0; i < 1000 && interp.next_decode_only(); ++i) {
  }
  CHECK(interp.error() == nullptr);
  CHECK(interp.endless_from().has_value());
}

TEST_CASE("a V.E. read in a loop body stops the stream on every pass") {
  core::SourceFile file("test.nc",
                        "%t\n$FOR P1 = 1, 3, 1\nP2 = V.E.PART\nG00 X[P2]\n$ENDFOR\nM30\n");
  Interpreter interp(file, test::machine());
  std::vector<double> xs;
  double part = 10.0;
  while (auto c = interp.next()) {
    if (const auto* b = std::get_if<Barrier>(&c->body)) {
      RunState st = interp.decode_only_state(*b);
      st.external["PART"] = part;
      part += 1.0;
      interp.resume(st);
    } else if (const auto* m = std::get_if<Motion>(&c->body)) {
      xs.push_back(m->end[0]);
    }
  }
  REQUIRE(interp.error() == nullptr);
  CHECK(xs == std::vector<double>{10.0, 11.0, 12.0});
}

TEST_CASE("an INDP move after INDP_ASYN asks only for its own axis") {
  auto s = stream(
      "%t\nX[INDP_ASYN POS20 FEED600] Y[INDP_ASYN POS5 FEED600]\nZ[INDP_SYN POS1 FEED600]\n"
      "Y[INDP_SYN POS2 FEED600]\nG01 X1 F600\nM30\n");
  REQUIRE(s.error_id.empty());
  CHECK(line_at(s, 3, "BARRIER").empty());                               // Z is known
  CHECK(line_at(s, 4, "BARRIER") == "4: BARRIER POSITION frame=MCS Y");  // Y only
  CHECK(line_at(s, 5, "BARRIER") == "5: BARRIER POSITION frame=MCS X");  // Y known again
}

TEST_CASE("next() before resume() after a barrier, and resume() without one, throw") {
  core::SourceFile file("test.nc", "%t\nP1 = V.E.A\nG00 X[P1]\nM30\n");
  Options options;
  options.external["A"] = 1.0;
  Interpreter interp(file, test::machine(), options);
  CHECK_THROWS_AS(interp.resume(RunState{}), std::logic_error);
  auto c = interp.next();
  REQUIRE(c.has_value());
  REQUIRE(std::holds_alternative<Barrier>(c->body));
  CHECK_THROWS_AS(interp.next(), std::logic_error);
  interp.resume(interp.decode_only_state(std::get<Barrier>(c->body)));
  auto m = interp.next();
  REQUIRE(m.has_value());
  CHECK(std::holds_alternative<Motion>(m->body));
}

TEST_CASE("resume() with positions in another frame than asked is API misuse") {
  core::SourceFile file("test.nc", "%t\nG74 X1\nG00 X1\nM30\n");
  Interpreter interp(file, test::machine());
  std::optional<Command> c;
  while ((c = interp.next()) && !std::holds_alternative<Barrier>(c->body)) {
  }
  REQUIRE(c.has_value());
  RunState st = interp.decode_only_state(std::get<Barrier>(c->body));
  st.frame.space = Space::pcs1;
  CHECK_THROWS_AS(interp.resume(st), std::logic_error);
}

TEST_CASE("a #SPLINE section streams: each point with its own line, feed and frame") {
  auto s = stream(
      "%t\nG00 X0 Y0\n#SPLINE ON\nG01 X1 Y1 F600\nG01 X2 Y0 F1200\nG01 X3 Y1\n#SPLINE OFF\n"
      "M30\n");
  REQUIRE(s.error_id.empty());
  REQUIRE(s.lines.size() >= 6);
  CHECK(s.lines[1] == "3: SPLINE_BEGIN AKIMA frame=MCS start X=0.0000 Y=0.0000 Z=0.0000");
  CHECK(s.lines[2] == "4: SPLINE_POINT 1 X=1.0000 Y=1.0000 Z=0.0000 F=10.0000 frame=MCS");
  CHECK(s.lines[3] == "5: SPLINE_POINT 2 X=2.0000 Y=0.0000 Z=0.0000 F=20.0000 frame=MCS");
  CHECK(s.lines[4] == "6: SPLINE_POINT 3 X=3.0000 Y=1.0000 Z=0.0000 F=20.0000 frame=MCS");
  CHECK(s.lines[5] == "7: SPLINE_END AKIMA points=4");
}

TEST_CASE("a spline point without a feed is 20008 at the point") {
  auto r = run("%t\n#SPLINE ON\nG01 X1 Y1\nG01 X2\nG01 X3\n#SPLINE OFF\nM30\n");
  CHECK(r.error_id == "20008");
  CHECK(r.error_line == 3);
}

}  // namespace
}  // namespace ncsim::interp
