#pragma once
// grammar/actions: the PEGTL actions that build the AST (internal). Actions sit only on rules
// that cannot be backtracked once they succeed (a must<> follows their commit point, or they
// are reached only after an at<> lookahead decided), so no action ever has to be undone.

#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>

#include "grammar/parser_state.hpp"

namespace ncsim::grammar {

template <typename Rule>
struct Action : tao::pegtl::nothing<Rule> {};

namespace detail {
inline std::uint32_t parse_uint(std::string_view text) {
  std::uint32_t v = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') break;
    const std::uint64_t next = std::uint64_t{v} * 10 + static_cast<std::uint32_t>(c - '0');
    v = next > 0xFFFFFFFFu ? 0xFFFFFFFFu : static_cast<std::uint32_t>(next);
  }
  return v;
}
/// A block number's digits as a number; nothing beyond 4294967295.
inline std::optional<std::uint32_t> parse_block_number(std::string_view digits) {
  std::uint64_t v = 0;
  for (const char c : digits) {
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
    if (v > 0xFFFFFFFFu) return std::nullopt;
  }
  return static_cast<std::uint32_t>(v);
}
inline ast::ExprNode leaf(ast::Op op, core::SourceLoc loc, std::string_view text) {
  ast::ExprNode n;
  n.op = op;
  n.loc = loc;
  n.text = text;
  return n;
}
}  // namespace detail

// rules::number builds its node itself (custom_rules_hot.hpp).

template <>
struct Action<rules::hex_number> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    std::string_view body = in.string_view();
    body = body.substr(1, body.size() - 2);
    int base = 16;
    if (body.starts_with("16#")) {
      body.remove_prefix(3);
    } else if (body.starts_with("2#")) {
      body.remove_prefix(2);
      base = 2;
    } else if (body.starts_with("0x") || body.starts_with("0X")) {
      body.remove_prefix(2);
    } else if (body.starts_with("H") || body.starts_with("h")) {
      body.remove_prefix(1);
    } else {
      base = 0;
    }
    std::uint64_t v = 0;
    const auto [ptr, ec] =
        std::from_chars(body.data(), body.data() + body.size(), v, base ? base : 16);
    if (base == 0 || body.empty() || ec != std::errc() || ptr != body.data() + body.size()) {
      st.fail(in.begin(),
              "a hexadecimal ('16#FA1B', '0x0ED2', 'H1869f') or binary ('2#1010') literal");
    }
    ast::ExprNode n = detail::leaf(ast::Op::number, st.loc(in.begin()), in.string_view());
    n.value = static_cast<double>(v);
    st.push(n);
  }
};

template <>
struct Action<rules::string_body> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.last_string = in.string_view();
    st.last_string_loc = st.loc(in.begin() - 1);
  }
};

template <>
struct Action<rules::string_operand> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.push(detail::leaf(ast::Op::string, st.last_string_loc, st.last_string));
  }
};

template <>
struct Action<rules::call> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    const CallFrame frame = st.calls.back();
    st.calls.pop_back();
    ast::ExprNode n = detail::leaf(ast::Op::call, frame.loc, frame.text);
    n.function = frame.function;
    for (std::size_t i = frame.stack_size; i < st.stack.size(); ++i) {
      if (i + 1 < st.stack.size()) st.block->exprs[st.stack[i]].next = st.stack[i + 1];
    }
    if (st.stack.size() > frame.stack_size) n.a = st.stack[frame.stack_size];
    st.stack.resize(frame.stack_size);
    st.push(n);
  }
};

template <>
struct Action<rules::constant> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    ast::ExprNode n = detail::leaf(ast::Op::constant, st.loc(in.begin()), in.string_view());
    const char c = in.peek_char(0);
    n.value = (c == 'T' || c == 't') ? 1.0 : (c == 'F' || c == 'f') ? 0.0 : std::numbers::pi;
    st.push(n);
  }
};

template <>
struct Action<rules::var_head> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const std::string_view t = in.string_view();
    VarFrame f{st.stack.size(), in.begin(), ast::VarClass::none, 0.0, t};
    if (t[0] == 'V' || t[0] == 'v') {
      const std::string_view cls = t.substr(2);
      using C = ast::VarClass;
      f.var_class = iequals(cls, "P")     ? C::v_p
                    : iequals(cls, "L")   ? C::v_l
                    : iequals(cls, "S")   ? C::v_s
                    : iequals(cls, "E")   ? C::v_e
                    : iequals(cls, "G")   ? C::v_g
                    : iequals(cls, "CYC") ? C::v_cyc
                                          : C::v_other;
    } else {
      std::size_t k = 0;
      const bool at = t[0] == '@';
      if (at) ++k;
      ++k;  // P
      const bool pp = t[k] == 'P' || t[k] == 'p';
      if (pp) ++k;
      f.var_class = at ? ast::VarClass::at_p : pp ? ast::VarClass::pp : ast::VarClass::p;
      f.number = detail::parse_uint(t.substr(k));
    }
    st.vars.push_back(f);
  }
};

