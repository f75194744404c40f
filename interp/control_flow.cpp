// interp/control_flow.cpp: $IF, $SWITCH, loops, $BREAK/$CONTINUE and $GOTO, one function per
// keyword group (interp/control_flow.hpp).
#include "interp/control_flow.hpp"

#include <algorithm>
#include <cmath>

#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

using ast::ControlKind;

bool is_opener(ControlKind k) {
  return k == ControlKind::for_ || k == ControlKind::while_ || k == ControlKind::do_ ||
         k == ControlKind::repeat || k == ControlKind::switch_;
}
bool is_closer(ControlKind k) {
  return k == ControlKind::endfor || k == ControlKind::endwhile || k == ControlKind::enddo ||
         k == ControlKind::until || k == ControlKind::endswitch;
}
bool is_loop(FrameKind k) {
  return k != FrameKind::switch_;
}
const ast::Control* control_of(const ast::Block* b) {
  return b == nullptr ? nullptr : std::get_if<ast::Control>(&b->body);
}
/// `$IF cond $GOTO label` has no $ENDIF (PROG-206915851).
bool is_block_if(const ast::Control& c) {
  return c.kind == ControlKind::if_ && c.target.kind == ast::GotoKind::none;
}

}  // namespace

bool ControlFlow::run(const ast::Block& b, const ast::Control& c) {
  // `b` and `c` live in the block cache: read them before any fetch (a search may evict them).
  const Site s{ip_.pc.ordinal - 1, ip_.pc.file, c.loc, b.loc.line};
  switch (c.kind) {
    case ControlKind::if_:
      return run_if(b, c, s);
    case ControlKind::elseif:
    case ControlKind::else_: {  // end of the branch taken: continue after $ENDIF
      auto k = next_if_branch(s.file, s.here + 1, true, s.at);
      if (!k) return false;
      ip_.pc.ordinal = *k + 1;
      return true;
    }
    case ControlKind::endif:
      return true;
    case ControlKind::switch_:
      return run_switch(b, c, s);
    case ControlKind::case_:
    case ControlKind::default_:
      return true;  // fall-through (decision, docs/interp.md)
    case ControlKind::endswitch:
      if (!frames_.empty() && frames_.back().kind == FrameKind::switch_) frames_.pop_back();
      return true;
    case ControlKind::for_:
      return run_for(b, c, s);
    case ControlKind::while_:
      return run_while(b, c, s);
    case ControlKind::do_:
      frames_.push_back({FrameKind::do_, s.file, s.here, 0xFFFFFFFFu, {}, 0, 0, s.line});
      return true;
    case ControlKind::repeat:
      frames_.push_back({FrameKind::repeat, s.file, s.here, 0xFFFFFFFFu, {}, 0, 0, s.line});
      return true;
    case ControlKind::endfor:
    case ControlKind::endwhile:
    case ControlKind::enddo:
    case ControlKind::until:
      return run_loop_end(b, c, s);
    case ControlKind::break_:
    case ControlKind::continue_:
      return run_break(c, s);
    case ControlKind::goto_:
      return jump_to_label(b, c.target);
  }
  return true;
}

bool ControlFlow::run_if(const ast::Block& b, const ast::Control& c, const Site& s) {
  auto v = ip_.eval(b, c.expr);
  if (!v) return false;
  if (!is_block_if(c)) {  // $IF cond $GOTO label
    return is_true(*v) ? jump_to_label(b, c.target) : true;
  }
  if (is_true(*v)) return true;
  std::uint32_t from = s.here + 1;
  for (;;) {
    auto k = next_if_branch(s.file, from, false, s.at);
    if (!k) return false;
    const ast::Block* nb = ip_.fetch({s.file, *k});
    const ast::Control* nc = control_of(nb);
    if (nc->kind == ControlKind::elseif) {
      auto cond = ip_.eval(*nb, nc->expr);
      if (!cond) return false;
      if (is_true(*cond)) {
        ip_.pc.ordinal = *k + 1;
        return true;
      }
      from = *k + 1;
      continue;
    }
    ip_.pc.ordinal = *k + 1;  // $ELSE or $ENDIF
    return true;
  }
}

