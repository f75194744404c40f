// The channel with conveyor tracking (issue 14; docs/conveyor.md "Synchronisation"): the
// attached Port is stepped every cycle; without #SYNC IN the axes run in MCS untouched.

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "ipo/channel.hpp"
#include "ipo/program_source.hpp"
#include "ipo/test_port.hpp"

namespace {

using namespace ncsim;

struct Ran {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::AxesState> axes;
  std::optional<ipo::RunTimeError> error;
  std::string source_error;
  std::string source_message;
};

// Runs `program` on `machine_name` (1 ms) with `port` attached (null: none).
Ran run(const std::string& program, conveyor::Port* port,
        const std::string& machine_name = "laser_portal") {
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine(machine_name);
  interp::Interpreter in(file, m);
  ipo::ProgramSource src(in, m);
  ipo::Channel ch(ipo::channel_config(m, 0.001), src);
  ch.attach_conveyor(port);
  Ran r;
  for (int guard = 0; guard < 200'000; ++guard) {
    r.status = ch.step();
    if (r.status != ipo::Status::running) break;
    r.axes.push_back(ch.axes());
  }
  r.error = ch.run_time_error();
  if (const core::Diagnostic* d = src.error()) {
    r.source_error = d->id;
    r.source_message = d->message;
  }
  return r;
}

}  // namespace

TEST_CASE("the attached Port is stepped every cycle; MCS motion is untouched by it") {
  const std::string program = "%t\nN10 G01 X100 Y20 F6000\nN20 M30\n";
  ipo::test::FakePort port(300.0);
  const Ran with = run(program, &port);
  const Ran without = run(program, nullptr);
  REQUIRE(with.status == ipo::Status::finished);
  REQUIRE(with.axes.size() == without.axes.size());
  CHECK(port.steps_ == static_cast<long>(with.axes.size()));
  CHECK(port.t_ == doctest::Approx(0.001 * static_cast<double>(with.axes.size())));
  for (std::size_t k = 0; k < with.axes.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(with.axes[k].command[i] == without.axes[k].command[i]);
}

TEST_CASE("a channel without conveyor tracking ignores an attached Port") {
  ipo::test::FakePort port(300.0);
  const Ran r = run("%t\nN10 G01 X10 F6000\nN20 M30\n", &port, "portal_3x");
  CHECK(r.status == ipo::Status::finished);
  CHECK(port.steps_ == 0);
}
