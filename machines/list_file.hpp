#pragma once
// machines/list_file: the ISG parameter-list text form, split into entries.
//
// Inputs: a SourceFile holding one list (channel or axis). Outputs: one ListEntry per
// `key value` line with its position, plus syntax diagnostics (NC3001).
// Syntax (seed 004 §4.8.1 listings; docs/machines.md "List syntax"):
//   - blank lines and lines whose first non-blank character is `#` are comments;
//   - `key value`, separated by blanks; keys are dotted and may carry indices
//     (`trafo[0].param[4]`); a value is a number (decimal, hex `0x...`, exponent form
//     `5.000e+004`), an identifier, a quoted string, or identifiers joined by `|`;
//   - after the value a trailing comment may follow, starting with `#` or `(`.
// Invariants: no value is interpreted here; types and ranges are the loader's job. Messages
// name a known key with its parameter id ("kenngr.swe_pos (P-AXIS-00178)").

#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"

namespace ncsim::machines {

struct ListEntry {
  std::string key;            ///< as written ("trafo[0].param[4]")
  std::string pattern;        ///< indices replaced by "[]" ("trafo[].param[]")
  std::vector<int> indices;   ///< the indices in order ({0, 4})
  std::string value;          ///< value text; flag sets normalised to "A|B"
  core::SourceLoc key_loc;    ///< where the key starts
  core::SourceLoc value_loc;  ///< where the value starts
};

struct ListParse {
  std::vector<ListEntry> entries;
  /// Lines whose key was read but whose value is malformed (key fields set, value empty):
  /// the loader must not report such a key as missing (one error per bad line).
  std::vector<ListEntry> rejected;
  std::vector<core::Diagnostic> diagnostics;  ///< NC3001 syntax errors, NC3021 BOM note
};

/// Splits a list into entries; a bad line gives one diagnostic and is skipped. A UTF-8 byte
/// order mark at the start of the file is skipped with note NC3021 (docs/machines.md).
ListParse parse_list(const core::SourceFile& file);

}  // namespace ncsim::machines
