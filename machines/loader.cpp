#include "machines/loader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "machines/conveyor_params.hpp"
#include "machines/list_file.hpp"
#include "machines/loader_detail.hpp"

namespace ncsim::machines {
namespace detail {
namespace {

bool is_identifier(std::string_view text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front())) != 0) return false;
  return std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

// Real literal: decimal with optional fraction and exponent ("5.000e+004").
std::optional<double> parse_real(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string_view last_segment(std::string_view key) {
  const std::size_t dot = key.rfind('.');
  return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

// "; did you mean getriebe[].vb_eilgang (P-AXIS-00209)?" for a key within two edits of a known
// key of the same list, or with the same last segment; empty when nothing is close.
std::string suggestion(ListKind kind, std::string_view pattern) {
  const ParamSpec* best = nullptr;
  std::size_t best_distance = 3;
  for (const ParamSpec& spec : param_table()) {
    if (spec.list != kind) continue;
    std::size_t d = core::edit_distance(pattern, spec.key);
    if (d >= 3 && last_segment(pattern) == last_segment(spec.key)) d = 2;
    if (d < best_distance) {
      best = &spec;
      best_distance = d;
    }
  }
  if (best == nullptr) return "";
  return "; did you mean " + std::string(best->key) + " (" + std::string(best->id) + ")?";
}

// A REAL64's range is the bound ncsim applies (1e300, param_table's kRealMax), not the
// type's MAX(REAL64): "1e308 is outside its range 0..MAX(REAL64)" contradicted itself.
std::string range_text(const ParamSpec& spec) {
  if (spec.type == ValueType::sgn32 && spec.min < -2.0e9) return "MIN(SGN32)..MAX(SGN32)";
  return number_text(spec.min) + ".." + number_text(spec.max);
}

}  // namespace

// loader_detail.hpp: integer literal: optional sign, decimal digits, or 0x hex digits.
std::optional<double> parse_integer(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    base = 16;
    text.remove_prefix(2);
  }
  if (text.empty() || text.size() > 18) return std::nullopt;
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return static_cast<double>(negative ? -value : value);
}

std::string pattern_of(std::string_view key) {
  std::string out;
  bool in_index = false;
  for (char c : key) {
    if (c == '[') in_index = true;
    if (c == ']') in_index = false;
    if (!in_index || c == '[') out += c;
  }
  return out;
}

std::string param_ref(std::string_view key, ListKind kind) {
  const ParamSpec* spec = find_param(kind, pattern_of(key));
  return std::string(key) + " (" + (spec ? std::string(spec->id) : std::string("?")) + ")";
}

core::Diagnostic make_diag(core::Severity severity, const std::string& file, core::SourceLoc loc,
                           std::string id, std::string message) {
  return core::Diagnostic{severity, file, loc, std::move(id), std::move(message)};
}

namespace {

/// A list's errors, added to the diagnostics with the list's file.
struct ErrorSink {
  core::DiagnosticList& diagnostics;
  const std::string& file;
  void operator()(core::SourceLoc loc, const char* id, std::string message) const {
    diagnostics.add(make_diag(core::Severity::error, file, loc, id, std::move(message)));
  }
};

// The key of a written entry whose value the list parser rejected, with its indices.
std::string rejected_key(const ParamSpec& spec, const ListEntry& entry) {
  std::string key;
  std::size_t index_no = 0;
  for (const char c : spec.key) {
    key += c;
    if (c == '[' && index_no < entry.indices.size()) {
      key += std::to_string(entry.indices[index_no++]);
    }
  }
  return key;
}

// A key the list's table lacks: retired (NC3015 / NC3013), the other list's (NC3011) or
// unknown (NC3002, with the closest known key).
void report_unknown(ListKind kind, const ListEntry& entry, const ErrorSink& error) {
  const ListKind other = kind == ListKind::axis ? ListKind::channel : ListKind::axis;
  const char* list_name = kind == ListKind::axis      ? "axis"
                          : kind == ListKind::channel ? "channel"
                                                      : "zero-offset";
  if (const RetiredKey* retired = find_retired(kind, entry.pattern)) {
    const bool replaced = retired->diagnostic == "NC3015";
    error(entry.key_loc, std::string(retired->diagnostic).c_str(),
          (replaced ? entry.key + " is no longer read (a retired ncsim key): "
                    : "not supported: " + entry.key + "; ") +
              std::string(retired->use_instead));
  } else if (const ParamSpec* elsewhere = find_param(other, entry.pattern)) {
    error(entry.key_loc, "NC3011",
          entry.key + " (" + std::string(elsewhere->id) + ") is a " +
              (other == ListKind::axis ? "axis" : "channel") +
              " parameter; it cannot be set in the " + list_name + " list");
  } else {
    error(entry.key_loc, "NC3002",
          "unknown parameter '" + entry.key + "' in the " + list_name + " list" +
              suggestion(kind, entry.pattern));
  }
}

// The normalised key (indices without leading zeros); nullopt after NC3009, an index outside
// the table's bounds.
std::optional<std::string> checked_key(const ParamSpec& spec, const ListEntry& entry,
                                       const ErrorSink& error) {
  std::string key;
  std::size_t index_no = 0;
  for (std::size_t i = 0; i < spec.key.size(); ++i) {
    key += spec.key[i];
    if (spec.key[i] == '[') {
      const int index = entry.indices[index_no];
      const int max = index_no == 0 ? spec.index_max_0 : spec.index_max_1;
      if (index > max) {
        error(entry.key_loc, "NC3009",
              entry.key + " (" + std::string(spec.id) + "): index " + std::to_string(index) +
                  " is outside 0.." + std::to_string(max));
        return std::nullopt;
      }
      key += std::to_string(index);
      ++index_no;
    }
  }
  return key;
}

// The value converted by the parameter's type into `value.number`; false after NC3003.
bool convert(const ParamSpec& spec, const ListEntry& entry, const std::string& ref,
             StoredValue& value, const ErrorSink& error) {
  switch (spec.type) {
    case ValueType::word:
      if (is_identifier(entry.value)) return true;
      error(entry.value_loc, "NC3003",
            ref + " expects a name (letters, digits, '_'), found '" + entry.value + "'");
      return false;
    case ValueType::flag_set:
      return true;  // flag names are checked where they are interpreted
    case ValueType::file_name:
      // TF5200 P-CHAN-00160: STRING, at most 83 characters (the list's token has no blanks)
      if (!entry.value.empty() && entry.value.size() <= 83) return true;
      error(entry.value_loc, "NC3003",
            ref + " expects a file name of 1 to 83 characters, found '" + entry.value + "'");
      return false;
    case ValueType::real64:
      if (const auto v = parse_real(entry.value)) {
        value.number = *v;
        return true;
      }
      error(entry.value_loc, "NC3003",
            ref + " expects a number (REAL64), found '" + entry.value + "'");
      return false;
    default:
      if (const auto v = parse_integer(entry.value)) {
        value.number = *v;
        return true;
      }
      error(entry.value_loc, "NC3003",
            ref + " expects an integer (" + std::string(type_name(spec.type)) + "), found '" +
                entry.value + "'");
      return false;
  }
}

// NC3004 for a number outside the parameter's range or an axis mode with undefined bits.
bool in_range(const ParamSpec& spec, const ListEntry& entry, const std::string& ref, double number,
              const ErrorSink& error) {
  const bool numeric = spec.type != ValueType::word && spec.type != ValueType::flag_set &&
                       spec.type != ValueType::file_name;
  if (numeric && (number < spec.min || number > spec.max)) {
    error(entry.value_loc, "NC3004",
          ref + " = " + entry.value + " is outside its range " + range_text(spec));
    return false;
  }
  if (spec.type == ValueType::axis_mode) {
    const auto bits = static_cast<std::uint32_t>(number);
    if ((bits & ~axis_mode::kKnownBits) != 0U) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%08X", bits & ~axis_mode::kKnownBits);
      error(entry.value_loc, "NC3004",
            ref + " = " + entry.value + " sets undefined mode bits " + buf);
      return false;
    }
  }
  return true;
}

}  // namespace

