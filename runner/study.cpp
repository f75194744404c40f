// runner/study: a study's jobs, its plan folder and its merged table (see the header).

#include "runner/study.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
#include <variant>

#include "core/number_text.hpp"
#include "core/output_file.hpp"

namespace ncsim::runner {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kPlanMagic = "# ncsim study plan";
constexpr std::string_view kPlanStudy = "# study: ";
constexpr std::string_view kPlanDigest = "# digest: ";
constexpr std::string_view kPlanJobs = "# jobs: ";

std::uint64_t size_of(std::size_t n) noexcept {
  return n == 0 ? 1 : n;
}

// The axes' sizes in product order (program, machine, belt_velocity, pitch, fluctuation, seed).
std::array<std::uint64_t, 6> radices(const scenario::StudyFile& s) noexcept {
  return {size_of(s.programs.values.size()),      size_of(s.machines.values.size()),
          size_of(s.belt_velocity.values.size()), size_of(s.pitch.values.size()),
          size_of(s.fluctuation.values.size()),   size_of(s.seed.values.size())};
}

// A varied value: 12 significant digits, so that a range's from + k step reads as written
// (0.30000000000000004 -> 0.3).
std::string value_text(double v) {
  return core::significant_text(v, 12);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::uint64_t study_job_count(const scenario::StudyFile& study) noexcept {
  std::uint64_t n = 1;
  for (const std::uint64_t r : radices(study))
    n *= r;
  return n;
}

StudyJob study_job(const scenario::StudyFile& s, std::uint64_t index) {
  StudyJob job;
  job.index = index;
  const auto r = radices(s);
  std::array<std::uint64_t, 6> digit{};
  std::uint64_t rest = index;
  for (std::size_t k = r.size(); k-- > 0;) {
    digit[k] = rest % r[k];
    rest /= r[k];
  }
  if (s.programs.given()) job.program = &s.programs.values[digit[0]];
  if (s.machines.given()) job.machine = &s.machines.values[digit[1]];
  if (s.belt_velocity.given()) job.belt_velocity = s.belt_velocity.values[digit[2]];
  if (s.pitch.given()) job.pitch = s.pitch.values[digit[3]];
  if (s.fluctuation.given()) job.fluctuation = s.fluctuation.values[digit[4]];
  if (s.seed.given()) job.seed = s.seed.values[digit[5]];
  return job;
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string study_jobs_header(const scenario::StudyFile& s) {
  std::string h = "job";
  if (s.programs.given()) h += ",program";
  if (s.machines.given()) h += ",machine";
  if (s.belt_velocity.given()) h += ",belt_velocity_mm_s";
  if (s.pitch.given()) h += ",pitch_mm";
  if (s.fluctuation.given()) h += ",fluctuation_percent";
  if (s.seed.given()) h += ",seed";
  return h + "\n";
}

std::string study_header(const scenario::StudyFile& s) {
  std::string h = study_jobs_header(s);
  h.pop_back();
  return h +
         ",exit,stop,error_id,end_s,arrived,taken,missed,per_minute,audit,audit_violations,"
         "error\n";
}

std::string study_job_fields(const scenario::StudyFile& s, const StudyJob& job) {
  std::string f = std::to_string(job.index);
  if (job.program) f += "," + csv_field(job.program->text);
  if (job.machine) f += "," + csv_field(job.machine->text);
  if (job.belt_velocity) f += "," + value_text(*job.belt_velocity);
  if (job.pitch) f += "," + value_text(*job.pitch);
  if (job.fluctuation) f += "," + value_text(*job.fluctuation);
  if (job.seed) f += "," + std::to_string(*job.seed);
  (void)s;
  return f;
}

std::string study_row(const scenario::StudyFile& s, const StudyJob& job, const StudyOutcome& o) {
  const auto count = [](const std::optional<std::uint64_t>& n) {
    return n ? std::to_string(*n) : std::string();
  };
  std::string row = study_job_fields(s, job);
  row += "," + std::to_string(static_cast<int>(o.exit));
  row += "," + csv_field(o.stop);
  row += "," + csv_field(o.error_id);
  row += "," + core::micro_text(o.t_end);
  row += "," + count(o.arrived);
  row += "," + count(o.taken);
  row += "," + count(o.missed);
  row += ",";
  if (o.taken && o.t_end > 0.0)
    row += core::micro_text(60.0 * static_cast<double>(*o.taken) / o.t_end);
  row += ",";
  row += !o.audited ? "off" : o.audit_violations == 0 ? "ok" : "violated";
  row += "," + (o.audited ? std::to_string(o.audit_violations) : std::string());
  row += "," + csv_field(o.error);
  return row + "\n";
}

std::string study_digest(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;  // FNV-1a 64 prime
  }
  std::array<char, 17> hex{};
  std::snprintf(hex.data(), hex.size(), "%016llx", static_cast<unsigned long long>(h));
  return std::string(hex.data());
}

std::string study_plan_text(const scenario::StudyFile& s, const fs::path& abs,
                            std::string_view digest) {
  const std::uint64_t n = study_job_count(s);
  std::string t(kPlanMagic);
  t += "\n";
  t += std::string(kPlanStudy) + abs.string() + "\n";
  t += std::string(kPlanDigest) + std::string(digest) + "\n";
  t += std::string(kPlanJobs) + std::to_string(n) + "\n";
  t += study_jobs_header(s);
  for (std::uint64_t i = 0; i < n; ++i)
    t += study_job_fields(s, study_job(s, i)) + "\n";
  return t;
}

std::optional<StudyPlan> read_study_plan(const fs::path& dir, std::string& why) {
  const fs::path path = study_jobs_path(dir);
  std::ifstream in(path);
  if (!in) {
    why = "'" + dir.string() + "' is not a planned study: no " + path.string() +
          " (ncsim study plan STUDY.toml -o DIR writes it)";
    return std::nullopt;
  }
  std::string magic, study, digest, jobs;
  std::getline(in, magic);
  std::getline(in, study);
  std::getline(in, digest);
  std::getline(in, jobs);
  const auto starts = [](const std::string& line, std::string_view prefix) {
    return line.compare(0, prefix.size(), prefix) == 0;
  };
  if (magic != kPlanMagic || !starts(study, kPlanStudy) || !starts(digest, kPlanDigest) ||
      !starts(jobs, kPlanJobs)) {
    why = path.string() + " is not an ncsim study plan (its first lines are not `" +
          std::string(kPlanMagic) + "`, study, digest, jobs)";
    return std::nullopt;
  }
  StudyPlan plan;
  plan.study = study.substr(kPlanStudy.size());
  plan.digest = digest.substr(kPlanDigest.size());
  try {
    std::size_t used = 0;
    const std::string n = jobs.substr(kPlanJobs.size());
    plan.jobs = std::stoull(n, &used);
    if (used != n.size()) throw std::invalid_argument(n);
  } catch (const std::exception&) {
    why = path.string() + ":4: the job count is not a number";
    return std::nullopt;
  }
  return plan;
}

fs::path study_jobs_path(const fs::path& dir) {
  return dir / "jobs.csv";
}
fs::path study_script_path(const fs::path& dir) {
  return dir / "study.sbatch";
}
fs::path study_merged_path(const fs::path& dir) {
  return dir / "results.csv";
}
fs::path study_result_path(const fs::path& dir, std::uint64_t index) {
  std::array<char, 32> name{};
  std::snprintf(name.data(), name.size(), "job-%06llu.csv", static_cast<unsigned long long>(index));
  return dir / "results" / name.data();
}

std::uint64_t study_default_chunk(std::uint64_t jobs) noexcept {
  return jobs <= kStudyArrayMax ? 1 : (jobs + kStudyArrayMax - 1) / kStudyArrayMax;
}

// The script quotes every path for the shell ('...' with ' as '\'').
std::string study_sbatch_text(const StudyBatch& b) {
  const auto quote = [](const fs::path& p) {
    std::string out = "'";
    for (const char c : p.string()) {
      if (c == '\'') {
        out += "'\\''";
      } else {
        out += c;
      }
    }
    return out + "'";
  };
  const std::uint64_t chunk = b.chunk == 0 ? 1 : b.chunk;
  const std::uint64_t tasks = (b.jobs + chunk - 1) / chunk;
  std::string t = "#!/bin/bash\n";
  t += "# ncsim study: one array task per " + std::to_string(chunk) + " job" +
       (chunk == 1 ? "" : "s") + " (" + std::to_string(b.jobs) +
       " jobs); written by `ncsim study plan`, submitted by `ncsim study submit` or sbatch.\n";
  t += "#SBATCH --job-name=ncsim-study\n";
  t += "#SBATCH --array=0-" + std::to_string(tasks == 0 ? 0 : tasks - 1) + "\n";
  t += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  // Slurm does not expand quotes in #SBATCH lines: the log path is written as it is.
  t += "#SBATCH --output=" + (b.dir / "logs" / "task-%a.log").string() + "\n";
  if (!b.partition.empty()) t += "#SBATCH --partition=" + b.partition + "\n";
  t += "set -eu\n";
  t += "ncsim=" + quote(b.ncsim) + "\n";
  t += "dir=" + quote(b.dir) + "\n";
  t += "chunk=" + std::to_string(chunk) + "\n";
  t += "jobs=" + std::to_string(b.jobs) + "\n";
  t += "first=$((SLURM_ARRAY_TASK_ID * chunk))\n";
  t += "for ((i = first; i < first + chunk && i < jobs; i++)); do\n";
  t += "  \"$ncsim\" study job \"$dir\" \"$i\"\n";
  t += "done\n";
  return t;
}

bool write_study_file(const fs::path& path, std::string_view text, std::string& why) {
  auto opened = core::OutputFile::open(path);
  if (auto* reason = std::get_if<std::string>(&opened)) {
    why = *reason;
    return false;
  }
  core::OutputFile& out = std::get<core::OutputFile>(opened);
  if (!out.write(text)) {
    out.commit(why);
    if (why.empty()) why = "cannot write '" + path.string() + "'";
    return false;
  }
  return out.commit(why);
}

std::optional<std::string> merge_study(const scenario::StudyFile& s, const fs::path& dir,
                                       std::vector<std::uint64_t>& missing) {
  std::string table = study_header(s);
  const std::uint64_t n = study_job_count(s);
  bool complete = true;
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::string row = read_text(study_result_path(dir, i));
    const std::string prefix = std::to_string(i) + ",";
    if (row.empty() || row.back() != '\n' || row.compare(0, prefix.size(), prefix) != 0) {
      complete = false;
      missing.push_back(i);
      continue;
    }
    table += row;
  }
  if (!complete) return std::nullopt;
  return table;
}

}  // namespace ncsim::runner
