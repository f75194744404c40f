#pragma once
// grammar/parser_state: the state the PEGTL actions of one block share (internal).
//
// One State lives in the BlockParser and is reset per block, so its vectors keep their
// capacity: no allocation per word on the normal path. Positions are computed from pointers
// into the block text: single-line blocks by subtraction, continued blocks by a short scan.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/ast.hpp"
#include "grammar/errors.hpp"
#include "grammar/keywords.hpp"

namespace ncsim::grammar {

struct PendingOp {
  ast::Op op;
  core::SourceLoc loc;
};

struct VarFrame {
  std::size_t stack_size;
  const char* begin;
  ast::VarClass var_class;
  double number;
  std::string_view segment;  // name the next [index] belongs to
  ast::NodeIndex first = ast::kNoNode;
  ast::NodeIndex last = ast::kNoNode;
};

struct CallFrame {
  std::size_t stack_size;
  ast::Function function;
  core::SourceLoc loc;
  std::string_view text;
};

struct State {
  ast::Block* block = nullptr;
  const char* begin = nullptr;  // block text
  const char* end = nullptr;
  core::SourceLoc base;  // position of `begin`
  bool multiline = false;
  int depth = 0;

  std::vector<ast::NodeIndex> stack;
  std::vector<PendingOp> ops;
  std::vector<VarFrame> vars;
  std::vector<CallFrame> calls;

  // the word being parsed
  char sign = 0;
  ast::WordKind word_kind = ast::WordKind::axis;
  bool local_header = false;  // this block's header is `%L name`
  core::SourceLoc word_loc;
  std::string_view word_name;
  ast::NodeIndex word_value = ast::kNoNode;
  std::uint32_t g_code = 0;
  ast::NodeIndex word_extra = ast::kNoNode;  // M/H additional value
  bool g_has_params = false;                 // G80-G839 [..] read (g_params)
  std::uint32_t g_first_item = 0;
  std::uint32_t g_item_count = 0;
  ast::NodeIndex assign_target = ast::kNoNode;
  ast::AssignOp assign_op = ast::AssignOp::set;
  std::string_view last_string;
  core::SourceLoc last_string_loc;
  std::string_view macro_name;
  core::SourceLoc macro_loc;
  bool call_pending = false;  // a call was the last word
  bool call_done = false;     // a call has been parsed in this block
  ast::Call call;
  ast::AxisCommand axis_command;

  // bracket lists
  ast::TableId table = ast::TableId::none;
  std::uint8_t group = 0;

  // statements
  ast::Control control;
  ast::GotoTarget goto_target;
  int for_slot = 0;
  ast::Declaration decl;
  ast::NodeIndex init_last = ast::kNoNode;

  /// Starts a block; `has_line_end` tells whether [text_begin, text_end) holds a '\n'.
  void reset(ast::Block& b, const char* text_begin, const char* text_end, core::SourceLoc at,
             bool has_line_end) {
    block = &b;
    begin = text_begin;
    end = text_end;
    base = at;
    multiline = has_line_end;
    depth = 0;
    stack.clear();
    ops.clear();
    vars.clear();
    calls.clear();
    sign = 0;
    local_header = false;
    word_name = {};  // a header without a name reads it
    word_value = ast::kNoNode;
    word_extra = ast::kNoNode;
    g_has_params = false;
    call_pending = false;
    call_done = false;
    table = ast::TableId::none;
    group = 0;
    for_slot = 0;
    decl = {};
    init_last = ast::kNoNode;
  }

  core::SourceLoc loc(const char* p) const {
    if (!multiline) {
      return {base.line, base.column + static_cast<std::uint32_t>(p - begin)};
    }
    return loc_across_lines(p);
  }
  /// loc() in a block that holds line ends (continuation lines): counts them up to `p`.
  core::SourceLoc loc_across_lines(const char* p) const {
    core::SourceLoc at = base;
    for (const char* q = begin; q < p; ++q) {
      if (*q == '\n') {
        ++at.line;
        at.column = 1;
      } else {
        ++at.column;
      }
    }
    return at;
  }

  ast::NodeIndex add(const ast::ExprNode& node) {
    block->exprs.push_back(node);
    return static_cast<ast::NodeIndex>(block->exprs.size() - 1);
  }
  void push(const ast::ExprNode& node) { stack.push_back(add(node)); }
  ast::NodeIndex pop() {
    const ast::NodeIndex top = stack.back();
    stack.pop_back();
    return top;
  }
  PendingOp pop_op() {
    const PendingOp top = ops.back();
    ops.pop_back();
    return top;
  }
  void binary() {
    const PendingOp op = pop_op();
    const ast::NodeIndex rhs = pop();
    const ast::NodeIndex lhs = pop();
    ast::ExprNode node;
    node.op = op.op;
    node.loc = op.loc;
    node.a = lhs;
    node.b = rhs;
    push(node);
  }
  void negate_top(core::SourceLoc at) {
    ast::ExprNode& top = block->exprs[stack.back()];
    if (top.op == ast::Op::number && stack.back() + 1 == block->exprs.size()) {
      top.value = -top.value;  // fold the sign into the literal (X-0 stays -0.0)
      top.loc = at;
      return;
    }
    ast::ExprNode node;
    node.op = ast::Op::negate;
    node.loc = at;
    node.a = pop();
    push(node);
  }
  void add_word(const ast::Word& word) { block->words.push_back(word); }
  /// An address value is complete (its sign, read at `at`, is applied to the operand on top).
  void end_address_value(core::SourceLoc at) {
    if (sign == '-') negate_top(at);
    sign = 0;
    word_value = pop();
  }
  /// An address word (head and value read) is complete: it joins the block's words.
  void add_address_word() {
    ast::Word w;
    w.kind = word_kind;
    w.loc = word_loc;
    w.name = word_name;
    w.value = word_value;
    w.extra = word_extra;
    word_value = ast::kNoNode;
    word_extra = ast::kNoNode;
    add_word(w);
  }

  [[noreturn]] void fail(const char* at, const char* expected) const {
    throw ParseFailure{at, "NC1001", expected, {}};
  }
  [[noreturn]] void fail_message(const char* at, const char* id, std::string message) const {
    throw ParseFailure{at, id, nullptr, std::move(message)};
  }
  [[noreturn]] void not_supported(const char* at, std::string_view construct) const {
    fail_message(at, "NC1002", "not supported: " + std::string(construct));
  }
};

}  // namespace ncsim::grammar
