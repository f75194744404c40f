// cli/study_command: `ncsim study` (see the header).

#include "cli/study_command.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <mutex>
#include <ostream>
#include <system_error>
#include <thread>
#include <vector>

#include "cli/commands.hpp"
#include "cli/study_job.hpp"
#include "core/source_file.hpp"
#include "runner/study.hpp"
#include "scenario/loader.hpp"
#include "scenario/study_file.hpp"

extern char** environ;

namespace ncsim::cli {
namespace fs = std::filesystem;
namespace {

// A validated study file, named by its absolute path (what the job list records: every job
// resolves the base's paths from it, wherever it runs).
struct OpenStudy {
  scenario::StudyFile study;
  fs::path abs;
  std::string digest;
};

std::optional<OpenStudy> open_study(const fs::path& path, std::ostream& err) {
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec).lexically_normal();
  std::optional<core::SourceFile> file;
  try {
    file.emplace(core::SourceFile::load_regular(path, scenario::kMaxScenarioBytes));
  } catch (const std::exception& e) {
    err << "ncsim: error: study: cannot read the study file '" << path.string() << "': " << e.what()
        << " [NC7010]\n";
    return std::nullopt;
  }
  scenario::StudyLoad r = scenario::parse_study(*file);
  for (const core::Diagnostic& d : r.diagnostics.items())
    err << core::format(d, *file);
  if (!r.study) {
    err << "ncsim: error: study '" << path.string() << "': " << r.diagnostics.error_count()
        << " error" << (r.diagnostics.error_count() == 1 ? "" : "s") << '\n';
    return std::nullopt;
  }
  OpenStudy s{std::move(*r.study), abs, runner::study_digest(file->text())};
  s.study.file = abs.string();
  return s;
}

// The planned study of DIR: the job list read, the study file read again and unchanged.
std::optional<OpenStudy> open_plan(const fs::path& dir, std::ostream& err) {
  std::string why;
  const std::optional<runner::StudyPlan> plan = runner::read_study_plan(dir, why);
  if (!plan) {
    err << "ncsim: error: study: " << why << " [" << runner::kStudyPlanId << "]\n";
    return std::nullopt;
  }
  std::optional<OpenStudy> s = open_study(plan->study, err);
  if (!s) return std::nullopt;
  if (s->digest != plan->digest || runner::study_job_count(s->study) != plan->jobs) {
    err << "ncsim: error: study: '" << plan->study.string() << "' changed since it was planned in '"
        << dir.string() << "': plan it again [" << runner::kStudyChangedId << "]\n";
    return std::nullopt;
  }
  return s;
}

std::string ncsim_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("ncsim") : self.string();
}

// Validates, checks the base and writes the plan folder.
std::optional<OpenStudy> plan(const StudyOptions& o, std::ostream& out, std::ostream& err) {
  std::optional<OpenStudy> s = open_study(o.study, err);
  if (!s) return std::nullopt;
  std::string messages;
  const bool ok = check_study_base(s->study, messages);
  err << messages;
  if (!ok) {
    err << "ncsim: error: study '" << o.study << "': its base cannot run the study\n";
    return std::nullopt;
  }
  std::error_code ec;
  const fs::path dir = fs::absolute(o.dir, ec).lexically_normal();
  fs::create_directories(dir / "results", ec);
  if (!ec) fs::create_directories(dir / "logs", ec);
  if (ec) {
    err << "ncsim: error: study: cannot make the plan folder '" << o.dir << "': " << ec.message()
        << '\n';
    return std::nullopt;
  }
  // An earlier plan's results in DIR belong to another study: they go.
  for (const auto& entry : fs::directory_iterator(dir / "results", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("job-", 0) == 0 && entry.path().extension() == ".csv")
      fs::remove(entry.path(), ec);
  }
  fs::remove(runner::study_merged_path(dir), ec);
  const std::uint64_t n = runner::study_job_count(s->study);
  runner::StudyBatch batch;
  batch.ncsim = ncsim_path();
  batch.dir = dir;
  batch.jobs = n;
  batch.chunk = o.chunk > 0 ? o.chunk : runner::study_default_chunk(n);
  batch.partition = o.partition;
  std::string why;
  if (!runner::write_study_file(runner::study_jobs_path(dir),
                                runner::study_plan_text(s->study, s->abs, s->digest), why) ||
      !runner::write_study_file(runner::study_script_path(dir), runner::study_sbatch_text(batch),
                                why)) {
    err << "ncsim: error: study: " << why << '\n';
    return std::nullopt;
  }
  out << "study: " << n << " job" << (n == 1 ? "" : "s") << " planned in " << dir.string()
      << " (jobs.csv, study.sbatch: " << (n + batch.chunk - 1) / batch.chunk << " array task"
      << ((n + batch.chunk - 1) / batch.chunk == 1 ? "" : "s") << ")\n";
  return s;
}

