#pragma once
// grammar/plain_expression: a hand-written reader for bracketed expressions of the plain
// shape (internal to grammar/).
//
// Purpose: speed. Every operand of a PEG expression passes the ten precedence levels of
// rules.hpp (expression ... power), each with its tail; most bracketed values in NC programs
// are plain arithmetic (`X[[63.607+33.715]/2]`, `Y[ABS[144.732]-10]`). This reader takes
// only that shape and otherwise changes nothing, so the PEG rules stay the definition and the
// fallback.
// The plain shape: numbers (rules::number), `[ ... ]` groups, calls of the function table
// (`SIN[30]`, `ATAN2[1, 2]`), unary `-` and `+`, and the binary operators `**`, `*`, `/`, `+`,
// `-`, with separators (rules::ws) between any two tokens. Anything else (variables,
// constants, strings, hexadecimal literals, MOD, NOT, comparisons, logical and bit operators,
// an error of any kind, nesting deeper than kMaxPlainNesting) leaves the shape.
// Inputs: the text at a `[` and the block's parser State. Outputs: on the plain shape, the
// same expression nodes in Block::exprs, in the same order and to the bit, as rules::group's
// actions add them, and the group's value on the State's stack, as rules::group leaves it.
// Invariants: off the plain shape the State and the block are left as they were, and the
// caller reads the text through the PEG rules, which then report any error themselves.

#include "grammar/parser_state.hpp"

namespace ncsim::grammar {

/// Deepest nesting of operands (groups, calls, unary operators, `**`) the plain reader takes;
/// deeper expressions go through the PEG rules, which count against kMaxNesting.
inline constexpr int kMaxPlainNesting = 32;

/// Reads the group `[ expression ]` starting at `open` (a `[`, before `end`) as rules::group
/// does, when it is of the plain shape (above): returns the end of the group (after its `]`).
/// Otherwise returns nullptr with nothing changed.
const char* read_plain_group(const char* open, const char* end, State& st);

}  // namespace ncsim::grammar
