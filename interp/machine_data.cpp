// interp/machine_data.cpp: #MACHINE DATA (isg-language.md §5.10, PROG-207492747)
// resolved at decode time: every parameter, given by its id (`P-AXIS-00178=...`,
// `P-AXIS-00209.0 5`) or by its list key (`AXPARAM="kenngr.swe_pos 15000000"`), is looked up
// in the machine's one parameter table (machines/param_table.hpp) and becomes a typed
// MachineSetting with its value converted to internal units. Errors name the parameter id.
#include <charconv>
#include <cmath>

#include "interp/interpreter_impl.hpp"
#include "machines/param_table.hpp"

namespace ncsim::interp {
namespace {

const machines::ParamSpec* find_by_id(std::string_view id) {
  for (const machines::ParamSpec& p : machines::param_table()) {
    if (grammar::iequals(p.id, id)) return &p;
  }
  return nullptr;
}

/// "getriebe[0].window" -> pattern "getriebe[].window" and first index 0.
std::string key_pattern(std::string_view key, std::optional<std::uint16_t>& index) {
  std::string out;
  for (std::size_t k = 0; k < key.size(); ++k) {
    out.push_back(key[k]);
    if (key[k] != '[') continue;
    std::size_t e = key.find(']', k);
    if (e == std::string_view::npos) break;
    unsigned value = 0;
    auto [ptr, ec] = std::from_chars(key.data() + k + 1, key.data() + e, value);
    if (ec == std::errc{} && ptr == key.data() + e && !index && value <= 0xFFFFu) {
      index = static_cast<std::uint16_t>(value);
    }
    k = e - 1;
  }
  return out;
}

}  // namespace

bool HashCommands::machine_setting(core::SourceLoc at, const machines::ParamSpec& spec,
                                   std::optional<std::uint16_t> index, double value,
                                   MachineData& md) {
  const std::string name = std::string(spec.id) + " (" + std::string(spec.key) + ")";
  if (spec.list == machines::ListKind::axis && !md.axis) {
    return ip_.fail(at, "NC4515", "#MACHINE DATA: axis parameter " + name + " needs AX= or AXNR=");
  }
  if (spec.type == machines::ValueType::word || spec.type == machines::ValueType::flag_set) {
    return ip_.fail(
        at, "NC4104",
        "#MACHINE DATA: " + name + " takes a name, which ncsim does not change at run time");
  }
  if (spec.index_max_0 < 0 && index) {
    return ip_.fail(at, "NC4514", "#MACHINE DATA: " + name + " has no index");
  }
  if (index && *index > spec.index_max_0) {
    return ip_.fail(at, "NC4514",
                    "#MACHINE DATA: index " + std::to_string(*index) + " of " + name +
                        " is beyond its largest index " + std::to_string(spec.index_max_0));
  }
  const bool integral = spec.type != machines::ValueType::real64;
  if ((integral && value != std::trunc(value)) || value < spec.min || value > spec.max) {
    return ip_.fail(at, "NC4514",
                    "#MACHINE DATA: value " + core::number_text(value) + " of " + name +
                        " is outside " + core::number_text(spec.min) + ".." +
                        core::number_text(spec.max) + (integral ? " (an integer)" : "") + " [" +
                        std::string(spec.unit) + "]");
  }
  md.settings.push_back(
      MachineSetting{spec.id, spec.key, index, value * spec.to_internal, spec.internal_unit});
  return true;
}

bool HashCommands::hash_machine_data(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  MachineData md;
  md.syn = items.find("SYN") != nullptr;
  md.wait = items.find("WAIT") != nullptr;
  if (const ast::Item* ax = items.find("AX")) {
    md.axis = ip_.axis_index(ax->text);
    if (!md.axis)
      return ip_.fail(ax->loc, "NC4103", "axis " + std::string(ax->text) + " does not exist");
  }
  if (const ast::Item* nr = items.find("AXNR")) {
    // AXNR: logical axis number, kopf.achs_nr (PROG-207492747).
    if (nr->value == ast::kNoNode) return ip_.fail(nr->loc, "NC4002", "AXNR needs a value");
    auto v = item_value(b, nr);
    if (!v) return false;
    for (std::size_t k = 0; k < ip_.machine.axes.size() && k < kMaxAxes; ++k) {
      if (ip_.machine.axes[k].number == static_cast<int>(std::lround(*v))) {
        md.axis = static_cast<std::uint8_t>(k);
      }
    }
    if (!md.axis) {
      return ip_.fail(nr->loc, "NC4103", "no axis with logical number " + core::number_text(*v));
    }
  }
  if (const ast::Item* p = items.find("AXPARAM")) {
    // AXPARAM="<key> <value>": the axis list's own spelling.
    const std::string_view text = p->text;
    const std::size_t gap = text.find_first_of(" \t");
    const std::string_view key = text.substr(0, gap);
    std::string_view rest = gap == std::string_view::npos ? std::string_view{} : text.substr(gap);
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
      rest.remove_prefix(1);
    std::optional<std::uint16_t> index;
    const machines::ParamSpec* spec =
        machines::find_param(machines::ListKind::axis, key_pattern(key, index));
    if (spec == nullptr) {
      return ip_.fail(p->loc, "NC4513",
                      "#MACHINE DATA: axis parameter " + std::string(key) +
                          " is not in ncsim's parameter table (docs/machines.md)");
    }
    double value = 0.0;
    auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
    if (rest.empty() || ec != std::errc{} || ptr != rest.data() + rest.size()) {
      return ip_.fail(p->loc, "NC4514",
                      "#MACHINE DATA: " + std::string(spec->id) + " (" + std::string(key) +
                          ") needs one number, got '" + std::string(rest) + "'");
    }
    if (!machine_setting(p->loc, *spec, index, value, md)) return false;
  }
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    // <Param_ID>=value / <Param_ID>.<idx> value (PROG-207492747): any keyword outside the
    // command's table is a parameter id.
    const ast::Item& it = b.items[k];
    if (it.key != ast::kUnknownKeyword || it.keyword.empty()) continue;
    if (it.value == ast::kNoNode) {
      return ip_.fail(it.loc, "NC4002",
                      "#MACHINE DATA: " + std::string(it.keyword) + " needs a value");
    }
    const std::string_view word = it.keyword;
    const std::size_t dot = word.find('.');
    std::optional<std::uint16_t> index;
    if (dot != std::string_view::npos) {
      unsigned value = 0;
      auto [ptr, ec] = std::from_chars(word.data() + dot + 1, word.data() + word.size(), value);
      if (ec != std::errc{} || ptr != word.data() + word.size() || value > 0xFFFFu) {
        return ip_.fail(it.loc, "NC4514", "#MACHINE DATA: bad index in " + std::string(word));
      }
      index = static_cast<std::uint16_t>(value);
    }
    const std::string_view id = word.substr(0, dot);
    const machines::ParamSpec* spec = find_by_id(id);
    if (spec == nullptr) {
      return ip_.fail(it.loc, "NC4513",
                      "#MACHINE DATA: parameter " + std::string(id) +
                          " is not in ncsim's parameter table (docs/machines.md)");
    }
    auto v = item_value(b, &it);
    if (!v) return false;
    if (!machine_setting(it.loc, *spec, index, *v, md)) return false;
  }
  ip_.emit(ip_.line, std::move(md));
  return true;
}

}  // namespace ncsim::interp