// Job `i` run and its row written; false with the reason in `why`.
bool run_one(const scenario::StudyFile& s, const fs::path& dir, std::uint64_t i, std::string& why) {
  const runner::StudyJob job = runner::study_job(s, i);
  const runner::StudyOutcome o = run_study_job(s, job);
  return runner::write_study_file(runner::study_result_path(dir, i), runner::study_row(s, job, o),
                                  why);
}

// The merged table written to `target` ("-": out).
int merge_into(const scenario::StudyFile& s, const fs::path& dir, const std::string& target,
               std::ostream& out, std::ostream& err) {
  std::vector<std::uint64_t> missing;
  const std::optional<std::string> table = runner::merge_study(s, dir, missing);
  if (!table) {
    err << "ncsim: error: study: " << missing.size() << " of " << runner::study_job_count(s)
        << " jobs have no result in '" << (dir / "results").string() << "': jobs";
    for (std::size_t k = 0; k < missing.size() && k < 20; ++k)
      err << ' ' << missing[k];
    if (missing.size() > 20) err << " ...";
    err << " (run them: ncsim study job DIR INDEX) [" << runner::kStudyMissingId << "]\n";
    return kExitUsage;
  }
  if (target == "-") {
    out << *table;
    return kExitOk;
  }
  const fs::path path = target.empty() ? runner::study_merged_path(dir) : fs::path(target);
  std::string why;
  if (!runner::write_study_file(path, *table, why)) {
    err << "ncsim: error: study: " << why << '\n';
    return kExitUsage;
  }
  out << "study: " << runner::study_job_count(s) << " rows merged into " << path.string() << '\n';
  return kExitOk;
}

}  // namespace

int study_plan(const StudyOptions& o, std::ostream& out, std::ostream& err) {
  return plan(o, out, err) ? kExitOk : kExitUsage;
}

int study_run(const StudyOptions& o, std::ostream& out, std::ostream& err) {
  const std::optional<OpenStudy> s = plan(o, out, err);
  if (!s) return kExitUsage;
  const fs::path dir = fs::absolute(o.dir).lexically_normal();
  const std::uint64_t n = runner::study_job_count(s->study);
  const unsigned threads = static_cast<unsigned>(std::min<std::uint64_t>(
      n, o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency())));
  std::atomic<std::uint64_t> next{0};
  std::mutex failed_mutex;
  std::string failed;  // the first write failure
  const auto worker = [&] {
    for (std::uint64_t i = next++; i < n; i = next++) {
      std::string why;
      if (run_one(s->study, dir, i, why)) continue;
      const std::lock_guard<std::mutex> lock(failed_mutex);
      if (failed.empty()) failed = why;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < threads; ++k)
    pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool)
    t.join();
  if (!failed.empty()) {
    err << "ncsim: error: study: " << failed << '\n';
    return kExitUsage;
  }
  out << "study: " << n << " job" << (n == 1 ? "" : "s") << " run on " << threads << " thread"
      << (threads == 1 ? "" : "s") << '\n';
  return merge_into(s->study, dir, o.merged, out, err);
}

int study_job(const StudyOptions& o, std::ostream&, std::ostream& err) {
  const std::optional<OpenStudy> s = open_plan(o.dir, err);
  if (!s) return kExitUsage;
  const std::uint64_t n = runner::study_job_count(s->study);
  if (o.index >= n) {
    err << "ncsim: error: study: job " << o.index << " is not in the study (its jobs are 0 .. "
        << n - 1 << ") [" << runner::kStudyPlanId << "]\n";
    return kExitUsage;
  }
  std::string why;
  if (!run_one(s->study, o.dir, o.index, why)) {
    err << "ncsim: error: study: " << why << '\n';
    return kExitUsage;
  }
  return kExitOk;
}

