#pragma once
// interp/interpreter: the NC decoder. Turns a program file into a lazily pulled stream of
// Commands, evaluating expressions, variables, control flow and subroutines at decode time,
// as the ISG kernel's decoder does (design.md §1).
//
// Inputs: the program file, the machine (axis names, conveyor, kinematics), Options (V.E.
// values, persistent V.S. store, limits). Outputs: `next()` gives one Command at a time; after
// End or after an error the stream ends (`error()` then names the problem with its position).
// The seam is two-way: before a block that needs run-time state (a V.E. read, the probe latch
// before #SYNC IN, the actual position after #SYNC IN/OUT, G74, INDP_ASYN or an INTERRUPTIBLE
// INDP move) `next()` returns a `Barrier`; the run time answers with `resume(RunState)`, and
// only then may `next()` be called again (API misuse otherwise: std::logic_error). `check` and
// `trace` answer from `decode_only_state()` (docs/interp.md "The seam").
// Memory: a bounded block cache and one 24-byte checkpoint per 256 blocks seen (BlockSource;
// the text stays in the mapped file), one frame per open loop / $SWITCH / subroutine level,
// bounded jump memos, and the variables the program creates. Nothing grows with the number
// of loop passes: an endless `$WHILE [TRUE]` runs in constant memory for as long as the
// consumer pulls.
// Invariants: commands come out in program order; each carries its source line and the modal
// snapshot in force; per-command code never throws (program errors are diagnostics).

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "interp/block_source.hpp"
#include "interp/command.hpp"
#include "interp/eval.hpp"
#include "interp/variables.hpp"
#include "machines/cs_stack.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

struct Options {
  std::map<std::string, double> external;     ///< V.E. values by name (upper case)
  PersistentVariables* persistent = nullptr;  ///< V.S. store shared by runs; null: own
  /// Blocks decoded in a row without motion or time passing before NC4903 (0: no limit). A
  /// loop that returns to the same state without motion is NC4901 long before that.
  std::uint64_t max_blocks_without_motion = 100'000'000;
  std::uint32_t skip_levels = 0;   ///< bit n-1 set: skip level /n active
  int max_subroutine_depth = 20;   ///< nesting limit of LL/L calls (NC4302)
  int macro_recursion_limit = 16;  ///< string macro expansion passes (NC4006)
  double centre_diff_max = 0.01;   ///< P-CHAN-00059 default [mm] (ncsim decision)
  double centre_factor = 0.05;     ///< P-CHAN-00060 default 50 x 0.1 % [-]
  /// true: `L file` opens only relative names without a `..` component, i.e. files in or below
  /// the main program's folder; anything else is NC4301 (the fuzz target uses it so that fuzzed
  /// programs cannot reach files elsewhere). false (default): any path, as the manual allows.
  bool confine_subroutine_files = false;
  /// [mm/s] when set, replaces the CONV_VEL of every `#SYNC IN` (after its unit, so a program in
  /// VEL_RESOLUTION=mm/s and one in mm/min get the same velocity): `ncsim sweep --conv-vel
  /// follow` (docs/conveyor.md "sweep"). The programmed word is still parsed and checked
  /// (NC4507, NC4030 at its line); 50587 is checked on the value used.
  std::optional<double> conv_vel;
  /// Folders a cycle's file is looked up in, in this order, before the machine folder's
  /// `cycles/` and the main program's folder (`--cycles DIR`; docs/interp.md "Cycles").
  std::vector<std::filesystem::path> cycle_dirs;
  /// `--missing-cycles skip`: a cycle call (G80-G89, G800-G839, L CYCLE) whose subroutine is
  /// not configured or not found is skipped (no motion, no time) with warning NC4307, once per
  /// G code or cycle name; false: error 20131 / NC4301.
  bool skip_missing_cycles = false;
  /// The channels of the run (#SIGNAL / #WAIT CH=.., docs/lines.md): a CH of a channel the run
  /// does not have is 250008 at its block. Unset (`check`, `trace` of one program): any
  /// channel 1 .. kMaxChannels.
  std::optional<std::vector<std::uint8_t>> channels;
  /// `time` / `run` without a stop condition ([stop], --max-time): the program ends (End with
  /// `endless`) before the block where the decoder finds itself back in an earlier state after
  /// motion with no run-time answer between, i.e. after whole passes of a loop nothing outside
  /// the program can end (docs/interp.md "Endless programs"). false: it runs on.
  bool end_when_endless = false;
};

