#pragma once
// interp/interpreter_impl: the decoder's private state, shared by interpreter.cpp (block
// stream, control flow, subroutines) and interpreter_block.cpp (words, modal state, motion,
// # commands). Not part of the public interface.

#include <deque>
#include <string_view>

#include "grammar/keywords.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

namespace ast = grammar::ast;

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

enum class FrameKind : std::uint8_t { for_, while_, do_, repeat, switch_ };

struct ControlFrame {
  FrameKind kind = FrameKind::for_;
  std::uint16_t file = 0;
  std::uint32_t open = 0;              // ordinal of the opening block
  std::uint32_t end = 0xFFFFFFFFu;     // ordinal of the closing block, once known
  VarRef counter;                      // $FOR
  double end_value = 0.0, step = 0.0;  // $FOR
  std::uint32_t line = 0;
};

/// A $GOTO target copied out of its block (the block may leave the cache during the search).
struct GotoLabel {
  ast::GotoKind kind = ast::GotoKind::none;
  std::uint32_t number = 0;  // block number for GotoKind::block_number
  std::string name;          // label name, or the block number's digits
  bool matches(const ast::Block& b) const {
    if (kind == ast::GotoKind::block_number) {
      return b.number && b.number->is_label && b.number->number == number;
    }
    return b.label && grammar::iequals(b.label->name, name);
  }
};

/// Where a $GOTO site lands and what the jump leaves or enters, remembered per site.
struct GotoResult {
  std::uint32_t label = 0;          // ordinal of the labelled block
  bool backward = false;            // found before the $GOTO
  int closed = 0;                   // forward: loop/$SWITCH ends passed (frames left)
  std::vector<std::uint32_t> open;  // backward: openers enclosing the label
};

/// Entries each memo of jump destinations holds at most; a full memo is cleared and refilled
/// on demand, so memory does not grow with the program length.
inline constexpr std::size_t kMaxMemoEntries = 1u << 16;

struct CallFrame {
  Pc ret;
  std::size_t control_depth = 0;
  std::uint32_t unit_start = 0;
};

struct Interpreter::Impl {
  Impl(const core::SourceFile& file, const machines::Machine& machine, Options options,
       core::DiagnosticList& diags);

  // --- stream (interpreter.cpp) ---
  bool step();  // decodes one block; false when the stream ended
  bool watch_for_repeat(std::uint32_t block_line);
  std::uint64_t state_fingerprint(std::size_t& cost) const;
  const ast::Block* fetch(Pc pc);
  bool run_control(const ast::Block& b, const ast::Control& c);
  bool jump_to_label(const ast::Block& b, const ast::GotoTarget& target);
  std::optional<GotoResult> find_label(const GotoLabel& target, core::SourceLoc at);
  static void remember(std::unordered_map<std::uint64_t, std::uint32_t>& memo, std::uint64_t key,
                       std::uint32_t value);
  std::optional<std::uint32_t> matching_end(std::uint16_t file, std::uint32_t from,
                                            core::SourceLoc at);
  std::optional<std::uint32_t> next_if_branch(std::uint16_t file, std::uint32_t from,
                                              bool endif_only, core::SourceLoc at);
  bool call(const ast::Block& b, const ast::Call& c);
  bool subroutine_return();
  bool find_main_start(ProgramFile& pf, std::uint16_t index);
  bool fail(core::SourceLoc loc, std::string id, std::string message);
  bool fail_eval();
  void warn(core::SourceLoc loc, std::string id, std::string message);
  std::optional<double> eval(const ast::Block& b, ast::NodeIndex n);

  // --- blocks (interpreter_block.cpp) ---
  bool run_words(const ast::Block& b);
  bool run_hash(const ast::Block& b, const ast::HashCommand& h);
  bool spline_on(core::SourceLoc at);   // #SPLINE ON / G151
  bool spline_off(core::SourceLoc at);  // #SPLINE OFF / G150 (emits the Spline)
  bool run_declaration(const ast::Block& b, const ast::Declaration& d);
  bool run_axis_commands(const ast::Block& b);
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
  std::optional<std::uint8_t> axis_index(std::string_view name) const;
  ModalSnapshot snapshot() const;
  void emit(std::uint32_t line, CommandBody body);
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
  std::vector<ControlFrame> control;
  std::vector<CallFrame> calls;
  std::unordered_map<std::uint64_t, std::uint32_t> jump_memo;  // $IF/loop partners
  std::unordered_map<std::uint64_t, GotoResult> goto_memo;     // by $GOTO site
  std::deque<Command> pending;
  std::uint64_t blocks_without_motion = 0;
  // Repeat detection (Brent's cycle finding over decoder states, docs/interp.md "Endless
  // programs"): the state saved at block `at` of the run, compared whenever pc returns to it.
  struct RepeatWatch {
    Pc pc{0xFFFF, 0};
    std::uint32_t line = 0;
    std::uint64_t fingerprint = 0;
    std::uint64_t at = 0;      // blocks decoded when saved
    std::uint64_t period = 1;  // blocks until the next save
    std::uint64_t credit = 0;  // blocks to decode before the next (costly) comparison
  } repeat;
  std::uint64_t decoded = 0;  // blocks decoded in this run
  std::optional<std::uint32_t> endless_from;
  std::uint32_t line = 0;  // line of the block being decoded
  std::uint16_t current_file = 0;

  Variables vars;
  Evaluator evaluator;

  // modal state
  AxisValues position{};
  AxisMask path_axes = 0;  // axes that take part in path motion (not spindles)
  MotionKind motion = MotionKind::rapid;
  // The programmed modal G state (G360 -> exact_stop, G261 -> contouring, #SLOPE -> slope);
  // snapshot() adds what a motion derives from elsewhere (cs_active, the forced slope).
  ModalSnapshot modal;
  bool centre_absolute = false;   // G161
  std::optional<double> feed;     // [mm/s]
  bool motion_since_sync = true;  // first motion after #SYNC IN not yet seen
  std::optional<int> kin_id;
  machines::CsStack cs;
  SplineType spline_type = SplineType::akima;
  std::optional<Spline> spline;                      // collecting points between #SPLINE ON and OFF
  std::array<std::optional<std::uint8_t>, 3> xyz{};  // machine indices of X, Y, Z
  std::string scratch_text;
};

}  // namespace ncsim::interp