bool ControlFlow::run_switch(const ast::Block& b, const ast::Control& c, const Site& s) {
  auto v = ip_.eval(b, c.expr);
  if (!v) return false;
  std::optional<std::uint32_t> default_at;
  int depth = 0;
  for (std::uint32_t k = s.here + 1;; ++k) {
    const ast::Block* nb = ip_.fetch({s.file, k});
    if (nb == nullptr || is_header(nb)) {
      return ip_.fail(s.at, "NC4020", "$SWITCH without $ENDSWITCH");
    }
    const ast::Control* nc = control_of(nb);
    if (nc == nullptr) continue;
    if (is_opener(nc->kind)) {
      ++depth;
    } else if (is_closer(nc->kind)) {
      if (depth > 0) {
        --depth;
        continue;
      }
      if (!default_at) {
        ip_.pc.ordinal = k + 1;  // no case matched, no $DEFAULT
        return true;
      }
      frames_.push_back({FrameKind::switch_, s.file, s.here, k, {}, 0, 0, s.line});
      ip_.pc.ordinal = *default_at + 1;
      return true;
    } else if (depth == 0 && nc->kind == ControlKind::case_) {
      auto cv = ip_.eval(*nb, nc->expr);
      if (!cv) return false;
      if (std::fabs(*cv - *v) < 0.001) {  // PROG-206908427
        frames_.push_back({FrameKind::switch_, s.file, s.here, 0xFFFFFFFFu, {}, 0, 0, s.line});
        ip_.pc.ordinal = k + 1;
        return true;
      }
    } else if (depth == 0 && nc->kind == ControlKind::default_) {
      default_at = k;
    }
  }
}

bool ControlFlow::run_for(const ast::Block& b, const ast::Control& c, const Site& s) {
  ControlFrame f{FrameKind::for_, s.file, s.here, 0xFFFFFFFFu, {}, 0, 0, s.line};
  if (!ip_.evaluator.resolve(b, c.counter, f.counter)) return ip_.fail_eval();
  auto start = ip_.eval(b, c.start);
  if (!start) return false;
  auto end = ip_.eval(b, c.end);
  if (!end) return false;
  std::optional<double> step = 1.0;
  if (c.step != ast::kNoNode) step = ip_.eval(b, c.step);
  if (!step) return false;
  f.end_value = *end;
  f.step = *step;
  VarError err;
  if (!ip_.vars.write(f.counter, *start, err)) return ip_.fail(s.at, err.id, err.message);
  if (f.step == 0.0) ip_.warn(s.at, "NC4024", "$FOR with step 0 loops forever (PROG-206929163)");
  const bool run = f.step > 0.0 ? *start <= *end : (f.step < 0.0 ? *start >= *end : true);
  if (!run) {
    auto k = matching_end(s.file, s.here + 1, s.at);
    if (!k) return false;
    ip_.pc.ordinal = *k + 1;
    return true;
  }
  frames_.push_back(std::move(f));
  return true;
}

bool ControlFlow::run_while(const ast::Block& b, const ast::Control& c, const Site& s) {
  auto v = ip_.eval(b, c.expr);
  if (!v) return false;
  const bool reentry = !frames_.empty() && frames_.back().open == s.here &&
                       frames_.back().file == s.file && frames_.back().kind == FrameKind::while_;
  if (is_true(*v)) {
    if (!reentry)
      frames_.push_back({FrameKind::while_, s.file, s.here, 0xFFFFFFFFu, {}, 0, 0, s.line});
    return true;
  }
  std::uint32_t end = 0;
  if (reentry && frames_.back().end != 0xFFFFFFFFu) {
    end = frames_.back().end;
  } else {
    auto k = matching_end(s.file, s.here + 1, s.at);
    if (!k) return false;
    end = *k;
  }
  if (reentry) frames_.pop_back();
  ip_.pc.ordinal = end + 1;
  return true;
}

