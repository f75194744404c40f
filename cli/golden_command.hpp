#pragma once
// cli/golden_command: `ncsim golden check [PROGRAM...]` and `ncsim golden bless PROGRAM...|--all`
// (docs/golden.md).
//
// Purpose: keep and check the golden trajectory of each program. Inputs: programs (a program
// folder `programs/<name>/` holding `<name>.nc`, or an .nc file; the golden is `<name>.golden`
// beside the program); without any, `check` takes every program folder of the library
// (--programs DIR, default the source tree's `programs/`). Each program runs through
// `run_run` (the code of `ncsim run`, with --audit) into a temporary CSV, which the golden
// library streams. Outputs: `check`: one verdict line per program on `out`, every deviation as
// `golden:line: error: ... [NC800x]` on `err`; `bless`: the golden files, written to
// `<file>.tmp` and renamed. Exit statuses: 0 all match, 1 a mismatch or a missing golden,
// 2 usage, a program that cannot run, a malformed golden.
// Invariants: `check` never writes a golden; memory does not grow with a run (the CSV is
// streamed from disk); temporary files are removed.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

namespace CLI {
class App;
}

namespace ncsim::cli {

struct GoldenOptions {
  std::vector<std::filesystem::path> programs;   ///< program folders or .nc files
  std::optional<std::filesystem::path> library;  ///< --programs DIR: the library folder
  bool all = false;                              ///< bless --all: every program of the library
};

/// `ncsim golden check`.
int run_golden_check(const GoldenOptions& options, std::ostream& out, std::ostream& err);
/// `ncsim golden bless`.
int run_golden_bless(const GoldenOptions& options, std::ostream& out, std::ostream& err);

/// The `golden` subcommand of `app` with `check` and `bless`: the hook main.cpp calls.
class GoldenCommands {
 public:
  explicit GoldenCommands(CLI::App& app);
  /// The exit status when `golden` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  GoldenOptions check_;
  GoldenOptions bless_;
  CLI::App* check_cmd_ = nullptr;
  CLI::App* bless_cmd_ = nullptr;
};

}  // namespace ncsim::cli
