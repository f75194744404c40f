#pragma once
// machines/tool_table: the machine's tool list (the ISG tool data, TF5200 "Tool data",
// P-TOOL-xxxxx) that the program's D word selects for tool radius compensation.
//
// Inputs: one list file in the ISG text form of the other lists (docs/machines.md "List
// syntax"), named by the `tools <file>` line of machine.lis. Keys, ids and units as the tool
// data manual writes them:
//   wz[i].gueltig       P-TOOL-00005  0/1, default 0 (a tool must be declared valid)
//   wz[i].laenge        P-TOOL-00003  SGN32, 0.1 um (0.0001 inch), default 0
//   wz[i].radius        P-TOOL-00004  SGN32, 0.1 um (0.0001 inch), default 0
//   wz[i].mass_einheit  P-TOOL-00008  0 mm, 1 inch, default 0
// Outputs: `ToolTable` with lengths and radii in mm (converted once, here), and positioned
// diagnostics NC3030..NC3033 (docs/diagnostics.md "machines/").
// Invariants: tool numbers 1..kMaxToolNumber (the manual's D1..D255 memory, ncsim decision);
// D0 is the tool without dimensions and is never in the table (docs/trc.md "Tool table").

#include <map>
#include <optional>
#include <string>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"

namespace ncsim::machines {

/// Highest tool number a list may define (TF5100 "Tool Data": D1..D255; ncsim decision).
inline constexpr int kMaxToolNumber = 255;

struct Tool {
  double length = 0.0;  ///< [mm] P-TOOL-00003: the tool length compensation (docs/trc.md)
  double radius = 0.0;  ///< [mm] P-TOOL-00004; negative swaps the TRC side (TF5200 TRC page)
  bool valid = false;   ///< P-TOOL-00005
};

struct ToolTable {
  std::string file;           ///< the list it was read from ("" when the machine has none)
  std::map<int, Tool> tools;  ///< by tool number (the D word)
  /// The tool for D<number>; nullptr when the list does not define it.
  const Tool* find(int number) const;
};

/// Reads and validates a tool list. Every bad line gives one positioned error (NC3001 syntax,
/// NC3030 unknown key, NC3031 value out of range, NC3032 tool number out of range, NC3033 key
/// given twice); bad entries are dropped.
ToolTable read_tool_list(const core::SourceFile& file, core::DiagnosticList& diagnostics);

}  // namespace ncsim::machines