int study_merge(const StudyOptions& o, std::ostream& out, std::ostream& err) {
  const std::optional<OpenStudy> s = open_plan(o.dir, err);
  if (!s) return kExitUsage;
  return merge_into(s->study, o.dir, o.merged, out, err);
}

int study_submit(const StudyOptions& o, std::ostream& out, std::ostream& err) {
  const std::optional<OpenStudy> s = plan(o, out, err);
  if (!s) return kExitUsage;
  const fs::path dir = fs::absolute(o.dir).lexically_normal();
  const std::string script = runner::study_script_path(dir).string();
  std::vector<std::string> args = {"sbatch", "--parsable", "--wait", script};
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  out.flush();
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "sbatch", nullptr, nullptr, argv.data(), environ);
  if (spawned != 0) {
    err << "ncsim: error: study: cannot run sbatch: " << std::strerror(spawned)
        << " (Slurm's client, Debian package slurm-client) [" << kStudySbatchId << "]\n";
    return kExitUsage;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    err << "ncsim: error: study: sbatch --wait " << script << " failed ("
        << (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                              : std::string("killed by a signal"))
        << "; the tasks' logs are in " << (dir / "logs").string() << ") [" << kStudySbatchId
        << "]\n";
    return kExitUsage;
  }
  out << "study: the job array ended\n";
  return merge_into(s->study, dir, o.merged, out, err);
}

StudyCommand::StudyCommand(CLI::App& app) {
  cmd_ = app.add_subcommand("study",
                            "A study: a base run over belt velocities, spacings, fluctuations, "
                            "seeds, programs or machines, locally or as a Slurm job array "
                            "(docs/study.md)");
  cmd_->require_subcommand(1);
  const auto planned = [this](CLI::App* c) {
    c->add_option("study", options_.study, "The study file (TOML)")->required();
    c->add_option("-o,--output", options_.dir, "The plan folder")->required();
  };
  const auto batch = [this](CLI::App* c) {
    c->add_option("--chunk", options_.chunk,
                  "Jobs per array task (default: 1, or what keeps the "
                  "array at 1000 tasks)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}));
    c->add_option("--partition", options_.partition,
                  "The Slurm partition (default: the cluster's)");
  };
  plan_ =
      cmd_->add_subcommand("plan", "Validate the study, write DIR/jobs.csv and DIR/study.sbatch");
  planned(plan_);
  batch(plan_);
  run_ = cmd_->add_subcommand("run", "Plan, run every job on this machine's cores, merge");
  planned(run_);
  run_->add_option("--jobs", options_.jobs, "Threads (default: the cores)")
      ->check(CLI::Range(1u, 256u));
  job_ = cmd_->add_subcommand("job", "Run one job of a planned study (what an array task calls)");
  job_->add_option("dir", options_.dir, "The plan folder")->required();
  job_->add_option("index", options_.index, "The job's index (0-based)")
      ->required()
      ->check(CLI::NonNegativeNumber);
  merge_ = cmd_->add_subcommand("merge", "Merge the jobs' results into one table");
  merge_->add_option("dir", options_.dir, "The plan folder")->required();
  merge_->add_option("-o,--output", options_.merged,
                     "The table (default DIR/results.csv; -: stdout)");
  submit_ = cmd_->add_subcommand("submit", "Plan, submit the job array with sbatch --wait, merge");
  planned(submit_);
  batch(submit_);
}

std::optional<int> StudyCommand::dispatch(std::ostream& out, std::ostream& err) const {
  if (!cmd_->parsed()) return std::nullopt;
  if (plan_->parsed()) return study_plan(options_, out, err);
  if (run_->parsed()) return study_run(options_, out, err);
  if (job_->parsed()) return study_job(options_, out, err);
  if (merge_->parsed()) return study_merge(options_, out, err);
  return study_submit(options_, out, err);
}

}  // namespace ncsim::cli
