// Run-time positions in subroutine files: a cycle, a block record and a run-time error carry
// the file of their block (an index into the interpreter's file table, interp::Command::file),
// so a block of a global subroutine file (`L name`) is named in its own file, not the main
// program's (docs/ipo.md "Blocks of subroutine files").

#include <doctest/doctest.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "audit/time.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "channel/trafo_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/interpreter.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"

namespace {

using namespace ncsim;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

TEST_CASE(
    "NC5502 in a block of a subroutine file names that file and its line, not the calling "
    "main program's") {
  const core::SourceFile file = core::SourceFile::load(
      interp::test::source_root() / "programs/subroutine_soft_limit/subroutine_soft_limit.nc");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Options options;
  options.external.emplace("PART_X", 765.0);  // both parts beyond the limit (no scenario here)
  interp::Interpreter in(file, m, options);
  program::ProgramSource src(in, m);
  channel::test::Recorder rec;
  channel::Channel ch(channel::channel_config(m, 0.001), src, &rec);
  REQUIRE(channel::test::run_to_end(ch, {}, 10'000'000) == ipo::Status::error);
  const auto& e = ch.run_time_error();
  REQUIRE(e);
  CHECK(e->id == "NC5502");
  CHECK(e->message.find("P-AXIS-00178") != std::string::npos);
  REQUIRE(e->file != 0);
  CHECK(ends_with(in.file_name(e->file), "part_contour.sub"));
  CHECK(e->line == 10);  // N70 G03 of part_contour.sub; the main program's line 10 is N20
  CHECK(&in.source_file(e->file) != &file);
  CHECK(in.source_file(e->file).line_text(10).starts_with("N70 G03"));
  // Every motion cycle is a block of the subroutine file (the main program has no motion).
  REQUIRE_FALSE(rec.cycles.empty());
  for (const ipo::Cycle& c : rec.cycles)
    CHECK(c.file == e->file);
}

TEST_CASE(
    "cycles and block records keep main-program blocks at file 0 and give a subroutine file's "
    "blocks its index") {
  // l_main.nc: line 4 `L sub_move.nc`, line 5 `G00 Y[P2] Z[V.P.LEN]`; sub_move.nc line 2
  // `G00 X[P1]`.
  const core::SourceFile file =
      core::SourceFile::load(interp::test::source_root() / "interp/testdata/l_main.nc");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::test::Recorder rec;
  channel::Channel ch(channel::channel_config(m, 0.001), src, &rec);
  std::vector<audit::BlockTime> blocks;
  audit::TimeCounter counter(0.001, [&](const audit::BlockTime& b) { blocks.push_back(b); });
  REQUIRE(channel::test::run_to_end(
              ch, [&] { counter.add(ch.cycle()); }, 1'000'000) == ipo::Status::finished);
  counter.finish();
  REQUIRE(blocks.size() == 2);
  CHECK(blocks[0].line == 2);
  REQUIRE(blocks[0].file != 0);
  CHECK(ends_with(in.file_name(blocks[0].file), "sub_move.nc"));
  CHECK(blocks[1].line == 5);
  CHECK(blocks[1].file == 0);
  std::size_t in_sub = 0;
  for (const ipo::Cycle& c : rec.cycles) {
    CHECK(c.file == (c.line == 2 ? blocks[0].file : 0));
    in_sub += c.file != 0 ? 1 : 0;
  }
  CHECK(in_sub > 0);
}

TEST_CASE(
    "a scenario line event counts main-program lines only: a subroutine file's block of the same "
    "number neither fires it nor counts as its pass") {
  // sub_move.nc line 2 `G00 X[P1]` runs; the main program's line 2 is `P1 = 4` (no block that
  // starts); the main's line 5 `G00 Y[P2] Z[V.P.LEN]` runs once.
  const core::SourceFile file =
      core::SourceFile::load(interp::test::source_root() / "interp/testdata/l_main.nc");
  const machines::Machine& m = interp::test::machine("portal_3x");
  const core::SourceFile toml("s.toml",
                              "[[event]]\nline = 2\nve = { HIT = 1 }\n"
                              "[[event]]\nline = 5\nve = { MAIN = 1 }\n");
  scenario::LoadResult loaded = scenario::parse_scenario(toml);
  REQUIRE(loaded.scenario);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  scenario::Player player(*loaded.scenario);
  src.answer_barriers_from(&player.ve(), true);
  channel::Channel ch(channel::channel_config(m, 0.001), src);
  ch.play(&player);
  REQUIRE(channel::test::run_to_end(ch, {}, 1'000'000) == ipo::Status::finished);
  CHECK(player.passes(2) == 0);
  CHECK(player.passes(5) == 1);
  CHECK_FALSE(player.ve().read("HIT"));
  CHECK(player.ve().read("MAIN") == 1.0);
}

namespace {

struct Adapted {
  std::vector<planner::Move> moves;
  std::optional<core::Diagnostic> error;
  std::string main_file;  // in.file_name(0)
  std::string error_file;
};

// The adapter's items of program `name` (channel/testdata) on machine `m`, without a channel.
Adapted adapt(const char* name, const machines::Machine& m) {
  const core::SourceFile file =
      core::SourceFile::load(interp::test::source_root() / "channel/testdata" / name);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  Adapted a;
  ipo::Item item;
  while (src.next(item))
    if (const auto* mv = std::get_if<planner::Move>(&item)) a.moves.push_back(*mv);
  if (const core::Diagnostic* e = src.error()) a.error = *e;
  a.main_file = in.file_name(0);
  return a;
}

}  // namespace

TEST_CASE(
    "a PCS1 block held for its tolerance ball keeps its own file when the next block is in a "
    "subroutine file") {
  // Under #TRAFO ON the adapter holds a PCS1 block that ends in a ball
  // (ProgramSource::ball_held_) until the next Motion is read; here that Motion is line 2 of
  // held_ball_trafo_sub.nc, called by `L` after main line 10 (N60 G261 G01). Before, the held
  // block went out with the file of the command read last: N60 was named in the subroutine
  // file (diagnostics, `run`'s CSV, `time --blocks`).
  const Adapted a = adapt("held_ball_trafo.nc", channel::test::picker());
  REQUIRE_FALSE(a.error);
  const auto n60 = std::find_if(a.moves.begin(), a.moves.end(),
                                [](const planner::Move& mv) { return mv.line == 10; });
  REQUIRE(n60 != a.moves.end());
  CHECK(n60->belt_joints);  // held: it carries the ball's share (it is a transformed PCS1 block)
  CHECK(n60->file == 0);
  REQUIRE(std::next(n60) != a.moves.end());
  CHECK(std::next(n60)->line == 2);
  CHECK(std::next(n60)->file != 0);
}

TEST_CASE(
    "a static unit's part held for its tolerance ball keeps its own file, in its items and "
    "in NC9100") {
  // On a static unit (x_virtual) the last part of a block that ends in a
  // ball waits for the next path part (ProgramSource::xv_held_), here line 2 of
  // held_ball_static_sub.nc after main line 5 (N40 G261 G01 X-100 Y-100).
  const machines::Machine& m = interp::test::machine("static_saw");
  SUBCASE("the held part's Move") {
    const Adapted a = adapt("held_ball_static.nc", m);
    REQUIRE_FALSE(a.error);
    std::size_t n40 = 0;
    for (const planner::Move& mv : a.moves) {
      CAPTURE(mv.line);
      if (mv.line == 5) ++n40;
      CHECK(mv.file == (mv.line == 2 ? a.moves.back().file : 0));
    }
    CHECK(n40 > 0);
    CHECK(a.moves.back().line == 2);
    CHECK(a.moves.back().file != 0);
  }
  SUBCASE("NC9100 of its ball (CONV_VEL 300 mm/s, a 2 mm ball) names the main program") {
    const Adapted a = adapt("held_ball_static_fast.nc", m);
    REQUIRE(a.error);
    CHECK(a.error->id == "NC9100");
    CHECK(a.error->loc.line == 5);
    CHECK(a.error->file == a.main_file);
  }
}
