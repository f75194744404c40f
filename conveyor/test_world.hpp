#pragma once
// conveyor/test_world: machines and scenarios the conveyor tests build in memory (test-only).

#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor::test {

/// X and a conveyor spindle S (machine index 1): v_max 1000 mm/s, A 2000 mm/s^2, J 750000
/// mm/s^3 (the seed's MC_MoveVelocity values), filters off, delay time 0, probing input 1,
/// edge POS. `encoder`: ACHSMODE_COUNTER.
inline machines::Machine machine(bool encoder, const char* signal = "DRIVE_TYPE_DEFAULT") {
  machines::Machine m;
  m.name = "conveyor_test";
  machines::AxisParams x;
  x.name = "X";
  x.number = 1;
  m.axes.push_back(x);
  machines::AxisParams s;
  s.name = "S";
  s.number = 4;
  s.kind = machines::AxisKind::spindle;
  s.encoder_only = encoder;
  s.measure_signal = signal;
  s.measure_input = 1;
  s.measure_edge = "POS";
  machines::Dynamics& d = s.dynamics;
  d.v_max = 1000.0;
  d.acc_max = d.acc_feed = d.dec_feed = 2000.0;
  d.ramp_acc_up = d.ramp_acc_down = d.ramp_dec_up = d.ramp_dec_down = 2000.0 / 750000.0;
  s.conveyor = machines::ConveyorAxisParams{};
  m.axes.push_back(s);
  m.channel.conveyor = machines::ConveyorSyncChannel{};
  m.channel.conveyor->master_axis_number = 4;
  return m;
}

/// A scenario with an encoder belt at v0 [mm/s] (or a spindle belt) and nothing else.
inline scenario::Scenario belt(scenario::ConveyorMode mode, double v0 = 0.0) {
  scenario::Scenario s;
  s.conveyor = scenario::Conveyor{};
  s.conveyor->mode = mode;
  s.conveyor->velocity = v0;
  return s;
}

}  // namespace ncsim::conveyor::test
