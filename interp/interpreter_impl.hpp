#pragma once
// interp/interpreter_impl: the decoder's private state: the block stream, the order of a
// block's parts, modal state, position, variables and the call stack, shared by the parts it
// owns (ControlFlow, Subroutines, Offsets, HashCommands, AxisCommands, Seam, Frames,
// WordReader, TrcWords, RepeatWatch: each in its own files) and by interpreter_*.cpp (G04, G74,
// G92, motion, program ends). Not part of the public interface.

#include <array>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string_view>

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "grammar/keywords.hpp"
#include "interp/axis_commands.hpp"
#include "interp/block_words.hpp"
#include "interp/control_flow.hpp"
#include "interp/frames.hpp"
#include "interp/hash_commands.hpp"
#include "interp/interpreter.hpp"
#include "interp/offsets.hpp"
#include "interp/repeat_watch.hpp"
#include "interp/seam.hpp"
#include "interp/subroutines.hpp"
#include "interp/trc.hpp"
#include "interp/trc_words.hpp"
#include "machines/param_table.hpp"

namespace ncsim::interp {

namespace ast = grammar::ast;

/// The bracket items of one # command or axis command, found by keyword.
struct Items {
  const ast::Block& b;
  std::uint32_t first, count;
  const ast::Item* find(std::string_view keyword) const {
    for (std::uint32_t k = first; k < first + count && k < b.items.size(); ++k) {
      if (grammar::iequals(b.items[k].keyword, keyword)) return &b.items[k];
    }
    return nullptr;
  }
};

/// A program file: the main one (index 0) or a global subroutine file (L name).
struct ProgramFile {
  std::unique_ptr<core::SourceFile> own;  // null for the main file
  const core::SourceFile* file = nullptr;
  std::unique_ptr<BlockSource> blocks;
  std::unordered_map<std::string, std::uint32_t> local_subs;  // upper-case name -> header
  std::uint32_t main_start = 0;                               // first block of the main part
};

struct Pc {
  std::uint16_t file = 0;
  std::uint32_t ordinal = 0;
};

/// Largest arc radius [mm] the interpreter accepts (NC4203; docs/interp.md "Arcs of a huge
/// radius"): a centre 1e9 mm away is represented to 1.2e-7 mm.
inline constexpr double kArcRadiusMax = 1e9;

/// "<what> <seconds> s is longer than ncsim's longest time, 86400 s (one day)": the text of
/// 20751 / 20752 / NC4032 (core/limits.hpp, docs/interp.md "The longest time").
inline std::string longest_time_text(std::string_view what, double seconds) {
  return std::string(what) + " " + core::number_text(seconds) +
         " s is longer than ncsim's longest time, " + core::number_text(core::kLongestTime) +
         " s (one day)";
}

/// The machine index of the axis named by each one-byte name (ASCII), kNoAxisIndex for none.
inline constexpr std::uint8_t kNoAxisIndex = 0xFF;

/// V.G.KIN[id].PARAM[k] covers the kinematic ids below this (P-TOOL-00011's ids are UNS16;
/// the kernel's own ids are below 1000: 500..999 TcCOM, TF5240).
inline constexpr int kMaxKinVarId = 1000;
using AxisByChar = std::array<std::uint8_t, 128>;
/// Interpreter::Impl::axis_index() of every one-byte name, once per machine.
AxisByChar axis_by_char(const machines::Machine& machine);

struct CallFrame {
  Pc ret;
  std::size_t control_depth = 0;
  std::uint32_t unit_start = 0;
};

struct Interpreter::Impl {
  Impl(const core::SourceFile& file, const machines::Machine& machine, Options options,
       core::DiagnosticList& diags);

  // stream (interpreter.cpp)
  bool step();  // decodes one block; false when the stream ended
  const ast::Block* fetch(Pc pc);

  bool fail(core::SourceLoc loc, std::string id, std::string message);
  bool fail_eval();
  /// A diagnostic that does not stop the program: a warning, or a note (`severity`).
  void warn(core::SourceLoc loc, std::string id, std::string message,
            core::Severity severity = core::Severity::warning);
  std::optional<double> eval(const ast::Block& b, ast::NodeIndex n);

  // blocks (interpreter_block.cpp)
  BlockWords block_words;               // run_words' scratch (one block at a time)
  bool run_words(const ast::Block& b);  // the order of a block's parts; calls the pieces below
  bool run_assignments(const ast::Block& b);
  trc::Compensator trc_filter;  // between pending and the consumer (Interpreter::next)
  CommandQueue trc_out;         // commands the filter released
  bool run_dwell(const ast::Block& b, const BlockWords& bw);     // G04
  void run_homing(const BlockWords& bw);                         // G74
  bool check_homing(const ast::Block& b, const BlockWords& bw);  // interpreter_homing.cpp
  void run_set_position(const BlockWords& bw);                   // G92
  bool run_block_motion(const ast::Block& b, const BlockWords& bw);
  bool run_program_m(const ast::Block& b, int code);  // M00/M01/M02/M30/M17/M29
  /// The channel's slope, P-CHAN-00071: the program's start slope and `#SLOPE DEFAULT`'s.
  SlopeType channel_slope() const;
  bool spline_on(core::SourceLoc at);   // #SPLINE ON / G151
  bool spline_off(core::SourceLoc at);  // #SPLINE OFF / G150 (emits SplineEnd)
  /// The stream's end without M02/M30 (end of file, or `end`'s endless stop): an open spline
  /// section's last points run first, as at M30; false on its error.
  bool end_stream(End end);
  bool run_declaration(const ast::Block& b, const ast::Declaration& d);
  /// What a block says about its own motion only (non-modal words, isg-language.md §2.4).
  struct BlockMotionWords {
    bool stop_at_end = false;          ///< G09
    bool exact_stop = false;           ///< G60
    bool contour = false;              ///< G61
    std::optional<double> block_time;  ///< G93 F [s]
    std::optional<double> end_feed;    ///< E [mm/s]
  };
  bool run_motion(const ast::Block& b, MotionKind kind, const AxisValues& target,
                  AxisMask programmed, const std::array<std::optional<double>, 3>& ijk,
                  std::optional<double> radius, const BlockMotionWords& words);
  /// The arc of a G02/G03 from `position` to `target` (centre from I/J/K or R, corrected onto
  /// the bisector); nullopt after an error.
  std::optional<Arc> make_arc(const ast::Block& b, MotionKind kind, const AxisValues& target,
                              const std::array<std::optional<double>, 3>& ijk,
                              std::optional<double> radius);
  std::optional<std::uint8_t> axis_index(std::string_view name) const;
  /// V.G.KIN[id].PARAM[k] from the channel list's trafo[] (read only).
  void provide_kinematic_params();
  ModalSnapshot snapshot() const;

