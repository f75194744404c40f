#pragma once
// grammar/custom_rules_hot: the rules on the hot path of every block (internal): separators,
// decimal numbers and the word dispatch. Each matches exactly the PEG rule it replaces
// (rules::sep_spec, rules::number_spec, rules::word_spec in rules.hpp) and differs only in
// speed: one pass over the characters, a switch on the first character instead of trying
// alternatives, no look-ahead that cannot succeed. Included by custom_rules_impl.hpp.

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>

#include "grammar/custom_rules.hpp"

namespace ncsim::grammar {

namespace detail {
/// 10^0 ... 10^22: the powers of ten a double holds exactly.
inline constexpr std::array<double, 23> kExactPow10 = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
/// Largest integer up to which every integer is exactly a double (2^53).
inline constexpr std::uint64_t kExactMantissa = std::uint64_t{1} << 53;
/// At most this many digits are accumulated in a uint64 without overflow.
inline constexpr int kMaxFastDigits = 19;

/// Value of a decimal literal `[digits][.digits]` (the text rules::number matched; `point` is
/// its '.', or `end` without one). When the digits form an integer m <= 2^53 and there are k <=
/// 22 decimals, m and 10^k are exact doubles and one IEEE division is correctly rounded, so
/// m / 10^k is bit-identical to std::from_chars (Clinger's fast path); every other literal goes
/// through from_chars. Nothing when the literal is beyond the range of a double; a literal below
/// the smallest double rounds to 0, as from_chars would round it.
inline std::optional<double> decimal_value(const char* begin, const char* point, const char* end) {
  const auto whole = static_cast<std::size_t>(point - begin);
  const std::size_t decimals = point < end ? static_cast<std::size_t>(end - point) - 1 : 0;
  if (whole + decimals <= static_cast<std::size_t>(kMaxFastDigits)) {
    // The digits before and after the point, in order, as one integer (at most 19 digits).
    std::uint64_t mantissa = 0;
    for (const char* p = begin; p < point; ++p)
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
    if (point < end) {
      for (const char* p = point + 1; p < end; ++p)
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
    }
    if (mantissa <= kExactMantissa && decimals < kExactPow10.size()) {
      return static_cast<double>(mantissa) / kExactPow10[decimals];
    }
  }
  double value = 0.0;
  if (std::from_chars(begin, end, value).ec == std::errc::result_out_of_range) {
    // Out of range is overflow when a significant digit stands before the point, else
    // underflow (0.000...1), which is 0.
    const char* p = begin;
    while (p < end && *p == '0')
      ++p;
    if (p < end && *p != '.') return std::nullopt;
    return 0.0;
  }
  return value;
}

/// Adds the Op::number node of the literal [b, end) (its '.' at `point`, or `end` without
/// one) as rules::number does; kNoNode, with nothing added, when it is beyond the range of a
/// double (NC1005).
inline ast::NodeIndex add_number(State& st, const char* b, const char* point, const char* end) {
  const std::optional<double> value = decimal_value(b, point, end);
  if (!value) return ast::kNoNode;
  ast::ExprNode n =
      leaf(ast::Op::number, st.loc(b), std::string_view(b, static_cast<std::size_t>(end - b)));
  n.value = *value;
  return st.add(n);
}
}  // namespace detail

/// Matches `Rule` as an alternative of a sor<> would (rewinding on failure).
template <typename Rule, pegtl::apply_mode A, template <typename...> class Act,
          template <typename...> class Ctl, typename Input, typename St>
bool try_alternative(Input& in, St& st) {
  return pegtl::match<Rule, A, pegtl::rewind_mode::required, Act, Ctl>(in, st);
}

#define NCSIM_HOT_MATCH(rule)                                                            \
  template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Act, \
            template <typename...> class Ctl, typename Input, typename St>               \
  bool rules::rule::match(Input& in, [[maybe_unused]] St& st)

namespace lex {
/// Where number_spec (`digits [ '.' digits* ] | '.' digits`) starting at `b` ends, or nullptr
/// when none starts there; `point` is set to its '.', or to the end without one.
inline const char* number_end(const char* b, const char* const e, const char*& point) {
  const char* p = b;
  while (p < e && is_digit(*p))
    ++p;
  const bool whole = p != b;
  if (p < e && *p == '.') {
    point = p;
    const char* q = p + 1;
    while (q < e && is_digit(*q))
      ++q;
    if (!whole && q == p + 1) return nullptr;  // a lone '.'
    return q;
  }
  point = p;
  return whole ? p : nullptr;
}

/// Where star<sep_spec> starting at `p` ends: blanks, '\r', nested ( ) comments (as
/// paren_comment), and `\` + line end.
inline const char* separators_end(const char* p, const char* const e) {
  while (p < e) {
    const char c = *p;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++p;
    } else if (c == '(') {
      p = lex::paren_comment_end(p, e);
    } else if (c == '\\') {
      const char* q = p + 1;
      while (q < e && (*q == ' ' || *q == '\t'))
        ++q;
      if (q < e && *q == '\r') ++q;
      if (q >= e || *q != '\n') break;
      p = q + 1;
    } else {
      break;
    }
  }
  return p;
}
}  // namespace lex

// star<sep_spec>: see lex::separators_end.
NCSIM_HOT_MATCH(ws) {
  const char* const p = lex::separators_end(in.current(), in.end());
  in.bump(static_cast<std::size_t>(p - in.current()));
  return true;
}

