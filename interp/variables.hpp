#pragma once
// interp/variables: the variable store of one interpreter run (isg-language.md §3.4-3.7).
//
// Purpose: P parameters, V.P. (program global), V.L. (one scope per subroutine level, inner
// declarations shadow outer ones), V.S. (persistent: kept in a PersistentVariables object the
// caller owns, so values survive several runs in one invocation), V.E. (external values given
// by the caller), V.G. and V.CYC. (stored by name), and string macros.
// Inputs: resolved references (class, number or name, indices). Outputs: values or errors.
// Invariants: names are stored upper-case without the class prefix ("V.P.TABLE" -> "TABLE");
// arrays are 0-based, at most 4 dimensions; P numbers are 1..kMaxPNumber (error 20400
// otherwise, PROG-206872331); memory grows only with the number of distinct variables.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "grammar/ast.hpp"

namespace ncsim::interp {

/// Highest P parameter number (ncsim decision, docs/interp.md "Variables").
inline constexpr std::uint32_t kMaxPNumber = 100000;
/// Highest index of an implicitly created P array (ncsim decision).
inline constexpr std::uint32_t kMaxPArrayIndex = 100000;
/// Most elements of one declared array, all dimensions together (ncsim decision, NC4015), and
/// of all implicitly created P arrays together (20400).
inline constexpr std::size_t kMaxArrayElements = 1'000'000;

/// STRING[1..126] (isg-language.md §3.5): the longest declared string; also the limit of a
/// STRING declared without a length.
inline constexpr std::uint32_t kMaxStringLength = 126;

struct Variable {
  grammar::ast::VarType type = grammar::ast::VarType::real64;
  std::vector<std::uint32_t> dims;              ///< empty: scalar
  std::vector<double> values;                   ///< row-major
  std::string text;                             ///< STRING value
  std::uint32_t max_length = kMaxStringLength;  ///< STRING[n]: at most n characters
  bool is_string() const { return type == grammar::ast::VarType::string; }
};

/// V.S. variables that outlive one Interpreter (isg-language.md §3.5, PROG-207973899).
struct PersistentVariables {
  std::unordered_map<std::string, Variable> values;
};

/// A variable reference with its indices evaluated.
struct VarRef {
  grammar::ast::VarClass cls = grammar::ast::VarClass::none;
  std::uint32_t number = 0;  ///< P number
  std::string name;          ///< V. name, upper case, without class prefix
  std::uint32_t index_count = 0;
  std::array<double, 4> index{};
};

/// A failed access: the ncsim or manual id and a message (the caller adds the location).
struct VarError {
  std::string id;
  std::string message;
};

class Variables {
 public:
  Variables(PersistentVariables* persistent, std::map<std::string, double> external);

  /// Reads a number. Never-written P parameters and unknown V. variables are errors.
  std::optional<double> read(const VarRef& ref, VarError& error) const;
  /// Reads a string variable (nullptr if `ref` is not one).
  const std::string* read_string(const VarRef& ref) const;
  /// Writes a number (creates P, V.P., V.S., V.E., V.G., V.CYC. on first write).
  bool write(const VarRef& ref, double value, VarError& error);
  bool write_string(const VarRef& ref, std::string value, VarError& error);
  /// #VAR declaration in the current level (V.L.) or globally (V.P., V.S., V.CYC.).
  bool declare(const VarRef& ref, Variable variable, VarError& error);
  bool exists(const VarRef& ref) const;
  /// A V.G. variable the kernel provides (V.G.NP[i].V.X, the zero-offset table), created with
  /// its values; upper-case `name` without the class prefix and indices ("NP.V.X").
  void provide_global(const std::string& name, Variable variable) {
    v_g_[name] = std::move(variable);
  }
  /// The value of element `index` of a provided V.G. array, 0 when absent.
  double global_element(const std::string& name, std::size_t index) const {
    auto it = v_g_.find(name);
    if (it == v_g_.end() || index >= it->second.values.size()) return 0.0;
    return it->second.values[index];
  }
  /// Elements in the first dimension (1 for a scalar); nullopt if unknown.
  std::optional<std::uint32_t> size_of(const VarRef& ref) const;
  bool remove(const VarRef& ref);

  void push_level() {
    locals_.emplace_back();
    cycle_params_.emplace_back();
  }
  void pop_level() {
    if (!locals_.empty()) locals_.pop_back();
    if (!cycle_params_.empty()) cycle_params_.pop_back();
  }
  /// The current level is a cycle (L CYCLE, G80-G89, G800-G839) with these transfer
  /// parameters: [k] is @P(k+1), nullopt where the call left a gap (PROG-206859019).
  void set_cycle_params(std::vector<std::optional<double>> params) {
    if (!cycle_params_.empty()) cycle_params_.back() = CycleParams{std::move(params)};
  }
  /// P-CHAN-00463 create_cycle_param_on_read: reading a @P the call did not program creates it
  /// with 0 (true, the manual's default) or is error 20394 (false).
  void create_cycle_param_on_read(bool on) { create_cycle_param_on_read_ = on; }
  std::size_t level_count() const { return locals_.size(); }

  void define_macro(std::string name, std::string text) {
    macros_[std::move(name)] = std::move(text);
  }
  const std::string* macro(std::string_view name) const;

  std::size_t p_count() const { return p_values_.size(); }

  // The program's own V.E. writes for the run time's shared store
  // (docs/scenario.md "The program's V.E. writes").
  /// Starts (or stops) recording the program's scalar V.E. writes; off by default.
  void record_ve_writes(bool on) { record_ve_ = on; }
  /// A program assignment wrote `ref`: recorded (its stored value, the last per name) when on.
  void note_ve_write(const VarRef& ref);
  /// The recorded writes since the last call, by name; clears them. Bounded by the number of
  /// V.E. names the program writes.
  std::map<std::string, double> take_ve_writes() { return std::exchange(ve_written_, {}); }

  /// A 64-bit hash of every value, name, type, scope and macro the store holds (equal stores
  /// give equal hashes; the order maps are iterated in does not matter). `visited` is set to
  /// the number of values hashed, the cost of the call.
  std::uint64_t fingerprint(std::size_t& visited) const;

 private:
  using Map = std::unordered_map<std::string, Variable>;
  const Variable* find(const VarRef& ref) const;
  Variable* find(const VarRef& ref);
  Map* map_for(grammar::ast::VarClass cls);

  std::vector<double> p_values_;  // index = P number
  std::vector<std::uint8_t> p_set_;
  std::unordered_map<std::uint32_t, std::vector<double>> p_arrays_;
  std::size_t p_array_elements_ = 0;  // elements of all p_arrays_ together
  Map v_p_, v_e_, v_g_, v_cyc_;
  PersistentVariables own_persistent_;
  PersistentVariables* persistent_;
  std::vector<Map> locals_;  // one per program level; back() is the current one
  struct CycleParams {
    std::vector<std::optional<double>> values;  // [k]: @P(k+1)
  };
  // One per program level, beside locals_: set for a cycle's level, empty elsewhere.
  std::vector<std::optional<CycleParams>> cycle_params_;
  bool create_cycle_param_on_read_ = true;
  std::optional<double>* cycle_param(const VarRef& ref, bool create, VarError& error);
  std::map<std::string, std::string, std::less<>> macros_;
  bool record_ve_ = false;
  std::map<std::string, double> ve_written_;
};

}  // namespace ncsim::interp
