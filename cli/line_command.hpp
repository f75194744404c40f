#pragma once
// cli/line_command: `ncsim line check|time|run LINE.toml` (issue 37 step 1, docs/lines.md):
// its options, a runner::LineSpec for runner/line_run (which loads and steps the line), then
// the printing. `check`: every channel's syntax and decode-only semantics with the line's
// channel numbers. `time`: each channel's end time, time waiting for signals and utilisation,
// the line's end, the belt's workpieces and each one's fate (cli/line_report; --json: one JSON
// object). `run -o DIR`: `time`, and one CSV per channel in DIR
// (`ch<number>_<name>.csv`: t, line, the axes' command positions; `# stop` / `# error` at its
// end). `report -o PAGE` (or `run --report PAGE`): the line's HTML page (cli/line_page).
// `sweep --belt-velocity LO:HI`: the highest belt velocity the line runs clean at
// (cli/line_sweep). Exit statuses as `time`: 0, 1 program errors (any channel), 2 usage,
// 3 audit.
// Invariants: parsing and printing only; reruns are byte-identical.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ncsim::cli {

struct LineOptions {
  std::string mode = "time";  ///< check, time, run, report or sweep
  std::string file;           ///< the line file
  std::string output;         ///< run: -o DIR, the folder of the CSVs; report: -o PAGE
  std::string report;         ///< run: --report PAGE, the line page in the same pass
  std::optional<std::uint64_t> cycle_us;
  std::optional<double> max_time;
  bool audit = false;
  bool json = false;  ///< --json: the results as one JSON object
  // sweep (cli/line_sweep.hpp)
  std::string belt_velocity;        ///< --belt-velocity LO:HI [mm/s]
  std::string conv_vel = "follow";  ///< follow: every #SYNC IN's CONV_VEL is the candidate
  double tolerance = 1.0;           ///< [mm/s]
  unsigned grid = 3;                ///< candidates per round
  unsigned jobs = 0;                ///< threads (0: the cores)
};

int run_line_command(const LineOptions& options, std::ostream& out, std::ostream& err);

/// One channel's part of run_line_golden.
struct LineGoldenChannel {
  std::string csv_name;    ///< `ch<number>_<name>.csv`; its golden is `ch<number>_<name>.golden`
  std::string program;     ///< the channel's program file (as the line file resolves it)
  int status = 0;          ///< 0, 1 (the channel's error), 3 (its audit found violations)
  std::string error_text;  ///< the error, positioned; "" when none
};

/// `ncsim line run FILE --audit` for `ncsim golden` (docs/golden.md "Lines"): channel k's CSV
/// is written to csv_path(its csv_name); `channels` gets each channel's outcome. Returns 2
/// (the reasons on `err`) when the line does not load or a CSV cannot be written, else 0.
int run_line_golden(const std::string& file,
                    const std::function<std::filesystem::path(const std::string&)>& csv_path,
                    std::vector<LineGoldenChannel>& channels, std::ostream& err);

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
