#pragma once
// machines/param_table: the one table of every parameter ncsim reads from an ISG list.
//
// Purpose: single source of truth for parameter id, key, list, data type, range, list unit,
// conversion to internal units and default. The loader, the diagnostics and the docs table in
// docs/machines.md all come from here; no other code knows a key's spelling.
// Inputs: none (constant data). Outputs: `param_table()`, `find_param()`.
// Invariants: keys are unique per list; indexed keys are written with empty brackets
// ("trafo[].param[]"); `min <= max`; `to_internal` multiplies a list value into mm, s, degrees
// or a plain fraction.

#include <cstdint>
#include <span>
#include <string_view>

namespace ncsim::machines {

/// Which list a parameter belongs to.
enum class ListKind { channel, axis, zero };  ///< zero: the zero-offset list (P-ZERO)

/// The data types of the ISG parameter manuals, plus the string forms ncsim needs.
enum class ValueType {
  boolean,  ///< 0 or 1
  uns16,
  uns32,
  sgn32,
  real64,
  word,       ///< one identifier (`X`, `S1`, `PLC_FIRST_EVENT`, `ZYX`)
  flag_set,   ///< identifiers joined by `|` (`FCT_IPO_DEFAULT | FCT_SYNC`)
  axis_mode,  ///< UNS32 bit set of P-AXIS-00015; unknown bits are errors
  file_name   ///< a program file name, at most 83 characters, no blanks (P-CHAN-00160)
};

/// Whether a key must be present.
enum class Need {
  optional,   ///< `default_value` applies when the key is absent
  mandatory,  ///< absence is an error (NC3006)
  derived     ///< absent: computed from another parameter (see `default_value` text)
};

struct ParamSpec {
  std::string_view id;             ///< manual id ("P-AXIS-00178") or ncsim id ("NCSIM-AXIS-001")
  std::string_view key;            ///< list key, indices as "[]" ("getriebe[].window")
  ListKind list;                   ///< channel or axis list
  ValueType type;                  ///< data type in the list
  double min;                      ///< smallest allowed list value (inclusive)
  double max;                      ///< largest allowed list value (inclusive)
  std::string_view unit;           ///< unit of the list value as the manual writes it
  double to_internal;              ///< list value * to_internal = internal value
  std::string_view internal_unit;  ///< unit after conversion
  std::string_view default_value;  ///< list text used when absent (Need::optional)
  Need need;                       ///< mandatory / optional / derived
  int index_max_0;                 ///< largest first index ([]), -1 when not indexed
  int index_max_1;                 ///< largest second index, -1 when none
  std::string_view source;         ///< where the manual describes it, or "ncsim"
};

/// A key ncsim no longer reads (its own invented keys before issue 10, NCSIM-AXIS-021 since
/// session 31) or reads only to say it does not run its model; the loader answers it with
/// `diagnostic` and `use_instead`.
struct RetiredKey {
  std::string_view key;          ///< list key, indices as "[]"
  ListKind list;                 ///< channel or axis list
  std::string_view diagnostic;   ///< NC3015 (replaced) or NC3013 (not supported)
  std::string_view use_instead;  ///< what to write instead, with ids and units
};

/// Every parameter known to ncsim, channel and axis lists together.
std::span<const ParamSpec> param_table();

/// The spec for a key pattern ("trafo[].param[]") in one list; nullptr when unknown.
const ParamSpec* find_param(ListKind list, std::string_view pattern);

/// Every retired key (docs/machines.md "Retired keys").
std::span<const RetiredKey> retired_keys();
/// The retired key for a pattern in one list; nullptr when it is not retired.
const RetiredKey* find_retired(ListKind list, std::string_view pattern);

/// Human text of a spec's range for messages ("-2147483648..2147483647").
std::string_view type_name(ValueType type);

/// Bits of P-AXIS-00015 (seed 004 §5.2.1). Only these may be set.
namespace axis_mode {
inline constexpr std::uint32_t kLinear = 0x00000001;
inline constexpr std::uint32_t kModulo = 0x00000004;
inline constexpr std::uint32_t kModuloLinear = 0x00000400;
inline constexpr std::uint32_t kCounter = 0x00100000;
inline constexpr std::uint32_t kKnownBits =
    0x00000001 | 0x00000004 | 0x00000040 | 0x00000080 | 0x00000100 | 0x00000200 | 0x00000400 |
    0x00000800 | 0x00001000 | 0x00008000 | 0x00010000 | 0x00020000 | 0x00040000 | 0x00080000 |
    0x00100000 | 0x00200000 | 0x00400000 | 0x00800000 | 0x02000000 | 0x04000000 | 0x08000000 |
    0x10000000;
}  // namespace axis_mode

}  // namespace ncsim::machines
