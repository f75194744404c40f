#pragma once
// channel/channel_test_support: the sinks and the run loop the channel tests share (beside
// ipo/test_support.hpp, which stays free of the channel so that the interpolator's tests need
// only ncsim_ipo).

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "conveyor/port.hpp"
#include "core/source_file.hpp"
#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel::test {

/// Records what a channel's sink receives: every cycle, and how many joint reports.
struct Recorder final : ipo::Sink {
  std::vector<ipo::Cycle> cycles;
  std::size_t joints = 0;
  void on_joint(const ipo::Joint&) override { ++joints; }
  void on_cycle(const ipo::Cycle& c) override { cycles.push_back(c); }
};

/// The audit and a recorder behind one sink, as the CLI wires them: the audit sees the joints
/// and the cycles, the recorder the cycles.
struct AuditedRecorder final : ipo::Sink {
  audit::Audit* audit;
  Recorder* rec;
  AuditedRecorder(audit::Audit* a, Recorder* r) : audit(a), rec(r) {}
  void on_joint(const ipo::Joint& j) override { audit->on_joint(j); }
  void on_cycle(const ipo::Cycle& c) override {
    audit->on_cycle(c);
    rec->on_cycle(c);
  }
};

/// Steps `ch` until it stops running (at most `guard` steps); `after_step` runs after each
/// step that left it running. Returns the last status.
inline ipo::Status run_to_end(Channel& ch, const std::function<void()>& after_step = {},
                              int guard = 1'000'000) {
  ipo::Status status = ipo::Status::finished;
  for (int k = 0; k < guard; ++k) {
    status = ch.step();
    if (status != ipo::Status::running) break;
    if (after_step) after_step();
  }
  return status;
}

/// What a test reads back from an audited run: the end, every cycle, the error, the verdict.
struct AuditedRun {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::Cycle> cycles;
  std::optional<RunTimeError> error;
  audit::Verdict verdict;
};

/// Steps `ch` to its end (run_to_end) and collects what `rec` recorded and `audit` judged.
inline AuditedRun finish(Channel& ch, Recorder& rec, const audit::Audit& audit) {
  AuditedRun r;
  r.status = run_to_end(ch);
  r.cycles = std::move(rec.cycles);
  r.error = ch.run_time_error();
  r.verdict = audit.verdict();
  return r;
}

/// A program on a channel with a conveyor: the source file, the interpreter, the adapter and the
/// channel of machine `m` (which must outlive the rig), `port` attached (null: none). The
/// conveyor tests' common set-up; they step `ch` with run_to_end().
struct ConveyorRig {
  core::SourceFile file;
  interp::Interpreter in;
  program::ProgramSource src;
  Channel ch;
  ConveyorRig(const std::string& text, const machines::Machine& m, ChannelConfig config,
              conveyor::Port* port, ipo::Sink* sink = nullptr)
      : file("t.nc", text),
        in(file, m),
        src(in, m, program::SourceConfig{.t_cycle = config.path.channel.t_cycle}),
        ch(std::move(config), src, sink) {
    ch.attach_conveyor(port);
  }
};

/// A ConveyorRig audited on its setpoints as `ncsim time --audit` does (the audit and a
/// recorder behind one sink). After run_to_end(rig.ch), `audit.verdict()` judges the run.
struct AuditedConveyorRig {
  audit::Audit audit;
  Recorder rec;
  AuditedRecorder tee;
  ConveyorRig rig;
  AuditedConveyorRig(const std::string& text, const machines::Machine& m, ChannelConfig config,
                     conveyor::Port* port)
      : audit(config.path.axes, config.path.channel.t_cycle, config.path.start),
        tee(&audit, &rec),
        rig(text, m, std::move(config), port, &tee) {
    audit.set_setpoints(&rig.ch.setpoints());
  }
};

/// Prints `verdict`'s violations as test messages (they say where a failing check went wrong).
inline void message_violations(const audit::Verdict& verdict) {
  for (const audit::Violation& v : verdict.violations)
    MESSAGE("audit: axis " << int(v.axis) << " t " << v.t << " value " << v.value << " limit "
                           << v.limit);
}

/// What a program run on a conveyor channel gave: the axes after every cycle that left the
/// channel running, how it ended, and the adapter's (ProgramSource's) error if it had one.
struct ConveyorRun {
  ipo::Status status = ipo::Status::finished;
  std::vector<AxesState> axes;
  std::optional<RunTimeError> error;
  std::string source_error;  ///< the adapter's error id ("" none)
  std::string source_message;
  std::uint32_t source_line = 0;
};

/// Runs `program` on machine `m` (1 ms cycles) with `port` attached (null: none), at most
/// `guard` cycles.
inline ConveyorRun run_conveyor(const std::string& program, const machines::Machine& m,
                                conveyor::Port* port, int guard = 200'000) {
  ConveyorRig rig(program, m, channel_config(m, 0.001), port);
  ConveyorRun r;
  r.status = run_to_end(
      rig.ch, [&] { r.axes.push_back(rig.ch.axes()); }, guard);
  r.error = rig.ch.run_time_error();
  if (const core::Diagnostic* d = rig.src.error()) {
    r.source_error = d->id;
    r.source_message = d->message;
    r.source_line = d->loc.line;
  }
  return r;
}

}  // namespace ncsim::channel::test
