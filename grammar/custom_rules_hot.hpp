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

namespace lex {
/// A decimal literal (number_spec: `digits [ '.' digits* ] | '.' digits`), read in one pass.
struct Decimal {
  const char* end = nullptr;    ///< after the literal; nullptr when none starts where it was read
  const char* point = nullptr;  ///< its '.', or `end` without one
  std::uint64_t mantissa = 0;   ///< its digits as one integer, exact up to 19 digits (mod 2^64)
  std::size_t digits = 0;       ///< how many digits it has
};

inline Decimal read_decimal(const char* const b, const char* const e) {
  Decimal d;
  std::uint64_t m = 0;
  const char* p = b;
  for (; p < e && is_digit(*p); ++p)
    m = m * 10 + static_cast<std::uint64_t>(*p - '0');
  const bool whole = p != b;
  d.point = p;
  if (p < e && *p == '.') {
    const char* q = p + 1;
    for (; q < e && is_digit(*q); ++q)
      m = m * 10 + static_cast<std::uint64_t>(*q - '0');
    if (!whole && q == p + 1) return d;  // a lone '.'
    d.end = q;
  } else if (whole) {
    d.end = p;
  } else {
    return d;
  }
  d.mantissa = m;
  d.digits = static_cast<std::size_t>(d.end - b) - (d.point < d.end ? 1 : 0);
  return d;
}
}  // namespace lex

