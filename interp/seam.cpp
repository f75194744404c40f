// interp/seam.cpp: the run-time half of the seam (interp/seam.hpp). Which blocks need run-time
// state (a Barrier before them), how the run time's answer (RunState) enters the interpreter, and
// the decode-only answer `check` and `trace` use (docs/interp.md "The seam").
#include "interp/seam.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

using ast::HashKind;

/// "V.E.PART[2]" -> "PART" (the key of Options::external).
std::string external_name(std::string_view text) {
  std::string out;
  std::size_t k = text.size() > 4 ? 4 : text.size();
  for (; k < text.size() && text[k] != '['; ++k)
    out.push_back(grammar::ascii_upper(text[k]));
  return out;
}

/// V.E. names in a string macro's text ("P1 = V.E.PART" -> PART): the macro's reads.
void external_names_in(std::string_view text, std::vector<std::string>& names) {
  for (std::size_t k = 0; k + 4 <= text.size(); ++k) {
    if (!grammar::iequals(text.substr(k, 4), "V.E.")) continue;
    std::size_t e = k + 4;
    while (e < text.size() && (std::isalnum(static_cast<unsigned char>(text[e])) != 0 ||
                               text[e] == '_' || text[e] == '.')) {
      ++e;
    }
    std::string name = external_name(text.substr(k, e - k));
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
      names.push_back(std::move(name));
    }
    k = e;
  }
}

/// Blocks whose decoding reads the current position: motions, re-basing commands, INDP moves.
bool uses_position(const ast::Block& b) {
  if (const auto* h = std::get_if<ast::HashCommand>(&b.body)) {
    switch (h->kind) {
      case HashKind::cs_on:
      case HashKind::cs_off:
      case HashKind::cs_off_all:
      case HashKind::trafo_on:
      case HashKind::trafo_off:
      case HashKind::sync_in:
      case HashKind::sync_out:
      case HashKind::sync_off:
      case HashKind::spline_on:
        return true;
      default:
        return false;
    }
  }
  if (!std::holds_alternative<ast::Words>(b.body)) return false;
  if (!b.axis_commands.empty()) return true;
  for (const ast::Word& w : b.words) {  // G92 sets the position of its axes: it needs none
    if (w.kind == ast::WordKind::g && w.code == 92) return false;
  }
  for (const ast::Word& w : b.words) {
    switch (w.kind) {
      case ast::WordKind::axis:
      case ast::WordKind::i:
      case ast::WordKind::j:
      case ast::WordKind::k:
      case ast::WordKind::r:
        return true;
      case ast::WordKind::g:
        if (w.code == 151) return true;  // #SPLINE ON: the position is the first vertex
        break;
      default:
        break;
    }
  }
  return false;
}

}  // namespace

bool Seam::barrier_before(const ast::Block& b) {
  if (ip_.resumed) {  // the barrier before this block was answered
    ip_.resumed = false;
    return false;
  }
  // The common case first, without building anything: no V.E. node, no #SYNC IN, no position
  // pending (this runs for every block; check's throughput depends on it).
  const auto* h = std::get_if<ast::HashCommand>(&b.body);
  const bool sync_in = h != nullptr && h->kind == HashKind::sync_in && !ip_.modal.synchronised;
  const AxisMask position_needed = ip_.unknown_axes != 0 ? position_needs(b) : 0;
  const bool external = may_read_external(b) &&
                        std::any_of(b.exprs.begin(), b.exprs.end(), [&](const ast::ExprNode& e) {
                          return (e.op == ast::Op::variable && e.var_class == ast::VarClass::v_e) ||
                                 (e.op == ast::Op::string && ip_.vars.macro(e.text) != nullptr);
                        });
  const bool signal =
      h != nullptr && (h->kind == HashKind::wait_signal || h->kind == HashKind::signal_read);
  if (!sync_in && position_needed == 0 && !external && !signal) return false;
  return emit_barrier(b, sync_in, position_needed);
}

