#pragma once
// grammar/errors: the one table of syntax error texts, and the PEGTL control that raises them.
//
// Every rule used as a `must<>` target has exactly one entry saying what was expected there;
// the message shown is "expected <entry>, found <what is there>" (block_parser.cpp). A missing
// entry is a compile error. Internal to grammar/.

#include <string>

#include "grammar/block_parser.hpp"
#include "grammar/rules.hpp"

namespace ncsim::grammar {

/// A parse failure: thrown on the error path only, caught at the block level.
struct ParseFailure {
  const char* at = nullptr;        ///< offending character
  const char* id = "NC1001";       ///< diagnostic id
  const char* expected = nullptr;  ///< "expected X" text, when message is empty
  std::string message;             ///< complete message (structural and "not supported" errors)
};

template <typename Rule>
inline constexpr const char* kExpected = nullptr;

#define NCSIM_EXPECT(rule, text) \
  template <>                    \
  inline constexpr const char* kExpected<rules::rule> = text

inline constexpr const char* kOperand = "an operand (number, variable, function or '[')";
NCSIM_EXPECT(expression, kOperand);
NCSIM_EXPECT(operand, kOperand);
NCSIM_EXPECT(product, kOperand);
NCSIM_EXPECT(sum, kOperand);
NCSIM_EXPECT(comparison, kOperand);
NCSIM_EXPECT(band, kOperand);
NCSIM_EXPECT(bxor, kOperand);
NCSIM_EXPECT(bor, kOperand);
NCSIM_EXPECT(land, kOperand);
NCSIM_EXPECT(lxor, kOperand);
NCSIM_EXPECT(argument, "a function argument");
NCSIM_EXPECT(index_expr, "an index expression");
NCSIM_EXPECT(g_arg, "a value after 'G<code>='");
NCSIM_EXPECT(assign_value, "an expression after the assignment operator");
NCSIM_EXPECT(block_number_expr, "a block number expression");
NCSIM_EXPECT(for_value, "a $FOR bound (start, end[, step])");
NCSIM_EXPECT(init_element, "an initial value");
NCSIM_EXPECT(decl_init, "an initial value or '[' list ']'");
NCSIM_EXPECT(address_value, "a value (number, variable or '[' expression ']')");
NCSIM_EXPECT(address_operand, "a value (number, variable or '[' expression ']')");
NCSIM_EXPECT(close_bracket, "']'");
NCSIM_EXPECT(open_bracket, "'['");
NCSIM_EXPECT(comma, "','");
NCSIM_EXPECT(hex_body, "hexadecimal digits");
NCSIM_EXPECT(close_quote1, "a closing '");
NCSIM_EXPECT(close_quote2, "a closing '\"'");
NCSIM_EXPECT(member_name, "a name after '.'");
NCSIM_EXPECT(g_code, "a G code number");
NCSIM_EXPECT(extra_value, "an additional value after '=' (M200=1200)");
NCSIM_EXPECT(macro_equals, "'=' after the macro name");
NCSIM_EXPECT(macro_text, "a quoted macro text");
NCSIM_EXPECT(call_target, "a subroutine name, \"macro\", variable or CYCLE [...]");
NCSIM_EXPECT(cycle_list, "'[' after CYCLE");
NCSIM_EXPECT(for_counter, "a counter variable (P<n> or V.<class>.<name>)");
NCSIM_EXPECT(for_equals, "'=' after the $FOR counter");
NCSIM_EXPECT(label_name, "a label name");
NCSIM_EXPECT(program_name, "a program name");
NCSIM_EXPECT(words_end, "a word (G.., M.., X.., ...) or the end of the block");
NCSIM_EXPECT(block_end, "the end of the block");
NCSIM_EXPECT(decl_variable, "a variable (V.P.NAME, V.L.NAME, V.S.NAME, V.CYC.NAME)");
NCSIM_EXPECT(decl_type, "a type (BOOLEAN, SGN08 ... UNS32, REAL64, STRING[n])");
#undef NCSIM_EXPECT

/// PEGTL control: raises ParseFailure with the table's text at must<> failures.
template <typename Rule>
struct Raise : tao::pegtl::normal<Rule> {
  template <typename Input, typename... States>
  [[noreturn]] static void raise(const Input& in, States&&...) {
    static_assert(kExpected<Rule> != nullptr, "every must<> target needs an error text");
    throw ParseFailure{in.current(), "NC1001", kExpected<Rule>, {}};
  }
};

template <typename Rule>
struct Control : Raise<Rule> {};

/// Counts recursion through `Rule` and stops at kMaxNesting, so deep `[[[...` or `- - -...`
/// input ends in a diagnostic instead of a stack overflow.
template <typename Rule>
struct DepthGuard : Raise<Rule> {
  template <typename Input, typename St>
  static void start(const Input& in, St& st) {
    if (++st.depth > kMaxNesting) {
      throw ParseFailure{
          in.current(), "NC1004", nullptr,
          "expression nested deeper than " + std::to_string(kMaxNesting) + " levels"};
    }
  }
  template <typename Input, typename St>
  static void success(const Input&, St& st) {
    --st.depth;
  }
  template <typename Input, typename St>
  static void failure(const Input&, St& st) {
    --st.depth;
  }
};
template <>
struct Control<rules::operand> : DepthGuard<rules::operand> {};
template <>
struct Control<rules::init_list> : DepthGuard<rules::init_list> {};

}  // namespace ncsim::grammar