namespace detail {
/// 10^0 ... 10^22: the powers of ten a double holds exactly.
inline constexpr std::array<double, 23> kExactPow10 = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
/// Largest integer up to which every integer is exactly a double (2^53).
inline constexpr std::uint64_t kExactMantissa = std::uint64_t{1} << 53;
/// At most this many digits are accumulated in a uint64 without overflow.
inline constexpr std::size_t kMaxFastDigits = 19;

/// Value of the decimal literal `d` read at `begin`. When its digits form an integer m <= 2^53
/// (at most 19 digits, so k <= 19 decimals), m and 10^k are exact doubles and one IEEE division
/// is correctly rounded, so m / 10^k is bit-identical to std::from_chars (Clinger's fast path);
/// every other literal goes through from_chars. Nothing when the literal is beyond the range of
/// a double; a literal below the smallest double rounds to 0, as from_chars would round it.
inline std::optional<double> decimal_value(const char* begin, const lex::Decimal& d) {
  if (d.digits <= kMaxFastDigits && d.mantissa <= kExactMantissa) {
    const std::size_t decimals =
        d.point < d.end ? static_cast<std::size_t>(d.end - d.point) - 1 : 0;
    return static_cast<double>(d.mantissa) / kExactPow10[decimals];
  }
  double value = 0.0;
  if (std::from_chars(begin, d.end, value).ec == std::errc::result_out_of_range) {
    // Out of range is overflow when a significant digit stands before the point, else
    // underflow (0.000...1), which is 0.
    const char* p = begin;
    while (p < d.end && *p == '0')
      ++p;
    if (p < d.end && *p != '.') return std::nullopt;
    return 0.0;
  }
  return value;
}

/// Appends the Op::number node of `value`, at `loc`, with the text of the literal `d` read at
/// `begin`, built in place in the block; returns its index.
inline ast::NodeIndex push_number(State& st, core::SourceLoc loc, double value, const char* begin,
                                  const lex::Decimal& d) {
  auto& exprs = st.block->exprs;
  ast::ExprNode& n = exprs.emplace_back();  // Op::number
  n.loc = loc;
  n.value = value;
  n.text = std::string_view(begin, static_cast<std::size_t>(d.end - begin));
  return static_cast<ast::NodeIndex>(exprs.size() - 1);
}

/// Adds the Op::number node of the literal `d` read at `begin` as rules::number does; kNoNode,
/// with nothing added, when it is beyond the range of a double (NC1005).
inline ast::NodeIndex add_number(State& st, const char* begin, const lex::Decimal& d) {
  const std::optional<double> value = decimal_value(begin, d);
  if (!value) return ast::kNoNode;
  return push_number(st, st.loc(begin), *value, begin, d);
}

/// NC1005 on the literal [b, end), as rules::number reports it.
[[noreturn]] inline void number_out_of_range(const State& st, const char* b, const char* end) {
  const auto length = static_cast<std::size_t>(end - b);
  st.fail_message(b, "NC1005",
                  "number out of range: " + std::string(b, std::min<std::size_t>(length, 24)) +
                      (length > 24 ? "..." : "") + " is beyond +-1.8e308");
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
/// True when a separator (rules::sep_spec) may start with `c`.
inline bool starts_separator(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '(' || c == '\\';
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
  const lex::Decimal d = lex::read_decimal(b, in.end());
  if (d.end == nullptr) return false;
  const auto length = static_cast<std::size_t>(d.end - b);
  if constexpr (A == pegtl::apply_mode::action) {
    const ast::NodeIndex node = detail::add_number(st, b, d);
    if (node == ast::kNoNode) detail::number_out_of_range(st, b, d.end);
    st.stack.push_back(node);
  }
  in.bump(length);
  return true;
}

namespace detail {
/// address_kind's table: the word kind of each character, kNotAddress where there is none.
inline constexpr auto kNotAddress = static_cast<ast::WordKind>(0xFF);
constexpr std::array<ast::WordKind, 256> address_kinds() {
  std::array<ast::WordKind, 256> kinds{};
  kinds.fill(kNotAddress);
  using K = ast::WordKind;
  const auto set = [&](char upper, K kind) {
    kinds[static_cast<unsigned char>(upper)] = kind;
    kinds[static_cast<unsigned char>(upper - 'A' + 'a')] = kind;
  };
  set('M', K::m);
  set('H', K::h);
  set('F', K::f);
  set('E', K::e);
  set('S', K::s);
  set('T', K::t);
  set('D', K::d);
  set('I', K::i);
  set('J', K::j);
  set('K', K::k);
  set('R', K::r);
  for (const char axis : {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'})
    set(axis, K::axis);
  return kinds;
}
inline constexpr std::array<ast::WordKind, 256> kAddressKinds = address_kinds();
}  // namespace detail

/// The word kind of the one-letter address `c` (address_head's letters: M H F E S T D I J K R
/// and the axes X Y Z A B C U V W, either case), or nothing.
inline std::optional<ast::WordKind> address_kind(char c) {
  const ast::WordKind kind = detail::kAddressKinds[static_cast<unsigned char>(c)];
  if (kind == detail::kNotAddress) return std::nullopt;
  return kind;
}

/// address_word on its common shape, a one-letter head followed at once by a number with or
/// without a sign (`X-1.5`, `Y20`, `F.5`): the same characters read and the same block built as
/// by address_word (address_head; sign; number; address_value's and address_word's actions: a
/// `-` folds into the literal, which then starts at the sign), in one step, without the State's
/// operand stack and word fields. False, with nothing read or done, on any other shape
/// (address_word itself then decides); a literal beyond the range of a double is NC1005, as
/// rules::number reports it. (`V.` followed by a letter, a variable, is no such shape: no number
/// follows the V.)
template <pegtl::apply_mode A, template <typename...> class Act, template <typename...> class Ctl,
          typename Input, typename St>
bool plain_address_word(Input& in, St& st) {
  const char* const head = in.current();
  const char* const e = in.end();
  const char* const value = head + 1;  // the operand starts right after the one-letter head
  if (value >= e) return false;
  const std::optional<ast::WordKind> kind = address_kind(*head);
  if (!kind) return false;
  const char sign = *value == '-' || *value == '+' ? *value : '\0';
  const char* const digits = sign != '\0' ? value + 1 : value;
  const lex::Decimal number = lex::read_decimal(digits, e);
  if (number.end == nullptr) return false;
  if constexpr (A == pegtl::apply_mode::action) {
    const std::optional<double> v = detail::decimal_value(digits, number);
    if (!v) detail::number_out_of_range(st, digits, number.end);
    const ast::NodeIndex node = detail::push_number(st, st.loc(sign == '-' ? value : digits),
                                                    sign == '-' ? -*v : *v, digits, number);
    ast::Word& w = st.block->words.emplace_back();
    w.kind = *kind;
    w.loc = st.loc(head);
    w.name = std::string_view(head, 1);
    w.value = node;
  }
  in.bump(static_cast<std::size_t>(number.end - head));
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