bool ControlFlow::run_loop_end(const ast::Block& b, const ast::Control& c, const Site& s) {
  const FrameKind want = c.kind == ControlKind::endfor     ? FrameKind::for_
                         : c.kind == ControlKind::endwhile ? FrameKind::while_
                         : c.kind == ControlKind::enddo    ? FrameKind::do_
                                                           : FrameKind::repeat;
  if (frames_.size() <= level_base() || frames_.back().kind != want ||
      frames_.back().file != s.file) {
    return ip_.fail(s.at, c.kind == ControlKind::endwhile ? "20237" : "NC4025",
                    "loop end without a matching loop start");
  }
  ControlFrame& f = frames_.back();
  f.end = s.here;
  if (want == FrameKind::while_) {
    ip_.pc.ordinal = f.open;
    return true;
  }
  if (want == FrameKind::for_) {
    VarError err;
    auto value = ip_.vars.read(f.counter, err);
    if (!value || !ip_.vars.write(f.counter, *value + f.step, err)) {
      return ip_.fail(s.at, err.id, err.message);
    }
    const double v = *value + f.step;
    const bool run = f.step > 0.0 ? v <= f.end_value : (f.step < 0.0 ? v >= f.end_value : true);
    if (run) {
      ip_.pc.ordinal = f.open + 1;
    } else {
      frames_.pop_back();
    }
    return true;
  }
  auto v = ip_.eval(b, c.expr);
  if (!v) return false;
  const bool again = want == FrameKind::do_ ? is_true(*v) : !is_true(*v);
  if (again) {
    ip_.pc.ordinal = f.open + 1;
  } else {
    frames_.pop_back();
  }
  return true;
}

bool ControlFlow::run_break(const ast::Control& c, const Site& s) {
  const std::size_t base = level_base();
  const bool brk = c.kind == ControlKind::break_;
  for (;;) {
    if (frames_.size() <= base) {
      return ip_.fail(s.at, brk ? "20243" : "20244",
                      brk ? "$BREAK outside a loop or $SWITCH" : "$CONTINUE outside a loop");
    }
    ControlFrame& f = frames_.back();
    if (f.end == 0xFFFFFFFFu) {
      auto k = matching_end(s.file, ip_.pc.ordinal, s.at);
      if (!k) return false;
      f.end = *k;
    }
    if (brk) {
      ip_.pc.ordinal = f.end + 1;
      frames_.pop_back();
      return true;
    }
    if (!is_loop(f.kind)) {  // $CONTINUE inside a $SWITCH: leave the switch first
      ip_.pc.ordinal = f.end + 1;
      frames_.pop_back();
      continue;
    }
    ip_.pc.ordinal = f.end;  // the loop end block does the step / the test
    return true;
  }
}

std::size_t ControlFlow::level_base() const {
  return ip_.calls.empty() ? 0 : ip_.calls.back().control_depth;
}

std::optional<std::uint32_t> ControlFlow::matching_end(std::uint16_t file, std::uint32_t from,
                                                       core::SourceLoc at) {
  const std::uint64_t key = (std::uint64_t{file} << 33) | (std::uint64_t{1} << 32) | from;
  if (auto it = jump_memo_.find(key); it != jump_memo_.end()) return it->second;
  int depth = 0;
  for (std::uint32_t k = from;; ++k) {
    const ast::Block* b = ip_.fetch({file, k});
    if (b == nullptr || is_header(b)) {
      ip_.fail(at, "NC4020", "no matching end of this loop or $SWITCH in the same program level");
      return std::nullopt;
    }
    const ast::Control* c = control_of(b);
    if (c == nullptr) continue;
    if (is_opener(c->kind)) {
      ++depth;
    } else if (is_closer(c->kind)) {
      if (depth == 0) {
        remember(key, k);
        return k;
      }
      --depth;
    }
  }
}

std::optional<std::uint32_t> ControlFlow::next_if_branch(std::uint16_t file, std::uint32_t from,
                                                         bool endif_only, core::SourceLoc at) {
  const std::uint64_t key =
      (std::uint64_t{file} << 33) | (endif_only ? 0u : (std::uint64_t{1} << 31)) | from;
  if (auto it = jump_memo_.find(key); it != jump_memo_.end()) return it->second;
  int depth = 0;
  for (std::uint32_t k = from;; ++k) {
    const ast::Block* b = ip_.fetch({file, k});
    if (b == nullptr || is_header(b)) {
      ip_.fail(at, "NC4021", "$IF without $ENDIF in the same program level");
      return std::nullopt;
    }
    const ast::Control* c = control_of(b);
    if (c == nullptr) continue;
    if (is_block_if(*c)) {
      ++depth;
    } else if (c->kind == ControlKind::endif) {
      if (depth == 0) {
        remember(key, k);
        return k;
      }
      --depth;
    } else if (!endif_only && depth == 0 &&
               (c->kind == ControlKind::elseif || c->kind == ControlKind::else_)) {
      remember(key, k);
      return k;
    }
  }
}

