#pragma once
// runner/study: a study's jobs, its plan folder and its one merged table (issue 37 step 5,
// docs/study.md).
//
// Purpose: everything about a study but running a job (cli/study_job does that): which values
// job i runs with, the plan folder's files (the job list `jobs.csv`, the Slurm batch script
// `study.sbatch`, one result file per job `results/job-NNNNNN.csv`) and the merge of the
// per-job results into `results.csv`.
// Inputs: a validated scenario::StudyFile; the plan folder. Outputs: texts and files.
// Method: the jobs are the product of the study's axes in a fixed order (program, machine,
// belt_velocity, pitch, fluctuation, seed; the last varies fastest), job i by its mixed-radix
// digits, so any process computes job i alone from the study file. The job list records the
// study file's absolute path and a digest of its text; `job` and `merge` refuse a study file
// that changed since the plan (NC7207). Each job's result is one CSV row written atomically
// (core::OutputFile: a temporary file renamed); the merge reads them in job order, so the
// table is byte-identical whoever ran the jobs, in whatever order, on however many machines.
// Invariants: rows contain no wall clock, host or process data; the varied values to 12
// significant digits, times and rates to the microsecond (core::micro_text, as the goldens).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runner/spec.hpp"
#include "scenario/study_file.hpp"

namespace ncsim::runner {

/// NC7207: the study file changed since it was planned (or cannot be read again).
inline constexpr const char* kStudyChangedId = "NC7207";
/// NC7208: a folder that is not a planned study, or a job index outside it.
inline constexpr const char* kStudyPlanId = "NC7208";
/// NC7209: jobs without a result at the merge.
inline constexpr const char* kStudyMissingId = "NC7209";

/// The values one job runs with (nullopt / null: the base's own).
struct StudyJob {
  std::uint64_t index = 0;
  const scenario::StudyPath* program = nullptr;  ///< vary.program's value
  const scenario::StudyPath* machine = nullptr;  ///< vary.machine's value
  std::optional<double> belt_velocity;           ///< [mm/s]
  std::optional<double> pitch;                   ///< [mm]
  std::optional<double> fluctuation;             ///< [%]
  std::optional<std::uint64_t> seed;
};

/// The number of jobs: the product of the axes' sizes (1 without axes).
std::uint64_t study_job_count(const scenario::StudyFile& study) noexcept;
/// Job `index` (< study_job_count) of `study` (points into it).
StudyJob study_job(const scenario::StudyFile& study, std::uint64_t index);

/// What one job's run gave (cli/study_job fills it).
struct StudyOutcome {
  Exit exit = Exit::ok;  ///< as `time` / `line time` would exit
  std::string stop;      ///< the stop reason ("program end", "error", "stop.time", ...)
  std::string error_id;  ///< the first error's id, "" when none
  std::string error;     ///< the first error's first line, or the first audit violation
  double t_end = 0.0;    ///< [s] the run's (the line's) end: its machining time
  /// Workpieces: taken (a program: the workpieces it completed); arrived and missed only on a
  /// line's belt, which counts every workpiece's fate (docs/lines.md).
  std::optional<std::uint64_t> arrived;
  std::optional<std::uint64_t> taken;
  std::optional<std::uint64_t> missed;
  bool audited = false;  ///< the audit ran
  std::uint64_t audit_violations = 0;
};

/// The merged table's header line (with '\n'): job, the varied values, the outcome.
std::string study_header(const scenario::StudyFile& study);
/// The job list's header line (with '\n'): job and the varied values.
std::string study_jobs_header(const scenario::StudyFile& study);
/// Job `job`'s values as CSV fields after its index ("3,300,105"), no newline.
std::string study_job_fields(const scenario::StudyFile& study, const StudyJob& job);
/// Job `job`'s row of the merged table (with '\n').
std::string study_row(const scenario::StudyFile& study, const StudyJob& job,
                      const StudyOutcome& outcome);
/// `text` as one CSV field: quoted (with "" for ") when it holds a comma, quote or newline.
std::string csv_field(std::string_view text);

/// 64-bit FNV-1a of `text` as 16 hex digits: the study file's digest in the job list.
std::string study_digest(std::string_view text);

/// A plan folder's job list, read back.
struct StudyPlan {
  std::filesystem::path study;  ///< the study file's absolute path
  std::string digest;           ///< its text's digest at the plan
  std::uint64_t jobs = 0;
};

/// The job list (`jobs.csv`): the study's path and digest as comments, then one row per job.
std::string study_plan_text(const scenario::StudyFile& study, const std::filesystem::path& abs,
                            std::string_view digest);
/// Reads DIR/jobs.csv; nullopt with the reason in `why` (NC7208).
std::optional<StudyPlan> read_study_plan(const std::filesystem::path& dir, std::string& why);

/// The plan folder's files.
std::filesystem::path study_jobs_path(const std::filesystem::path& dir);
std::filesystem::path study_script_path(const std::filesystem::path& dir);
std::filesystem::path study_result_path(const std::filesystem::path& dir, std::uint64_t index);
std::filesystem::path study_merged_path(const std::filesystem::path& dir);

/// Options of the batch script.
struct StudyBatch {
  std::filesystem::path ncsim;  ///< the ncsim executable (absolute)
  std::filesystem::path dir;    ///< the plan folder (absolute)
  std::uint64_t jobs = 0;       ///< the study's jobs
  std::uint64_t chunk = 1;      ///< jobs per array task
  std::string partition;        ///< `#SBATCH --partition` ("": the cluster's default)
};
/// The smallest chunk that keeps the array at most kStudyArrayMax tasks.
std::uint64_t study_default_chunk(std::uint64_t jobs) noexcept;
/// Most tasks of one job array (Slurm's default MaxArraySize is 1001: indices 0 .. 1000).
inline constexpr std::uint64_t kStudyArrayMax = 1000;
/// The Slurm batch script: a job array, task k runs jobs k x chunk .. (k + 1) x chunk - 1 with
/// `ncsim study job DIR INDEX`.
std::string study_sbatch_text(const StudyBatch& batch);

/// Writes `text` to `path` atomically (core::OutputFile); false with the reason in `why`.
bool write_study_file(const std::filesystem::path& path, std::string_view text, std::string& why);

/// The merged table of a planned study: the header and every job's result row in job order;
/// nullopt when results are missing (their indices in `missing`, in order).
std::optional<std::string> merge_study(const scenario::StudyFile& study,
                                       const std::filesystem::path& dir,
                                       std::vector<std::uint64_t>& missing);

}  // namespace ncsim::runner
