#pragma once
// scenario/study_file: a study's TOML file (issue 37 step 5, docs/study.md), read and validated
// like a scenario.
//
// Purpose: what a study varies and on what: the base (a program with its machine and scenario,
// or a line file) and the axes of variation (belt velocity, workpiece spacing, belt
// fluctuation, seed, programs, machines); each combination is one job (runner/study). The files
// named are not opened here (runner/ does, with the positions kept here).
// Inputs: the file (path or text with its name). Outputs: StudyFile when there are no errors,
// and every diagnostic of the file, each at file:line:col with its key (`vary.pitch[2]`): TOML
// syntax (NC7001), wrong types (NC7003), values out of range (NC7004), unknown keys (NC7201,
// "did you mean"), a base missing or given twice (NC7202), a value of an axis given twice
// (NC7203), more jobs than kStudyJobsMax (NC7204). Never throws for bad input.
// Invariants: every axis given has 1 .. kStudyAxisValuesMax distinct values in file order (a
// range `{ from, to, step }` as the list it spans); exactly one base; paths as written (relative
// to the study file's folder: resolved()).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"

namespace ncsim::scenario {

/// Most values of one axis (a list or the range it spans).
inline constexpr std::size_t kStudyAxisValuesMax = 10000;
/// Most jobs of one study (the product of its axes' sizes).
inline constexpr std::uint64_t kStudyJobsMax = 100000;

/// A path of the study file with the position of its value.
struct StudyPath {
  std::string text;     ///< as written
  core::SourceLoc loc;  ///< the value's position in the study file
};

/// One axis of variation: its values in file order and where it stands.
template <typename T>
struct StudyAxis {
  std::vector<T> values;  ///< empty: the axis is not varied
  core::SourceLoc loc;    ///< its key in `[vary]`
  bool given() const noexcept { return !values.empty(); }
};

/// The study file.
struct StudyFile {
  std::string file;                       ///< the file it was read from, as given
  std::string description;                ///< `description`
  std::optional<StudyPath> line;          ///< `line`: the base is a line file (docs/lines.md)
  std::optional<StudyPath> program;       ///< `program`: the base is one program
  std::optional<StudyPath> machine;       ///< `machine` (program base): a machine folder
  std::optional<StudyPath> scenario;      ///< `scenario` (program base), else the program folder's
  std::optional<std::uint64_t> cycle_us;  ///< `cycle_us` [us] over the machines'
  std::optional<double> max_time;         ///< `max_time` [s]: each job stops there at the latest
  bool audit = true;                      ///< `audit`: every job's setpoints audited
  core::SourceLoc vary_loc;               ///< the `[vary]` header (1:1 when absent)

  StudyAxis<StudyPath> programs;    ///< `vary.program`: the programs (program base)
  StudyAxis<StudyPath> machines;    ///< `vary.machine`: the machine folders (program base)
  StudyAxis<double> belt_velocity;  ///< `vary.belt_velocity` [mm/s]
  StudyAxis<double> pitch;          ///< `vary.pitch` [mm] the workpiece series' spacing
  StudyAxis<double> fluctuation;    ///< `vary.fluctuation` [%] the belt's fluctuation amplitude
  StudyAxis<std::uint64_t> seed;    ///< `vary.seed`: the world's random parts' seed

  /// `path` relative to the study file's folder (absolute paths unchanged).
  std::filesystem::path resolved(const StudyPath& path) const;
};

struct StudyLoad {
  std::optional<StudyFile> study;    ///< set when diagnostics has no errors
  core::DiagnosticList diagnostics;  ///< every error of the file
};

/// Validates `file` (its name is the one diagnostics show).
StudyLoad parse_study(const core::SourceFile& file);
/// Loads and validates the file at `path`; a file that cannot be read is NC7010.
StudyLoad load_study(const std::filesystem::path& path);

}  // namespace ncsim::scenario
