#include "machines/tool_table.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string_view>

#include "core/number_text.hpp"
#include "machines/list_file.hpp"

namespace ncsim::machines {
namespace {

constexpr double kTenthMicron = 1.0e-4;  // 0.1 um -> mm (docs/machines.md "Units")
constexpr double kInch = 25.4;           // P-TOOL-00008 = 1: 0.0001 inch -> mm

struct ToolKey {
  std::string_view pattern;
  std::string_view id;
  double min, max;
};
constexpr std::array kKeys = {
    ToolKey{"wz[].gueltig", "P-TOOL-00005", 0, 1},
    ToolKey{"wz[].laenge", "P-TOOL-00003", -2147483648.0, 2147483647.0},
    ToolKey{"wz[].radius", "P-TOOL-00004", -2147483648.0, 2147483647.0},
    ToolKey{"wz[].mass_einheit", "P-TOOL-00008", 0, 1},
};

const ToolKey* find_key(std::string_view pattern) {
  for (const ToolKey& k : kKeys) {
    if (k.pattern == pattern) return &k;
  }
  return nullptr;
}

core::Diagnostic diag(const core::SourceFile& file, core::SourceLoc loc, std::string id,
                      std::string message) {
  return core::Diagnostic{core::Severity::error, file.name(), loc, std::move(id),
                          std::move(message)};
}

// An integer value as written (decimal only; the manual's types are integers).
std::optional<double> integer_value(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (end == nullptr || *end != '\0') return std::nullopt;
  return static_cast<double>(v);
}

struct RawTool {
  std::optional<double> length, radius;  // list units
  bool valid = false;
  bool inch = false;
};

}  // namespace

const Tool* ToolTable::find(int number) const {
  auto it = tools.find(number);
  return it == tools.end() ? nullptr : &it->second;
}

ToolTable read_tool_list(const core::SourceFile& file, core::DiagnosticList& diagnostics) {
  ToolTable table;
  table.file = file.name();
  ListParse parse = parse_list(file);
  for (core::Diagnostic& d : parse.diagnostics)
    diagnostics.add(std::move(d));
  std::map<int, RawTool> raw;
  std::set<std::string> seen;
  for (const ListEntry& e : parse.entries) {
    const ToolKey* key = find_key(e.pattern);
    if (key == nullptr || e.indices.size() != 1) {
      diagnostics.add(diag(file, e.key_loc, "NC3030",
                           "unknown tool list key '" + e.key +
                               "'; ncsim reads wz[i].gueltig (P-TOOL-00005), wz[i].laenge "
                               "(P-TOOL-00003), wz[i].radius (P-TOOL-00004) and "
                               "wz[i].mass_einheit (P-TOOL-00008)"));
      continue;
    }
    const std::string ref = e.key + " (" + std::string(key->id) + ")";
    const int number = e.indices[0];
    if (number < 1 || number > kMaxToolNumber) {
      diagnostics.add(diag(file, e.key_loc, "NC3032",
                           ref + ": tool number " + std::to_string(number) + " is outside 1.." +
                               std::to_string(kMaxToolNumber)));
      continue;
    }
    if (!seen.insert(e.key).second) {
      diagnostics.add(diag(file, e.key_loc, "NC3033", ref + " is given twice"));
      continue;
    }
    const std::optional<double> v = integer_value(e.value);
    if (!v || *v < key->min || *v > key->max) {
      diagnostics.add(diag(file, e.value_loc, "NC3031",
                           ref + " = " + e.value + " must be an integer in " +
                               core::number_text(key->min) + ".." + core::number_text(key->max)));
      continue;
    }
    RawTool& t = raw[number];
    if (key->id == "P-TOOL-00005") t.valid = *v != 0.0;
    if (key->id == "P-TOOL-00003") t.length = *v;
    if (key->id == "P-TOOL-00004") t.radius = *v;
    if (key->id == "P-TOOL-00008") t.inch = *v != 0.0;
  }
  for (const auto& [number, t] : raw) {
    const double unit = kTenthMicron * (t.inch ? kInch : 1.0);
    Tool tool;
    tool.valid = t.valid;
    tool.length = t.length.value_or(0.0) * unit;
    tool.radius = t.radius.value_or(0.0) * unit;
    table.tools.emplace(number, tool);
  }
  return table;
}

}  // namespace ncsim::machines
