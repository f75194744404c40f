#pragma once
// scenario/loader_detail: what the scenario readers share (loader.cpp reads the operator's
// part, conveyor_loader.cpp the `[conveyor]` world): diagnostic ids, number and name checks
// that report with file, line, column and key. Internal to scenario/; not an API.
// Inputs: toml++ nodes of a parsed file. Outputs: diagnostics added to the list; values only
// when they are valid. Invariants: every reported value is named by its key path.

#include <toml++/toml.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/source_file.hpp"
#include "scenario/loader.hpp"

namespace ncsim::scenario::detail {
// Diagnostic ids (docs/diagnostics.md "scenario/").
constexpr const char* kSyntax = "NC7001";
constexpr const char* kUnknownKey = "NC7002";
constexpr const char* kWrongType = "NC7003";
constexpr const char* kRange = "NC7004";
constexpr const char* kOrder = "NC7005";
constexpr const char* kCombination = "NC7006";
constexpr const char* kConveyor = "NC7007";
constexpr const char* kName = "NC7008";
constexpr const char* kUnreadable = "NC7010";
constexpr const char* kUnknownAxis = "NC7011";
constexpr const char* kLineBeyond = "NC7012";
constexpr const char* kLineEmpty = "NC7013";
constexpr const char* kNoConveyorAxis = "NC7019";
constexpr const char* kPathAxisOverride = "NC7020";
// The channel's run-time ids, raised at load when Context gives the machine's limits.
constexpr const char* kOverrideBeyondType = "NC6102";
constexpr const char* kIndpOverride = "NC6105";

constexpr double kTimeMax = core::kLongestTime;  // [s] largest `at`, `duration`, stop.time
constexpr double kOverrideMaxPercent = kOverrideMax * 100.0;
constexpr double kOverrideMinPercent = kOverrideMin * 100.0;
constexpr std::int64_t kLineMax = 4294967295;  // line and pass counts are 32-bit
// TOML integers are 64-bit signed: 2^63-1, compared and printed as the integer it is.
constexpr std::int64_t kCyclesMax = std::numeric_limits<std::int64_t>::max();

// The file as a TOML table; nullopt after NC7001 (kSyntax) at the error's line and column.
std::optional<toml::table> parse_toml(const core::SourceFile& file, core::DiagnosticList& diags);
// NC7010 (kUnreadable) for a file that cannot be read: "cannot read the <what>: <why>".
void add_unreadable(const std::filesystem::path& path, std::string_view what,
                    const std::exception& e, core::DiagnosticList& diags);

std::string upper(std::string_view s);
// "; did you mean `x`?" for the closest candidate within two edits (case ignored); else "".
std::string suggestion(std::string_view word, std::initializer_list<std::string_view> known);
std::string_view type_name(const toml::node& node);
// A V.E. or axis name: a letter or '_', then letters, digits, '_' (the NC language's names).
bool is_name(std::string_view s);
// The number text a user wrote (integers without ".0").
std::string value_text(double v);

// Reports problems of one file; the readers derive from it.
class ReaderBase {
 public:
  ReaderBase(const core::SourceFile& file, const Context& context, core::DiagnosticList& diags)
      : file_(file), context_(context), diags_(diags) {}

  // A node toml++ made implicitly (the `a` of a dotted key `a.b = 1`) has no position: the
  // key being read stands in for it.
  void error(const char* id, const toml::source_region& at, std::string message) {
    error(id, at.begin.line != 0 ? loc(at) : loc(key_), std::move(message));
  }
  void error(const char* id, core::SourceLoc at, std::string message) {
    core::Diagnostic d;
    d.file = file_.name();
    d.loc = at;
    d.id = id;
    d.message = std::move(message);
    diags_.add(std::move(d));
  }
  static core::SourceLoc loc(const toml::source_region& at) {
    return core::SourceLoc{at.begin.line, at.begin.column};
  }

  void wrong_type(const toml::node& node, const std::string& path, std::string_view expected) {
    error(kWrongType, node.source(),
          path + " must be " + std::string(expected) + ", not " + std::string(type_name(node)));
  }

  // A string; nullopt when reported (`expected` names what the string is for).
  std::optional<std::string> text(const toml::node& node, const std::string& path,
                                  std::string_view expected = "a string") {
    const auto* str = node.as_string();
    if (str == nullptr) {
      wrong_type(node, path, expected);
      return std::nullopt;
    }
    return str->get();
  }

