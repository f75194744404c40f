#pragma once
// grammar/word_actions: PEGTL actions for words, block prefixes, statements and declarations
// (internal; included by actions.hpp).

#include "grammar/parser_state.hpp"

namespace ncsim::grammar {

template <>
struct Action<rules::sign> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.sign = in.peek_char(0);
  }
};

template <>
struct Action<rules::address_value> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.end_address_value(st.loc(in.begin()));
  }
};

template <>
struct Action<rules::g_code> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.g_code = detail::parse_uint(in.string_view());
  }
};

namespace detail {
/// Action<rules::g_word> on the word's text `t` starting at `begin` (also the block shortcut's).
inline void add_g_word(State& st, const char* begin, std::string_view t) {
  ast::Word& w = st.block->words.emplace_back();
  w.kind = ast::WordKind::g;
  w.loc = st.loc(begin);
  w.code = st.g_code;
  std::size_t n = 1;
  while (n < t.size() && t[n] >= '0' && t[n] <= '9')
    ++n;
  w.name = t.substr(0, n);
  w.value = st.word_value;
  w.has_params = st.g_has_params;
  w.first_item = st.g_first_item;
  w.item_count = st.g_item_count;
  st.word_value = ast::kNoNode;
  st.g_has_params = false;
}
}  // namespace detail

template <>
struct Action<rules::g_arg> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.word_value = st.pop();
  }
};

template <>
struct Action<rules::g_word> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    detail::add_g_word(st, in.begin(), in.string_view());
  }
};

template <>
struct Action<rules::extra_value> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    if (st.sign == '-') st.negate_top(st.loc(in.begin()));
    st.sign = 0;
    st.word_extra = st.pop();
  }
};

struct AddAddressWord {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.add_address_word();
  }
};
template <>
struct Action<rules::address_word> : AddAddressWord {};
template <>
struct Action<rules::named_axis> : AddAddressWord {};
template <>
struct Action<rules::mh_word> : AddAddressWord {};

template <>
struct Action<rules::assign_target> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.assign_target = st.pop();
    st.word_loc = st.loc(in.begin());
  }
};

template <>
struct Action<rules::assign_op> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    using A = ast::AssignOp;
    const char c = in.peek_char(0);
    st.assign_op = c == '='   ? A::set
                   : c == '+' ? A::add
                   : c == '-' ? A::subtract
                   : c == '*' ? A::multiply
                              : A::divide;
  }
};

template <>
struct Action<rules::assign_value> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    ast::Word w;
    w.kind = ast::WordKind::assignment;
    w.loc = st.word_loc;
    w.target = st.assign_target;
    w.assign = st.assign_op;
    w.value = st.pop();
    st.add_word(w);
  }
};

template <>
struct Action<rules::macro_name> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.macro_name = st.last_string;
    st.macro_loc = st.loc(in.begin());
  }
};

template <>
struct Action<rules::macro_text> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    ast::Word w;
    w.kind = ast::WordKind::macro_def;
    w.loc = st.macro_loc;
    w.name = st.macro_name;
    w.text = st.last_string;
    st.add_word(w);
  }
};

template <>
struct Action<rules::bare_value> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    ast::Word w;
    w.kind = ast::WordKind::bare_value;
    w.loc = st.loc(in.begin());
    w.value = st.pop();
    st.add_word(w);
  }
};

// A call must be the last thing in its block (DIAG-21542, isg-language.md §4.9).
template <>
struct Action<rules::word> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    if (st.call_done) {
      st.fail_message(in.begin(), "21542",
                      "a subroutine call must be the last command in its block");
    }
    if (st.call_pending) {
      st.call_done = true;
      st.call_pending = false;
    }
  }
};

template <>
struct Action<rules::call_variable> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.call.target = ast::CallTarget::variable;
    st.call.variable = st.pop();
  }
};

template <>
struct Action<rules::call_macro> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.call.target = ast::CallTarget::macro;
    st.call.name = st.last_string;
  }
};

template <>
struct Action<rules::cycle_kw> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.call.kind = ast::CallKind::cycle;
    st.call.first_item = static_cast<std::uint32_t>(st.block->items.size());
    st.table = ast::TableId::cycle;
    st.group = 0;
  }
};

