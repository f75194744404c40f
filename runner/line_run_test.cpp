// runner/line_run: several channels in one run (docs/lines.md): a #WAIT SYN ends one cycle
// after the signalling block's end, #SIGNAL at decoder level goes out long before, waits that
// can never be answered end the run with NC6401 naming both channels, reruns are identical.

#include "runner/line_run.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "runner/load.hpp"
#include "runner/locate.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ncsim;
using namespace ncsim::runner;

// A folder of its own per test with the given files (name, text).
fs::path folder(const std::string& name,
                const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path dir = fs::temp_directory_path() / ("ncsim_line_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& [file, text] : files)
    std::ofstream(dir / file) << text;
  return dir;
}

const std::string kTwoChannels =
    "[[channel]]\nnumber = 1\nname = \"first\"\nprogram = \"a.nc\"\nmachine = \"portal_3x\"\n"
    "[[channel]]\nnumber = 2\nname = \"second\"\nprogram = \"b.nc\"\nmachine = \"portal_3x\"\n";

// The line in `dir` run to its end.
std::unique_ptr<LineRun> run_line(const fs::path& dir) {
  LineSpec spec;
  spec.file = dir / "line.toml";
  LineLoadResult r = load_line_run(spec);
  INFO(r.messages);
  REQUIRE(r.ok());
  r.line->start();
  r.line->run();
  return std::move(r.line);
}

// [s] a program's time alone (`ncsim time`).
double time_alone(const fs::path& program) {
  RunSpec spec;
  spec.program.program = program;
  spec.program.machine_dir = bundled_machine("portal_3x");
  LoadResult r = load(spec);
  REQUIRE(r.ok());
  Run run(std::move(r.loaded), spec);
  run.start();
  run.count_time();
  REQUIRE(run.run() == ipo::Status::finished);
  return run.time_result().total;
}

const char* kCut = "%a\nG01 X100 F6000\n";  // about 1 s on portal_3x

}  // namespace

TEST_CASE("#WAIT SYN ends two cycles after the signalling block's last cycle") {
  const fs::path dir = folder("syn", {{"line.toml", kTwoChannels},
                                      {"a.nc", std::string(kCut) + "#SIGNAL SYN [ID1 CH2]\nM30\n"},
                                      {"b.nc", "%b\n#WAIT SYN [ID1 CH1]\nG01 Y10 F6000\nM30\n"},
                                      {"a_alone.nc", std::string(kCut) + "M30\n"},
                                      {"b_alone.nc", "%b\nG01 Y10 F6000\nM30\n"}});
  const double t1 = time_alone(dir / "a_alone.nc");  // the signalling block ends here
  const double t2 = time_alone(dir / "b_alone.nc");
  auto line = run_line(dir);
  REQUIRE(line->status(0) == ipo::Status::finished);
  REQUIRE(line->status(1) == ipo::Status::finished);
  const double t = line->t_cycle();
  CHECK(line->time(0).t_end == doctest::Approx(t1).epsilon(1e-12));
  // The cut's last cycle ends at t1; the signal goes out in the next cycle (the channel moves
  // past the block), is seen one cycle later, and channel 2 moves in that cycle: it stood
  // t1 / T + 1 cycles.
  CHECK(line->time(1).t_waiting == doctest::Approx(t1 + t).epsilon(1e-12));
  CHECK(line->time(1).t_end == doctest::Approx(t1 + t + t2).epsilon(1e-12));
  CHECK(line->t_end() == doctest::Approx(t1 + t + t2).epsilon(1e-12));
  CHECK(t == doctest::Approx(0.001));
}

TEST_CASE("#SIGNAL at decoder level goes out when the decoder reaches it, long before SYN") {
  const fs::path dir = folder("dec", {{"line.toml", kTwoChannels},
                                      {"a.nc", std::string(kCut) + "#SIGNAL [ID1 CH2]\nM30\n"},
                                      {"b.nc", "%b\n#WAIT [ID1 CH1]\nG01 Y10 F6000\nM30\n"},
                                      {"a_alone.nc", std::string(kCut) + "M30\n"}});
  const double t1 = time_alone(dir / "a_alone.nc");
  auto line = run_line(dir);
  REQUIRE(line->status(1) == ipo::Status::finished);
  // The decoder reads past the cut in the first cycle: the signal is seen in the second.
  CHECK(line->time(1).t_waiting <= 2 * line->t_cycle() + 1e-12);
  CHECK(line->time(1).t_waiting < t1 / 10.0);
}

TEST_CASE("a #WAIT of a #SIGNAL sent already is answered at once at decoder level") {
  const fs::path dir =
      folder("ahead", {{"line.toml", kTwoChannels},
                       {"a.nc", "%a\n#SIGNAL [ID4 P[0]=25 CH2]\nG01 X10 F6000\nM30\n"},
                       {"b.nc", "%b\nG01 Y100 F6000\n#WAIT [ID4 P[0]=P7 CH1]\nG01 X=P7\nM30\n"}});
  auto line = run_line(dir);
  REQUIRE(line->status(1) == ipo::Status::finished);
  CHECK(line->time(1).t_waiting == 0.0);  // the decoder found the signal: no stop
  CHECK(line->channel(1).channel().axes().command[0] == doctest::Approx(25.0));
}

