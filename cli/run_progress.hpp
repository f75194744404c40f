#pragma once
// cli/run_progress: the progress bar of `ncsim run` / `ncsim time` on stderr (issue 12).
//
// Purpose: tell a person at a terminal how far a long run is: time simulated and blocks done.
// Inputs: the channel's cycles (update() every cycle; cheap: the clock is read once per 4096
// cycles). Outputs: one line rewritten with '\r' on `err`, erased at the end.
// Invariants: shown only when `err` is the process's stderr, stderr is a terminal and the run
// has taken more than 2 s of wall-clock time; it writes nothing else anywhere, so no output
// file and no other stream depends on it (the wall clock decides only whether it is shown).

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <ostream>

#include "core/number_text.hpp"

namespace ncsim::cli {

class Progress {
 public:
  explicit Progress(std::ostream& err)
      : err_(err),
        enabled_(&err == &std::cerr && ::isatty(STDERR_FILENO) == 1),
        start_(std::chrono::steady_clock::now()) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { finish(); }

  /// After each cycle: `t` simulated time [s], `line` the cycle's source line.
  void update(double t, std::uint32_t line) {
    if (line != line_) {
      line_ = line;
      ++blocks_;
    }
    if (!enabled_ || (++calls_ & 4095u) != 0) return;
    const auto now = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(now - start_).count();
    if (wall < 2.0 || now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    shown_ = true;
    err_ << "\rncsim: " << core::decimals_text(t, 3) << " s simulated, " << blocks_
         << " blocks, line " << line << ", " << core::decimals_text(wall > 0.0 ? t / wall : 0.0, 0)
         << "x real time " << std::flush;
  }

  /// Erases the bar (before any message is printed on stderr).
  void finish() {
    if (!shown_) return;
    shown_ = false;
    err_ << "\r\033[K" << std::flush;
  }

 private:
  std::ostream& err_;
  bool enabled_ = false;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
  std::uint64_t calls_ = 0;
  std::uint64_t blocks_ = 0;
  std::uint32_t line_ = 0;
};

}  // namespace ncsim::cli
