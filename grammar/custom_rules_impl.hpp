#pragma once
// grammar/custom_rules_impl: match() of the custom rules declared in rules.hpp (internal).

#include "grammar/custom_rules_hot.hpp"
#include "grammar/hash_commands.hpp"

namespace ncsim::grammar {

#define NCSIM_CUSTOM_MATCH(rule)                                                         \
  template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Act, \
            template <typename...> class Ctl, typename Input, typename St>               \
  bool rules::rule::match(Input& in, [[maybe_unused]] St& st)

// `( ... )` comments nest; an unclosed one runs to the end of the block (§1.5).
NCSIM_CUSTOM_MATCH(paren_comment) {
  if (in.empty() || in.peek_char() != '(') return false;
  const char* const end = lex::paren_comment_end(in.current(), in.end());
  in.bump(static_cast<std::size_t>(end - in.current()));
  return true;
}

NCSIM_CUSTOM_MATCH(function_name) {
  const std::string_view name = lex::ident(lex::rest(in));
  if (name.empty() || !lex::is_alpha(name[0])) return false;
  const ast::Function f = function_by_name(name);
  if (f == ast::Function::none) return false;
  if constexpr (A == pegtl::apply_mode::action) {
    st.calls.push_back({st.stack.size(), f, st.loc(in.current()), name});
  }
  in.bump(name.size());
  return true;
}

/// The single-letter axis addresses X Y Z A B C U V W (isg-language.md §2.1).
inline bool is_axis_letter(char c) {
  switch (ascii_upper(c)) {
    case 'X':
    case 'Y':
    case 'Z':
    case 'A':
    case 'B':
    case 'C':
    case 'U':
    case 'V':
    case 'W':
      return true;
    default:
      return false;
  }
}

// One-letter addresses (§2.1). `V.` followed by a letter starts a variable, not an axis word.
NCSIM_CUSTOM_MATCH(address_head) {
  if (in.empty()) return false;
  const std::optional<ast::WordKind> kind = address_kind(in.peek_char());
  if (!kind) return false;
  // `V.` followed by a letter starts a variable (V.P.X), not a V axis word
  if (ascii_upper(in.peek_char()) == 'V' && in.size() > 2 && in.peek_char(1) == '.' &&
      lex::is_alpha(in.peek_char(2))) {
    return false;
  }
  if constexpr (A == pegtl::apply_mode::action) {
    st.word_kind = *kind;
    st.word_loc = st.loc(in.current());
    st.word_name = std::string_view(in.current(), 1);
  }
  in.bump(1);
  return true;
}

// The parameter list of an implicit subroutine call, `G805 [-27.1, 28.9,, 2.8]`
// (PROG-206278923): up to 50 expressions, gaps marked by consecutive commas, blanks anywhere.
// It belongs to the G word only for G80-G89 / G800-G839 written without `=`; after any other
// G code a `[` starts the next word (`G04 [2*P1]`), so the rule then matches empty. A bad
// character inside the list is the manual's error 22151.
NCSIM_CUSTOM_MATCH(g_params) {
  const char* const code_end = in.current();
  const char* code_begin = code_end;
  while (code_begin > in.begin() && lex::is_digit(code_begin[-1]))
    --code_begin;
  if (code_begin == code_end || code_begin == in.begin() || ascii_upper(code_begin[-1]) != 'G' ||
      code_end - code_begin > 4) {
    return true;
  }
  std::uint32_t code = 0;
  for (const char* p = code_begin; p < code_end; ++p)
    code = code * 10 + static_cast<std::uint32_t>(*p - '0');
  if (!is_implicit_call_g(code)) return true;
  const std::string_view r = lex::rest(in);
  const std::size_t k = lex::blanks(r);
  if (k >= r.size() || r[k] != '[') return true;
  in.bump(k);
  const std::size_t first = st.block->items.size();
  const ast::TableId outer = st.table;
  st.table = ast::TableId::g_params;
  try {
    (void)parse_list(in, st, 0);
  } catch (ParseFailure& f) {
    if (std::string_view(f.id) == "NC1001") {
      f.id = "22151";
      if (f.message.empty() && f.expected != nullptr) {
        f.message = std::string("invalid character in the parameter list of G") +
                    std::to_string(code) + ": expected " + f.expected;
      }
    }
    throw;
  }
  st.table = outer;
  const std::size_t count = st.block->items.size() - first;
  if (count > kMaxImplicitCallParams) {
    st.fail_message(in.current() - 1, "22151",
                    "G" + std::to_string(code) + " has " + std::to_string(count) +
                        " parameters; at most " + std::to_string(kMaxImplicitCallParams) +
                        " may be passed");
  }
  if constexpr (A == pegtl::apply_mode::action) {
    st.g_has_params = true;
    st.g_first_item = static_cast<std::uint32_t>(first);
    st.g_item_count = static_cast<std::uint32_t>(count);
  }
  return true;
}

// Multi-letter axis names are written with '=' (§1.9): AB=90.
NCSIM_CUSTOM_MATCH(axis_name_eq) {
  const std::string_view r = lex::rest(in);
  const std::string_view name = lex::ident(r);
  if (name.empty() || !lex::is_alpha(name[0])) return false;
  if (name.size() == 1 && !is_axis_letter(name[0])) return false;
  std::size_t k = name.size() + lex::blanks(r.substr(name.size()));
  if (k >= r.size() || r[k] != '=' || (k + 1 < r.size() && r[k + 1] == '=')) return false;
  if constexpr (A == pegtl::apply_mode::action) {
    st.word_kind = ast::WordKind::axis;
    st.word_loc = st.loc(in.current());
    st.word_name = name;
  }
  in.bump(name.size());
  return true;
}

// L / LL followed by a blank or '"' (§4.9: the blank after LL is mandatory).
NCSIM_CUSTOM_MATCH(call_head) {
  const std::string_view r = lex::rest(in);
  if (r.empty() || ascii_upper(r[0]) != 'L') return false;
  const std::size_t n = (r.size() > 1 && ascii_upper(r[1]) == 'L') ? 2 : 1;
  if (n >= r.size() || !(r[n] == ' ' || r[n] == '\t' || r[n] == '"')) return false;
  if constexpr (A == pegtl::apply_mode::action) {
    st.call = {};
    st.call.kind = n == 2 ? ast::CallKind::local : ast::CallKind::global;
    st.call.loc = st.loc(in.current());
  }
  in.bump(n);
  return true;
}

// File names exclude the characters of §1.1 ( ( " ] # $ ; , ) and blanks.
NCSIM_CUSTOM_MATCH(file_name) {
  const std::string_view r = lex::rest(in);
  std::size_t n = 0;
  while (n < r.size()) {
    const char c = r[n];
    if (c == ' ' || c == '\t' || c == '(' || c == '"' || c == ']' || c == '[' || c == '#' ||
        c == '$' || c == ';' || c == ',' || c == '\r' || c == '\n')
      break;
    ++n;
  }
  if (n == 0) return false;
  if constexpr (A == pegtl::apply_mode::action) {
    st.call.target = ast::CallTarget::name;
    st.call.name = r.substr(0, n);
  }
  in.bump(n);
  return true;
}

// `<axis> [KEYWORD ...]` (§6): the first keyword inside the bracket decides.
NCSIM_CUSTOM_MATCH(bracket_axis) {
  const std::string_view r = lex::rest(in);
  const std::string_view axis = lex::ident(r);
  if (axis.empty() || !lex::is_alpha(axis[0])) return false;
  std::size_t k = axis.size() + lex::blanks(r.substr(axis.size()));
  if (k >= r.size() || r[k] != '[') return false;
  ++k;
  k += lex::blanks(r.substr(k));
  const std::string_view word = lex::ident(r.substr(k));
  if (word.empty()) return false;
  using K = ast::AxisCommandKind;
  struct Entry {
    std::string_view name;
    K kind;
    ast::TableId table;
  };
  static constexpr std::array<Entry, 13> kCommands = {{
      {"INDP_SYN", K::indp_syn, ast::TableId::indp},
      {"INDP_ASYN", K::indp_asyn, ast::TableId::indp},
      {"MC_HOME", K::mc_home, ast::TableId::mc_other},
      {"MC_MOVEABSOLUTE", K::mc_move_absolute, ast::TableId::mc_other},
      {"MC_MOVEADDITIVE", K::mc_move_additive, ast::TableId::mc_other},
      {"MC_MOVERELATIVE", K::mc_move_relative, ast::TableId::mc_other},
      {"MC_MOVESUPERIMPOSED", K::mc_move_superimposed, ast::TableId::mc_other},
      {"MC_MOVEVELOCITY", K::mc_move_velocity, ast::TableId::mc_move_velocity},
      {"MC_STOP", K::mc_stop, ast::TableId::mc_other},
      {"MC_GEARIN", K::mc_gear_in, ast::TableId::mc_other},
      {"MC_GEAROUT", K::mc_gear_out, ast::TableId::mc_other},
      {"MC_PHASING", K::mc_phasing, ast::TableId::mc_other},
      {"MC_TOUCHPROBE", K::mc_touch_probe, ast::TableId::mc_touch_probe},
  }};
  for (const Entry& e : kCommands) {
    if (!iequals(e.name, word)) continue;
    if constexpr (A == pegtl::apply_mode::action) {
      st.axis_command = {};
      st.axis_command.kind = e.kind;
      st.axis_command.loc = st.loc(in.current());
      st.axis_command.axis = axis;
      st.axis_command.first_item = static_cast<std::uint32_t>(st.block->items.size());
      st.table = e.table;
      st.group = 0;
    }
    in.bump(axis.size());
    return true;
  }
  // Other axis-specific functions of PROG-5252363631026771979 (§6) exist but are not simulated.
  static constexpr std::array<std::string_view, 12> kOther = {
      "OSC",        "COMP",     "DIST_CTRL", "OVERRIDE", "DYNAMIC", "LIFT",
      "LIFT_START", "LIFT_END", "SYNC",      "POLY",     "INDP",    "STOP"};
  const bool other = word.size() > 3 && iequals(word.substr(0, 3), "MC_");
  bool listed = false;
  for (const auto o : kOther)
    listed = listed || iequals(o, word);
  if (other || listed) {
    st.not_supported(in.current() + k,
                     std::string(axis) + "[" + std::string(word) + " ...] axis command");
  }
  return false;
}

NCSIM_CUSTOM_MATCH(bracket_items) {
  parse_items(in, st);
  return true;
}

// '#' or a '$' keyword other than $GOTO among the words of a block.
NCSIM_CUSTOM_MATCH(misplaced_statement) {
  if (in.empty()) return false;
  const char c = in.peek_char();
  if (c == '#') {
    st.fail_message(in.current(), "NC2007",
                    "a # command must stand alone in its block (only a block number may "
                    "precede it)");
  }
  if (c != '$') return false;
  const std::string_view r = lex::rest(in).substr(1);
  const std::string_view word = lex::ident(r.substr(lex::blanks(r)));
  if (iequals(word, "GOTO")) return false;
  if (iequals(word, "ENDIF")) {
    st.fail_message(in.current(), "20219", "$ENDIF must stand alone in its block");
  }
  st.fail_message(in.current(), "NC2008",
                  "$" + std::string(word) + " must stand alone in its block");
}

// $GOTO N10 | [name] | V.E.x (§4.7); anything else is error 20839.
NCSIM_CUSTOM_MATCH(goto_target) {
  const std::string_view r = lex::rest(in);
  ast::GotoTarget t;
  t.loc = st.loc(in.current());
  if (r.size() > 1 && ascii_upper(r[0]) == 'N' && lex::is_digit(r[1])) {
    std::size_t n = 1;
    while (n < r.size() && lex::is_digit(r[n]))
      ++n;
    t.kind = ast::GotoKind::block_number;
    t.name = r.substr(1, n - 1);
    t.number = detail::parse_uint(t.name);
    in.bump(n);
  } else if (!r.empty() && r[0] == '[') {
    const std::string_view name = lex::ident(r.substr(1));
    if (name.empty() || name.size() + 1 >= r.size() || r[name.size() + 1] != ']') {
      st.fail(in.current() + 1 + name.size(), "a label name and ']' after $GOTO [");
    }
    t.kind = ast::GotoKind::name;
    t.name = name;
    in.bump(name.size() + 2);
  } else if (r.size() > 4 && iequals(r.substr(0, 4), "V.E.") &&
             match_rule<rules::variable>(in, st)) {
    t.kind = ast::GotoKind::variable;
    t.variable = st.pop();
  } else {
    st.fail_message(in.current(), "20839",
                    "bad character after $GOTO: expected N<number>, [label] or a V.E. "
                    "variable, found " +
                        lex::describe(in.current(), in.end()));
  }
  st.goto_target = t;
  return true;
}

NCSIM_CUSTOM_MATCH(control_keyword) {
  if (in.empty() || in.peek_char() != '$') return false;
  const char* dollar = in.current();
  in.bump(1);
  in.bump(lex::blanks(lex::rest(in)));
  const std::string_view word = lex::ident(lex::rest(in));
  using K = ast::ControlKind;
  struct Entry {
    std::string_view name;
    K kind;
  };
  static constexpr std::array<Entry, 19> kKeywords = {{
      {"IF", K::if_},           {"ELSEIF", K::elseif},       {"ELSE", K::else_},
      {"ENDIF", K::endif},      {"SWITCH", K::switch_},      {"CASE", K::case_},
      {"DEFAULT", K::default_}, {"ENDSWITCH", K::endswitch}, {"FOR", K::for_},
      {"ENDFOR", K::endfor},    {"WHILE", K::while_},        {"ENDWHILE", K::endwhile},
      {"DO", K::do_},           {"ENDDO", K::enddo},         {"REPEAT", K::repeat},
      {"UNTIL", K::until},      {"BREAK", K::break_},        {"CONTINUE", K::continue_},
      {"GOTO", K::goto_},
  }};
  for (const Entry& e : kKeywords) {
    if (!iequals(e.name, word)) continue;
    st.control = {};
    st.control.kind = e.kind;
    st.control.loc = st.loc(dollar);
    st.block->body = st.control;
    in.bump(word.size());
    return true;
  }
  st.fail(in.current(), "a control keyword ($IF, $FOR, $WHILE, $GOTO, ...)");
}

NCSIM_CUSTOM_MATCH(control_operands) {
  using K = ast::ControlKind;
  ast::Control& c = st.control;
  skip_ws(in, st);
  switch (c.kind) {
    case K::if_:
      c.expr = parse_expression(in, st, "a condition after $IF");
      skip_ws(in, st);
      if (match_rule<rules::goto_kw>(in, st)) {
        skip_ws(in, st);
        (void)match_rule<rules::goto_target>(in, st);
        c.target = st.goto_target;
      }
      break;
    case K::elseif:
    case K::while_:
    case K::enddo:
    case K::until:
      c.expr = parse_expression(in, st, "a condition");
      break;
    case K::switch_:
    case K::case_:
      c.expr = parse_expression(in, st, "a value");
      break;
    case K::for_:
      (void)match_rule<rules::for_header>(in, st);
      break;
    case K::goto_:
      (void)match_rule<rules::goto_target>(in, st);
      c.target = st.goto_target;
      break;
    default:
      break;
  }
  st.block->body = c;
  return true;
}

NCSIM_CUSTOM_MATCH(statement_end) {
  skip_ws(in, st);
  if (in.empty() || in.peek_char() == ';') {
    in.bump(in.size());
    return true;
  }
  const std::string found = lex::describe(in.current(), in.end());
  if (const auto* c = std::get_if<ast::Control>(&st.block->body)) {
    if (c->kind == ast::ControlKind::endif) {
      st.fail_message(in.current(), "20219",
                      "$ENDIF must stand alone in its block, found " + found);
    }
    st.fail_message(in.current(), "NC2008",
                    "a $ keyword must stand alone in its block (apart from its operands), "
                    "found " +
                        found);
  }
  st.fail_message(in.current(), "NC2007",
                  "a # command must stand alone in its block, found " + found);
}

NCSIM_CUSTOM_MATCH(decl_type) {
  const std::string_view name = lex::ident(lex::rest(in));
  using T = ast::VarType;
  struct Entry {
    std::string_view name;
    T type;
  };
  static constexpr std::array<Entry, 10> kTypes = {{{"BOOLEAN", T::boolean},
                                                    {"SGN08", T::sgn08},
                                                    {"UNS08", T::uns08},
                                                    {"SGN16", T::sgn16},
                                                    {"UNS16", T::uns16},
                                                    {"SGN32", T::sgn32},
                                                    {"UNS32", T::uns32},
                                                    {"REAL64", T::real64},
                                                    {"REAL", T::real64},
                                                    {"STRING", T::string}}};
  for (const Entry& e : kTypes) {
    if (!iequals(e.name, name)) continue;
    st.decl.type = e.type;
    st.decl.type_given = true;
    in.bump(name.size());
    if (e.type == T::string && !in.empty() && in.peek_char() == '[') {
      in.bump(1);
      st.decl.string_length = parse_expression(in, st, "a string length");
      if (in.empty() || in.peek_char() != ']') st.fail(in.current(), "']'");
      in.bump(1);
    }
    return true;
  }
  return false;
}

NCSIM_CUSTOM_MATCH(hash_command) {
  return parse_hash_command(in, st);
}

#undef NCSIM_CUSTOM_MATCH

}  // namespace ncsim::grammar
