// program/program_homing: G74 as the adapter sees it (--- static-saw, docs/homing.md). The homing
// itself is a channel event (channel/channel_homing.cpp) that stops the path; here only the
// decoder's view of the homed axes' positions: they stand wherever the channel left them (at
// P-AXIS-00152), so the next position barrier wanting them is answered from the channel's set
// positions (answer_positions), as after an INDP_ASYN motion.

#include "program/program_source.hpp"

namespace ncsim::ipo {

void ProgramSource::note_homing(const interp::CommandBody& body) noexcept {
  if (const auto* h = std::get_if<interp::Homing>(&body))
    for (const auto& [axis, order] : h->axes)
      indp_running_ |= interp::AxisMask{1} << axis;
}

}  // namespace ncsim::ipo