void ListValues::read(const core::SourceFile& source, core::DiagnosticList& diagnostics) {
  ListParse parsed = parse_list(source);
  for (core::Diagnostic& d : parsed.diagnostics)
    diagnostics.add(std::move(d));
  const ErrorSink error{diagnostics, file_};
  for (const ListEntry& entry : parsed.rejected) {
    if (const ParamSpec* spec = find_param(kind_, entry.pattern)) {
      rejected_.push_back(rejected_key(*spec, entry));
    }
  }
  for (const ListEntry& entry : parsed.entries) {
    const ParamSpec* spec = find_param(kind_, entry.pattern);
    if (spec == nullptr) {
      report_unknown(kind_, entry, error);
      continue;
    }
    const std::optional<std::string> key = checked_key(*spec, entry, error);
    if (!key) continue;
    StoredValue value{spec, *key, 0.0, entry.value, entry.key_loc};
    const std::string ref = *key + " (" + std::string(spec->id) + ")";
    if (!convert(*spec, entry, ref, value, error) ||
        !in_range(*spec, entry, ref, value.number, error)) {
      rejected_.push_back(*key);
      continue;
    }
    if (const StoredValue* first = find(*key)) {
      error(entry.key_loc, "NC3005",
            ref + " is given twice; first on line " + std::to_string(first->loc.line));
      continue;
    }
    values_.push_back(std::move(value));
  }
}