bool Seam::emit_barrier(const ast::Block& b, bool sync_in, AxisMask position_needed) {
  Barrier barrier;
  if (const auto* h = std::get_if<ast::HashCommand>(&b.body)) {
    // #WAIT / #SIGNAL READ at decoder level (docs/lines.md): the decoder stops before the
    // block until the run time has the signal (a faulty block asks nothing: it reports).
    if (h->kind == HashKind::wait_signal || h->kind == HashKind::signal_read) {
      barrier.signal = ip_.hash.signal_wait(b, *h);
      if (barrier.signal) barrier.needs |= static_cast<std::uint8_t>(BarrierNeed::signal);
    }
  }
  // V.E. reads, not the targets of plain assignments (a write needs no run-time value).
  std::vector<ast::NodeIndex> written;
  for (const ast::Word& w : b.words) {
    if (w.kind == ast::WordKind::assignment && w.assign == ast::AssignOp::set) {
      written.push_back(w.target);
    }
  }
  for (std::size_t n = 0; n < b.exprs.size(); ++n) {
    const ast::ExprNode& e = b.exprs[n];
    if (e.op != ast::Op::variable || e.var_class != ast::VarClass::v_e) continue;
    if (std::find(written.begin(), written.end(), n) != written.end()) continue;
    std::string name = external_name(e.text);
    if (std::find(barrier.external.begin(), barrier.external.end(), name) ==
        barrier.external.end()) {
      barrier.external.push_back(std::move(name));
    }
  }
  for (const ast::ExprNode& e : b.exprs) {  // reads hidden in a string macro's text
    if (e.op != ast::Op::string) continue;
    if (const std::string* text = ip_.vars.macro(e.text))
      external_names_in(*text, barrier.external);
  }
  if (!barrier.external.empty()) barrier.needs |= static_cast<std::uint8_t>(BarrierNeed::external);
  if (sync_in) {
    const auto* h = std::get_if<ast::HashCommand>(&b.body);
    // #SYNC IN waits for the measured value (seed 004 §3): the conveyor's latched position.
    std::optional<std::uint8_t> conveyor;
    for (std::uint32_t k = 0; k < h->item_count && k < b.items.size(); ++k) {
      if (grammar::iequals(b.items[k].keyword, "CONVEYOR"))
        conveyor = ip_.axis_index(b.items[k].text);
    }
    if (!conveyor) {
      if (const auto* a = ip_.machine.conveyor_axis()) conveyor = ip_.axis_index(a->name);
    }
    if (conveyor) {  // else #SYNC IN itself reports the missing conveyor
      barrier.needs |= static_cast<std::uint8_t>(BarrierNeed::probe_latch);
      barrier.probe = conveyor;
    }
  }
  if (position_needed != 0) {
    barrier.needs |= static_cast<std::uint8_t>(BarrierNeed::position);
    barrier.axes = position_needed;
    barrier.frame = ip_.frames.frame();
  }
  if (barrier.needs == 0) return false;
  ip_.current_file = ip_.pc.file;
  ip_.emit(b.loc.line, std::move(barrier));
  return true;
}

bool Seam::may_read_external(const ast::Block& b) {
  // A block is identified by its file and byte offset: a loop body decodes the same blocks
  // again and again, so their scan is remembered (a direct-mapped table, bounded).
  const std::uint64_t key = ((std::uint64_t{ip_.pc.file} << 48) ^ b.offset) + 1;  // 0: empty
  ExternalScan& memo = external_scans_[(key * 0x9E3779B97F4A7C15ull) >> 56];
  if (memo.key == key) return memo.may_read;
  memo.key = key;
  memo.may_read = std::any_of(b.exprs.begin(), b.exprs.end(), [](const ast::ExprNode& e) {
    return (e.op == ast::Op::variable && e.var_class == ast::VarClass::v_e) ||
           e.op == ast::Op::string;
  });
  return memo.may_read;
}

AxisMask Seam::position_needs(const ast::Block& b) const {
  if (!uses_position(b)) return 0;
  const bool moves = std::any_of(b.words.begin(), b.words.end(), [](const ast::Word& w) {
    return w.kind == ast::WordKind::axis || w.kind == ast::WordKind::i ||
           w.kind == ast::WordKind::j || w.kind == ast::WordKind::k || w.kind == ast::WordKind::r ||
           (w.kind == ast::WordKind::g && w.code == 151);
  });
  if (!std::holds_alternative<ast::Words>(b.body)) return ip_.unknown_axes;
  if (moves) {
    // An axis an INDP motion made unknown is asked for only by a block that names it
    // (isg-language.md 6.1: INDP_ASYN is synchronised by #WAIT INDP or by programming the axis
    // again as a path axis); a block with I / J / K / R or #SPLINE ON asks for every one.
    AxisMask named = 0;
    for (const ast::Word& w : b.words) {
      switch (w.kind) {
        case ast::WordKind::axis:
          if (auto axis = ip_.axis_index(w.name)) named |= AxisMask{1} << *axis;
          break;
        case ast::WordKind::i:
        case ast::WordKind::j:
        case ast::WordKind::k:
        case ast::WordKind::r:
          return ip_.unknown_axes;
        case ast::WordKind::g:
          if (w.code == 151) return ip_.unknown_axes;
          break;
        default:
          break;
      }
    }
    return (ip_.unknown_axes & ~ip_.indp_unknown) | (ip_.indp_unknown & named);
  }
  // Only axis-bracket commands: an INDP move needs the position of its own axis only.
  AxisMask mask = 0;
  for (const ast::AxisCommand& ac : b.axis_commands) {
    if (ac.kind != ast::AxisCommandKind::indp_syn && ac.kind != ast::AxisCommandKind::indp_asyn) {
      continue;
    }
    if (auto axis = ip_.axis_index(ac.axis)) mask |= AxisMask{1} << *axis;
  }
  return mask & ip_.unknown_axes;
}

