// The channel under a scenario, issue 13 leftovers (helper "operator"):
// - block starts (docs/ipo.md "Block starts", docs/scenario.md "When events fire"): every block
//   that starts reaches the player, also several within one cycle, and a `line` event fires in
//   the cycle in which its block starts;
// - the program's own V.E. writes reach the shared store (docs/scenario.md "The program's V.E.
//   writes").

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "channel/channel.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"

namespace {

using namespace ncsim;

// Per cycle, as the sink sees it (after the cycle was computed).
struct Seen {
  double x = 0.0;              // [mm] X at the cycle's end
  std::uint32_t line = 0;      // the cycle's line
  std::optional<double> done;  // V.E.DONE after the cycle
  std::uint32_t passes = 0;    // passes of the watched line
};

struct Watch final : ipo::Sink {
  const scenario::Player* player = nullptr;
  std::uint32_t line = 0;
  std::vector<Seen> seen;
  void on_joint(const ipo::Joint&) override {}
  void on_cycle(const ipo::Cycle& c) override {
    seen.push_back(Seen{c.x[0], c.line, player->ve().read("DONE"), player->passes(line)});
  }
};

struct Run {
  ipo::Status status = ipo::Status::finished;
  std::vector<Seen> seen;
  std::vector<std::uint32_t> passes;              // of each line 1..n at the end
  std::map<std::string, double, std::less<>> ve;  // the store at the end
  std::string error_id;                           // the run-time error's id, if any
};

bool ran_line(const Run& r, std::uint32_t line) {
  for (const Seen& s : r.seen)
    if (s.line == line) return true;
  return false;
}

// Runs `program` on portal_3x with cycle `t_cycle` under `toml`, watching line `watch`.
Run play(const std::string& program, const std::string& toml, std::uint32_t watch,
         double t_cycle = 0.001) {
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine("portal_3x");
  const core::SourceFile sfile("s.toml", toml);
  scenario::LoadResult loaded = scenario::parse_scenario(sfile);
  REQUIRE(loaded.scenario);
  const scenario::Scenario& s = *loaded.scenario;
  interp::Interpreter in(file, m, interp::Options{});
  program::ProgramSource src(in, m);
  scenario::Player player(s);
  bool writes = false;  // as the CLI decides the flush
  for (const scenario::Event& e : s.events)
    for (const scenario::Action& a : e.actions)
      writes = writes || std::holds_alternative<scenario::VeWrite>(a);
  src.answer_barriers_from(&player.ve(), writes);
  Watch w;
  w.player = &player;
  w.line = watch;
  channel::Channel ch(channel::channel_config(m, t_cycle), src, &w);
  ch.play(&player);
  Run r;
  for (int guard = 0; guard < 1'000'000; ++guard) {
    r.status = ch.step();
    if (r.status != ipo::Status::running) break;
  }
  if (const auto& e = ch.run_time_error()) r.error_id = e->id;
  r.seen = std::move(w.seen);
  for (std::uint32_t l = 1; l <= 12; ++l)
    r.passes.push_back(player.passes(l));
  r.ve = player.ve().values();
  return r;
}

// The first cycle whose end position is clearly past x (the one before clearly short of it).
std::optional<std::size_t> crossing(const std::vector<Seen>& seen, double x) {
  for (std::size_t k = 1; k < seen.size(); ++k)
    if (seen[k - 1].x < x - 1e-7 && seen[k].x > x + 1e-7) return k;
  return std::nullopt;
}

}  // namespace

TEST_CASE(
    "blocks shorter than a cycle in one chain all reach the player; the line event fires "
    "in the cycle its pass starts") {
  // 50 passes of a 0.01 mm line at 100 mm/s: several blocks per 1 ms cycle (one chain).
  const char* program =
      "%s\n"                       // 1
      "N10 G90 G01 X0 Y0 F6000\n"  // 2
      "$FOR P1 = 1, 50, 1\n"       // 3
      "N20 G91 X0.01\n"            // 4
      "$ENDFOR\n"                  // 5
      "N30 G90 X10\n"              // 6
      "N40 M30\n";                 // 7
  const Run r = play(program, "[[event]]\nline = 4\npass = 40\nve = { DONE = 1 }\n", 4);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.passes[4 - 1] == 50);
  // More passes than cycles spent on line 4: blocks shorter than a cycle were counted.
  std::size_t on_line = 0;
  for (const Seen& s : r.seen)
    on_line += s.line == 4 ? 1 : 0;
  CHECK(on_line < 50);
  // The 40th pass starts at X = 0.39: the cycle that crosses it already holds DONE.
  const auto k = crossing(r.seen, 0.39);
  REQUIRE(k);
  CHECK_FALSE(r.seen[*k - 1].done);
  CHECK(r.seen[*k].done == 1.0);
  CHECK(r.seen[*k].passes >= 40);  // several passes start per cycle
  CHECK(r.seen[*k - 1].passes < 40);
  CHECK(r.seen[*k].passes - r.seen[*k - 1].passes > 1);
}

