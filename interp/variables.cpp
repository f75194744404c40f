#include "interp/variables.hpp"

#include <cmath>
#include <cstring>

#include "core/number_text.hpp"

namespace ncsim::interp {
namespace {

using grammar::ast::VarClass;
using grammar::ast::VarType;

std::string class_name(VarClass cls) {
  switch (cls) {
    case VarClass::v_p:
      return "V.P.";
    case VarClass::v_l:
      return "V.L.";
    case VarClass::v_s:
      return "V.S.";
    case VarClass::v_e:
      return "V.E.";
    case VarClass::v_g:
      return "V.G.";
    case VarClass::v_cyc:
      return "V.CYC.";
    default:
      return "V.";
  }
}

std::string describe(const VarRef& ref) {
  std::string s =
      ref.cls == VarClass::p ? "P" + std::to_string(ref.number) : class_name(ref.cls) + ref.name;
  for (std::uint32_t k = 0; k < ref.index_count; ++k) {
    s += "[" + std::to_string(static_cast<long long>(ref.index[k])) + "]";
  }
  return s;
}

/// Flat element index of `ref` in `v`; nullopt when out of range.
std::optional<std::size_t> element(const Variable& v, const VarRef& ref) {
  if (ref.index_count != v.dims.size()) return std::nullopt;
  std::size_t flat = 0;
  for (std::uint32_t k = 0; k < ref.index_count; ++k) {
    const double i = ref.index[k];
    if (!(i >= 0.0) || i >= static_cast<double>(v.dims[k])) return std::nullopt;
    flat = flat * v.dims[k] + static_cast<std::size_t>(i);
  }
  return flat;
}

/// Value as stored in a variable of `type` (truncation toward 0, range check).
std::optional<double> convert(VarType type, double value) {
  const auto in = [&](double lo, double hi) -> std::optional<double> {
    const double t = std::trunc(value);
    if (t < lo || t > hi) return std::nullopt;
    return t;
  };
  switch (type) {
    case VarType::boolean:
      return std::fabs(value) >= 0.5 ? 1.0 : 0.0;
    case VarType::sgn08:
      return in(-128.0, 127.0);
    case VarType::uns08:
      return in(0.0, 255.0);
    case VarType::sgn16:
      return in(-32768.0, 32767.0);
    case VarType::uns16:
      return in(0.0, 65535.0);
    case VarType::sgn32:
      return in(-2147483648.0, 2147483647.0);
    case VarType::uns32:
      return in(0.0, 4294967295.0);
    case VarType::real64:
      return value;
    case VarType::string:
      return std::nullopt;
  }
  return value;
}

}  // namespace

Variables::Variables(PersistentVariables* persistent, std::map<std::string, double> external)
    : persistent_(persistent != nullptr ? persistent : &own_persistent_) {
  for (auto& [name, value] : external) {
    Variable v;
    v.values.push_back(value);
    v_e_[name] = std::move(v);
  }
  locals_.emplace_back();
}

// The program's own V.E. writes (docs/scenario.md "The program's V.E. writes")
void Variables::note_ve_write(const VarRef& ref) {
  if (!record_ve_ || ref.cls != VarClass::v_e || ref.index_count != 0) return;
  VarError err;
  if (const auto v = read(ref, err)) ve_written_[ref.name] = *v;
}

Variables::Map* Variables::map_for(VarClass cls) {
  switch (cls) {
    case VarClass::v_p:
      return &v_p_;
    case VarClass::v_s:
      return &persistent_->values;
    case VarClass::v_e:
      return &v_e_;
    case VarClass::v_g:
      return &v_g_;
    case VarClass::v_cyc:
      return &v_cyc_;
    case VarClass::v_l:
      return &locals_.back();
    default:
      return nullptr;
  }
}

const Variable* Variables::find(const VarRef& ref) const {
  return const_cast<Variables*>(this)->find(ref);
}

Variable* Variables::find(const VarRef& ref) {
  if (ref.cls == VarClass::v_l) {
    for (auto it = locals_.rbegin(); it != locals_.rend(); ++it) {
      auto found = it->find(ref.name);
      if (found != it->end()) return &found->second;
    }
    return nullptr;
  }
  Map* map = map_for(ref.cls);
  if (map == nullptr) return nullptr;
  auto found = map->find(ref.name);
  return found == map->end() ? nullptr : &found->second;
}

/// Most transfer parameters of one cycle call (PROG-206859019: @P1 .. @P200).
constexpr std::uint32_t kMaxCycleParam = 200;

std::optional<double>* Variables::cycle_param(const VarRef& ref, bool create, VarError& error) {
  const std::string name = "@P" + std::to_string(ref.number);
  if (cycle_params_.empty() || !cycle_params_.back()) {
    error = {"21382", "cycle parameter " + name +
                          " outside a cycle (only a cycle called by L CYCLE [...], G80-G89 or "
                          "G800-G839 reads and writes its @P parameters)"};
    return nullptr;
  }
  if (ref.number == 0 || ref.number > kMaxCycleParam || ref.index_count != 0) {
    error = {"20394", "invalid cycle parameter " + name + " (@P1 .. @P" +
                          std::to_string(kMaxCycleParam) + ")"};
    return nullptr;
  }
  auto& values = cycle_params_.back()->values;
  if (values.size() < ref.number) values.resize(ref.number);
  std::optional<double>& slot = values[ref.number - 1];
  if (!slot) {
    if (!create) {
      error = {
          "20394",
          "cycle parameter " + name +
              " was not programmed in the cycle call (P-CHAN-00463 create_cycle_param_on_read 0)"};
      return nullptr;
    }
    slot = 0.0;
  }
  return &slot;
}

std::optional<double> Variables::read(const VarRef& ref, VarError& error) const {
  if (ref.cls == VarClass::at_p) {
    // A read of a @P the call did not program creates it (P-CHAN-00463): the store changes,
    // as the manual's kernel's does, so the const is only outward.
    auto* self = const_cast<Variables*>(this);
    std::optional<double>* slot = self->cycle_param(ref, create_cycle_param_on_read_, error);
    if (slot == nullptr) return std::nullopt;
    return **slot;
  }
  if (ref.cls == VarClass::p) {
    if (ref.number == 0 || ref.number > kMaxPNumber) {
      error = {"20400", "invalid P parameter number " + describe(ref)};
      return std::nullopt;
    }
    if (ref.index_count == 0) {
      if (ref.number < p_set_.size() && p_set_[ref.number] != 0) return p_values_[ref.number];
    } else {
      auto found = p_arrays_.find(ref.number);
      const double i = ref.index[0];
      if (ref.index_count > 1 || !(i >= 0.0) || i > kMaxPArrayIndex) {
        error = {"20400", "invalid P parameter index " + describe(ref)};
        return std::nullopt;
      }
      if (found != p_arrays_.end() && static_cast<std::size_t>(i) < found->second.size()) {
        return found->second[static_cast<std::size_t>(i)];
      }
    }
    error = {"NC4010", describe(ref) + " is read before it was written"};
    return std::nullopt;
  }
  const Variable* v = find(ref);
  if (v == nullptr) {
    error = {"NC4011", "unknown variable " + describe(ref)};
    return std::nullopt;
  }
  if (v->is_string()) {
    error = {"NC4014", describe(ref) + " is a STRING, a number is expected"};
    return std::nullopt;
  }
  auto at = element(*v, ref);
  if (!at) {
    error = {"NC4015", "index out of range: " + describe(ref)};
    return std::nullopt;
  }
  return v->values[*at];
}

const std::string* Variables::read_string(const VarRef& ref) const {
  const Variable* v = find(ref);
  return (v != nullptr && v->is_string()) ? &v->text : nullptr;
}

bool Variables::write(const VarRef& ref, double value, VarError& error) {
  if (ref.cls == VarClass::at_p) {
    std::optional<double>* slot = cycle_param(ref, true, error);
    if (slot == nullptr) return false;
    *slot = value;
    return true;
  }
  if (ref.cls == VarClass::p) {
    if (ref.number == 0 || ref.number > kMaxPNumber) {
      error = {"20400", "invalid P parameter number " + describe(ref)};
      return false;
    }
    if (ref.index_count == 0) {
      if (p_set_.size() <= ref.number) {
        p_set_.resize(ref.number + 1, 0);
        p_values_.resize(ref.number + 1, 0.0);
      }
      p_values_[ref.number] = value;
      p_set_[ref.number] = 1;
      return true;
    }
    const double i = ref.index[0];
    if (ref.index_count > 1 || !(i >= 0.0) || i > kMaxPArrayIndex) {
      error = {"20400", "invalid P parameter index " + describe(ref)};
      return false;
    }
    auto& array = p_arrays_[ref.number];
    const auto k = static_cast<std::size_t>(i);
    if (array.size() <= k) {
      // All implicit P arrays together stay within kMaxArrayElements, so memory is bounded
      // however many P<n>[i] a program writes (decision, docs/interp.md "Variables").
      const std::size_t growth = k + 1 - array.size();
      if (p_array_elements_ + growth > kMaxArrayElements) {
        error = {"20400", "P parameter index " + describe(ref) + ": P arrays hold at most " +
                              std::to_string(kMaxArrayElements) + " elements in all"};
        return false;
      }
      p_array_elements_ += growth;
      array.resize(k + 1, 0.0);
    }
    array[k] = value;
    return true;
  }
  if (ref.cls == VarClass::v_g && ref.name == "KIN.PARAM") {
    error = {"NC1002", "not supported: writing " + describe(ref) +
                           ": ncsim builds the kinematic from the channel list's "
                           "trafo[j].param[k] (P-CHAN-00263); set it there"};
    return false;
  }
  Variable* v = find(ref);
  if (v == nullptr) {
    if (ref.cls == VarClass::v_l || ref.cls == VarClass::v_other || ref.cls == VarClass::none ||
        ref.index_count > 0) {
      error = {"NC4011", "unknown variable " + describe(ref) + " (declare it with #VAR)"};
      return false;
    }
    Map* map = map_for(ref.cls);
    Variable created;
    created.values.push_back(value);
    (*map)[ref.name] = std::move(created);
    return true;
  }
  if (v->is_string()) {
    error = {"NC4014", describe(ref) + " is a STRING, a number cannot be assigned"};
    return false;
  }
  auto at = element(*v, ref);
  if (!at) {
    error = {"NC4015", "index out of range: " + describe(ref)};
    return false;
  }
  auto converted = convert(v->type, value);
  if (!converted) {
    error = {"NC4013", "value " + core::number_text(value) + " out of range for " + describe(ref)};
    return false;
  }
  v->values[*at] = *converted;
  return true;
}

bool Variables::write_string(const VarRef& ref, std::string value, VarError& error) {
  Variable* v = find(ref);
  if (v == nullptr && ref.index_count == 0 &&
      (ref.cls == VarClass::v_e || ref.cls == VarClass::v_p || ref.cls == VarClass::v_s)) {
    // A text written to an undeclared V.E. (V.P., V.S.) variable creates a STRING of the
    // longest length, as a number written creates a REAL (docs/interp.md "Strings"): the PLC's
    // declaration of V.E. types is not part of ncsim's model.
    Variable created;
    created.type = grammar::ast::VarType::string;
    Map* map = map_for(ref.cls);
    v = &((*map)[ref.name] = std::move(created));
  }
  if (v == nullptr || !v->is_string()) {
    error = {"NC4014", describe(ref) + " is not a STRING variable"};
    return false;
  }
  if (value.size() > v->max_length) {
    error = {"NC4014", "a text of " + std::to_string(value.size()) + " characters is longer than " +
                           describe(ref) + " holds (STRING[" + std::to_string(v->max_length) +
                           "])"};
    return false;
  }
  v->text = std::move(value);
  return true;
}

bool Variables::declare(const VarRef& ref, Variable variable, VarError& error) {
  Map* map = map_for(ref.cls);
  if (map == nullptr || ref.cls == VarClass::v_e || ref.cls == VarClass::v_g) {
    error = {"20908",
             "only V.P., V.L., V.S. and V.CYC. variables can be declared: " + describe(ref)};
    return false;
  }
  if (ref.cls == VarClass::v_s && map->count(ref.name) != 0) return true;  // persists
  (*map)[ref.name] = std::move(variable);
  return true;
}

bool Variables::exists(const VarRef& ref) const {
  if (ref.cls == VarClass::at_p) {  // EXIST[@P3]: whether the cycle call programmed it
    if (cycle_params_.empty() || !cycle_params_.back()) return false;
    const auto& values = cycle_params_.back()->values;
    return ref.number >= 1 && ref.number <= values.size() && values[ref.number - 1].has_value();
  }
  if (ref.cls == VarClass::p) {
    if (ref.index_count == 0) return ref.number < p_set_.size() && p_set_[ref.number] != 0;
    return p_arrays_.count(ref.number) != 0;
  }
  return find(ref) != nullptr;
}

std::optional<std::uint32_t> Variables::size_of(const VarRef& ref) const {
  if (ref.cls == VarClass::p) {
    auto found = p_arrays_.find(ref.number);
    if (found != p_arrays_.end()) return static_cast<std::uint32_t>(found->second.size());
    return exists(ref) ? std::optional<std::uint32_t>(1) : std::nullopt;
  }
  const Variable* v = find(ref);
  if (v == nullptr) return std::nullopt;
  return v->dims.empty() ? 1u : v->dims[0];
}

bool Variables::remove(const VarRef& ref) {
  Map* map = map_for(ref.cls);
  return map != nullptr && map->erase(ref.name) != 0;
}

const std::string* Variables::macro(std::string_view name) const {
  auto found = macros_.find(name);
  return found == macros_.end() ? nullptr : &found->second;
}

namespace {

// splitmix64 finaliser: a well-mixed 64-bit hash of one word.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
std::uint64_t mix(std::uint64_t seed, std::uint64_t x) {
  return mix(seed ^ mix(x));
}
std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
std::uint64_t text_hash(std::string_view text) {
  std::uint64_t h = mix(text.size());
  for (const char c : text)
    h = mix(h, static_cast<unsigned char>(c));
  return h;
}
std::uint64_t variable_hash(const Variable& v, std::size_t& visited) {
  std::uint64_t h = mix(static_cast<std::uint64_t>(v.type));
  for (const std::uint32_t d : v.dims)
    h = mix(h, d);
  for (const double x : v.values)
    h = mix(h, bits(x));
  visited += v.values.size() + 1;
  return mix(h, text_hash(v.text));
}
// Order-independent: the sum of the entries' hashes.
template <typename Map>
std::uint64_t map_hash(const Map& map, std::uint64_t salt, std::size_t& visited) {
  std::uint64_t sum = mix(salt, map.size());
  for (const auto& [name, v] : map)
    sum += mix(text_hash(name), variable_hash(v, visited));
  return sum;
}

}  // namespace

std::uint64_t Variables::fingerprint(std::size_t& visited) const {
  visited = p_values_.size();
  std::uint64_t h = mix(p_values_.size());
  for (std::size_t i = 0; i < p_values_.size(); ++i) {
    if (p_set_[i] != 0) h = mix(h, mix(i, bits(p_values_[i])));
  }
  std::uint64_t arrays = 0;
  for (const auto& [number, values] : p_arrays_) {
    std::uint64_t a = mix(number);
    for (const double x : values)
      a = mix(a, bits(x));
    visited += values.size();
    arrays += a;
  }
  h = mix(h, arrays);
  h = mix(h, map_hash(v_p_, 1, visited));
  h = mix(h, map_hash(v_e_, 2, visited));
  h = mix(h, map_hash(v_g_, 3, visited));
  h = mix(h, map_hash(v_cyc_, 4, visited));
  h = mix(h, map_hash(persistent_->values, 5, visited));
  for (const Map& level : locals_)
    h = mix(h, map_hash(level, 6, visited));
  for (const auto& level : cycle_params_) {
    std::uint64_t c = mix(level ? 7 : 8);
    if (level) {
      for (const auto& v : level->values)
        c = mix(c, v ? bits(*v) : 9);
      visited += level->values.size();
    }
    h = mix(h, c);
  }
  for (const auto& [name, text] : macros_)
    h = mix(h, mix(text_hash(name), text_hash(text)));
  visited += macros_.size();
  return h;
}

}  // namespace ncsim::interp