TEST_CASE("two channels waiting for each other end with NC6401 naming both, never hang") {
  const fs::path dir = folder("dead", {{"line.toml", kTwoChannels},
                                       {"a.nc", "%a\nG01 X5 F6000\n#WAIT SYN [ID1 CH2]\nM30\n"},
                                       {"b.nc", "%b\n#WAIT SYN [ID2 CH1]\nM30\n"}});
  auto line = run_line(dir);
  for (std::size_t k = 0; k < 2; ++k) {
    REQUIRE(line->status(k) == ipo::Status::error);
    const Ending e = line->channel(k).ending(line->status(k));
    CHECK(e.error_text.find("[NC6401]") != std::string::npos);
    CHECK(e.error_text.find("channel 1 (first)") != std::string::npos);
    CHECK(e.error_text.find("channel 2 (second)") != std::string::npos);
  }
  const Ending a = line->channel(0).ending(line->status(0));
  CHECK(a.error_text.find("a.nc:3:1: error:") != std::string::npos);
  CHECK(a.error_text.find("waits itself at line 2") != std::string::npos);
}

TEST_CASE("a wait for a channel that ended is NC6401 naming it and its last line") {
  const fs::path dir = folder("ended", {{"line.toml", kTwoChannels},
                                        {"a.nc", "%a\nG01 X5 F6000\nM30\n"},
                                        {"b.nc", "%b\n#WAIT [ID1 CH1]\nM30\n"}});
  auto line = run_line(dir);
  CHECK(line->status(0) == ipo::Status::finished);
  REQUIRE(line->status(1) == ipo::Status::error);
  const std::string text = line->channel(1).ending(line->status(1)).error_text;
  CHECK(text.find("b.nc:2:1: error:") != std::string::npos);
  CHECK(text.find("channel 1 (first) ended after line 2") != std::string::npos);  // its G01
}

TEST_CASE("a program alone waiting for a broadcast signal nobody sends ends with NC6401") {
  const fs::path dir = folder("alone", {{"p.nc", "%p\nG01 X5 F6000\n#WAIT SYN [ID9]\nM30\n"}});
  RunSpec spec;
  spec.program.program = dir / "p.nc";
  LoadResult r = load(spec);
  REQUIRE(r.ok());
  Run run(std::move(r.loaded), spec);
  run.start();
  const ipo::Status s = run.run();
  REQUIRE(s == ipo::Status::error);
  const Ending e = run.ending(s);
  CHECK(e.error_text.find("p.nc:3:1: error:") != std::string::npos);
  CHECK(e.error_text.find("[NC6401]") != std::string::npos);
}

TEST_CASE("a line reruns identically, cycle by cycle") {
  const fs::path dir =
      folder("rerun", {{"line.toml", kTwoChannels},
                       {"a.nc", std::string(kCut) + "#SIGNAL SYN [ID1 CH2]\nM30\n"},
                       {"b.nc", "%b\n#WAIT SYN [ID1 CH1]\nG01 Y10 F6000\nM30\n"}});
  const auto trace = [&] {
    LineSpec spec;
    spec.file = dir / "line.toml";
    LineLoadResult r = load_line_run(spec);
    REQUIRE(r.ok());
    r.line->start();
    std::vector<double> out;
    while (r.line->step())
      for (std::size_t k = 0; k < r.line->size(); ++k)
        for (const double p : r.line->channel(k).channel().axes().command)
          out.push_back(p);
    return out;
  };
  const std::vector<double> first = trace();
  CHECK(first.size() > 1000);
  CHECK(first == trace());
}

TEST_CASE("channels at different cycles are NC7105 at the second one's machine") {
  const fs::path dir =
      folder("cycles", {{"line.toml",
                         "[[channel]]\nnumber = 1\nprogram = \"a.nc\"\nmachine = \"portal_3x\"\n"
                         "[[channel]]\nnumber = 2\nprogram = \"a.nc\"\nmachine = \"m\"\n"},
                        {"a.nc", "%a\nG01 X5 F6000\nM30\n"}});
  fs::copy(bundled_machine("portal_3x"), dir / "m");
  { std::ofstream(dir / "m" / "channel.lis", std::ios::app) << "\nncsim.cycle_time 2000\n"; }
  LineSpec spec;
  spec.file = dir / "line.toml";
  const LineLoadResult r = load_line_run(spec);
  CHECK_FALSE(r.ok());
  CHECK(r.exit == Exit::usage);
  CHECK(r.messages.find("line.toml:8:11: error:") != std::string::npos);
  CHECK(r.messages.find("[NC7105]") != std::string::npos);
  spec.cycle_us = 1000;  // one cycle for the line: both run
  CHECK(load_line_run(spec).ok());
}

