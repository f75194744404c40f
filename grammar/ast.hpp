#pragma once
// grammar/ast: the syntax tree of one NC block, as the block parser hands it out.
//
// Purpose: the interpreter's input. The parser streams a program block by block into one reused
// `Block` (clear() keeps capacity), so a whole program is never held in memory.
// Inputs: produced by grammar::BlockParser. Outputs: read by grammar::check_program's structure
// checker and by the interpreter.
// Invariants:
//   - every block, word, item and expression node carries a 1-based line and column;
//   - `std::string_view`s point into the SourceFile's text: the SourceFile outlives the Block;
//   - expressions are a compact node array per block (`Block::exprs`); a node refers to its
//     children by index (`kNoNode` = none), never by pointer; children precede their parent;
//   - names keep their source spelling; comparisons are case-insensitive (docs/language.md).

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "core/source_file.hpp"

namespace ncsim::grammar::ast {

using NodeIndex = std::uint32_t;
inline constexpr NodeIndex kNoNode = 0xFFFFFFFFu;

enum class Op : std::uint8_t {
  // leaves
  number,     ///< `value`
  constant,   ///< TRUE / FALSE / PI; `value` holds 1, 0 or pi; `text` the spelling
  variable,   ///< P1, PP10, @P1, V.x.y; `text` whole reference; `a` first subscript
  string,     ///< "..." : a macro use (or string value); `text` raw contents, escapes kept
  subscript,  ///< one `[i]` of a variable; `text` segment name before it; `a` index; `next`
  // unary; operand in `a`
  negate,
  plus,
  logical_not,
  bit_inv,
  // binary; operands in `a`, `b`
  power,
  multiply,
  divide,
  modulo,
  add,
  subtract,
  equal,
  not_equal,
  less,
  greater,
  less_equal,
  greater_equal,
  bit_and,
  bit_xor,
  bit_or,
  logical_and,
  logical_xor,
  logical_or,
  // function call; `function` names it, first argument in `a`, further ones via `next`
  call,
};

enum class Function : std::uint8_t {
  none,
  sin,
  cos,
  tan,
  cot,
  asin,
  acos,
  atan,
  acot,
  atan2,
  sqrt,
  sqr,
  abs,
  int_,
  fract,
  round,
  ceil,
  floor,
  exp,
  ln,
  dexp,
  log,
  sizeof_,
  exist,
};

enum class VarClass : std::uint8_t {
  none,
  p,        ///< P<n>
  pp,       ///< PP<n>
  at_p,     ///< @P<n> (cycle parameter)
  v_p,      ///< V.P.
  v_l,      ///< V.L.
  v_s,      ///< V.S.
  v_e,      ///< V.E.
  v_g,      ///< V.G.
  v_cyc,    ///< V.CYC.
  v_other,  ///< any other V. class (V.A., V.SPDL., ...)
};

struct ExprNode {
  Op op = Op::number;
  Function function = Function::none;   ///< for Op::call
  VarClass var_class = VarClass::none;  ///< for Op::variable
  core::SourceLoc loc;                  ///< first character of the node's text
  double value = 0.0;                   ///< number / constant value; P/PP/@P number
  std::string_view text;                ///< spelling (see Op)
  NodeIndex a = kNoNode;
  NodeIndex b = kNoNode;
  NodeIndex next = kNoNode;  ///< next argument / next subscript
};

// Words

enum class WordKind : std::uint8_t {
  g,  ///< G<code>[=value]
  m,  ///< M<value>
  h,  ///< H<value>
  f,  ///< F feed (mm/min by default)
  e,  ///< E non-modal end feed
  s,  ///< S spindle speed
  t,  ///< T tool
  d,  ///< D tool offset
  i,
  j,
  k,
  r,           ///< circle centre / radius
  axis,        ///< X10, AB=90; `name` the axis
  bare_value,  ///< a value standing alone (G04 3.0, G04 P1)
  assignment,  ///< target op= value
  macro_def,   ///< "NAME" = "text"
};

enum class AssignOp : std::uint8_t { set, add, subtract, multiply, divide };

struct Word {
  WordKind kind = WordKind::g;
  core::SourceLoc loc;              ///< the address letter (or target / macro name)
  std::uint32_t code = 0;           ///< G code number (G01 -> 1)
  std::string_view name;            ///< axis name; macro name; G spelling ("G01")
  NodeIndex value = kNoNode;        ///< value expression (G: argument after '=' if any)
  NodeIndex extra = kNoNode;        ///< M/H additional value (`M200=1200`: 1200)
  std::uint32_t first_item = 0;     ///< G80-G839 parameter list in Block::items
  std::uint32_t item_count = 0;     ///< its components (ItemKind::positional / empty)
  bool has_params = false;          ///< G80-G839 written with a `[...]` list
  NodeIndex target = kNoNode;       ///< assignment target (an Op::variable node)
  AssignOp assign = AssignOp::set;  ///< assignment operator
  std::string_view text;            ///< macro_def: replacement text (raw, escapes kept)
};

// Bracket lists (# commands, axis-bracket commands, L CYCLE)

enum class ItemKind : std::uint8_t {
  flag,        ///< KEYWORD without value
  keyword,     ///< KEYWORD[=]value (value in expr, word or text)
  positional,  ///< a bare expression (`[0,0,10]`, `#TIME 2`)
  empty,       ///< an empty positional component (`[,,5]`)
  string,      ///< a bare string ("text")
};

inline constexpr std::uint16_t kUnknownKeyword = 0xFFFF;

struct Item {
  ItemKind kind = ItemKind::flag;
  core::SourceLoc loc;                  ///< first character of the item
  std::uint8_t group = 0;               ///< which `[...]` list of the command (0-based)
  std::uint16_t key = kUnknownKeyword;  ///< index into the command's KeywordTable
  std::string_view keyword;             ///< keyword spelling as written
  NodeIndex value = kNoNode;            ///< expression value
  std::string_view text;                ///< word value (AX=C, TYPE=TRAPEZ) or string contents
  /// The index of an indexed keyword (`P[2]=V.P.X` of #SIGNAL / #WAIT: the 2); value is then
  /// the right-hand side.
  NodeIndex index = kNoNode;
};

/// Which keyword table a bracket list uses; see grammar/keywords.hpp.
enum class TableId : std::uint8_t {
  none,
  sync_in,
  sync_out,
  caxtrack_on,
  caxtrack_off,
  contour_mode,
  slope,
  machine_data,
  transvelmin,
  wait_indp,
  trafo,
  kin_id,
  cs,
  msg,
  time,
  delete_,
  init,
  indp,
  mc_move_velocity,
  mc_touch_probe,
  mc_other,
  cycle,
  g_params,      ///< G80-G89 / G800-G839 [v1, v2,, v4] (implicit subroutine call)
  file_name,     ///< #FILE NAME [G80="x.nc"]
  hsc,           ///< #HSC ON [PATH_DEV=.. ...]
  vector_limit,  ///< #VECTOR LIMIT ON [VEL=.. ACC=.. DEC=..]
  scale,         ///< #SCALE [ON] X2 Y0.5
  signal,        ///< #SIGNAL / #WAIT / #SIGNAL READ [ID=.. COUNT=.. P[i]=.. CH=..]
  tangfeed,      ///< #TANGFEED [RMIN=..] / #SET TANGFEED RMIN [..]
};

// Axis-bracket commands and calls

enum class AxisCommandKind : std::uint8_t {
  indp_syn,
  indp_asyn,
  mc_home,
  mc_move_absolute,
  mc_move_additive,
  mc_move_relative,
  mc_move_superimposed,
  mc_move_velocity,
  mc_stop,
  mc_gear_in,
  mc_gear_out,
  mc_phasing,
  mc_touch_probe,
};

struct AxisCommand {
  AxisCommandKind kind = AxisCommandKind::indp_syn;
  core::SourceLoc loc;           ///< the axis name
  std::string_view axis;         ///< "X", "S1"
  std::uint32_t first_item = 0;  ///< range in Block::items
  std::uint32_t item_count = 0;
};

enum class CallKind : std::uint8_t { local, global, cycle };
enum class CallTarget : std::uint8_t { name, macro, variable };

struct Call {
  CallKind kind = CallKind::local;
  CallTarget target = CallTarget::name;
  core::SourceLoc loc;           ///< the L / LL
  std::string_view name;         ///< subroutine / file name, macro name
  NodeIndex variable = kNoNode;  ///< CallTarget::variable
  std::uint32_t first_item = 0;  ///< L CYCLE [...] items in Block::items
  std::uint32_t item_count = 0;
};

// Block bodies

struct Empty {};

struct ProgramHeader {
  bool local = false;     ///< %L name
  std::string_view name;  ///< may be empty (bare %)
};

enum class ControlKind : std::uint8_t {
  if_,
  elseif,
  else_,
  endif,
  switch_,
  case_,
  default_,
  endswitch,
  for_,
  endfor,
  while_,
  endwhile,
  do_,
  enddo,
  repeat,
  until,
  break_,
  continue_,
  goto_,
};

enum class GotoKind : std::uint8_t { none, block_number, name, variable };

struct GotoTarget {
  GotoKind kind = GotoKind::none;
  core::SourceLoc loc;       ///< first character of the target
  std::string_view name;     ///< N10 -> "10" (digits), [name] -> name
  std::uint32_t number = 0;  ///< block number for GotoKind::block_number
  NodeIndex variable = kNoNode;
};

struct Control {
  ControlKind kind = ControlKind::if_;
  core::SourceLoc loc;          ///< the `$`
  NodeIndex expr = kNoNode;     ///< condition / switch value / case value / enddo/until cond
  NodeIndex counter = kNoNode;  ///< $FOR counter variable
  NodeIndex start = kNoNode, end = kNoNode, step = kNoNode;  ///< $FOR a, b, c
  GotoTarget target;                                         ///< $GOTO, and `$IF cond $GOTO label`
};

enum class HashKind : std::uint8_t {
  sync_in,
  sync_out,
  sync_off,
  cs_def,
  cs_on,
  cs_off,
  cs_off_all,
  bcs_def,
  bcs_on,
  bcs_off,
  bcs_off_all,
  caxtrack_on,
  caxtrack_off,
  spline_type_akima,
  spline_type_bspline,
  spline_on,
  spline_off,
  contour_mode,
  contour_mode_on,
  contour_mode_off,
  slope,
  slope_default,
  kin_id,
  trafo_on,
  trafo_off,
  trafo_steps,
  machine_data,
  msg,
  flush,
  flush_continue,
  flush_wait,
  time,
  transvelmin_on,
  transvelmin_off,
  wait_indp,
  wait_indp_all,
  delete_,
  init,
  var,
  endvar,
  comment_begin,
  comment_end,
  pre_if,
  pre_else,
  pre_endif,          ///< #IF / #ELSE / #ENDIF
  file_name,          ///< #FILE NAME / #FILENAME [G8x="..."]
  hsc_on,             ///< #HSC ON [...] / #HSC [...]
  hsc_off,            ///< #HSC OFF
  vector_limit_on,    ///< #VECTOR LIMIT ON [...] / ON ALL
  vector_limit_off,   ///< #VECTOR LIMIT OFF [...] / OFF ALL
  tangfeed,           ///< #TANGFEED [RMIN=..] / #SET TANGFEED RMIN [..] (G11's minimum radius)
  scale_on,           ///< #SCALE [ON] X.. Y..
  scale_off,          ///< #SCALE OFF
  mcs_on,             ///< #MCS ON [EX TOOL]
  mcs_off,            ///< #MCS OFF
  pset,               ///< #PSET X.. Y.. (position preset)
  accepted,           ///< read and shown in trace, no effect on motion or time (docs/language.md)
  signal,             ///< #SIGNAL [...] (decoder level, PROG-207409035)
  signal_syn,         ///< #SIGNAL SYN [...] (interpolator level)
  wait_signal,        ///< #WAIT [...] (decoder level, PROG-207421579)
  wait_signal_syn,    ///< #WAIT SYN [...] (interpolator level)
  signal_read,        ///< #SIGNAL READ [...] (PROG-913718283)
  signal_remove,      ///< #SIGNAL REMOVE [...] (decoder level, PROG-207414923)
  signal_remove_syn,  ///< #SIGNAL REMOVE SYN [...] (interpolator level)
};

struct HashCommand {
  HashKind kind = HashKind::flush;
  TableId table = TableId::none;
  core::SourceLoc loc;           ///< the `#`
  std::uint32_t item_count = 0;  ///< items are Block::items[0 .. item_count)
  NodeIndex expr = kNoNode;      ///< #IF condition
};

enum class VarType : std::uint8_t {
  boolean,
  sgn08,
  uns08,
  sgn16,
  uns16,
  sgn32,
  uns32,
  real64,
  string,
};

/// One line between #VAR and #ENDVAR: `V.P.NAME[dims] : TYPE = init`.
struct Declaration {
  core::SourceLoc loc;
  NodeIndex variable = kNoNode;  ///< the declared variable (subscripts = dimensions)
  VarType type = VarType::real64;
  bool type_given = false;
  NodeIndex string_length = kNoNode;  ///< STRING[n]
  NodeIndex init = kNoNode;           ///< scalar initialiser
  std::uint32_t init_count = 0;       ///< array initialiser: nodes chained from `init` by next
  bool array_init = false;
};

struct Words {};  ///< the body is the word list in Block::words (plus calls/axis commands)

using Body = std::variant<Empty, ProgramHeader, Control, HashCommand, Declaration, Words>;

struct BlockNumber {
  core::SourceLoc loc;
  bool is_label = false;     ///< `N10:`
  std::uint32_t number = 0;  ///< literal number
  NodeIndex expr = kNoNode;  ///< N[expr]
  std::string_view digits;   ///< spelling of the number
};

struct Label {
  core::SourceLoc loc;
  std::string_view name;  ///< `[name]`
};

struct Block {
  core::SourceLoc loc;               ///< first character of the block
  std::size_t offset = 0;            ///< byte offset of the block in the file
  std::string_view text;             ///< the block's source (continuation lines included)
  std::optional<std::uint8_t> skip;  ///< skip level: `/` = 1, `/n` = n
  std::optional<BlockNumber> number;
  std::optional<Label> label;
  Body body;
  std::vector<Word> words;
  std::vector<AxisCommand> axis_commands;
  std::optional<Call> call;
  std::optional<Control> trailing_goto;  ///< `... $GOTO label` after words
  std::vector<Item> items;
  std::vector<ExprNode> exprs;
  bool has_error = false;  ///< a syntax error was reported; the body may be partial

  /// Empties the block but keeps the vectors' capacity.
  void clear() {
    loc = {};
    offset = 0;
    text = {};
    skip.reset();
    number.reset();
    label.reset();
    body = Empty{};
    words.clear();
    axis_commands.clear();
    call.reset();
    trailing_goto.reset();
    items.clear();
    exprs.clear();
    has_error = false;
  }
};

}  // namespace ncsim::grammar::ast