template <>
struct Action<rules::member_name> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.vars.back().segment = in.string_view();
  }
};

template <>
struct Action<rules::var_subscript> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    VarFrame& f = st.vars.back();
    ast::ExprNode n = detail::leaf(ast::Op::subscript, st.loc(in.begin()), f.segment);
    n.a = st.pop();
    const ast::NodeIndex idx = st.add(n);
    if (f.last != ast::kNoNode) {
      st.block->exprs[f.last].next = idx;
    } else {
      f.first = idx;
    }
    f.last = idx;
  }
};

template <>
struct Action<rules::variable> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const VarFrame f = st.vars.back();
    st.vars.pop_back();
    ast::ExprNode n = detail::leaf(ast::Op::variable, st.loc(in.begin()), in.string_view());
    n.var_class = f.var_class;
    n.value = f.number;
    n.a = f.first;
    st.push(n);
  }
};

template <>
struct Action<rules::unary_op> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const char c = in.peek_char(0);
    const ast::Op op = c == '-'                 ? ast::Op::negate
                       : c == '+'               ? ast::Op::plus
                       : (c == 'N' || c == 'n') ? ast::Op::logical_not
                                                : ast::Op::bit_inv;
    st.ops.push_back({op, st.loc(in.begin())});
  }
};

template <>
struct Action<rules::unary> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    const PendingOp op = st.pop_op();
    if (op.op == ast::Op::negate) {
      st.negate_top(op.loc);
      return;
    }
    ast::ExprNode n;
    n.op = op.op;
    n.loc = op.loc;
    n.a = st.pop();
    st.push(n);
  }
};

// Binary operators: the operator rule records the op, its tail rule builds the node.
template <ast::Op Op>
struct PushOp {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.ops.push_back({Op, st.loc(in.begin())});
  }
};
struct BuildBinary {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.binary();
  }
};

template <>
struct Action<rules::op_power> : PushOp<ast::Op::power> {};
template <>
struct Action<rules::op_band> : PushOp<ast::Op::bit_and> {};
template <>
struct Action<rules::op_bxor> : PushOp<ast::Op::bit_xor> {};
template <>
struct Action<rules::op_bor> : PushOp<ast::Op::bit_or> {};
template <>
struct Action<rules::op_land> : PushOp<ast::Op::logical_and> {};
template <>
struct Action<rules::op_lxor> : PushOp<ast::Op::logical_xor> {};
template <>
struct Action<rules::op_lor> : PushOp<ast::Op::logical_or> {};
template <>
struct Action<rules::power_tail> : BuildBinary {};
template <>
struct Action<rules::mul_tail> : BuildBinary {};
template <>
struct Action<rules::add_tail> : BuildBinary {};
template <>
struct Action<rules::cmp_tail> : BuildBinary {};
template <>
struct Action<rules::band_tail> : BuildBinary {};
template <>
struct Action<rules::bxor_tail> : BuildBinary {};
template <>
struct Action<rules::bor_tail> : BuildBinary {};
template <>
struct Action<rules::land_tail> : BuildBinary {};
template <>
struct Action<rules::lxor_tail> : BuildBinary {};
template <>
struct Action<rules::lor_tail> : BuildBinary {};

template <>
struct Action<rules::op_mul> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const char c = in.peek_char(0);
    const ast::Op op = c == '*' ? ast::Op::multiply : c == '/' ? ast::Op::divide : ast::Op::modulo;
    st.ops.push_back({op, st.loc(in.begin())});
  }
};
template <>
struct Action<rules::op_add> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.ops.push_back(
        {in.peek_char(0) == '+' ? ast::Op::add : ast::Op::subtract, st.loc(in.begin())});
  }
};
template <>
struct Action<rules::op_cmp> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const std::string_view t = in.string_view();
    using O = ast::Op;
    const O op = t == "=="   ? O::equal
                 : t == "!=" ? O::not_equal
                 : t == "<=" ? O::less_equal
                 : t == ">=" ? O::greater_equal
                 : t == "<"  ? O::less
                             : O::greater;
    st.ops.push_back({op, st.loc(in.begin())});
  }
};

}  // namespace ncsim::grammar

#include "grammar/word_actions.hpp"