const StoredValue* ListValues::find(std::string_view key) const {
  for (const StoredValue& v : values_) {
    if (v.key == key) return &v;
  }
  return nullptr;
}

bool ListValues::rejected(std::string_view key) const {
  return std::find(rejected_.begin(), rejected_.end(), key) != rejected_.end();
}

double ListValues::number(std::string_view key) const {
  if (const StoredValue* v = find(key)) return v->number;
  const ParamSpec* spec = find_param(kind_, pattern_of(key));
  if (spec == nullptr) {
    throw std::logic_error("machines: no parameter spec for key " + std::string(key));
  }
  const std::string_view d = spec->default_value;
  if (d.empty() || d.front() == '=') return 0.0;
  if (spec->type == ValueType::real64) return parse_real(d).value_or(0.0);
  return parse_integer(d).value_or(0.0);
}

double ListValues::internal(std::string_view key) const {
  const ParamSpec* spec = find_param(kind_, pattern_of(key));
  return number(key) * (spec ? spec->to_internal : 1.0);
}

std::string ListValues::text(std::string_view key) const {
  if (const StoredValue* v = find(key)) return v->text;
  const ParamSpec* spec = find_param(kind_, pattern_of(key));
  return spec ? std::string(spec->default_value) : std::string();
}

core::SourceLoc ListValues::loc(std::string_view key) const {
  if (const StoredValue* v = find(key)) return v->loc;
  return core::SourceLoc{};
}

std::vector<const StoredValue*> ListValues::matching(std::string_view pattern) const {
  std::vector<const StoredValue*> out;
  for (const StoredValue& v : values_) {
    if (pattern_of(v.key) == pattern) out.push_back(&v);
  }
  return out;
}

}  // namespace detail

namespace {

using detail::ListValues;

struct IndexEntry {
  std::string name;  // axis name in the index (empty for the channel)
  std::filesystem::path file;
  core::SourceLoc loc;
};

struct MachineIndex {
  std::string name;
  std::optional<IndexEntry> channel;
  std::vector<IndexEntry> axes;
  std::optional<IndexEntry> zero;   ///< `zero <file>`: the zero-offset list (P-ZERO)
  std::optional<IndexEntry> tools;  // `tools <file>`: the tool list (docs/trc.md)
};

std::vector<std::string> split_words(std::string_view line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
      ++i;
    if (i == line.size() || line[i] == '#') break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
      ++i;
    words.emplace_back(line.substr(start, i - start));
  }
  return words;
}

