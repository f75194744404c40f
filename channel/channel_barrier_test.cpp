// Position barriers answered from run time (docs/ipo.md "Position barriers"): after INDP_ASYN a
// block that programs the axis again waits for its INDP motion (P-CHAN-00451's implicit
// synchronisation, isg-language.md 6.1) and starts where the axis stands; a block that does not
// program it runs on beside the motion.

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"

namespace {

using namespace ncsim;

struct Result {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::Cycle> cycles;
  std::optional<channel::RunTimeError> error;
};

// Runs `text` on portal_3x (1 ms); `run_time`: the channel answers position barriers (as the
// CLI wires it), else the decode-only state.
Result run(const std::string& text, bool run_time = true) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::test::Recorder rec;
  channel::Channel ch(channel::channel_config(m, 0.001), src, &rec);
  if (run_time) src.answer_positions_from(&ch.axes().command);
  Result r;
  r.status = channel::test::run_to_end(ch);
  r.cycles = std::move(rec.cycles);
  r.error = ch.run_time_error();
  REQUIRE(src.error() == nullptr);
  return r;
}

// Y moves 0 -> 5 at 10 mm/s beside the path (0.5 s and the ramps); X10 -> X20 at 50 mm/s takes
// 0.2 s, so Y is still moving when the path reaches the G91 Y2 block.
const char* const kNoWait =
    "%t\n"                             // 1
    "G01 X10 F3000\n"                  // 2
    "Y[INDP_ASYN G01 POS5 FEED600]\n"  // 3
    "G01 X20\n"                        // 4
    "G91 G01 Y2\n"                     // 5
    "M30\n";                           // 6

}  // namespace

TEST_CASE("after INDP_ASYN a G91 move of the axis waits for its INDP motion, then adds to it") {
  const Result r = run(kNoWait);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  REQUIRE_FALSE(r.cycles.empty());
  // Line 4 does not program Y: it runs beside the INDP motion, reaching X20 with Y < 5.
  std::size_t k20 = 0;
  while (k20 < r.cycles.size() && r.cycles[k20].x[0] != 20.0)
    ++k20;
  REQUIRE(k20 < r.cycles.size());
  CHECK(r.cycles[k20].x[1] > 0.0);
  CHECK(r.cycles[k20].x[1] < 5.0);
  // Then the path holds at line 5 (channel cycles) until Y is in position at 5 ...
  std::size_t held = 0;
  double y_first_motion = -1.0;
  for (const ipo::Cycle& c : r.cycles) {
    if (c.line == 5 && c.activity == ipo::Activity::channel) ++held;
    if (c.line == 5 && c.activity == ipo::Activity::motion && y_first_motion < 0.0)
      y_first_motion = c.x[1];
  }
  CHECK(held > 100);
  CHECK(y_first_motion >= 5.0);
  CHECK(y_first_motion < 5.01);
  // ... and G91 Y2 adds to where it stands.
  CHECK(r.cycles.back().x[1] == doctest::Approx(7.0).epsilon(1e-12));
  CHECK(r.cycles.back().x[0] == 20.0);
}

TEST_CASE("without the run-time answer the same program is NC6103 (implicit sync not done)") {
  const Result r = run(kNoWait, false);
  REQUIRE(r.error);
  CHECK(r.error->id == std::string(channel::kIndpPathId));
  CHECK(r.error->line == 5);
}

TEST_CASE("with #WAIT INDP before the G91 move nothing more waits: the same cycles as decoded") {
  const char* text =
      "%t\nG01 X10 F3000\nY[INDP_ASYN G01 POS5 FEED600]\nG01 X20\n#WAIT INDP [Y]\n"
      "G91 G01 Y2\nM30\n";
  const Result waited = run(text);
  const Result decoded = run(text, false);
  REQUIRE_FALSE(waited.error);
  REQUIRE_FALSE(decoded.error);
  CHECK(waited.cycles.back().x[1] == doctest::Approx(7.0).epsilon(1e-12));
  REQUIRE(waited.cycles.size() == decoded.cycles.size());
  for (std::size_t k = 0; k < waited.cycles.size(); ++k) {
    CHECK(waited.cycles[k].x[0] == decoded.cycles[k].x[0]);
    CHECK(waited.cycles[k].x[1] == decoded.cycles[k].x[1]);
  }
}

TEST_CASE("the answer is the channel's set position, not the decoded target") {
  // The source alone: the set positions are a vector the test writes, standing for an INDP
  // motion that ended away from its target (e.g. cut short).
  const core::SourceFile file("t.nc", kNoWait);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  ipo::AxisVec set{};
  src.answer_positions_from(&set);
  ipo::Item item;
  std::optional<ipo::ChannelWait> wait;
  for (int k = 0; k < 10 && !wait; ++k) {
    REQUIRE(src.next(item));
    if (const auto* w = std::get_if<ipo::ChannelWait>(&item)) wait = *w;
  }
  REQUIRE(wait);  // the implicit synchronisation before line 5
  CHECK(wait->line == 5);
  program::ChannelEvent e;
  REQUIRE(src.take_event(wait->tag, e));  // the INDP_ASYN of line 3
  REQUIRE(src.take_event(wait->tag, e));  // the #WAIT INDP [Y] of the implicit sync
  const auto* w = std::get_if<interp::WaitIndp>(&e.body);
  REQUIRE(w != nullptr);
  CHECK(w->axes == 2u);  // Y
  set = {20.0, 3.5, 0.0};
  REQUIRE(src.next(item));
  const auto* move = std::get_if<planner::Move>(&item);
  REQUIRE(move != nullptr);
  CHECK(move->line == 5);
  CHECK(move->start[1] == 3.5);
  CHECK(move->end[1] == 5.5);
}
