// The channel loop playing a scenario (docs/scenario.md "Wiring into the channel loop"): [stop]
// conditions end the run with their reason, V.E. writes reach the barriers after them, override
// and feed hold are refused at run time until the interpolator's override is wired.

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"

namespace {

using namespace ncsim;

using channel::test::Recorder;

struct Played {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::Cycle> cycles;
  std::optional<scenario::StopReason> stop;
  std::optional<channel::RunTimeError> error;
  std::string source_error;
};

scenario::Scenario parse(const std::string& toml) {
  const core::SourceFile file("s.toml", toml);
  scenario::LoadResult r = scenario::parse_scenario(file);
  REQUIRE(r.scenario);
  return std::move(*r.scenario);
}

// Runs `program` on portal_3x (1 ms) under `toml`; `flush` as the CLI sets it.
Played play(const std::string& program, const std::string& toml, bool flush = true) {
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Options options;
  const scenario::Scenario s = parse(toml);
  for (const scenario::VeInitial& v : s.ve)
    options.external.emplace(v.name, v.value);
  interp::Interpreter in(file, m, options);
  program::ProgramSource src(in, m);
  scenario::Player player(s);
  src.answer_barriers_from(&player.ve(), flush);
  Recorder rec;
  channel::Channel ch(channel::channel_config(m, 0.001), src, &rec);
  ch.play(&player);
  Played r;
  r.status = channel::test::run_to_end(ch);
  CHECK(ch.step() == r.status);  // the stream stays ended
  r.cycles = std::move(rec.cycles);
  r.stop = ch.scenario_stop();
  r.error = ch.run_time_error();
  if (const core::Diagnostic* d = src.error()) r.source_error = d->id;
  return r;
}

const char* const kBranch =
    "%b\n"                // 1
    "N10 G01 X10 F600\n"  // 2: 1 s
    "$IF V.E.SEL == 1\n"  // 3
    "N20 G01 Y20\n"       // 4
    "$ELSE\n"             // 5
    "N30 G01 Y5\n"        // 6
    "$ENDIF\n"            // 7
    "N40 M30\n";          // 8

bool ran_line(const Played& r, std::uint32_t line) {
  for (const ipo::Cycle& c : r.cycles)
    if (c.line == line) return true;
  return false;
}

}  // namespace

TEST_CASE("[stop] time ends the run before the first cycle at or after it, reason stop.time") {
  const Played r = play(kBranch, "[ve]\nSEL = 0\n[stop]\ntime = 0.25\n");
  CHECK(r.status == ipo::Status::finished);
  REQUIRE(r.stop);
  CHECK(*r.stop == scenario::StopReason::time);
  REQUIRE(r.cycles.size() == 250);
  CHECK(r.cycles.back().t == doctest::Approx(0.25));
  CHECK(r.cycles.back().x[0] < 10.0);  // stopped inside the move
  CHECK_FALSE(r.error);
}

TEST_CASE("[stop] cycles ends the run after that many cycles, reason stop.cycles") {
  const Played r = play(kBranch, "[ve]\nSEL = 0\n[stop]\ncycles = 123\n");
  REQUIRE(r.stop);
  CHECK(*r.stop == scenario::StopReason::cycles);
  CHECK(r.cycles.size() == 123);
}

TEST_CASE("[stop] passes ends the run when the n-th pass of the line has ended") {
  const char* loop =
      "%l\n"                       // 1
      "N10 G90 G01 X0 Y0 F6000\n"  // 2
      "$FOR P1 = 1, 5, 1\n"        // 3
      "N20 G91 X10\n"              // 4
      "N30 Y10\n"                  // 5
      "$ENDFOR\n"                  // 6
      "N40 M30\n";                 // 7
  const Played r = play(loop, "[stop]\nline = 4\npasses = 2\n");
  REQUIRE(r.stop);
  CHECK(*r.stop == scenario::StopReason::line_passes);
  int entries = 0;
  std::uint32_t prev = 0;
  for (const ipo::Cycle& c : r.cycles) {
    if (c.line == 4 && prev != 4) ++entries;
    prev = c.line;
  }
  CHECK(entries == 2);
  CHECK(r.cycles.back().line == 5);  // the block after the 2nd pass had started
  CHECK(r.cycles.back().x[0] == doctest::Approx(20.0));

  const Played whole = play(loop, "[stop]\ncycles = 1000000\n");
  CHECK_FALSE(whole.stop);
  CHECK(whole.cycles.back().x[0] == doctest::Approx(50.0));
}

