#pragma once
// interp/offsets: what shifts, scales or limits the programmed path without being a motion of
// its own: zero offsets G53..G59 / G159=n and V.G.NP[i].V.<axis> (TF5200 PROG-206487307,
// P-ZERO), #PSET (PROG-207101835), #SCALE (PROG-207656459), #MCS ON/OFF (PROG-208517515),
// #HSC and #VECTOR LIMIT (PROG-207477899); docs/interp.md "Offsets, scaling and path limits".
//
// Input: the G codes and # commands above. Output: the offset and the scale factor of each
// axis (zero_offset, scale_of) that the motion applies to its axis words, the arc scaling,
// the path velocity cap and the G26x state #HSC replaces. Program errors through the decoder.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

class Offsets {
 public:
  explicit Offsets(Interpreter::Impl& decoder) : ip_(decoder) {}

  /// Zero-offset groups np_grp[0..96] (P-ZERO-00002's range).
  static constexpr std::size_t kZeroGroups = 97;

  void init_zero_offsets();                     // V.G.NP[i].V.<axis> from the machine
  double zero_offset(std::uint8_t axis) const;  // the active offset of `axis` [mm | deg]
  /// What an absolute value of `axis` is shifted by: zero_offset(), except X/Y/Z while the
  /// #CS chain carries their offsets as its base (0 then).
  double axis_offset(std::uint8_t axis) const;
  /// Under #CS (no #TRAFO, not synchronised) the X/Y/Z zero offsets are the chain's base.
  bool cs_carries_offsets() const;
  /// The X/Y/Z zero offsets [mm] a #CS selection puts below the chain (0 where it cannot).
  std::array<double, 3> cs_base() const;
  /// Before a motion or a #CS command: when the X/Y/Z offsets changed below an active chain
  /// (G54.., V.G.NP[i]), the stack takes the new base, the position is re-based (the tool
  /// stays, its coordinates change) and the adapter follows (SelectCs CsOp::base).
  void follow_cs_base();
  double scale_of(std::uint8_t axis) const;  // its #SCALE factor (1 when off)
  bool select_zero_offset(const grammar::ast::Block& b,
                          const grammar::ast::Word& w);  // G53..G59, G159=n
  /// NC4102 at the axis word when an axis whose absolute value the block programs (`used`:
  /// targets, G161 centres) has a zero offset under #TRAFO or #SYNC IN (docs/interp.md).
  bool check_offsets_frame(const grammar::ast::Block& b, AxisMask used);
  bool hash_scale(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  bool hash_mcs(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  bool hash_hsc(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  bool hash_vector_limit(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  bool hash_pset(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  /// #SCALE on an arc: I/J/K and R scaled by the plane's factor, which must be the same for
  /// both plane axes (NC4312; an arc does not scale into an ellipse).
  bool scale_arc(const grammar::ast::Block& b, std::array<std::optional<double>, 3>& ijk,
                 std::optional<double>& radius);

  std::size_t zero_group = 0;                    // G53..G59 / G159=n: the active group
  std::array<std::string, kMaxAxes> zero_names;  // "NP.V.X": each axis's V.G. offset array
  bool mcs_on = false;                           // #MCS ON: the zero offsets are off
  bool scale_on = false;                         // #SCALE ON
  std::array<double, kMaxAxes> scale_factors{};  // #SCALE factors by machine index
  std::optional<std::pair<bool, ContourParams>> hsc_saved;  // #HSC ON: G26x state replaced
  std::optional<double> vector_vel;             // #VECTOR LIMIT ON [VEL]: path velocity cap [mm/s]
  std::array<double, kMaxAxes> pset_offsets{};  // #PSET: program = machine - zero - this [mm]

 private:
  /// An `X<value>` item of #SCALE / #PSET: its machine axis and value (NC4103 for an axis the
  /// machine does not have).
  std::optional<double> axis_item(const grammar::ast::Block& b, const grammar::ast::Item& it,
                                  const char* command, std::uint8_t& axis);

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
