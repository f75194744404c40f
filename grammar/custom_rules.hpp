#pragma once
// grammar/custom_rules: the hand-matched rules of rules.hpp (internal). They read names and
// look them up in the keyword tables, which PEG alternatives would do slowly and with poor
// error positions. Each consumes input only when it succeeds.

#include <array>
#include <string>

#include "grammar/actions.hpp"

namespace ncsim::grammar {
namespace pegtl = tao::pegtl;

namespace lex {
inline bool is_alpha(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
inline bool is_ident(char c) {
  return is_alpha(c) || is_digit(c) || c == '_';
}

template <typename Input>
std::string_view rest(const Input& in) {
  return {in.current(), in.size()};
}
/// The name (letters, digits, '_') at the start of `s`.
inline std::string_view ident(std::string_view s) {
  std::size_t n = 0;
  while (n < s.size() && is_ident(s[n]))
    ++n;
  return s.substr(0, n);
}
inline std::size_t blanks(std::string_view s) {
  std::size_t n = 0;
  while (n < s.size() && (s[n] == ' ' || s[n] == '\t'))
    ++n;
  return n;
}
/// End of the nested `( ... )` comment that starts at `p` (§1.5): after its closing ')', or `e`
/// when it is not closed (an unclosed comment runs to the end of the block). Iterative, so
/// 10,000 nested parentheses cost no stack.
inline const char* paren_comment_end(const char* p, const char* e) {
  std::size_t depth = 0;
  for (; p < e; ++p) {
    if (*p == '(') {
      ++depth;
    } else if (*p == ')' && --depth == 0) {
      return p + 1;
    }
  }
  return e;
}
/// Length of a manual parameter id `P-<letters>-<digits>` (P-AXIS-00008, P-CHAN-00262) at the
/// start of `s`, 0 if there is none.
inline std::size_t parameter_id_length(std::string_view s) {
  if (s.size() < 5 || ascii_upper(s[0]) != 'P' || s[1] != '-') return 0;
  std::size_t n = 2;
  while (n < s.size() && is_alpha(s[n]))
    ++n;
  if (n == 2 || n >= s.size() || s[n] != '-') return 0;
  const std::size_t digits = ++n;
  while (n < s.size() && is_digit(s[n]))
    ++n;
  return n > digits ? n : 0;
}
/// Describes what stands at `p` for "found ..." texts.
inline std::string describe(const char* p, const char* end) {
  if (p >= end || *p == '\n' || *p == '\r' || *p == ';') return "end of block";
  const std::string_view name = ident(std::string_view(p, static_cast<std::size_t>(end - p)));
  if (!name.empty()) return "'" + std::string(name.substr(0, 24)) + "'";
  return std::string("'") + *p + "'";
}
}  // namespace lex

template <typename Input>
void skip_ws(Input& in, State& st) {
  (void)pegtl::match<rules::ws, pegtl::apply_mode::action, pegtl::rewind_mode::dontcare, Action,
                     Control>(in, st);
}

template <typename Rule, typename Input>
bool match_rule(Input& in, State& st) {
  return pegtl::match<Rule, pegtl::apply_mode::action, pegtl::rewind_mode::required, Action,
                      Control>(in, st);
}

template <typename Input>
ast::NodeIndex parse_expression(Input& in, State& st, const char* expected) {
  if (!match_rule<rules::expression>(in, st)) st.fail(in.current(), expected);
  return st.pop();
}

/// Accepts the keyword `word` (case-insensitive, not followed by a name character).
template <typename Input>
bool accept(Input& in, std::string_view word) {
  const std::string_view name = lex::ident(lex::rest(in));
  if (!iequals(name, word)) return false;
  in.bump(name.size());
  return true;
}

// Items of bracket lists

inline bool starts_expression(char c) {
  return lex::is_digit(c) || c == '.' || c == '+' || c == '-' || c == '[' || c == '\'';
}

template <typename Input>
void parse_value(Input& in, State& st, ast::Item& item, ValueKind kind) {
  if (kind == ValueKind::none) return;
  if (kind == ValueKind::code) {
    const std::string_view digits = [&] {
      std::string_view r = lex::rest(in);
      std::size_t n = 0;
      while (n < r.size() && lex::is_digit(r[n]))
        ++n;
      return r.substr(0, n);
    }();
    if (digits.empty()) st.fail(in.current(), "a code number");
    ast::ExprNode n = detail::leaf(ast::Op::number, st.loc(in.current()), digits);
    n.value = detail::parse_uint(digits);
    item.value = st.add(n);
    item.kind = ast::ItemKind::keyword;
    in.bump(digits.size());
    return;
  }
  in.bump(lex::blanks(lex::rest(in)));
  const bool has_equals = !in.empty() && in.peek_char() == '=';
  if (has_equals) {
    in.bump(1);
    skip_ws(in, st);
  }
  if (kind == ValueKind::opt_expr) {
    if (!has_equals && (in.empty() || !starts_expression(in.peek_char()))) return;
    kind = ValueKind::expr;
  }
  item.kind = ast::ItemKind::keyword;
  if (kind == ValueKind::expr) {
    item.value = parse_expression(in, st, "a value after the keyword");
  } else if (kind == ValueKind::string) {
    if (!match_rule<rules::quoted>(in, st)) st.fail(in.current(), "a quoted string");
    item.text = st.last_string;
  } else {  // word
    const std::string_view r = lex::rest(in);
    std::size_t n = 0;
    while (n < r.size() && (lex::is_ident(r[n]) || r[n] == '.' || r[n] == '/'))
      ++n;
    if (n == 0) st.fail(in.current(), "a name after the keyword");
    item.text = r.substr(0, n);
    in.bump(n);
  }
}

/// Items of the current table (State::table) up to, not including, ']' or the block end.
template <typename Input>
void parse_items(Input& in, State& st) {
  const KeywordTable& table = keyword_table(st.table);
  bool component_open = true;  // at the list start or after ','
  bool comma_seen = false;
  for (;;) {
    skip_ws(in, st);
    if (in.empty()) return;
    const char c = in.peek_char();
    ast::Item item;
    item.loc = st.loc(in.current());
    item.group = st.group;
    if (c == ',' || c == ']') {
      if (table.positional && component_open && (c == ',' || comma_seen)) {
        item.kind = ast::ItemKind::empty;  // `[,,5]`: empty components are 0 (§5.8)
        st.block->items.push_back(item);
      }
      if (c == ']') return;
      in.bump(1);
      comma_seen = true;
      component_open = true;
      continue;
    }
    component_open = false;
    if (c == '"') {
      if (!table.strings) st.fail(in.current(), "a keyword or ']'");
      (void)match_rule<rules::quoted>(in, st);
      item.kind = ast::ItemKind::string;
      item.text = st.last_string;
      st.block->items.push_back(item);
      continue;
    }
    if (lex::is_alpha(c) || c == '_' || c == '@') {
      // longest keyword of the table that is not followed by a letter or '_'
      const std::string_view r = lex::rest(in);
      std::size_t best = ast::kUnknownKeyword;
      std::size_t best_len = 0;
      for (std::size_t k = 0; k < table.entries.size(); ++k) {
        const std::string_view name = table.entries[k].name;
        if (name.size() <= best_len || name.size() > r.size()) continue;
        if (!iequals(r.substr(0, name.size()), name)) continue;
        if (name.size() < r.size() && (lex::is_alpha(r[name.size()]) || r[name.size()] == '_'))
          continue;
        best = k;
        best_len = name.size();
      }
      if (best != ast::kUnknownKeyword) {
        item.key = static_cast<std::uint16_t>(best);
        item.keyword = r.substr(0, best_len);
        in.bump(best_len);
        parse_value(in, st, item, table.entries[best].value);
        st.block->items.push_back(item);
        continue;
      }
      if (table.positional && match_rule<rules::expression>(in, st)) {
        item.kind = ast::ItemKind::positional;
        item.value = st.pop();
        st.block->items.push_back(item);
        continue;
      }
      // The manuals' parameter ids (P-AXIS-00008, P-CHAN-00262) name parameters in open
      // tables (#MACHINE DATA, isg-language.md §5.10): the dash-joined id is one name.
      std::size_t n = table.open ? lex::parameter_id_length(r) : 0;
      while (n < r.size() && (lex::is_ident(r[n]) || r[n] == '.' || r[n] == '@'))
        ++n;
      item.keyword = r.substr(0, n);
      in.bump(n);
      const std::string_view after = lex::rest(in).substr(lex::blanks(lex::rest(in)));
      if (!after.empty() && (after[0] == '=' || (table.open && starts_expression(after[0])))) {
        parse_value(in, st, item,
                    after[0] == '=' && after.size() > 1 && after[1] == '"' ? ValueKind::string
                                                                           : ValueKind::expr);
      }
      st.block->items.push_back(item);
      continue;
    }
    if (table.positional && starts_expression(c)) {
      item.kind = ast::ItemKind::positional;
      item.value = parse_expression(in, st, "a value");
      st.block->items.push_back(item);
      continue;
    }
    st.fail(in.current(), table.positional ? "a value, ',' or ']'" : "a keyword or ']'");
  }
}

template <typename Input>
bool parse_list(Input& in, State& st, std::uint8_t group) {
  if (in.empty() || in.peek_char() != '[') return false;
  in.bump(1);
  st.group = group;
  parse_items(in, st);
  if (in.empty() || in.peek_char() != ']') st.fail(in.current(), "']'");
  in.bump(1);
  return true;
}

}  // namespace ncsim::grammar

#include "grammar/custom_rules_impl.hpp"
