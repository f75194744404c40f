#pragma once
// machines/loader_detail: internals shared by loader.cpp and loader_checks.cpp. Not API.
//
// ListValues holds the validated entries of one list (type- and range-checked, duplicates
// rejected) and answers typed lookups with the table defaults; it is used only while loading.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/number_text.hpp"
#include "core/source_file.hpp"
#include "machines/machine.hpp"
#include "machines/param_table.hpp"

namespace ncsim::machines::detail {

struct StoredValue {
  const ParamSpec* spec = nullptr;
  std::string key;      ///< normalised key ("trafo[0].param[4]")
  double number = 0.0;  ///< numeric types, in list units
  std::string text;     ///< word / flag_set values, and the value as written
  core::SourceLoc loc;  ///< position of the key
};

class ListValues {
 public:
  ListValues(ListKind kind, std::string file) : kind_(kind), file_(std::move(file)) {}

  /// Parses and validates `source`, adding diagnostics for bad entries (which are dropped).
  void read(const core::SourceFile& source, core::DiagnosticList& diagnostics);

  const StoredValue* find(std::string_view key) const;
  bool given(std::string_view key) const { return find(key) != nullptr; }
  /// True when the key was written but its value was rejected (one error already reported):
  /// checks that would compare against its default, or call it missing, stay silent.
  bool rejected(std::string_view key) const;
  /// Value in list units, or the table default.
  double number(std::string_view key) const;
  /// Value converted to internal units (spec.to_internal applied).
  double internal(std::string_view key) const;
  /// Word / flag value as written, or the table default.
  std::string text(std::string_view key) const;
  /// Position of the key; line 0 when absent.
  core::SourceLoc loc(std::string_view key) const;
  /// Every stored value whose key matches an indexed pattern ("trafo[].id").
  std::vector<const StoredValue*> matching(std::string_view pattern) const;

  const std::string& file() const { return file_; }
  ListKind kind() const { return kind_; }

 private:
  ListKind kind_;
  std::string file_;
  std::vector<StoredValue> values_;
  std::vector<std::string> rejected_;  // normalised keys of written but rejected values
};

/// A list's integer literal: optional sign, decimal digits, or 0x hex digits (loader.cpp).
std::optional<double> parse_integer(std::string_view text);
/// The names of a flag value as the list parser normalised it ("A|B" -> {"A", "B"}).
std::vector<std::string> split_flags(const std::string& text);
/// Bits as the lists write them: "0x00020002" (loader_checks.cpp).
std::string hex_text(std::uint32_t bits);

/// "kenngr.swe_pos (P-AXIS-00178)"
std::string param_ref(std::string_view key, ListKind kind);
/// Pattern of a normalised key: digits inside brackets removed.
std::string pattern_of(std::string_view key);
/// Number text for messages: the project's one formatter.
using core::number_text;

core::Diagnostic make_diag(core::Severity severity, const std::string& file, core::SourceLoc loc,
                           std::string id, std::string message);

/// Cross-list checks and derived values (loader_checks.cpp). `axis_values` is parallel to
/// machine.axes. Adds diagnostics; may limit values where the manual says so (21483).
void check_machine(Machine& machine, const ListValues& channel_values,
                   const std::vector<ListValues>& axis_values, core::DiagnosticList& diagnostics);

/// The technology functions' synchronisation types and execution times (tech_sync.cpp).
void read_tech_table(ChannelParams& channel, const ListValues& channel_values,
                     core::DiagnosticList& diagnostics);

}  // namespace ncsim::machines::detail