TEST_CASE("a V.E. write at a time reaches the $IF after it through the barrier's flush") {
  const std::string write_at = "[ve]\nSEL = 0\n[[event]]\nat = 0.5\nve = { SEL = 1 }\n";
  const Played r = play(kBranch, write_at);
  CHECK(r.status == ipo::Status::finished);
  CHECK_FALSE(r.stop);
  CHECK(ran_line(r, 4));
  CHECK_FALSE(ran_line(r, 6));
  CHECK(r.cycles.back().x[1] == doctest::Approx(20.0));

  // Without the write the $ELSE branch runs.
  const Played no_write = play(kBranch, "[ve]\nSEL = 0\n[stop]\ncycles = 1000000\n");
  CHECK(ran_line(no_write, 6));
  CHECK_FALSE(ran_line(no_write, 4));

  // A write after the barrier was answered comes too late for it.
  const Played late = play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 1.5\nve = { SEL = 1 }\n");
  CHECK(ran_line(late, 6));
  CHECK_FALSE(ran_line(late, 4));

  // Without the flush the look-ahead decodes the $IF at the start, before the write.
  const Played ahead = play(kBranch, write_at, false);
  CHECK(ran_line(ahead, 6));
}

TEST_CASE("the flush stops the path at the barrier: no motion crosses it") {
  const Played r = play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 0.5\nve = { SEL = 1 }\n");
  // The cycle that ends line 2 stands at X10 with v = 0 before line 4 starts.
  bool stood = false;
  for (std::size_t k = 1; k < r.cycles.size(); ++k)
    if (r.cycles[k].line == 4 && r.cycles[k - 1].line == 2)
      stood = r.cycles[k - 1].x[0] == 10.0 && r.cycles[k - 1].path.v == 0.0;
  CHECK(stood);
}

TEST_CASE("path override and feed hold events reach the interpolator") {
  const std::string ve = "[ve]\nSEL = 0\n";
  const Played plain = play(kBranch, ve + "[stop]\ncycles = 1000000\n");
  // A 0.5 s feed hold from 0.2 s: the run is longer by about the hold; the contour is the same.
  const Played hold = play(kBranch, ve + "[[event]]\nat = 0.2\nfeed_hold = true\nduration = 0.5\n");
  CHECK(hold.status == ipo::Status::finished);
  CHECK_FALSE(hold.error);
  const double t_plain = plain.cycles.back().t;
  const double t_hold = hold.cycles.back().t;
  CHECK(t_hold > t_plain + 0.45);
  CHECK(t_hold < t_plain + 0.6);
  CHECK(hold.cycles.back().x == plain.cycles.back().x);
  bool stood = false;  // some cycle inside the hold stands on line 2 short of X10
  for (const ipo::Cycle& c : hold.cycles)
    if (c.t > 0.5 && c.t < 0.6 && c.line == 2 && c.path.v == 0.0 && c.x[0] < 10.0) stood = true;
  CHECK(stood);
  // 50 % from 0.1 s: slower (REDUCED type of portal_3x), same end point.
  const Played half = play(kBranch, ve + "[[event]]\nat = 0.1\noverride = 50\n");
  CHECK_FALSE(half.error);
  CHECK(half.cycles.back().t > t_plain + 1.0);
  CHECK(half.cycles.back().x == plain.cycles.back().x);
}

TEST_CASE(
    "NC6102: a path override above the type's largest stops the channel; NC6105 an axis "
    "override above 100 % or of no channel axis") {
  const Played r = play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 0.1\noverride = 150\n");
  CHECK(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == std::string(channel::kOverrideRangeId));
  CHECK(r.cycles.size() == 100);  // the run ends before the cycle at 0.1 s

  // An axis with no INDP motion keeps the override for its next one (002_* 2.2).
  const Played plain = play(kBranch, "[ve]\nSEL = 0\n");
  const Played ax =
      play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 0.1\naxis_override = { X = 50 }\n");
  CHECK_FALSE(ax.error);
  CHECK(ax.cycles.size() == plain.cycles.size());
  const Played high =
      play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 0.1\naxis_override = { X = 150 }\n");
  REQUIRE(high.error);
  CHECK(high.error->id == std::string(channel::kIndpOverrideId));
  CHECK(high.cycles.size() == 100);
  const Played none =
      play(kBranch, "[ve]\nSEL = 0\n[[event]]\nat = 0.1\naxis_override = { S = 50 }\n");
  REQUIRE(none.error);
  CHECK(none.error->id == std::string(channel::kIndpOverrideId));
}

TEST_CASE("reruns under a scenario are identical to the bit") {
  const std::string s =
      "[ve]\nSEL = 0\n[[event]]\nat = 0.5\nve = { SEL = 1 }\n[stop]\ntime = 1.7\n";
  const Played a = play(kBranch, s);
  const Played b = play(kBranch, s);
  REQUIRE(a.cycles.size() == b.cycles.size());
  for (std::size_t k = 0; k < a.cycles.size(); ++k) {
    CHECK(a.cycles[k].t == b.cycles[k].t);
    CHECK(a.cycles[k].x == b.cycles[k].x);
    CHECK(a.cycles[k].line == b.cycles[k].line);
  }
  REQUIRE(a.stop);
  CHECK(*a.stop == scenario::StopReason::time);
}
