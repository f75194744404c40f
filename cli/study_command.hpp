#pragma once
// cli/study_command: `ncsim study plan|run|job|merge|submit` (issue 37 step 5, docs/study.md).
//
// Purpose: a study (belt velocities x workpiece spacing x fluctuation x seeds x programs or
// machines, runner/study) run on this machine's cores or as a Slurm job array, with one merged
// table either way.
// - plan STUDY.toml -o DIR [--chunk K] [--partition P]: validates the study (every error at
//   file:line:col, exit 2), checks its axes against the base (NC7205, NC7206), writes DIR/jobs.csv
//   and the batch script DIR/study.sbatch (a job array, K jobs per task); removes the results of
//   an earlier plan in DIR.
// - run STUDY.toml -o DIR [--jobs N]: plan, every job on N threads (default: the cores), merge.
// - job DIR INDEX: job INDEX of the planned study (what each array task calls), its row written
//   to DIR/results/job-NNNNNN.csv atomically.
// - merge DIR [-o FILE]: the rows in job order into DIR/results.csv (or FILE, `-`: stdout);
//   jobs without a result are NC7209.
// - submit STUDY.toml -o DIR [--chunk K] [--partition P]: plan, `sbatch --wait` the script (the
//   array's tasks run `ncsim study job`), merge.
// Exit: 0 when the table is written (jobs that failed are rows of it, not failures of the
// study), 2 for a bad study, plan folder or index, missing results, a failed sbatch or a file
// that cannot be written.
// Invariants: the table depends on the study file only (jobs are pure functions of it, merged
// in job order): byte-identical for `run --jobs 1`, `run --jobs N` and `submit`.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace ncsim::cli {

/// NC7210: sbatch could not be run or the array failed.
inline constexpr const char* kStudySbatchId = "NC7210";

struct StudyOptions {
  std::string study;        ///< STUDY.toml (plan, run, submit)
  std::string dir;          ///< -o DIR (plan, run, submit) or DIR (job, merge)
  std::uint64_t index = 0;  ///< INDEX (job)
  unsigned jobs = 0;        ///< --jobs N threads (run; 0: the cores)
  std::uint64_t chunk = 0;  ///< --chunk K jobs per array task (0: runner::study_default_chunk)
  std::string partition;    ///< --partition P (plan, submit)
  std::string merged;       ///< merge -o FILE ("": DIR/results.csv)
};

int study_plan(const StudyOptions& o, std::ostream& out, std::ostream& err);
int study_run(const StudyOptions& o, std::ostream& out, std::ostream& err);
int study_job(const StudyOptions& o, std::ostream& out, std::ostream& err);
int study_merge(const StudyOptions& o, std::ostream& out, std::ostream& err);
int study_submit(const StudyOptions& o, std::ostream& out, std::ostream& err);

class StudyCommand {
 public:
  explicit StudyCommand(CLI::App& app);
  /// The exit status when `study` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  StudyOptions options_;
  CLI::App* cmd_ = nullptr;
  CLI::App* plan_ = nullptr;
  CLI::App* run_ = nullptr;
  CLI::App* job_ = nullptr;
  CLI::App* merge_ = nullptr;
  CLI::App* submit_ = nullptr;
};

}  // namespace ncsim::cli
