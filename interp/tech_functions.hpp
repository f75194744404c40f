#pragma once
// interp/tech_functions: when a block's technology functions are output and how long the path
// waits for their acknowledgement (docs/interp.md "Technology functions").
//
// Inputs: the block's M / H / S / T / D functions in program order, the channel's TechTable
// (machines/machine.hpp: P-CHAN-00041 / 00027 / 00081 / 00086 and NCSIM-CHAN-650..653).
// Outputs: each function's sync set; the block's waits. Method (TF5200 "Synchronisation
// types"): MOS, MVS_SVS and MVS_SNS functions are output before the block's motion, MNS_SNS
// after it; MVS_SVS holds the motion until acknowledged (a wait before it), MNS_SNS waits after
// the motion, MVS_SNS stops the path at the block's end only for what is left of its time
// there. Functions of one block are acknowledged side by side: each wait is the longest of
// its functions'. D selects a tool offset inside the kernel: never output, no time.

#include <optional>
#include <vector>

#include "interp/command.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

/// The waits of one block [s]; nullopt: none (a 0 s wait still stops the path).
struct TechWaits {
  std::optional<double> before;  ///< MVS_SVS: before the block's motion
  std::optional<double> since;   ///< MVS_SNS: after the motion, counted from the output
  std::optional<double> after;   ///< MNS_SNS: after the motion, from their output there
};

/// Sets each function's `sync` from `table` and returns the block's waits.
TechWaits resolve_tech(std::vector<Tech>& functions, const machines::TechTable& table);

}  // namespace ncsim::interp
