#pragma once
// cli/line_command: `ncsim line check|time|run LINE.toml` (issue 37 step 1, docs/lines.md):
// its options, a runner::LineSpec for runner/line_run (which loads and steps the line), then
// the printing. `check`: every channel's syntax and decode-only semantics with the line's
// channel numbers. `time`: each channel's end time, time waiting for signals and utilisation,
// and the line's end. `run -o DIR`: `time`, and one CSV per channel in DIR
// (`ch<number>_<name>.csv`: t, line, the axes' command positions; `# stop` / `# error` at its
// end). Exit statuses as `time`: 0, 1 program errors (any channel), 2 usage, 3 audit.
// Invariants: parsing and printing only; reruns are byte-identical.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace ncsim::cli {

struct LineOptions {
  std::string mode = "time";  ///< check, time or run
  std::string file;           ///< the line file
  std::string output;         ///< run: -o DIR, the folder of the CSVs
  std::optional<std::uint64_t> cycle_us;
  std::optional<double> max_time;
  bool audit = false;
};

int run_line_command(const LineOptions& options, std::ostream& out, std::ostream& err);

class LineCommand {
 public:
  explicit LineCommand(CLI::App& app);
  /// The exit status when `line` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  LineOptions options_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace ncsim::cli