MachineIndex read_index(const core::SourceFile& file, const std::filesystem::path& dir,
                        core::DiagnosticList& diagnostics) {
  MachineIndex index;
  auto error = [&](std::uint32_t line, std::string message) {
    diagnostics.add(detail::make_diag(core::Severity::error, file.name(), core::SourceLoc{line, 1},
                                      "NC3010", std::move(message)));
  };
  for (std::uint32_t line = 1; line <= file.line_count(); ++line) {
    const std::vector<std::string> w = split_words(file.line_text(line));
    if (w.empty()) continue;
    const core::SourceLoc loc{line, 1};
    if (w[0] == "name" && w.size() == 2) {
      index.name = w[1];
    } else if (w[0] == "channel" && w.size() == 2) {
      if (index.channel) {
        error(line,
              "second 'channel' line; first on line " + std::to_string(index.channel->loc.line));
      } else {
        index.channel = IndexEntry{"", dir / w[1], loc};
      }
    } else if (w[0] == "zero" && w.size() == 2) {
      if (index.zero) {
        error(line, "second 'zero' line; first on line " + std::to_string(index.zero->loc.line));
      } else {
        index.zero = IndexEntry{"", dir / w[1], loc};
      }
    } else if (w[0] == "axis" && w.size() == 3) {
      if (index.axes.size() == kMaxChannelAxes) {
        diagnostics.add(detail::make_diag(core::Severity::error, file.name(), loc, "NC3014",
                                          "not supported: more than " +
                                              std::to_string(kMaxChannelAxes) +
                                              " axes in one channel"));
        continue;
      }
      index.axes.push_back(IndexEntry{w[1], dir / w[2], loc});
    } else if (w[0] == "tools" && w.size() == 2) {
      if (index.tools) {
        error(line, "second 'tools' line; first on line " + std::to_string(index.tools->loc.line));
      } else {
        index.tools = IndexEntry{"", dir / w[1], loc};
      }
    } else {
      error(line,
            "expected 'name <text>', 'channel <file>', 'axis <name> <file>', 'zero <file>' or "
            "'tools <file>', "
            "found '" +
                std::string(file.line_text(line)) + "'");
    }
  }
  if (!index.channel) error(0, "no 'channel <file>' line");
  if (index.axes.empty()) error(0, "no 'axis <name> <file>' line");
  return index;
}

std::optional<core::SourceFile> load_source(const std::filesystem::path& path,
                                            const std::string& index_file, core::SourceLoc loc,
                                            core::DiagnosticList& diagnostics) {
  try {
    return core::SourceFile::load_regular(path, kMaxListBytes);
  } catch (const std::exception& e) {
    diagnostics.add(detail::make_diag(core::Severity::error, index_file, loc, "NC3010",
                                      "cannot read list '" + path.string() + "': " + e.what()));
    return std::nullopt;
  }
}

void require(const ListValues& values, std::string_view key, core::DiagnosticList& diagnostics) {
  if (values.given(key) || values.rejected(key)) return;
  diagnostics.add(detail::make_diag(core::Severity::error, values.file(), core::SourceLoc{},
                                    "NC3006",
                                    "missing mandatory " + detail::param_ref(key, values.kind())));
}