template <typename Rule, char... First>
template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Act,
          template <typename...> class Ctl, typename Input, typename St>
bool rules::when_next<Rule, First...>::match(Input& in, St& st) {
  const char* const p = lex::separators_end(in.current(), in.end());
  if (p == in.end() || ((*p != First) && ...)) return true;  // Rule would match empty
  return pegtl::match<Rule, A, M, Act, Ctl>(in, st);
}

// number_spec: digits [ '.' digits* ] | '.' digits. Pushes an Op::number leaf.
NCSIM_HOT_MATCH(number) {
  const char* const b = in.current();
  const char* point = nullptr;
  const char* const p = lex::number_end(b, in.end(), point);
  if (p == nullptr) return false;
  const auto length = static_cast<std::size_t>(p - b);
  if constexpr (A == pegtl::apply_mode::action) {
    const ast::NodeIndex node = detail::add_number(st, b, point, p);
    if (node == ast::kNoNode) {
      st.fail_message(b, "NC1005",
                      "number out of range: " + std::string(b, std::min<std::size_t>(length, 24)) +
                          (length > 24 ? "..." : "") + " is beyond +-1.8e308");
    }
    st.stack.push_back(node);
  }
  in.bump(length);
  return true;
}

/// address_word on its common shape, a one-letter head followed at once by a number with or
/// without a sign (`X-1.5`, `Y20`, `F.5`): the same characters read and the same actions done as
/// address_word's (address_head; sign; number; address_value's and address_word's actions), but
/// without stepping through its sequence of optional parts. False, with nothing read or done,
/// on any other shape: address_word itself then decides.
template <pegtl::apply_mode A, template <typename...> class Act, template <typename...> class Ctl,
          typename Input, typename St>
bool plain_address_word(Input& in, St& st) {
  const char* const head = in.current();
  const char* const e = in.end();
  const char* const value = head + 1;  // the operand starts right after the one-letter head
  if (value >= e) return false;
  const char sign = *value == '-' || *value == '+' ? *value : '\0';
  const char* const d = sign != '\0' ? value + 1 : value;
  // number_spec matches here: digits first, or '.' and a digit
  if (d >= e || !(lex::is_digit(*d) || (*d == '.' && d + 1 < e && lex::is_digit(d[1])))) {
    return false;
  }
  if (!rules::address_head::match<A, pegtl::rewind_mode::dontcare, Act, Ctl>(in, st)) return false;
  if (sign != '\0') {
    if constexpr (A == pegtl::apply_mode::action) st.sign = sign;  // Action<rules::sign>
    in.bump(1);
  }
  rules::number::match<A, pegtl::rewind_mode::dontcare, Act, Ctl>(in, st);  // matches (above)
  if constexpr (A == pegtl::apply_mode::action) {
    st.end_address_value(st.loc(value));  // Action<rules::address_value>
    st.add_address_word();                // Action<rules::address_word>
  }
  return true;
}

// word_spec, dispatched on the first character. An alternative is skipped only where it
// cannot match: its first character is wrong, or (axis_command, named_axis) the name is not
// followed by '[' or '=' (bracket_axis and axis_name_eq read name, blanks, then need those).
NCSIM_HOT_MATCH(word) {
  if (in.empty()) return false;
  const char c = in.peek_char();
  switch (c) {
    case '#':
    case '$':
      return try_alternative<misplaced_statement, A, Act, Ctl>(in, st);
    case '"':
      return try_alternative<macro_def, A, Act, Ctl>(in, st);
    case '@':
      return try_alternative<assignment, A, Act, Ctl>(in, st) ||
             try_alternative<bare_value, A, Act, Ctl>(in, st);
    case '.':
    case '\'':
    case '[':
      return try_alternative<bare_value, A, Act, Ctl>(in, st);
    default:
      break;
  }
  if (lex::is_digit(c)) return try_alternative<bare_value, A, Act, Ctl>(in, st);
  if (!lex::is_alpha(c)) return false;

  const char* p = in.current();
  const char* const e = in.end();
  while (p < e && lex::is_ident(*p))
    ++p;
  while (p < e && (*p == ' ' || *p == '\t'))
    ++p;
  const char after = p < e ? *p : '\0';
  const char u = ascii_upper(c);
  const bool variable = u == 'P' || u == 'V';

  if (u == 'L' && try_alternative<subroutine_call, A, Act, Ctl>(in, st)) return true;
  if (variable && try_alternative<assignment, A, Act, Ctl>(in, st)) return true;
  if (after == '[' && try_alternative<axis_command, A, Act, Ctl>(in, st)) return true;
  if (u == 'G') return try_alternative<g_word, A, Act, Ctl>(in, st);
  // M200=1200: an M/H function with an additional value, not an axis named M200
  if ((u == 'M' || u == 'H') && after == '=' && in.size() > 1 && lex::is_digit(in.peek_char(1)) &&
      try_alternative<mh_word, A, Act, Ctl>(in, st)) {
    return true;
  }
  if (after == '=' && try_alternative<named_axis, A, Act, Ctl>(in, st)) return true;
  if (plain_address_word<A, Act, Ctl>(in, st)) return true;
  if (try_alternative<address_word, A, Act, Ctl>(in, st)) return true;
  return variable && try_alternative<bare_value, A, Act, Ctl>(in, st);
}

#undef NCSIM_HOT_MATCH

}  // namespace ncsim::grammar