/// The run time's answer to a Barrier. Only what the barrier asks for is read.
struct RunState {
  std::map<std::string, double> external;  ///< V.E. values by name ("PART" for V.E.PART)
  double latch = 0.0;                      ///< latched conveyor position [mm] (probe_latch)
  CoordFrame frame;                        ///< the frame of `position`; must equal Barrier::frame
  AxisValues position{};                   ///< actual positions [mm | deg]; Barrier::axes are read
  SignalAnswer signal;                     ///< the signal waited for or read (Barrier::signal)
  bool signal_decode_only = false;         ///< `signal` is decode_only_state()'s (no 21549 then)
};

class Interpreter {
 public:
  Interpreter(const core::SourceFile& file, const machines::Machine& machine, Options options = {});
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  /// The next command; nullopt when the stream has ended (after End, or on an error). After a
  /// Barrier, calling next() before resume() throws std::logic_error (API misuse).
  std::optional<Command> next();

  /// Answers the open Barrier; the interpreter then decodes the block the barrier stood
  /// before with these values. Throws std::logic_error when no barrier is open or the state's
  /// frame is not the one asked for.
  void resume(const RunState& state);

  /// The decode-only answer to `barrier` that `check` and `trace` use: V.E. values as given
  /// (`Options::external`, `--ve`) or last written by the program, latch 0, and the programmed
  /// positions re-based with the belt travel 0 (docs/interp.md "Decode-only state").
  RunState decode_only_state(const Barrier& barrier) const;

  /// next(), answering a Barrier at once from decode_only_state() (check, trace, tests). The
  /// barrier is still returned, so that a trace shows it.
  std::optional<Command> next_decode_only();

  /// The error that ended the stream, if any.
  const core::Diagnostic* error() const { return error_ ? &*error_ : nullptr; }
  /// Warnings and notes met so far (the error, if any, is the last item).
  const core::DiagnosticList& diagnostics() const { return diags_; }
  /// The line from which the program repeats forever: the decoder came back to the same block
  /// with the same variables, control stack and modal state after motion or time passed
  /// (a program that runs endlessly, e.g. a `$WHILE 1` pick-and-place cycle); nullopt while
  /// no such repeat was seen. Without motion in between the repeat is error NC4901 instead.
  std::optional<std::uint32_t> endless_from() const;
  // The program's own V.E. writes (docs/scenario.md "The program's V.E. writes")
  /// Records the program's scalar V.E. assignments from now on (off by default).
  void record_ve_writes(bool on);
  /// The V.E. values the program assigned since the last call (the last per name, as
  /// stored); clears them. The run time writes them into the shared V.E. store.
  std::map<std::string, double> take_ve_writes();
  /// File name of Command::file (0: the main program).
  const std::string& file_name(std::uint16_t file) const;
  /// The source of Command::file (0: the main program), for echoing a block's text in a
  /// run-time error. Valid as long as the interpreter.
  const core::SourceFile& source_file(std::uint16_t file) const;

  /// `ncsim check`: the main program's syntax and structure check rides on the interpreter's
  /// first parse of it, so each block is parsed once (grammar::ProgramCheck; call before the
  /// first next()). After the last next(), parse_rest() feeds it the blocks not reached.
  void share_first_parse(grammar::ProgramCheck& check);
  void parse_rest();

  /// Sizes of the containers that must stay bounded (for tests).
  struct Footprint {
    std::size_t control_frames, call_frames, pending, indexed_blocks, jump_memo, p_params;
  };
  Footprint footprint() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  std::optional<Command> open_barrier_;  // the Barrier next() returned, until resume()
  std::optional<core::Diagnostic> error_;
  core::DiagnosticList diags_;
};

}  // namespace ncsim::interp