AxisParams build_axis(const ListValues& v, core::DiagnosticList& diagnostics) {
  require(v, "kopf.log_achs_name", diagnostics);
  require(v, "kopf.achs_nr", diagnostics);
  AxisParams a;
  a.list_file = v.file();
  a.name = v.text("kopf.log_achs_name");
  a.number = static_cast<int>(v.number("kopf.achs_nr"));
  const int typ = static_cast<int>(v.number("kenngr.achs_typ"));
  a.kind = typ == 2 ? AxisKind::rotary : (typ == 4 ? AxisKind::spindle : AxisKind::linear);
  a.mode_bits = static_cast<std::uint32_t>(v.number("kenngr.achs_mode"));
  a.encoder_only = (a.mode_bits & axis_mode::kCounter) != 0U;
  a.modulo = (a.mode_bits & axis_mode::kModulo) != 0U;
  a.modulo_lower = v.internal("getriebe[0].modulou");
  a.modulo_upper = v.internal("getriebe[0].moduloo");
  a.drive_type = static_cast<int>(v.number("kenngr.antr_typ"));
  a.measure_signal = v.text("kenngr.measure.signal");
  a.measure_input = static_cast<int>(v.number("kenngr.measure.input"));
  a.measure_edge = v.text("kenngr.measure.edge");
  a.soft_limits = SoftLimits{v.internal("kenngr.swe_neg"), v.internal("kenngr.swe_pos")};

  // Gear 0 only (docs/machines.md): getriebe[1..7] are accepted and not used.
  Dynamics& d = a.dynamics;
  d.v_max = v.internal("getriebe[0].dynamik.vb_max");
  d.v_rapid = v.internal("getriebe[0].vb_eilgang");
  d.acc_max = v.internal("getriebe[0].dynamik.a_max");
  d.acc_feed = v.internal("getriebe[0].slope_profil.a_beschl");
  d.dec_feed = v.internal("getriebe[0].slope_profil.a_brems");
  d.acc_rapid = v.internal("getriebe[0].slope_profil.a_grenz");
  // P-AXIS-00053 / P-AXIS-00081: 0 (the default) stands for the rapid value (TF5200 remarks).
  const double feedhold = v.internal("getriebe[0].slope_profil.a_feedh");
  d.dec_feedhold = feedhold > 0.0 ? feedhold : d.acc_rapid;
  d.ramp_acc_up = v.internal("getriebe[0].slope_profil.tr_beschl_zu");
  d.ramp_acc_down = v.internal("getriebe[0].slope_profil.tr_beschl_ab");
  d.ramp_dec_up = v.internal("getriebe[0].slope_profil.tr_brems_zu");
  d.ramp_dec_down = v.internal("getriebe[0].slope_profil.tr_brems_ab");
  d.ramp_rapid = v.internal("getriebe[0].slope_profil.tr_grenz");
  const double ramp_feedhold = v.internal("getriebe[0].slope_profil.tr_feedh");
  d.ramp_feedhold = ramp_feedhold > 0.0 ? ramp_feedhold : d.ramp_rapid;
  d.ramp_min = v.internal("getriebe[0].dynamik.tr_min");
  d.ramp_geom = v.internal("getriebe[0].dynamik.tr_geom");
  d.velo_jump_factor = v.internal("nci.velo_jump_factor");
  d.time_optimal_profiles = v.text("ncsim.profile_rule") == "time_optimal";

  Monitoring& m = a.monitoring;
  m.exact_stop_window = v.internal("getriebe[0].window");
  // P-AXIS-00532 (seed 001 §3.2): 0 disables; negative falls back to P-AXIS-00151, which
  // ncsim does not model, so it disables too (docs/machines.md).
  const double settling = v.internal("getriebe[0].position_settling_time");
  if (settling > 0.0) m.settling_time = settling;
  m.position_lag = v.number("monitoring.position_lag") != 0.0;
  m.position_lag_max = v.internal("monitoring.position_lag_max");
  m.position_lag_filter_time = v.internal("monitoring.position_lag_filter_time");
  m.target_position = v.number("monitoring.target_position") != 0.0;
  m.target_position_window = v.internal("monitoring.target_position_window");
  m.target_position_time = v.internal("monitoring.target_position_time");

  a.control.kv = v.internal("getriebe[0].kv");
  a.control.pt1_time = v.internal("drive.pt1_time");

  // G74 homing (docs/homing.md)
  a.reference_position = v.internal("getriebe[0].pos_refpkt");
  a.homing_velocity = v.internal("getriebe[0].vb_refmax");
  a.conv_sync_optim = v.number("kenngr.conv_sync_optim") != 0.0;  // P-AXIS-00555
  if (v.number("conv_sync.is_master") != 0.0) {
    ConveyorAxisParams c;
    for (const ConveyorFilterParam& f : kConveyorFilterParams)
      f.set(c, v.internal(f.key));
    c.optimised_monitoring = v.number("kenngr.conv_sync_optim") != 0.0;
    a.conveyor = c;
  }
  return a;
}