namespace {

// programs/lines/two_pickers with the stream's seed, its gaps and count set: a line file in a
// folder of its own naming the bundled programs and machine by absolute paths.
fs::path two_pickers(std::uint64_t seed, double pitch, double scatter, int count) {
  const fs::path src = fs::path(NCSIM_SOURCE_ROOT) / "programs" / "lines" / "two_pickers";
  const auto ch = [&](int n, const char* name, double at) {
    return "[[channel]]\nnumber = " + std::to_string(n) + "\nname = \"" + name +
           "\"\nprogram = \"" + (src / (std::string(name) + ".nc")).string() + "\"\nmachine = \"" +
           (src / "delta_encoder").string() + "\"\nsensor_at = " + std::to_string(at) + "\n";
  };
  return folder(
      "pickers_" + std::to_string(seed),
      {{"line.toml", "belt_end = 1500\n" + ch(1, "picker_up", 0.0) + ch(2, "picker_down", 700.0) +
                         "[conveyor]\nmode = \"encoder\"\nvelocity = 300\n"
                         "[conveyor.workpieces]\nfirst = 100\npitch = " +
                         std::to_string(pitch) + "\nscatter = " + std::to_string(scatter) +
                         "\nseed = " + std::to_string(seed) + "\ncount = " + std::to_string(count) +
                         "\nlength = 100\n"}});
}

}  // namespace

TEST_CASE("two delta pickers share seeded random streams: taken + missed = arrived, every run") {
  // Streams from sparse (one robot could take all) to denser than both can take.
  std::uint64_t taken_by_second = 0;
  std::uint64_t missed = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const double pitch = 105.0 + 10.0 * static_cast<double>(seed % 4);
    const auto line =
        run_line(two_pickers(seed, pitch, 60.0 + 20.0 * static_cast<double>(seed % 3), 12));
    INFO("seed " << seed);
    const conveyor::LineWorld* belt = line->belt();
    REQUIRE(belt != nullptr);
    CHECK(belt->arrived() == 12);
    CHECK(belt->on_belt() == 0);
    CHECK(belt->taken_total() + belt->missed() == belt->arrived());
    CHECK(belt->taken(0) + belt->taken(1) == belt->taken_total());
    for (std::size_t k = 0; k < line->size(); ++k) {
      const Ending end = line->channel(k).ending(line->status(k));
      INFO("channel " << k + 1 << ": " << end.error_text);
      CHECK_FALSE(end.failed);
    }
    taken_by_second += belt->taken(1);
    missed += belt->missed();
  }
  CHECK(taken_by_second > 0);  // the second robot gets what the first lets pass
  CHECK(missed > 0);           // and some leave the belt untaken, counted
}

TEST_CASE("run's after-cycle hook sees every cycle, the waits and the belt where it is") {
  const fs::path dir = folder("hook", {{"line.toml", kTwoChannels},
                                       {"a.nc", std::string(kCut) + "#SIGNAL SYN [ID1 CH2]\nM30\n"},
                                       {"b.nc", "%b\n#WAIT SYN [ID1 CH1]\nG01 Y10 F6000\nM30\n"}});
  LineSpec spec;
  spec.file = dir / "line.toml";
  LineLoadResult r = load_line_run(spec);
  REQUIRE(r.ok());
  LineRun& line = *r.line;
  line.start();
  std::uint64_t cycles = 0;
  std::uint64_t waited = 0;
  double t_last = 0.0;
  line.run([&] {
    ++cycles;
    CHECK(line.t() > t_last);
    t_last = line.t();
    if (line.waiting(1)) ++waited;
    CHECK_FALSE(line.waiting(0));         // channel 1 never waits
    CHECK(line.belt_state() == nullptr);  // no conveyor world on portal_3x
  });
  // One call per cycle, the last one too (the cycle the last channel ended in, after its end
  // time); the waiting cycles are time()'s waiting.
  CHECK(static_cast<double>(cycles - 1) * line.t_cycle() == doctest::Approx(line.t_end()));
  CHECK(static_cast<double>(waited) * line.t_cycle() == doctest::Approx(line.time(1).t_waiting));
  CHECK(waited > 900);  // channel 2 stood through channel 1's cut of about 1 s
}

TEST_CASE("line sweep's hooks: the belt scaled before it is built, CONV_VEL for every channel") {
  const fs::path dir = two_pickers(7, 150.0, 0.0, 3);
  LineSpec spec;
  spec.file = dir / "line.toml";
  spec.adjust_conveyor = [](scenario::Conveyor& c) { c.velocity = 240.0; };
  spec.conv_vel = 240.0;
  int wrapped = 0;
  spec.wrap = [&](std::unique_ptr<conveyor::Port> port) {
    ++wrapped;
    return port;
  };
  LineLoadResult r = load_line_run(spec);
  INFO(r.messages);
  REQUIRE(r.ok());
  CHECK(wrapped == 1);  // the one belt, not once per channel
  LineRun& line = *r.line;
  line.start();
  double v_max = 0.0;
  line.run([&] {
    REQUIRE(line.belt_state() != nullptr);
    v_max = std::max(v_max, line.belt_state()->v);
  });
  CHECK(v_max == doctest::Approx(240.0));
  CHECK(line.belt()->taken_total() == 3);
  for (std::size_t k = 0; k < line.size(); ++k)
    CHECK_FALSE(line.channel(k).ending(line.status(k)).failed);
}
