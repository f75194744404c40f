// interp/repeat_watch.cpp: the decoder state's fingerprint and Brent's cycle finding over it.
#include "interp/repeat_watch.hpp"

#include <cstring>
#include <string>

#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull + h;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
std::uint64_t bits(const std::optional<double>& v) {
  return v ? bits(*v) : 0x7FF4000000000001ull;  // a NaN payload no computation yields
}

}  // namespace

// Everything that decides what the following blocks do: where the decoder is, the open loops
// and calls, every variable, and the modal state motions and checks depend on. Two equal
// fingerprints at the same block mean the decoder runs the same way again from there.
std::uint64_t RepeatWatch::fingerprint(std::size_t& cost) const {
  const Interpreter::Impl& d = ip_;
  std::uint64_t h = d.vars.fingerprint(cost);
  h = mix(h, (std::uint64_t{d.pc.file} << 32) | d.pc.ordinal);
  h = mix(h, d.unit_start);
  for (const ControlFrame& f : d.flow.frames()) {
    h = mix(h, (static_cast<std::uint64_t>(f.kind) << 48) | (std::uint64_t{f.file} << 32) | f.open);
    h = mix(h, f.end);
    h = mix(h, (static_cast<std::uint64_t>(f.counter.cls) << 32) | f.counter.number);
    for (const char c : f.counter.name)
      h = mix(h, static_cast<unsigned char>(c));
    for (std::uint32_t i = 0; i < f.counter.index_count && i < f.counter.index.size(); ++i)
      h = mix(h, bits(f.counter.index[i]));
    h = mix(h, bits(f.end_value));
    h = mix(h, bits(f.step));
  }
  for (const CallFrame& f : d.calls) {
    h = mix(h, (std::uint64_t{f.ret.file} << 32) | f.ret.ordinal);
    h = mix(h, (std::uint64_t{f.unit_start} << 32) | f.control_depth);
  }
  for (const double v : d.position)
    h = mix(h, bits(v));
  h = mix(h, static_cast<std::uint64_t>(d.motion));
  h = mix(h, bits(d.feed));
  h = mix(h, (std::uint64_t{d.departure_pending} << 4) | (std::uint64_t{d.centre_absolute} << 3) |
                 (std::uint64_t{d.motion_since_sync} << 2) |
                 (std::uint64_t{d.spline.has_value()} << 1) | std::uint64_t{d.kin_id.has_value()});
  if (d.kin_id) h = mix(h, static_cast<std::uint64_t>(*d.kin_id));
  const ModalSnapshot& m = d.modal;
  h = mix(h, (static_cast<std::uint64_t>(m.plane) << 40) |
                 (static_cast<std::uint64_t>(m.feed_mode) << 32) |
                 (static_cast<std::uint64_t>(m.transition) << 24) |
                 (static_cast<std::uint64_t>(m.slope) << 16) | (std::uint64_t{m.inch} << 7) |
                 (std::uint64_t{m.incremental} << 6) | (std::uint64_t{m.exact_stop} << 5) |
                 (std::uint64_t{m.contouring} << 4) | (std::uint64_t{m.synchronised} << 3) |
                 (std::uint64_t{m.cs_active} << 2) | (std::uint64_t{m.kinematics_on} << 1) |
                 std::uint64_t{m.caxtrack});
  h = mix(h, bits(m.transvelmin));
  h = mix(h, (static_cast<std::uint64_t>(m.trc.side) << 16) |
                 (static_cast<std::uint64_t>(m.trc.corner) << 8) |
                 (static_cast<std::uint64_t>(m.trc.adapt_feed) << 4) |
                 static_cast<std::uint64_t>(m.trc.approach));
  h = mix(h, bits(m.trc.radius));
  h = mix(h, bits(m.trc.tangfeed_rmin));
  h = mix(h, bits(d.trc_words.d_number));
  h = mix(h, d.files.size());
  // offsets, scaling and path limits (offsets.cpp)
  h = mix(h, (std::uint64_t{d.offsets.zero_group} << 8) | (std::uint64_t{d.offsets.mcs_on} << 2) |
                 (std::uint64_t{d.offsets.scale_on} << 1) |
                 std::uint64_t{d.offsets.hsc_saved.has_value()});
  for (const double f : d.offsets.scale_factors)
    h = mix(h, bits(f));
  h = mix(h, bits(d.offsets.vector_vel));
  for (const auto& [code, name] : d.subs.file_names)
    h = mix(h, code);
  for (const auto& name : d.subs.word_files)
    h = mix(h, name.has_value());
  cost += d.flow.frames().size() + d.calls.size() + kMaxAxes;
  return h;
}

bool RepeatWatch::watch(std::uint32_t block_line) {
  ++decoded_;
  if (credit_ > 0) --credit_;
  const std::uint64_t pc = (std::uint64_t{ip_.pc.file} << 32) | ip_.pc.ordinal;
  if (pc == pc_ && credit_ == 0) {
    std::size_t cost = 0;
    const std::uint64_t now = fingerprint(cost);
    credit_ = cost / 16;
    if (now == fingerprint_) {
      // No motion or time since the saved state: the decoder would loop here forever.
      if (ip_.blocks_without_motion >= decoded_ - at_) {
        const std::uint32_t loop_line = ip_.flow.loop_line(line_);
        return ip_.fail({loop_line, 1}, "NC4901",
                        "endless loop without motion: the decoder returns to this block with the "
                        "same variables and state after " +
                            std::to_string(decoded_ - at_) + " blocks, so the program cannot end");
      }
      if (!endless_from_) {
        endless_from_ = line_;
        on_its_own_ = ip_.world_waits == world_at_;
      }
    }
  }
  if (decoded_ - at_ >= period_) {
    std::size_t cost = 0;
    pc_ = pc;
    line_ = block_line;
    fingerprint_ = fingerprint(cost);
    at_ = decoded_;
    world_at_ = ip_.world_waits;
    period_ *= 2;
    credit_ = cost / 16;
  }
  return true;
}

}  // namespace ncsim::interp