ChannelParams build_channel(const ListValues& v) {
  ChannelParams ch;
  // Flags and their look-ahead sizes are interpreted in check_machine (loader_checks.cpp).
  if (const auto seq = parse_rotation_sequence(v.text("coordinate_system.rotation_sequence"))) {
    ch.cs_rotation_sequence = *seq;
  }
  // P-CHAN-00071 (isg-language.md §5.5); 3 (HSC) is refused in check_channel_refs.
  const double slope = v.number("prog_start.slope.profile");
  if (slope == 1.0) ch.start_slope = SlopeProfile::trapez;
  if (slope == 2.0) ch.start_slope = SlopeProfile::sin2;
  ch.corr_v_trans_jerk = v.number("corr_v_trans_jerk") != 0.0;  // P-CHAN-00009
  ch.default_path_dev = v.internal("ncsim.default_path_dev");   // NCSIM-CHAN-620
  ch.cycle_time = v.internal("ncsim.cycle_time");               // NCSIM-CHAN-610
  for (std::uint32_t g = 80; g <= 89; ++g) {                    // P-CHAN-00160..00169
    const std::string key = "g" + std::to_string(g) + "_prog_file";
    if (v.given(key)) ch.implicit_call_files[g] = v.text(key);
  }
  for (std::uint32_t i = 0; i < 40; ++i) {  // P-CHAN-00187
    const std::string key = "g800_prog_file[" + std::to_string(i) + "]";
    if (v.given(key)) ch.implicit_call_files[800 + i] = v.text(key);
  }
  if (v.given("m6_prog_file")) ch.m6_prog_file = v.text("m6_prog_file");          // P-CHAN-00118
  if (v.given("d_prog_file")) ch.d_prog_file = v.text("d_prog_file");             // P-CHAN-00429
  ch.create_cycle_param_on_read = v.number("create_cycle_param_on_read") != 0.0;  // P-CHAN-00463
  ch.d_with_t = v.number("einrechnen_mit_t") != 0.0;                              // P-CHAN-00014
  ch.vector_velocity = v.internal("vector.velocity");                             // P-CHAN-00090
  ch.feedrate_factor = v.number("prog_start.feedrate_factor");                    // P-CHAN-00108
  ch.default_feed = v.internal("prog_start.feedrate");                            // P-CHAN-00099
  const std::string override_type = v.text("ncsim.path_override_type");
  if (override_type == "ORIGINAL") ch.path_override_type = PathOverrideType::original;
  if (override_type == "REDUCED_ABOVE_100")
    ch.path_override_type = PathOverrideType::reduced_above_100;
  ch.spindle_count = static_cast<int>(v.number("spdl_anzahl"));
  if (v.given("main_spindle_ax_nr")) {
    ch.main_spindle_number = static_cast<int>(v.number("main_spindle_ax_nr"));
  }
  ch.main_spindle_name = v.text("main_spindle_name");
  if (v.given("log_number_tracking_axis")) {
    ch.tracking_axis_number = static_cast<int>(v.number("log_number_tracking_axis"));
  }

  ConveyorSyncChannel c;
  c.master_axis_number = static_cast<int>(v.number("conveyor_sync.log_number_master"));
  c.direction = v.number("conveyor_sync.move_direction") != 0.0 ? MoveDirection::negative_x
                                                                : MoveDirection::positive_x;
  c.x_virtual = v.number("conveyor_sync.x_virtual") != 0.0;
  c.sync_in_tolerance = v.internal("conveyor_sync.sync_in_tolerance");
  c.hold_limit_vel_factor = v.internal("conveyor_sync.hold_limit_vel_factor");
  c.hold_limit_tolerance = v.internal("conveyor_sync.hold_limit_tolerance");
  c.t0_shift = Eigen::Vector3d(v.internal("conveyor_sync.cart_t0_shift_x"),
                               v.internal("conveyor_sync.cart_t0_shift_y"),
                               v.internal("conveyor_sync.cart_t0_shift_z"));
  c.t0_rot_abc = Eigen::Vector3d(v.internal("conveyor_sync.cart_t0_rot_a"),
                                 v.internal("conveyor_sync.cart_t0_rot_b"),
                                 v.internal("conveyor_sync.cart_t0_rot_c"));
  c.pos_limit = v.internal("conveyor_sync.pos_limit");
  c.dynamics_reserve = v.internal("conveyor_sync.ncsim_dynamics_reserve");
  c.workspace.upper = Eigen::Vector3d(v.internal("conveyor_sync.cart_swe_pos_x"),
                                      v.internal("conveyor_sync.cart_swe_pos_y"),
                                      v.internal("conveyor_sync.cart_swe_pos_z"));
  c.workspace.lower = Eigen::Vector3d(v.internal("conveyor_sync.cart_swe_neg_x"),
                                      v.internal("conveyor_sync.cart_swe_neg_y"),
                                      v.internal("conveyor_sync.cart_swe_neg_z"));
  for (const char axis : {'x', 'y', 'z'}) {
    for (const char* side : {"pos", "neg"}) {
      const std::string key = std::string("conveyor_sync.cart_swe_") + side + "_" + axis;
      if (v.given(key)) c.workspace_configured = true;
    }
  }
  ch.conveyor = c;  // check_machine drops it again when FCT_DLM is not set

  int max_trafo = -1;
  for (const auto* id : v.matching("trafo[].id")) {
    max_trafo = std::max(max_trafo, std::stoi(id->key.substr(6)));
  }
  for (int j = 0; j <= max_trafo; ++j) {
    TrafoParams t;
    const std::string prefix = "trafo[" + std::to_string(j) + "].";
    t.id = static_cast<int>(v.number(prefix + "id"));
    t.type = static_cast<int>(v.number(prefix + "type"));
    for (std::size_t k = 0; k < t.param.size(); ++k) {
      t.param[k] = v.internal(prefix + "param[" + std::to_string(k) + "]");
    }
    ch.trafos.push_back(t);
  }
  return ch;
}

}  // namespace