TEST_CASE("blocks shorter than a cycle in separate entries and a dwell all reach the player") {
  // Alternating feeds: collinear blocks not chained (two feeds), joined at speed.
  const char* program =
      "%s\n"                       // 1
      "N10 G90 G01 X0 Y0 F6000\n"  // 2
      "$FOR P1 = 1, 30, 1\n"       // 3
      "N20 G91 X0.01 F6000\n"      // 4
      "N30 X0.01 F5940\n"          // 5
      "$ENDFOR\n"                  // 6
      "N40 G04 X0.01\n"            // 7: 10 ms dwell
      "N50 G90 X10\n"              // 8
      "N60 M30\n";                 // 9
  const Run r = play(program,
                     "[[event]]\nline = 5\npass = 30\nve = { DONE = 1 }\n"
                     "[[event]]\nline = 4\npass = 31\nve = { NEVER = 1 }\n"
                     "[[event]]\nline = 7\nve = { DWELL = 1 }\n"
                     "[[event]]\nline = 8\nve = { LAST = 1 }\n",
                     5);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.passes[4 - 1] == 30);
  CHECK(r.passes[5 - 1] == 30);
  CHECK(r.passes[7 - 1] == 1);
  CHECK(r.passes[8 - 1] == 1);
  // The 30th pass of line 5 starts at X = 0.59.
  const auto k = crossing(r.seen, 0.59);
  REQUIRE(k);
  CHECK_FALSE(r.seen[*k - 1].done);
  CHECK(r.seen[*k].done == 1.0);
}

TEST_CASE("a 4 ms cycle: every pass of a short block counts and events fire once") {
  const char* program =
      "%s\n"                       // 1
      "N10 G90 G01 X0 Y0 F6000\n"  // 2
      "$FOR P1 = 1, 200, 1\n"      // 3
      "N20 G91 X0.05\n"            // 4
      "$ENDFOR\n"                  // 5
      "N30 M30\n";                 // 6
  const Run r = play(program, "[[event]]\nline = 4\npass = 200\nfeed_hold = true\nduration = 0.1\n",
                     4, 0.004);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.passes[4 - 1] == 200);
  CHECK(r.seen.back().x == doctest::Approx(10.0));
}

// The program writes V.E.SEL = 1 before it reads it in $IF (a barrier answered from the store).
const char* const kOwnWrite =
    "%v\n"                // 1
    "N10 G01 X10 F600\n"  // 2: 1 s
    "V.E.SEL = 1\n"       // 3
    "$IF V.E.SEL == 1\n"  // 4
    "N20 G01 Y20\n"       // 5
    "$ELSE\n"             // 6
    "N30 G01 Y5\n"        // 7
    "$ENDIF\n"            // 8
    "N40 M30\n";          // 9

TEST_CASE("the program's own V.E. write reaches the store: a later barrier reads it") {
  SUBCASE("with the flush (the scenario writes V.E. too)") {
    const Run r = play(kOwnWrite, "[ve]\nSEL = 0\n[[event]]\nat = 5\nve = { OTHER = 1 }\n", 0);
    CHECK(ran_line(r, 5));
    CHECK_FALSE(ran_line(r, 7));
    CHECK(r.ve.at("SEL") == 1.0);
  }
  SUBCASE("without the flush (no V.E. write events)") {
    const Run r = play(kOwnWrite, "[ve]\nSEL = 0\n[[event]]\nat = 0.1\noverride = 50\n", 0);
    CHECK(ran_line(r, 5));
    CHECK_FALSE(ran_line(r, 7));
  }
  SUBCASE("a name the scenario never gave is in the store after the program wrote it") {
    const Run r = play("%v\nN10 G01 X1 F600\nV.E.NEW = 4\nN20 M30\n",
                       "[[event]]\nat = 0.05\noverride = 50\n", 0);
    CHECK(r.ve.at("NEW") == 4.0);
  }
  SUBCASE("the write is performed when it is decoded: a PLC write at 0.5 s comes later") {
    // Decision (docs/scenario.md): the look-ahead decoded line 3 at the start; the scenario's
    // write at 0.5 s, before the barrier is answered at 1 s, is the later one.
    const Run r = play(kOwnWrite, "[ve]\nSEL = 0\n[[event]]\nat = 0.5\nve = { SEL = 2 }\n", 0);
    CHECK(ran_line(r, 7));
    CHECK(r.ve.at("SEL") == 2.0);
  }
}

TEST_CASE("NC6301: a hold nothing releases ends the run instead of standing forever") {
  const char* program = "%h\nN10 G01 X10 F600\nN20 M30\n";
  SUBCASE("feed hold without duration or release") {
    const Run r = play(program, "[[event]]\nat = 0.2\nfeed_hold = true\n", 0);
    CHECK(r.status == ipo::Status::error);
    CHECK(r.error_id == "NC6301");
    CHECK(r.seen.back().x < 10.0);
  }
  SUBCASE("override 0 as the last event") {
    const Run r = play(program, "[[event]]\nat = 0.2\noverride = 0\n", 0);
    CHECK(r.error_id == "NC6301");
  }
  SUBCASE("a later release or a [stop] time keeps the run going") {
    const Run released =
        play(program,
             "[[event]]\nat = 0.2\nfeed_hold = true\n[[event]]\nat = 0.9\nfeed_hold = false\n", 0);
    CHECK(released.status == ipo::Status::finished);
    CHECK(released.seen.back().x == doctest::Approx(10.0));
    const Run stopped = play(program, "[[event]]\nat = 0.2\noverride = 0\n[stop]\ntime = 2\n", 0);
    CHECK(stopped.status == ipo::Status::finished);
    CHECK(stopped.error_id.empty());
  }
}
