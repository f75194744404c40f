#include "conveyor/probe_arming.hpp"

namespace ncsim::conveyor {

std::optional<PortError> probe_arm_error(const machines::ProbeArm& c, bool rising,
                                         const std::optional<ProbeArming>& active,
                                         std::uint8_t axis, const std::string& axis_name,
                                         int input) {
  if (active) {  // seed 004 §6.3.1: not retriggerable; the active command stays
    if (c.axis != active->axis) {
      return PortError{"P-ERR-44001",
                       "MC_TouchProbe on another axis while a measurement is active "
                       "(ERR_PO_AX_REF_CHG_WHILE_ACTIVE)"};
    }
    if (c.channel != active->channel) {
      return PortError{"P-ERR-44011", "MC_TouchProbe Channel=" + std::to_string(c.channel) +
                                          " while the measurement on channel " +
                                          std::to_string(active->channel) +
                                          " is active (ERR_PO_AX_INPREF_TPCH_CHW_ACTIVE)"};
    }
    if (rising != active->rising) {
      return PortError{"P-ERR-44012", std::string("MC_TouchProbe Mode changed to the ") +
                                          (rising ? "rising" : "falling") +
                                          " edge while a measurement is active "
                                          "(ERR_PO_AX_INPREF_TPMD_CHW_ACTIVE)"};
    }
    return PortError{"P-ERR-44009",
                     "MC_TouchProbe retriggered while its measurement is active "
                     "(ERR_PO_AX_TPROBE_RETRIG)"};
  }
  if (c.axis != axis) {
    return PortError{kNotConveyorId, "MC_TouchProbe on machine axis " + std::to_string(c.axis) +
                                         ": the sensor latches the conveyor axis " + axis_name};
  }
  if (c.channel != input) {
    return PortError{kProbeInputId, "MC_TouchProbe Channel=" + std::to_string(c.channel) +
                                        ": the sensor is wired to probing input " +
                                        std::to_string(input) + " of axis " + axis_name +
                                        " (P-AXIS-00517 kenngr.measure.input); no edge would "
                                        "ever come"};
  }
  return std::nullopt;
}

}  // namespace ncsim::conveyor