void Seam::apply(const RunState& state, const Barrier& barrier) {
  if (barrier.wants(BarrierNeed::external)) {
    for (const std::string& name : barrier.external) {
      auto it = state.external.find(name);
      if (it == state.external.end()) continue;  // not given: the value stays
      VarRef ref;
      ref.cls = ast::VarClass::v_e;
      ref.name = name;
      VarError err;
      ip_.vars.write(ref, it->second, err);  // a scalar V.E. write cannot fail
    }
  }
  if (barrier.wants(BarrierNeed::probe_latch)) ip_.latch = state.latch;
  if (barrier.wants(BarrierNeed::signal)) {
    ip_.signal_answer = state.signal;
    ip_.signal_decode_only = state.signal_decode_only;
  }
  if (barrier.wants(BarrierNeed::position)) {
    for (std::size_t i = 0; i < kMaxAxes; ++i) {
      if ((barrier.axes >> i) & 1u) ip_.position[i] = state.position[i];
    }
    ip_.unknown_axes &= ~barrier.axes;
    ip_.indp_unknown &= ip_.unknown_axes;
  }
  // A run-time answer is time passing (the channel drained its queue and waited), as motion
  // is: a loop that waits for a V.E. value the outside world writes is not "cannot end".
  ip_.blocks_without_motion = 0;
  ++ip_.world_waits;
  ip_.resumed = true;
}

RunState Seam::decode_only(const Barrier& barrier) const {
  RunState s;
  for (const std::string& name : barrier.external) {
    VarRef ref;
    ref.cls = ast::VarClass::v_e;
    ref.name = name;
    VarError err;
    if (auto v = ip_.vars.read(ref, err)) s.external[name] = *v;
  }
  s.latch = 0.0;
  // check / trace: a #WAIT gets its signal with every parameter 0, a #SIGNAL READ finds none
  // (V.G.SIGNAL_READ FALSE, the manual's default).
  if (barrier.signal) s.signal.received = !barrier.signal->read;
  s.signal_decode_only = true;
  s.frame = barrier.frame;
  s.position = ip_.position;  // programmed, re-based with the belt travel 0 (Frames::sync_rebased)
  return s;
}

void Interpreter::resume(const RunState& state) {
  if (!open_barrier_) {
    throw std::logic_error(
        "Interpreter::resume(): no barrier is open (resume() answers the "
        "Barrier command next() returned)");
  }
  const auto& barrier = std::get<Barrier>(open_barrier_->body);
  if (barrier.wants(BarrierNeed::position) && !(state.frame == barrier.frame)) {
    throw std::logic_error("Interpreter::resume(): the barrier at line " +
                           std::to_string(open_barrier_->line) + " wants positions in " +
                           frame_name(barrier.frame) + ", the state gives " +
                           frame_name(state.frame));
  }
  impl_->seam.apply(state, barrier);
  open_barrier_.reset();
}

RunState Interpreter::decode_only_state(const Barrier& barrier) const {
  return impl_->seam.decode_only(barrier);
}

std::optional<Command> Interpreter::next_decode_only() {
  auto c = next();
  if (c) {
    if (const auto* b = std::get_if<Barrier>(&c->body)) resume(decode_only_state(*b));
  }
  return c;
}

std::string frame_name(const CoordFrame& f) {
  std::string out = f.space == Space::pcs1 ? "PCS1" : (f.space == Space::pcs ? "PCS" : "MCS");
  if (f.cs_depth > 0) out += "/CS" + std::to_string(f.cs_depth);
  if (f.kinematics) out += "+KIN";
  return out;
}

}  // namespace ncsim::interp
