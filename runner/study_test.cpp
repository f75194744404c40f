// runner/study: the jobs of a study (the product of its axes, the last fastest), their rows,
// the plan's job list read back and the merge in job order (docs/study.md).
#include "runner/study.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace ncsim;
namespace fs = std::filesystem;

scenario::StudyFile study(const std::string& text) {
  scenario::StudyLoad r = scenario::parse_study(core::SourceFile("/x/s.toml", text));
  REQUIRE(r.study);
  return *r.study;
}

}  // namespace

TEST_CASE("the jobs of a study are the product of its axes, the last axis fastest") {
  const scenario::StudyFile s =
      study("line = \"l.toml\"\n[vary]\nseed = [7, 8, 9]\nbelt_velocity = [100, 200]\n");
  REQUIRE(runner::study_job_count(s) == 6);
  std::vector<std::string> rows;
  for (std::uint64_t i = 0; i < 6; ++i)
    rows.push_back(runner::study_job_fields(s, runner::study_job(s, i)));
  CHECK(rows ==
        std::vector<std::string>{"0,100,7", "1,100,8", "2,100,9", "3,200,7", "4,200,8", "5,200,9"});
  CHECK(runner::study_jobs_header(s) == "job,belt_velocity_mm_s,seed\n");
  CHECK(runner::study_job_count(study("program = \"a.nc\"\n")) == 1);
}

TEST_CASE("a row carries the outcome; texts with commas or quotes are quoted") {
  const scenario::StudyFile s = study("program = \"a.nc\"\n[vary]\npitch = [400.5]\n");
  runner::StudyOutcome o;
  o.exit = runner::Exit::program_errors;
  o.stop = "error";
  o.error_id = "50653";
  o.error = "a.nc:3:1: error: \"too fast\", really";
  o.t_end = 1.5;
  o.taken = 3;
  o.audited = true;
  CHECK(runner::study_row(s, runner::study_job(s, 0), o) ==
        "0,400.5,1,error,50653,1.5,,3,,120,ok,0,\"a.nc:3:1: error: \"\"too fast\"\", really\"\n");
  CHECK(runner::study_header(s) ==
        "job,pitch_mm,exit,stop,error_id,end_s,arrived,taken,missed,per_minute,audit,"
        "audit_violations,error\n");
}

TEST_CASE("the job list is read back; the merge is in job order and names what is missing") {
  const scenario::StudyFile s = study("program = \"a.nc\"\n[vary]\nseed = [1, 2, 3]\n");
  const fs::path dir = fs::temp_directory_path() / "ncsim_study_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  std::string why;
  REQUIRE(runner::write_study_file(runner::study_jobs_path(dir),
                                   runner::study_plan_text(s, "/x/s.toml", "0123"), why));
  const auto plan = runner::read_study_plan(dir, why);
  REQUIRE(plan);
  CHECK(plan->study == "/x/s.toml");
  CHECK(plan->digest == "0123");
  CHECK(plan->jobs == 3);
  CHECK_FALSE(runner::read_study_plan(dir / "none", why));
  CHECK(why.find("not a planned study") != std::string::npos);
  // Results written in another order than the jobs'.
  for (const std::uint64_t i : {2u, 0u})
    REQUIRE(runner::write_study_file(runner::study_result_path(dir, i), std::to_string(i) + ",r\n",
                                     why));
  std::vector<std::uint64_t> missing;
  CHECK_FALSE(runner::merge_study(s, dir, missing));
  CHECK(missing == std::vector<std::uint64_t>{1});
  REQUIRE(runner::write_study_file(runner::study_result_path(dir, 1), "1,r\n", why));
  missing.clear();
  const auto table = runner::merge_study(s, dir, missing);
  REQUIRE(table);
  CHECK(*table == runner::study_header(s) + "0,r\n1,r\n2,r\n");
  fs::remove_all(dir);
}

TEST_CASE("the batch script is a job array of chunks calling ncsim study job") {
  runner::StudyBatch b;
  b.ncsim = "/opt/nc sim/ncsim";
  b.dir = "/data/st";
  b.jobs = 5;
  b.chunk = 2;
  const std::string t = runner::study_sbatch_text(b);
  CHECK(t.find("#SBATCH --array=0-2\n") != std::string::npos);
  CHECK(t.find("ncsim='/opt/nc sim/ncsim'\n") != std::string::npos);
  CHECK(t.find("\"$ncsim\" study job \"$dir\" \"$i\"") != std::string::npos);
  CHECK(runner::study_default_chunk(1000) == 1);
  CHECK(runner::study_default_chunk(1001) == 2);
  CHECK(runner::study_digest("") == "cbf29ce484222325");
}
