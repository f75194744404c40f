#pragma once
// grammar/keywords: the fixed vocabularies of the NC language: function names, the keyword
// tables of bracket commands, and the G and M code classes.
//
// Inputs: spellings from the source (any letter case). Outputs: table entries and code classes.
// Invariants: tables are constant data; lookups are case-insensitive and allocation-free.
// The sources of each list are cited in keywords.cpp and docs/language.md.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "grammar/ast.hpp"

namespace ncsim::grammar {

/// How a keyword inside a bracket list takes its value.
enum class ValueKind : std::uint8_t {
  none,      ///< flag (INTERRUPTIBLE, WAIT)
  expr,      ///< expression, `=` optional (POS500, ANGLIMIT 3, CONV_VEL=18000)
  opt_expr,  ///< expression if one follows, else a flag
  word,      ///< a name (AX=C, TYPE=TRAPEZ, VEL_RESOLUTION=mm/s)
  string,    ///< a quoted string (AXPARAM="kenngr.swe_pos 15000000")
  code,      ///< a code number directly after the keyword (G90 in INDP lists)
};

struct KeywordSpec {
  std::string_view name;  ///< upper case
  ValueKind value;
};

struct KeywordTable {
  std::span<const KeywordSpec> entries;
  bool open = false;        ///< unknown names are accepted (parameter ids, axis names)
  bool positional = false;  ///< bare expressions / empty components are accepted
  bool strings = false;     ///< bare strings are accepted
};

const KeywordTable& keyword_table(ast::TableId id);

/// ASCII upper case of one character: NC text is ASCII and addresses, keywords and names are
/// case-insensitive (isg-language.md §1.1, docs/language.md).
constexpr char ascii_upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}
/// ASCII upper case of a name, the form names are compared and stored in.
std::string to_upper(std::string_view s);
/// Case-insensitive equality of ASCII text.
bool iequals(std::string_view a, std::string_view b);

/// Function by name (case-insensitive), Function::none if unknown.
ast::Function function_by_name(std::string_view name);
std::string_view function_name(ast::Function f);

enum class GClass : std::uint8_t {
  supported,      ///< in isg-language.md §2.2-2.4
  not_supported,  ///< a real ISG G code ncsim does not implement (§2.5: G41, ...)
  implicit_call,  ///< G80-G89, G800-G839: calls a configured subroutine (else 20131)
  unknown,        ///< not an ISG G code (20131)
};
GClass classify_g(std::uint32_t code);
/// G80-G89 and G800-G839: implicit subroutine calls (PROG-206278923, P-CHAN-00160..00169,
/// P-CHAN-00187).
bool is_implicit_call_g(std::uint32_t code);
/// Most parameters of an implicit call's list (PROG-206278923: <Val1> .. <Val50>).
inline constexpr std::uint32_t kMaxImplicitCallParams = 50;

/// Highest M function number ncsim accepts (decision, docs/language.md "M codes").
inline constexpr std::uint32_t kMaxMCode = 999;

/// True for the M codes ncsim knows: the kernel's own (M00-M06, M17, M19, M29, M30, M40-M45)
/// and every other M up to kMaxMCode as a technology function for the PLC.
bool known_m_code(std::uint32_t code);

}  // namespace ncsim::grammar
