// runner/: load() reports instead of printing (a missing program, --ve, a cycle too long for
// Kv), and a loaded program runs through Run to its end with the audit, the time count and the
// workpieces on a conveyor, as `ncsim time --audit` does.

#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "runner/line.hpp"
#include "runner/load.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ncsim::runner;

fs::path program(const std::string& name) {
  return fs::path(NCSIM_SOURCE_ROOT) / "programs" / name / (name + ".nc");
}

}  // namespace

TEST_CASE("a missing program is a usage error with its message, nothing loaded") {
  RunSpec spec;
  spec.program.program = "/nonexistent/prog.nc";
  const LoadResult r = load(spec);
  CHECK_FALSE(r.ok());
  CHECK(r.exit == Exit::usage);
  CHECK(r.messages == "ncsim: error: no such file: '/nonexistent/prog.nc'\n");
  CHECK_FALSE(r.failure.empty());
}

TEST_CASE("--ve is refused for a run: V.E. values come with the scenario") {
  RunSpec spec;
  spec.program.program = program("helix_bore");
  spec.program.external = {"A=1"};
  const LoadResult r = load(spec);
  CHECK(r.exit == Exit::usage);
  CHECK(r.messages.find("not supported: --ve") != std::string::npos);
}

TEST_CASE("a cycle too long for an axis's Kv is a usage error naming --cycle-us") {
  RunSpec spec;
  spec.program.program = program("helix_bore");
  spec.cycle_us = 1000000;
  const LoadResult r = load(spec);
  CHECK(r.exit == Exit::usage);
  CHECK(r.messages.find("--cycle-us 1000000: axis ") != std::string::npos);
}

TEST_CASE("a program runs to its end through Run: time equals the cycles, the audit is clean") {
  RunSpec spec;
  spec.program.program = program("helix_bore");
  spec.audit = true;
  LoadResult r = load(spec);
  REQUIRE(r.ok());
  CHECK(r.messages.empty());
  Run run(std::move(r.loaded), spec);
  CHECK(run.config().path.axes.size() == axis_names(run.loaded().machine).size());
  run.start();
  run.count_time();
  std::uint64_t cycles = 0;
  const ncsim::ipo::Status last = run.run([&](const ncsim::channel::Channel&) { ++cycles; });
  const Ending end = run.ending(last);
  CHECK_FALSE(end.failed);
  CHECK(end.stop == "program end");
  CHECK(run.time_result().cycles == cycles);
  REQUIRE(run.audit() != nullptr);
  CHECK(run.audit()->verdict().ok());
  CHECK_FALSE(run.tracks_conveyor());
}

TEST_CASE("a conveyor program counts its workpieces; the headless run agrees on the end") {
  RunSpec spec;
  spec.program.program = program("conveyor_squares");
  spec.audit = true;
  LoadResult r = load(spec);
  REQUIRE(r.ok());
  Run run(std::move(r.loaded), spec);
  run.start();
  REQUIRE(run.tracks_conveyor());
  std::uint64_t rows = 0;
  run.count_workpieces([&](const ncsim::audit::WorkpieceCycle&) { ++rows; });
  const Ending end = run.ending(run.run());
  CHECK_FALSE(end.failed);
  CHECK(run.workpiece_summary().has_value());
  CHECK(rows > 0);
  std::ostringstream err;
  const LineOutcome line = run_line(spec, {}, err);
  CHECK(line.status == Exit::ok);
  CHECK(line.t_end == run.channel().cycle().t);
}