  // A number (integer or float) in [lo, hi] (`unit` for the message); nullopt when reported.
  std::optional<double> number(const toml::node& node, const std::string& path, double lo,
                               double hi, std::string_view unit) {
    double v = 0.0;
    if (const auto* i = node.as_integer()) {
      v = static_cast<double>(i->get());
    } else if (const auto* f = node.as_floating_point()) {
      v = f->get();
    } else {
      wrong_type(node, path, "a number");
      return std::nullopt;
    }
    const std::string u = unit.empty() ? "" : " " + std::string(unit);
    if (!std::isfinite(v)) {
      error(kRange, node.source(), path + " = " + value_text(v) + u + " is not a finite number");
      return std::nullopt;
    }
    if (v < lo || v > hi) {
      error(kRange, node.source(),
            path + " = " + value_text(v) + u + " is out of range " + value_text(lo) + " .. " +
                value_text(hi) + u);
      return std::nullopt;
    }
    return v;
  }

  // An override in %: 0 (a stop) or kOverrideMinPercent .. kOverrideMaxPercent.
  std::optional<double> percent(const toml::node& node, const std::string& path) {
    const auto v = number(node, path, 0.0, kOverrideMaxPercent, "%");
    if (v && *v > 0.0 && *v < kOverrideMinPercent) {
      error(kRange, node.source(),
            path + " = " + value_text(*v) + " % is out of range: 0 (a stop) or " +
                value_text(kOverrideMinPercent) + " .. " + value_text(kOverrideMaxPercent) + " %");
      return std::nullopt;
    }
    return v;
  }

  // An integer in [lo, hi]; a float is a wrong type (a count is whole).
  // Compared and printed as integers (a double cannot hold 2^63-1).
  std::optional<std::uint64_t> integer(const toml::node& node, const std::string& path,
                                       std::int64_t lo, std::int64_t hi) {
    const auto* i = node.as_integer();
    if (i == nullptr) {
      wrong_type(node, path, "an integer");
      return std::nullopt;
    }
    const std::int64_t v = i->get();
    if (v < lo || v > hi) {
      error(kRange, node.source(),
            path + " = " + std::to_string(v) + " is out of range " + std::to_string(lo) + " .. " +
                std::to_string(hi));
      return std::nullopt;
    }
    return static_cast<std::uint64_t>(i->get());
  }

  // NAME = number pairs of `[ve]` or an event's `ve` / `axis_override` (names upper-cased,
  // unique ignoring case). `percent`: values are overrides in % (stored as fractions).
  template <typename Out>
  void read_named(const toml::node& node, const std::string& path, bool percent, Out&& out) {
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      wrong_type(node, path, "a table of NAME = number");
      return;
    }
    std::vector<std::string> seen;
    for (auto&& [key, value] : *t) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string item = path + "." + name;
      if (value.is_table() && upper(name) == "V") {
        error(kName, key.source(),
              item +
                  ": write V.E. names without the `V.E.` prefix (`PART = 3`, not "
                  "`V.E.PART = 3`)");
        continue;
      }
      if (!is_name(name)) {
        error(
            kName, key.source(),
            item + ": `" + name + "` is not a name (a letter or `_`, then letters, digits or `_`)");
        continue;
      }
      const std::string up = upper(name);
      if (std::find(seen.begin(), seen.end(), up) != seen.end()) {
        error(kName, key.source(), item + ": " + up + " is given twice (names ignore case)");
        continue;
      }
      seen.push_back(up);
      const auto v = percent ? this->percent(value, item)
                             : number(value, item, std::numeric_limits<double>::lowest(),
                                      std::numeric_limits<double>::max(), "");
      if (v) out(up, percent ? *v / 100.0 : *v, key.source());
    }
  }

  const core::SourceFile& file_;
  const Context& context_;
  core::DiagnosticList& diags_;
  toml::source_region key_;  // the key being read (position of nodes that have none)
};

/// Reads `[conveyor]` (conveyor_loader.cpp) into s.conveyor, reporting every problem.
void read_conveyor(ReaderBase& reader, const toml::node& node, Scenario& s);

}  // namespace ncsim::scenario::detail
