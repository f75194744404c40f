// interp/interpreter_homing: what G74 may home, checked when the block is decoded (--- static-saw,
// docs/homing.md). The interpreter knows the modal couplings and the machine's axes, so a G74 it
// cannot run is a positioned program error before anything of its block is emitted.
// Inputs: the block's words (BlockWords), the modal state, the machine. Output: true, or the
// interpreter's error (fail) with the id below.
//   20137   G74 with an active coupling (isg-language.md l.148): #SYNC IN (the channel follows
//           the belt), #TRAFO ON (the axes are coupled by the kinematics), #CAXTRACK ON (C is
//           coupled to the path tangent).
//   NC9104  G74 of the conveyor axis or an encoder axis (ACHSMODE_COUNTER): its position is the
//           scenario's measured value; no program homes it.
//   NC9105  G74 S (spindle homing): not supported (no spindle model beyond the conveyor).
//   NC9106  G74 without an axis, or an order number that is not a whole number >= 1.

#include <cmath>
#include <string>

#include "core/number_text.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

bool Interpreter::Impl::check_homing(const ast::Block& b, const BlockWords& bw) {
  for (const Tech& t : bw.tech)
    if (t.kind == TechKind::s)
      return fail(b.loc, "NC9105",
                  "not supported: G74 S (homing a spindle); home the path axes only");
  const char* coupling = modal.synchronised    ? "#SYNC IN (the axes follow the conveyor)"
                         : modal.kinematics_on ? "#TRAFO ON (the kinematics couples the axes)"
                         : modal.caxtrack      ? "#CAXTRACK ON (C follows the path tangent)"
                                               : nullptr;
  if (coupling != nullptr)
    return fail(
        b.loc, "20137",
        std::string("G74 homing with an active coupling: ") + coupling + "; end it before homing");
  if (bw.axis_words.empty()) return fail(b.loc, "NC9106", "G74 without an axis to home");
  for (const auto& [axis, order] : bw.axis_words) {
    const machines::AxisParams& a = machine.axes[axis];
    if (a.encoder_only || a.conveyor.has_value())
      return fail(b.loc, "NC9104",
                  "G74 of axis " + a.name +
                      ": the conveyor or an encoder axis is not homed by the program (its "
                      "position is the scenario's measured value)");
    if (!(order >= 1.0) || order != std::floor(order) || order > 1e6)
      return fail(b.loc, "NC9106",
                  "G74: the order number of axis " + a.name +
                      " must be a whole number >= 1 (equal numbers home together), got " +
                      core::number_text(order));
  }
  return true;
}

}  // namespace ncsim::interp