template <>
struct Action<rules::subroutine_call> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    if (st.call.kind == ast::CallKind::cycle) {
      st.call.item_count = static_cast<std::uint32_t>(st.block->items.size()) - st.call.first_item;
    }
    st.block->call = st.call;
    st.call_pending = true;
  }
};

template <>
struct Action<rules::axis_command> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.axis_command.item_count =
        static_cast<std::uint32_t>(st.block->items.size()) - st.axis_command.first_item;
    st.block->axis_commands.push_back(st.axis_command);
  }
};

template <>
struct Action<rules::trailing_goto> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    if (st.call_done || st.call_pending) {
      st.fail_message(in.begin(), "21542",
                      "a subroutine call must be the last command in its block");
    }
    ast::Control c;
    c.kind = ast::ControlKind::goto_;
    c.loc = st.loc(in.begin());
    c.target = st.goto_target;
    st.block->trailing_goto = c;
  }
};

template <>
struct Action<rules::word_list> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    ast::Block& b = *st.block;
    if (!b.words.empty() || b.call || !b.axis_commands.empty() || b.trailing_goto) {
      b.body = ast::Words{};
    }
  }
};

// Block prefixes

template <>
struct Action<rules::skip_level> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    const std::string_view t = in.string_view();
    const std::uint32_t level = t.size() > 1 ? detail::parse_uint(t.substr(1)) : 1;
    if (level < 1 || level > 10) st.fail(in.begin() + 1, "a skip level /1 ... /10");
    st.block->skip = static_cast<std::uint8_t>(level);
  }
};

template <>
struct Action<rules::block_number_expr> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.word_value = st.pop();
  }
};

namespace detail {
/// Action<rules::block_number> on the number's text `t` starting at `begin` (also the block
/// shortcut's).
inline void add_block_number(State& st, const char* begin, std::string_view t) {
  if (t.size() > 1 && t[1] == '[') {
    ast::BlockNumber& n = st.block->number.emplace();
    n.loc = st.loc(begin);
    n.expr = st.word_value;
    st.word_value = ast::kNoNode;
    return;
  }
  const bool is_label = t.back() == ':';
  const std::string_view digits = t.substr(1, t.size() - 1 - (is_label ? 1 : 0));
  const std::optional<std::uint32_t> number = parse_block_number(digits);
  if (!number) st.fail_message(begin, "NC1005", "block number out of range: at most 4294967295");
  ast::BlockNumber& n = st.block->number.emplace();
  n.loc = st.loc(begin);
  n.is_label = is_label;
  n.digits = digits;
  n.number = *number;
}
}  // namespace detail

template <>
struct Action<rules::block_number> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    detail::add_block_number(st, in.begin(), in.string_view());
  }
};

template <>
struct Action<rules::label_name> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.block->label = ast::Label{st.loc(in.begin() - 1), in.string_view()};
  }
};

template <>
struct Action<rules::program_name> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.word_name = in.string_view();
  }
};

template <>
struct Action<rules::main_program_name> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.word_name = in.string_view();  // blanks inside the name kept
  }
};

template <>
struct Action<rules::local_header> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.local_header = true;  // for the header action
  }
};

template <>
struct Action<rules::header> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    ast::ProgramHeader h;
    h.local = st.local_header;
    h.name = st.word_name;
    st.block->body = h;
  }
};

// $FOR operands

template <>
struct Action<rules::for_counter> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.control.counter = st.pop();
  }
};

template <>
struct Action<rules::for_value> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    const ast::NodeIndex v = st.pop();
    (st.for_slot == 0 ? st.control.start : st.for_slot == 1 ? st.control.end : st.control.step) = v;
    ++st.for_slot;
  }
};

// Declarations

template <>
struct Action<rules::decl_variable> {
  template <typename Input>
  static void apply(const Input& in, State& st) {
    st.decl.loc = st.loc(in.begin());
    st.decl.variable = st.pop();
  }
};

template <>
struct Action<rules::init_value> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    const ast::NodeIndex v = st.pop();
    if (st.init_last == ast::kNoNode) {
      st.decl.init = v;
    } else {
      st.block->exprs[st.init_last].next = v;
    }
    st.init_last = v;
    ++st.decl.init_count;
  }
};

template <>
struct Action<rules::init_list> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.decl.array_init = true;
  }
};

template <>
struct Action<rules::declaration> {
  template <typename Input>
  static void apply(const Input&, State& st) {
    st.block->body = st.decl;
  }
};

}  // namespace ncsim::grammar