void ControlFlow::remember(std::uint64_t key, std::uint32_t value) {
  if (jump_memo_.size() >= kMaxMemoEntries) jump_memo_.clear();  // bounded: rebuilt on demand
  jump_memo_[key] = value;
}

std::optional<GotoResult> ControlFlow::find_label(const GotoLabel& target, core::SourceLoc at) {
  const std::uint16_t file = ip_.pc.file;
  const std::uint32_t here = ip_.pc.ordinal;  // block after the $GOTO
  // Forward search to the end of the program level (PROG-206915851: both directions).
  GotoResult r;
  int depth = 0;
  for (std::uint32_t k = here;; ++k) {
    const ast::Block* blk = ip_.fetch({file, k});
    if (blk == nullptr || is_header(blk)) break;
    if (target.matches(*blk)) {
      if (depth > 0) {
        ip_.fail(at, "21480", "$GOTO jumps into a loop");
        return std::nullopt;
      }
      r.label = k;
      return r;
    }
    if (const ast::Control* c = control_of(blk)) {
      if (is_opener(c->kind)) ++depth;
      if (is_closer(c->kind)) {
        if (depth > 0) {
          --depth;
        } else {
          ++r.closed;
        }
      }
    }
  }
  // Backward: from the start of the program level up to the $GOTO.
  r = GotoResult{};
  r.backward = true;
  for (std::uint32_t k = ip_.unit_start; k < here; ++k) {
    const ast::Block* blk = ip_.fetch({file, k});
    if (blk == nullptr) break;
    if (k != ip_.unit_start && is_header(blk)) break;
    if (target.matches(*blk)) {
      r.label = k;
      return r;
    }
    if (const ast::Control* c = control_of(blk)) {
      if (is_opener(c->kind)) r.open.push_back(k);  // unmatched openers before the label
      if (is_closer(c->kind) && !r.open.empty()) r.open.pop_back();
    }
  }
  ip_.fail(at, "NC4023", "jump label " + target.name + " not found in this program level");
  return std::nullopt;
}

bool ControlFlow::jump_to_label(const ast::Block& b, const ast::GotoTarget& target) {
  // Copy what is needed of the $GOTO block now: the label search fetches blocks through the
  // cache, which may reuse the slot holding `b` (issue 9, defect 1).
  const core::SourceLoc at = target.loc.line != 0 ? target.loc : b.loc;
  if (target.kind == ast::GotoKind::variable || target.kind == ast::GotoKind::none) {
    return ip_.fail(at, "NC4022", "$GOTO to a variable target is not supported by ncsim");
  }
  const std::uint16_t file = ip_.pc.file;
  // The result depends only on the program text between the level start and the label, so it
  // is remembered per $GOTO site: a backward jump in a loop scans once, not every pass.
  const std::uint64_t key = (std::uint64_t{file} << 32) | ip_.pc.ordinal;
  auto it = goto_memo_.find(key);
  if (it == goto_memo_.end()) {
    const GotoLabel label{target.kind, target.number, std::string(target.name)};
    auto found = find_label(label, at);
    if (!found) return false;
    if (goto_memo_.size() >= kMaxMemoEntries) goto_memo_.clear();
    it = goto_memo_.emplace(key, std::move(*found)).first;
  }
  const GotoResult& r = it->second;
  if (!r.backward) {
    for (int i = 0; i < r.closed && !frames_.empty(); ++i)
      frames_.pop_back();
    ip_.pc.ordinal = r.label;
    return true;
  }
  const std::size_t base = level_base();
  for (std::uint32_t o : r.open) {
    const bool is_open =
        std::any_of(frames_.begin() + static_cast<std::ptrdiff_t>(base), frames_.end(),
                    [&](const ControlFrame& f) { return f.file == file && f.open == o; });
    if (!is_open) return ip_.fail(at, "21480", "$GOTO jumps into a loop");
  }
  while (frames_.size() > base && frames_.back().open >= r.label)
    frames_.pop_back();
  ip_.pc.ordinal = r.label;
  return true;
}

}  // namespace ncsim::interp
