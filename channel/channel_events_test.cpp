// Channel events (program/channel_event.hpp): commands beside the path reach the channel at their
// place in the program; those that need the path standing stop it; the rest never slow it.

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "ipo/test_support.hpp"
#include "program/program_source.hpp"

namespace {

using namespace ncsim;

using channel::test::Recorder;

struct Result {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::Cycle> cycles;
  std::optional<channel::RunTimeError> error;
};

Result run(const std::string& text) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  Recorder rec;
  channel::Channel ch(channel::channel_config(m, 0.001), src, &rec);
  Result r;
  r.status = channel::test::run_to_end(ch);
  r.cycles = std::move(rec.cycles);
  r.error = ch.run_time_error();
  return r;
}

/// Answers every wait with `answer`; counts the waits it saw.
struct Handler final : ipo::WaitHandler {
  bool answer = true;
  std::vector<std::uint32_t> tags;
  bool on_wait(const ipo::ChannelWait& w) noexcept override {
    tags.push_back(w.tag);
    return answer;
  }
};

using ipo::test::line;
using ipo::test::vec;

std::vector<ipo::Cycle> interpolate(std::vector<ipo::Item> items, Handler* handler,
                                    int release_after = 0) {
  ipo::test::ListSource src(std::move(items));
  ipo::Config cfg;
  cfg.axes.assign(3, ipo::test::axis(100.0, 1000.0, 1e5));
  cfg.channel.t_cycle = 0.001;
  ipo::PathInterpolator ipo(cfg, src);
  ipo.standstill().set_wait_handler(handler);
  std::vector<ipo::Cycle> out;
  int held = 0;
  while (ipo.step() == ipo::Status::running) {
    out.push_back(ipo.cycle());
    if (ipo.standstill().holding_channel() && ++held >= release_after)
      ipo.standstill().release_wait();
    REQUIRE(out.size() < 100'000);
  }
  return out;
}

}  // namespace

TEST_CASE(
    "an M function between two moves does not slow the path; its tag rides on the next block") {
  const Result plain = run("%t\nG01 X10 F3000\nX20 Y5\nM30\n");
  const Result with_m = run("%t\nG01 X10 F3000\nM05\nX20 Y5\nM30\n");
  REQUIRE(plain.status == ipo::Status::finished);
  REQUIRE(with_m.status == ipo::Status::finished);
  REQUIRE(plain.cycles.size() == with_m.cycles.size());
  for (std::size_t k = 0; k < plain.cycles.size(); ++k)
    CHECK(plain.cycles[k].x == with_m.cycles[k].x);
  CHECK(with_m.cycles.front().event_tag == 0);
  CHECK(with_m.cycles.back().event_tag == 1);  // the M05 was due when line 4 started
}

TEST_CASE("#WAIT INDP stops the path at the end of the block before it, then it goes on") {
  const Result plain = run("%t\nG01 X10 F3000\nX20\nM30\n");
  const Result waited = run("%t\nG01 X10 F3000\n#WAIT INDP ALL\nX20\nM30\n");
  REQUIRE(waited.status == ipo::Status::finished);
  CHECK(waited.cycles.size() > plain.cycles.size());  // a stop where there was none
  bool stood_at_10 = false;
  for (const ipo::Cycle& c : waited.cycles)
    if (c.x[0] == 10.0 && c.path.v == 0.0) stood_at_10 = true;
  CHECK(stood_at_10);
  CHECK(waited.cycles.back().x[0] == doctest::Approx(20.0).epsilon(1e-12));
}

// INDP moves are executed now (channel/channel_indp.cpp, docs/ipo.md "INDP axes ...").
TEST_CASE("INDP_ASYN rides on the next block and runs beside the path; the end waits for it") {
  const Result plain = run("%t\nG01 X10 F3000\nX20\nM30\n");
  const Result r = run("%t\nG01 X10 F3000\nY[INDP_ASYN G01 POS5 FEED600]\nX20\nM30\n");
  REQUIRE(r.status == ipo::Status::finished);
  CHECK_FALSE(r.error);
  // The path does not stop for it: it reaches X20 when it would without.
  std::size_t k20 = 0;
  while (k20 < r.cycles.size() && r.cycles[k20].x[0] != 20.0)
    ++k20;
  CHECK(k20 + 1 == plain.cycles.size());
  CHECK(r.cycles[k20].x[1] > 0.0);
  CHECK(r.cycles[k20].x[1] < 5.0);
  CHECK(r.cycles.back().x[1] == 5.0);  // the program end waits for the INDP axis
  CHECK(r.cycles.back().activity == ipo::Activity::channel);
}

TEST_CASE(
    "INDP_SYN: the path stops before it and the next block starts when the axes are in "
    "position") {
  const Result r =
      run("%t\nG01 X10 F3000\nY[INDP_SYN G01 POS5 FEED600] Z[INDP_SYN G00 POS2]\n"
          "X20\nM30\n");
  REQUIRE(r.status == ipo::Status::finished);
  CHECK_FALSE(r.error);
  bool y_and_z_together = false;
  for (const ipo::Cycle& c : r.cycles) {
    if (c.x[1] > 0.0 && c.x[1] < 5.0 && c.x[2] > 0.0 && c.x[2] < 2.0) y_and_z_together = true;
    if (c.x[0] > 10.0) {  // line 4 runs only with Y and Z in position
      CHECK(c.x[1] == 5.0);
      CHECK(c.x[2] == 2.0);
    }
  }
  CHECK(y_and_z_together);  // one block's INDP_SYN axes start together
  CHECK(r.cycles.back().x[0] == 20.0);
}

TEST_CASE("events after the last motion run before the program ends, never dropped") {
  const Result r = run("%t\nG01 X10 F3000\nY[INDP_SYN G01 POS5 FEED600]\nM30\n");
  REQUIRE(r.status == ipo::Status::finished);
  CHECK(r.cycles.back().x[0] == 10.0);
  CHECK(r.cycles.back().x[1] == 5.0);
}

TEST_CASE("a ChannelWait answered at once costs no cycle; held, it costs exactly the held cycles") {
  const auto a = vec(0, 0, 0), b = vec(10, 0, 0), c = vec(10, 10, 0);
  const std::vector<ipo::Item> with_dwell{line(a, b, 50, 1), ipo::Dwell{0.0, 2, 0},
                                          line(b, c, 50, 3)};
  const std::vector<ipo::Item> with_wait{line(a, b, 50, 1), ipo::ChannelWait{2, 7},
                                         line(b, c, 50, 3)};
  Handler at_once;
  const auto d = interpolate(with_dwell, nullptr);
  const auto w = interpolate(with_wait, &at_once);
  CHECK(w.size() == d.size());
  CHECK(at_once.tags == std::vector<std::uint32_t>{7});
  Handler holding;
  holding.answer = false;
  const auto h = interpolate(with_wait, &holding, 5);
  REQUIRE(h.size() == d.size() + 5);
  int channel_cycles = 0;
  for (const ipo::Cycle& cy : h) {
    if (cy.activity != ipo::Activity::channel) continue;
    ++channel_cycles;
    CHECK(cy.line == 2);
    CHECK(cy.event_tag == 7);
    CHECK(cy.path.v == 0.0);
  }
  CHECK(channel_cycles == 5);
  CHECK(h.back().x == d.back().x);
}
