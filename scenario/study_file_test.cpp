// scenario/study_file: the study file validated like a scenario (docs/study.md "The study
// file"): every error at file:line:col with its key, all of them in one pass.
#include "scenario/study_file.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace {

using namespace ncsim;

// "line:col id" of every diagnostic.
std::vector<std::string> diagnostics(const std::string& text) {
  const scenario::StudyLoad r = scenario::parse_study(core::SourceFile("s.toml", text));
  std::vector<std::string> out;
  for (const core::Diagnostic& d : r.diagnostics.items())
    out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.id);
  return out;
}

}  // namespace

TEST_CASE("a study file gives its base and its axes, ranges spelled out in order") {
  const std::string text =
      "description = \"belt x spacing\"\nline = \"lines/two/line.toml\"\nmax_time = 30\n"
      "audit = false\n[vary]\nbelt_velocity = { from = 200, to = 300.0000001, step = 50 }\n"
      "pitch = [105, 120]\nseed = { from = 1, to = 3 }\nfluctuation = [0, 2.5]\n";
  const scenario::StudyLoad r = scenario::parse_study(core::SourceFile("dir/s.toml", text));
  REQUIRE(r.study);
  const scenario::StudyFile& s = *r.study;
  CHECK(s.description == "belt x spacing");
  CHECK(s.resolved(*s.line) == "dir/lines/two/line.toml");
  CHECK(s.max_time == 30.0);
  CHECK_FALSE(s.audit);
  CHECK(s.belt_velocity.values == std::vector<double>{200, 250, 300});
  CHECK(s.belt_velocity.loc.line == 6);
  CHECK(s.pitch.values == std::vector<double>{105, 120});
  CHECK(s.seed.values == std::vector<std::uint64_t>{1, 2, 3});
  CHECK(s.fluctuation.values == std::vector<double>{0, 2.5});
  CHECK_FALSE(s.programs.given());
}

TEST_CASE("a program base may vary its programs and machines") {
  const scenario::StudyLoad r = scenario::parse_study(
      core::SourceFile("s.toml",
                       "scenario = \"w.toml\"\n[vary]\nprogram = [\"a.nc\", \"b.nc\"]\n"
                       "machine = [\"portal_3x\", \"m\"]\n"));
  REQUIRE(r.study);
  CHECK(r.study->programs.values.size() == 2);
  CHECK(r.study->programs.values[1].text == "b.nc");
  CHECK(r.study->programs.values[1].loc.column == 20);
  CHECK(r.study->machines.values[0].text == "portal_3x");
}

TEST_CASE("every error of a study file is positioned, all in one pass") {
  // No base; an unknown key with its suggestion; a range with a missing step.
  CHECK(diagnostics("programm = \"a.nc\"\n[vary]\nseed = { from = 3 }\n") ==
        std::vector<std::string>{"1:1 NC7201", "1:1 NC7202", "3:8 NC7202"});
  // Both bases; machine with a line; a value twice; a velocity of 0; a fluctuation above 100 %.
  CHECK(diagnostics("line = \"l.toml\"\nprogram = \"a.nc\"\nmachine = \"m\"\n[vary]\n"
                    "belt_velocity = [100, 0, 100]\nfluctuation = [101]\n") ==
        std::vector<std::string>{"1:8 NC7202", "3:11 NC7202", "5:23 NC7004", "5:26 NC7203",
                                 "6:16 NC7004"});
  CHECK(diagnostics("program = \"a.nc\"\nmax_time = 0\naudit = 1\n[vary]\nspeed = [1]\n") ==
        std::vector<std::string>{"2:12 NC7004", "3:9 NC7003", "5:1 NC7201"});
  CHECK(diagnostics("program = \"a.nc\"\n[vary]\npitch = { from = 10, to = 5, step = 1 }\n") ==
        std::vector<std::string>{"3:9 NC7004"});
  CHECK(diagnostics("program = \"a.nc\"\n[vary]\nprogram = [\"b.nc\"]\n") ==
        std::vector<std::string>{"3:1 NC7202"});
  const std::vector<std::string> syntax = diagnostics("[vary\n");
  REQUIRE(syntax.size() == 1);
  CHECK(syntax[0].rfind("1:", 0) == 0);
}

TEST_CASE("a study of more than kStudyJobsMax jobs is refused at its [vary]") {
  CHECK(diagnostics("program = \"a.nc\"\n[vary]\nseed = { from = 1, to = 1000 }\n"
                    "pitch = { from = 1, to = 1000, step = 1 }\n") ==
        std::vector<std::string>{"2:1 NC7204"});
}