/// The two indices of "np_grp[3].achse[1].versch": {3, 1}.
std::pair<std::size_t, std::size_t> two_indices(const std::string& key) {
  std::size_t out[2] = {0, 0};
  std::size_t k = 0;
  for (std::size_t n = 0; n < 2; ++n) {
    k = key.find('[', k);
    if (k == std::string::npos) break;
    ++k;
    while (k < key.size() && key[k] >= '0' && key[k] <= '9')
      out[n] = out[n] * 10 + static_cast<std::size_t>(key[k++] - '0');
  }
  return {out[0], out[1]};
}

LoadResult load_machine(const std::filesystem::path& dir) {
  LoadResult result;
  const std::filesystem::path index_path = dir / kMachineIndexFile;
  const std::string index_name = index_path.string();
  std::optional<core::SourceFile> index_file;
  try {
    index_file = core::SourceFile::load_regular(index_path, kMaxListBytes);
  } catch (const std::exception& e) {
    result.diagnostics.add(
        detail::make_diag(core::Severity::error, index_name, core::SourceLoc{}, "NC3010",
                          std::string("cannot read the machine index: ") + e.what()));
    return result;
  }
  const MachineIndex index = read_index(*index_file, dir, result.diagnostics);

  Machine machine;
  machine.folder = dir;
  machine.name = !index.name.empty() ? index.name : dir.filename().string();

  ListValues channel_values(ListKind::channel,
                            index.channel ? index.channel->file.string() : std::string());
  if (index.channel) {
    if (auto src =
            load_source(index.channel->file, index_name, index.channel->loc, result.diagnostics)) {
      channel_values.read(*src, result.diagnostics);
    }
  }
  machine.channel = build_channel(channel_values);

  std::vector<ListValues> axis_values;
  for (const IndexEntry& entry : index.axes) {
    auto src = load_source(entry.file, index_name, entry.loc, result.diagnostics);
    if (!src) continue;
    ListValues values(ListKind::axis, entry.file.string());
    values.read(*src, result.diagnostics);
    AxisParams axis = build_axis(values, result.diagnostics);
    if (values.given("kopf.log_achs_name") && axis.name != entry.name) {
      result.diagnostics.add(detail::make_diag(
          core::Severity::error, index_name, entry.loc, "NC3007",
          "axis '" + entry.name + "' in the index, but its list gives " +
              detail::param_ref("kopf.log_achs_name", ListKind::axis) + " = " + axis.name));
    }
    machine.axes.push_back(std::move(axis));
    axis_values.push_back(std::move(values));
  }

  // The zero-offset list (P-ZERO), when the index names one: G53..G59 / G159=i select its
  // groups; achse[j] is the channel's axis j in machine.lis order.
  if (index.zero) {
    if (auto src = load_source(index.zero->file, index_name, index.zero->loc, result.diagnostics)) {
      ListValues zero_values(ListKind::zero, index.zero->file.string());
      zero_values.read(*src, result.diagnostics);
      ZeroOffsets& z = machine.zero_offsets;
      z.g53_available = zero_values.number("g53_verfuegbar") != 0.0;
      z.default_index = static_cast<int>(zero_values.number("default_index"));
      for (const auto* e : zero_values.matching("np_grp[].achse[].versch")) {
        const auto [group, axis] = two_indices(e->key);
        if (axis >= machine.axes.size()) {
          result.diagnostics.add(detail::make_diag(
              core::Severity::error, index.zero->file.string(), e->loc, "NC3016",
              e->key + ": the channel has " + std::to_string(machine.axes.size()) +
                  " axes (achse[0.." + std::to_string(machine.axes.size() - 1) + "])"));
          continue;
        }
        const std::string inactive =
            "np_grp[" + std::to_string(group) + "].achse[" + std::to_string(axis) + "].inaktiv";
        if (zero_values.number(inactive) != 0.0) continue;
        z.offsets[group][axis] = zero_values.internal(e->key);
      }
    }
  }

  if (index.tools) {
    if (auto src =
            load_source(index.tools->file, index_name, index.tools->loc, result.diagnostics)) {
      machine.tools = read_tool_list(*src, result.diagnostics);
    }
  }

  detail::check_machine(machine, channel_values, axis_values, result.diagnostics);
  if (!result.diagnostics.has_errors()) result.machine = std::move(machine);
  return result;
}

std::filesystem::path bundled_machine_dir(const std::filesystem::path& source_root,
                                          std::string_view name) {
  return source_root / "machines" / std::string(name);
}

}  // namespace ncsim::machines