  // run-time state the seam (seam.hpp) keeps for the whole decoder
  bool resumed = false;       // the barrier before the block at pc was answered
  AxisMask unknown_axes = 0;  // axes whose actual position only the run time knows
  // The part of unknown_axes that only an INDP_ASYN motion made unknown: a
  // block asks for them only when it programs them (P-CHAN-00451: programming the axis again
  // synchronises it: docs/ipo.md "Position barriers"). Always a subset of unknown_axes.
  AxisMask indp_unknown = 0;
  double latch = 0.0;              // conveyor position latched before the last #SYNC IN [mm]
  SignalAnswer signal_answer;      // the signal the barrier before a #WAIT / #SIGNAL READ gave
  bool signal_decode_only = true;  // that answer is the decode-only one (no 21549 then)
  /// Queues a command of this block (the body built once into the queue's storage: a Motion
  /// is some 700 bytes, every move of it costs).
  template <typename Body>
  void emit(std::uint32_t at_line, Body&& body) {
    pending.emplace_back(at_line, current_file, std::forward<Body>(body));
  }
  const ast::Block* expand_macros(const ast::Block& b);

  const machines::Machine& machine;
  Options options;
  core::DiagnosticList& diags;
  std::optional<core::Diagnostic> error;
  bool error_reported = false;  // the error is a parser diagnostic already in diags

  std::vector<std::unique_ptr<ProgramFile>> files;
  std::unordered_map<std::string, std::uint16_t> file_by_name;
  Pc pc;
  std::uint32_t unit_start = 0;  // header ordinal of the running program level
  bool started = false;
  bool finished = false;
  std::vector<CallFrame> calls;
  ControlFlow flow{*this};            // $IF, $SWITCH, loops, $GOTO (control_flow.hpp)
  Subroutines subs{*this};            // calls, program levels, cycles (subroutines.hpp)
  Offsets offsets{*this};             // zero offsets, #PSET, #SCALE, #MCS, #HSC, #VECTOR LIMIT
  HashCommands hash{*this};           // # commands (hash_commands.hpp)
  AxisCommands axis_commands{*this};  // INDP, MC_* (axis_commands.hpp)
  Seam seam{*this};                   // barriers and the run time's answers (seam.hpp)
  WordReader word_reader{*this};      // a block's G codes and addresses (block_words.hpp)
  TrcWords trc_words{*this};          // G40/G41/G42, D: the TRC state (trc_words.hpp)
  CommandQueue pending;
  std::uint64_t blocks_without_motion = 0;
  /// Run-time answers, #WAITs and #SYNC INs decoded: the outside world's part in a loop
  /// (RepeatWatch::endless_on_its_own)
  std::uint64_t world_waits = 0;
  RepeatWatch repeat{*this};  // endless programs (repeat_watch.hpp)
  std::uint32_t line = 0;     // line of the block being decoded
  std::uint16_t current_file = 0;

  Variables vars;
  Evaluator evaluator;

  // modal state
  AxisValues position{};
  AxisMask path_axes = 0;  // axes that take part in path motion (not spindles)
  MotionKind motion = MotionKind::rapid;
  // The programmed modal G state (G360 -> exact_stop, G261 -> contouring, #SLOPE -> slope;
  // the slope starts as P-CHAN-00071, set in the constructor); snapshot() adds what a motion
  // derives from elsewhere (cs_active, the forced slope).
  ModalSnapshot modal;
  bool centre_absolute = false;    // G161
  std::optional<double> feed;      // [mm/s]
  bool motion_since_sync = true;   // first motion after #SYNC IN not yet seen
  bool departure_pending = false;  // #SYNC OUT decoded, its desynchronisation motion not yet
  std::optional<int> kin_id;
  machines::CsStack cs;
  SplineType spline_type = SplineType::akima;
  struct OpenSpline {
    SplineType type = SplineType::akima;
    std::uint32_t points = 1;    // vertices so far, start included
    std::uint32_t distinct = 1;  // of them, those unlike the one before (the planner drops
                                 // a repeated vertex: planner/spline.cpp kSamePoint)
  };
  std::optional<OpenSpline> spline;        // between #SPLINE ON and OFF
  Frames::Xyz xyz{};                       // machine indices of X, Y, Z
  Frames frames{machine, cs, modal, xyz};  // the frame of `position`, re-basing (frames.hpp)
  /// axis_index() of every one-character name (the axis words of most blocks)
  AxisByChar single_letter_axes = axis_by_char(machine);
};

}  // namespace ncsim::interp
