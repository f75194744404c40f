// interp/interpreter.cpp: the block stream, control flow ($IF ... $GOTO), subroutines.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/number_text.hpp"
#include "grammar/check.hpp"
#include "grammar/keywords.hpp"
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

/// A subroutine file name that stays in or below the program's folder: relative, no `..`
/// (Options::confine_subroutine_files).
bool is_confined_name(const std::string& name) {
  const std::filesystem::path p(name);
  if (p.has_root_path()) return false;
  return std::none_of(p.begin(), p.end(),
                      [](const std::filesystem::path& part) { return part == ".."; });
}

/// Why `path` cannot be a subroutine file (" not found", " is a directory", ...), or nothing.
std::optional<std::string> subroutine_file_problem(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return std::string(" not found");
  switch (st.type()) {
    case fs::file_type::regular:
      return std::nullopt;
    case fs::file_type::directory:
      return std::string(" is a directory, not a program file");
    case fs::file_type::character:
    case fs::file_type::block:
      return std::string(" is a device, not a program file");
    case fs::file_type::fifo:
      return std::string(" is a pipe, not a program file");
    case fs::file_type::socket:
      return std::string(" is a socket, not a program file");
    default:
      return std::string(" is not a regular file");
  }
}

const ast::Control* control_of(const ast::Block* b) {
  return b == nullptr ? nullptr : std::get_if<ast::Control>(&b->body);
}
bool is_header(const ast::Block* b) {
  return b != nullptr && std::holds_alternative<ast::ProgramHeader>(b->body);
}
/// `$IF cond $GOTO label` has no $ENDIF (PROG-206915851).
bool is_block_if(const ast::Control& c) {
  return c.kind == ControlKind::if_ && c.target.kind == ast::GotoKind::none;
}

}  // namespace

Interpreter::Impl::Impl(const core::SourceFile& file, const machines::Machine& m, Options o,
                        core::DiagnosticList& d)
    : machine(m),
      options(std::move(o)),
      diags(d),
      vars(options.persistent, options.external),
      evaluator(vars),
      cs(m.channel.cs_rotation_sequence) {
  auto main = std::make_unique<ProgramFile>();
  main->file = &file;
  main->blocks = std::make_unique<BlockSource>(file);
  files.push_back(std::move(main));
  for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i) {
    if (machine.axes[i].kind != machines::AxisKind::spindle) path_axes |= AxisMask{1} << i;
  }
  xyz = {axis_index("X"), axis_index("Y"), axis_index("Z")};
  trc_filter = trc::Compensator(xyz);
  modal.slope = channel_slope();  // P-CHAN-00071 prog_start.slope.profile
  // G261 without #CONTOUR MODE PATH_DEV: the channel's radius (NCSIM-CHAN-620, default the
  // manual's 1 mm; docs/planner.md "Tolerance balls").
  modal.contour.path_dev = machine.channel.default_path_dev;
  scale_factors.fill(1.0);
  init_zero_offsets();
  vars.create_cycle_param_on_read(machine.channel.create_cycle_param_on_read);  // P-CHAN-00463
  if (machine.channel.default_feed > 0.0) feed = machine.channel.default_feed;  // P-CHAN-00099
}

bool Interpreter::Impl::fail(core::SourceLoc loc, std::string id, std::string message) {
  if (loc.line == 0) loc = {line, 1};
  error = core::Diagnostic{core::Severity::error, files[current_file]->file->name(), loc,
                           std::move(id), std::move(message)};
  finished = true;
  return false;
}

bool Interpreter::Impl::fail_eval() {
  const EvalError& e = evaluator.error();
  return fail(e.loc, e.id, e.message);
}

void Interpreter::Impl::warn(core::SourceLoc loc, std::string id, std::string message) {
  diags.add({core::Severity::warning, files[current_file]->file->name(), loc, std::move(id),
             std::move(message)});
}

std::optional<double> Interpreter::Impl::eval(const ast::Block& b, ast::NodeIndex n) {
  auto v = evaluator.eval(b, n);
  if (!v) fail_eval();
  return v;
}

const ast::Block* Interpreter::Impl::fetch(Pc at) {
  return files[at.file]->blocks->fetch(at.ordinal, diags);
}

bool Interpreter::Impl::find_main_start(ProgramFile& pf, std::uint16_t index) {
  // Local subroutines precede the main part (PROG-206828043); record them, skip their bodies.
  std::uint32_t k = 0;
  for (;;) {
    const ast::Block* b = pf.blocks->fetch(k, diags);
    if (b == nullptr) break;
    const auto* h = std::get_if<ast::ProgramHeader>(&b->body);
    if (h == nullptr) break;
    if (!h->local) {
      pf.main_start = k + 1;
      return true;
    }
    const std::string name = grammar::to_upper(h->name);
    pf.local_subs[name] = k;
    for (++k;; ++k) {
      const ast::Block* body = pf.blocks->fetch(k, diags);
      if (body == nullptr || is_header(body)) break;
    }
  }
  pf.main_start = k;
  (void)index;
  return true;
}

std::optional<std::uint32_t> Interpreter::Impl::matching_end(std::uint16_t file, std::uint32_t from,
                                                             core::SourceLoc at) {
  const std::uint64_t key = (std::uint64_t{file} << 33) | (std::uint64_t{1} << 32) | from;
  if (auto it = jump_memo.find(key); it != jump_memo.end()) return it->second;
  int depth = 0;
  for (std::uint32_t k = from;; ++k) {
    const ast::Block* b = fetch({file, k});
    if (b == nullptr || is_header(b)) {
      fail(at, "NC4020", "no matching end of this loop or $SWITCH in the same program level");
      return std::nullopt;
    }
    const ast::Control* c = control_of(b);
    if (c == nullptr) continue;
    if (is_opener(c->kind)) {
      ++depth;
    } else if (is_closer(c->kind)) {
      if (depth == 0) {
        remember(jump_memo, key, k);
        return k;
      }
      --depth;
    }
  }
}

std::optional<std::uint32_t> Interpreter::Impl::next_if_branch(std::uint16_t file,
                                                               std::uint32_t from, bool endif_only,
                                                               core::SourceLoc at) {
  const std::uint64_t key =
      (std::uint64_t{file} << 33) | (endif_only ? 0u : (std::uint64_t{1} << 31)) | from;
  if (auto it = jump_memo.find(key); it != jump_memo.end()) return it->second;
  int depth = 0;
  for (std::uint32_t k = from;; ++k) {
    const ast::Block* b = fetch({file, k});
    if (b == nullptr || is_header(b)) {
      fail(at, "NC4021", "$IF without $ENDIF in the same program level");
      return std::nullopt;
    }
    const ast::Control* c = control_of(b);
    if (c == nullptr) continue;
    if (is_block_if(*c)) {
      ++depth;
    } else if (c->kind == ControlKind::endif) {
      if (depth == 0) {
        remember(jump_memo, key, k);
        return k;
      }
      --depth;
    } else if (!endif_only && depth == 0 &&
               (c->kind == ControlKind::elseif || c->kind == ControlKind::else_)) {
      remember(jump_memo, key, k);
      return k;
    }
  }
}

void Interpreter::Impl::remember(std::unordered_map<std::uint64_t, std::uint32_t>& memo,
                                 std::uint64_t key, std::uint32_t value) {
  if (memo.size() >= kMaxMemoEntries) memo.clear();  // bounded: rebuilt on demand
  memo[key] = value;
}

std::optional<GotoResult> Interpreter::Impl::find_label(const GotoLabel& target,
                                                        core::SourceLoc at) {
  const std::uint16_t file = pc.file;
  const std::uint32_t here = pc.ordinal;  // block after the $GOTO
  // Forward search to the end of the program level (PROG-206915851: both directions).
  GotoResult r;
  int depth = 0;
  for (std::uint32_t k = here;; ++k) {
    const ast::Block* blk = fetch({file, k});
    if (blk == nullptr || is_header(blk)) break;
    if (target.matches(*blk)) {
      if (depth > 0) {
        fail(at, "21480", "$GOTO jumps into a loop");
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
  for (std::uint32_t k = unit_start; k < here; ++k) {
    const ast::Block* blk = fetch({file, k});
    if (blk == nullptr) break;
    if (k != unit_start && is_header(blk)) break;
    if (target.matches(*blk)) {
      r.label = k;
      return r;
    }
    if (const ast::Control* c = control_of(blk)) {
      if (is_opener(c->kind)) r.open.push_back(k);  // unmatched openers before the label
      if (is_closer(c->kind) && !r.open.empty()) r.open.pop_back();
    }
  }
  fail(at, "NC4023", "jump label " + target.name + " not found in this program level");
  return std::nullopt;
}

bool Interpreter::Impl::jump_to_label(const ast::Block& b, const ast::GotoTarget& target) {
  // Copy what is needed of the $GOTO block now: the label search fetches blocks through the
  // cache, which may reuse the slot holding `b` (issue 9, defect 1).
  const core::SourceLoc at = target.loc.line != 0 ? target.loc : b.loc;
  if (target.kind == ast::GotoKind::variable || target.kind == ast::GotoKind::none) {
    return fail(at, "NC4022", "$GOTO to a variable target is not supported by ncsim");
  }
  const std::uint16_t file = pc.file;
  // The result depends only on the program text between the level start and the label, so it
  // is remembered per $GOTO site: a backward jump in a loop scans once, not every pass.
  const std::uint64_t key = (std::uint64_t{file} << 32) | pc.ordinal;
  auto it = goto_memo.find(key);
  if (it == goto_memo.end()) {
    const GotoLabel label{target.kind, target.number, std::string(target.name)};
    auto found = find_label(label, at);
    if (!found) return false;
    if (goto_memo.size() >= kMaxMemoEntries) goto_memo.clear();
    it = goto_memo.emplace(key, std::move(*found)).first;
  }
  const GotoResult& r = it->second;
  if (!r.backward) {
    for (int i = 0; i < r.closed && !control.empty(); ++i)
      control.pop_back();
    pc.ordinal = r.label;
    return true;
  }
  const std::size_t base = calls.empty() ? 0 : calls.back().control_depth;
  for (std::uint32_t o : r.open) {
    const bool is_open =
        std::any_of(control.begin() + static_cast<std::ptrdiff_t>(base), control.end(),
                    [&](const ControlFrame& f) { return f.file == file && f.open == o; });
    if (!is_open) return fail(at, "21480", "$GOTO jumps into a loop");
  }
  while (control.size() > base && control.back().open >= r.label)
    control.pop_back();
  pc.ordinal = r.label;
  return true;
}

bool Interpreter::Impl::call(const ast::Block& b, const ast::Call& c) {
  std::string name;
  if (c.target == ast::CallTarget::macro) {
    const std::string* text = vars.macro(c.name);
    if (text == nullptr)
      return fail(c.loc, "NC4005", "macro \"" + std::string(c.name) + "\" is not defined");
    name = *text;
  } else if (c.target == ast::CallTarget::variable) {
    VarRef ref;
    if (!evaluator.resolve(b, c.variable, ref)) return fail_eval();
    const std::string* text = vars.read_string(ref);
    if (text == nullptr) return fail(c.loc, "NC4303", "the call needs a STRING variable");
    name = *text;
  } else {
    name = std::string(c.name);
  }
  if (c.kind == ast::CallKind::cycle) return read_cycle_call(b, c) && run_cycle_call();
  if (static_cast<int>(calls.size()) >= options.max_subroutine_depth) {
    return fail(c.loc, "NC4302",
                "subroutine nesting deeper than " + std::to_string(options.max_subroutine_depth) +
                    " levels (call of " + name + ")");
  }
  Pc target;
  std::uint32_t header = 0;
  if (c.kind == ast::CallKind::local) {
    auto& subs = files[pc.file]->local_subs;
    auto it = subs.find(grammar::to_upper(name));
    if (it == subs.end()) {
      return fail(c.loc, "NC4301",
                  "local subroutine " + name + " is not defined before the main program");
    }
    target = {pc.file, it->second + 1};
    header = it->second;
  } else {
    auto it = file_by_name.find(name);
    std::uint16_t index = 0;
    if (it == file_by_name.end()) {
      const std::filesystem::path dir = std::filesystem::path(files[0]->file->name()).parent_path();
      if (options.confine_subroutine_files && !is_confined_name(name)) {
        return fail(c.loc, "NC4301",
                    "global subroutine file " + name +
                        " is outside the program's folder (absolute path or '..')");
      }
      const std::filesystem::path path = dir / name;
      if (auto problem = subroutine_file_problem(path)) {
        return fail(c.loc, "NC4301", "global subroutine file " + path.string() + *problem);
      }
      auto loaded = load_global_file(name, path, c.loc);
      if (!loaded) return false;
      index = *loaded;
    } else {
      index = it->second;
    }
    target = {index, files[index]->main_start};
    header = files[index]->main_start == 0 ? 0 : files[index]->main_start - 1;
  }
  enter_level(target, header);
  return true;
}

std::optional<std::uint16_t> Interpreter::Impl::load_global_file(const std::string& key,
                                                                 const std::filesystem::path& path,
                                                                 core::SourceLoc at) {
  auto pf = std::make_unique<ProgramFile>();
  try {
    pf->own = std::make_unique<core::SourceFile>(core::SourceFile::load(path));
  } catch (const std::exception& e) {
    fail(at, "NC4301", e.what());
    return std::nullopt;
  }
  // A subroutine file is checked whole when it is first called, as the main program is
  // before it runs: its syntax errors are reported even in blocks never reached.
  const core::DiagnosticList syntax = grammar::check_program(*pf->own);
  if (syntax.has_errors()) {
    for (const core::Diagnostic& d : syntax.items())
      diags.add(d);
    fail(at, "NC4306",
         "global subroutine file " + path.string() + " has " +
             std::to_string(syntax.error_count()) + " syntax error" +
             (syntax.error_count() == 1 ? "" : "s"));
    return std::nullopt;
  }
  pf->file = pf->own.get();
  pf->blocks = std::make_unique<BlockSource>(*pf->file);
  const auto index = static_cast<std::uint16_t>(files.size());
  files.push_back(std::move(pf));
  file_by_name[key] = index;
  find_main_start(*files[index], index);
  return index;
}

void Interpreter::Impl::enter_level(Pc target, std::uint32_t header) {
  calls.push_back({pc, control.size(), unit_start});
  vars.push_level();
  pc = target;
  unit_start = header;
}

bool Interpreter::Impl::subroutine_return() {
  if (calls.empty()) return true;  // M17 in the main program: ignored
  const CallFrame f = calls.back();
  calls.pop_back();
  control.resize(std::min(control.size(), f.control_depth));
  vars.pop_level();
  pc = f.ret;
  unit_start = f.unit_start;
  return true;
}

bool Interpreter::Impl::run_control(const ast::Block& b, const ast::Control& c) {
  const std::uint32_t here = pc.ordinal - 1;
  const std::uint16_t file = pc.file;
  const core::SourceLoc at = c.loc;
  // `b` and `c` live in the block cache: read them before any fetch (a search may evict them).
  const std::uint32_t open_line = b.loc.line;
  switch (c.kind) {
    case ControlKind::if_: {
      auto v = eval(b, c.expr);
      if (!v) return false;
      if (!is_block_if(c)) {  // $IF cond $GOTO label
        return is_true(*v) ? jump_to_label(b, c.target) : true;
      }
      if (is_true(*v)) return true;
      std::uint32_t from = here + 1;
      for (;;) {
        auto k = next_if_branch(file, from, false, at);
        if (!k) return false;
        const ast::Block* nb = fetch({file, *k});
        const ast::Control* nc = control_of(nb);
        if (nc->kind == ControlKind::elseif) {
          auto cond = eval(*nb, nc->expr);
          if (!cond) return false;
          if (is_true(*cond)) {
            pc.ordinal = *k + 1;
            return true;
          }
          from = *k + 1;
          continue;
        }
        pc.ordinal = *k + 1;  // $ELSE or $ENDIF
        return true;
      }
    }
    case ControlKind::elseif:
    case ControlKind::else_: {  // end of the branch taken: continue after $ENDIF
      auto k = next_if_branch(file, here + 1, true, at);
      if (!k) return false;
      pc.ordinal = *k + 1;
      return true;
    }
    case ControlKind::endif:
      return true;
    case ControlKind::switch_: {
      auto v = eval(b, c.expr);
      if (!v) return false;
      std::optional<std::uint32_t> default_at;
      int depth = 0;
      for (std::uint32_t k = here + 1;; ++k) {
        const ast::Block* nb = fetch({file, k});
        if (nb == nullptr || is_header(nb)) {
          return fail(at, "NC4020", "$SWITCH without $ENDSWITCH");
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
            pc.ordinal = k + 1;  // no case matched, no $DEFAULT
            return true;
          }
          control.push_back({FrameKind::switch_, file, here, k, {}, 0, 0, open_line});
          pc.ordinal = *default_at + 1;
          return true;
        } else if (depth == 0 && nc->kind == ControlKind::case_) {
          auto cv = eval(*nb, nc->expr);
          if (!cv) return false;
          if (std::fabs(*cv - *v) < 0.001) {  // PROG-206908427
            control.push_back({FrameKind::switch_, file, here, 0xFFFFFFFFu, {}, 0, 0, open_line});
            pc.ordinal = k + 1;
            return true;
          }
        } else if (depth == 0 && nc->kind == ControlKind::default_) {
          default_at = k;
        }
      }
    }
    case ControlKind::case_:
    case ControlKind::default_:
      return true;  // fall-through (decision, docs/interp.md)
    case ControlKind::endswitch:
      if (!control.empty() && control.back().kind == FrameKind::switch_) control.pop_back();
      return true;
    case ControlKind::for_: {
      ControlFrame f{FrameKind::for_, file, here, 0xFFFFFFFFu, {}, 0, 0, b.loc.line};
      if (!evaluator.resolve(b, c.counter, f.counter)) return fail_eval();
      auto start = eval(b, c.start);
      if (!start) return false;
      auto end = eval(b, c.end);
      if (!end) return false;
      std::optional<double> step = 1.0;
      if (c.step != ast::kNoNode) step = eval(b, c.step);
      if (!step) return false;
      f.end_value = *end;
      f.step = *step;
      VarError err;
      if (!vars.write(f.counter, *start, err)) return fail(at, err.id, err.message);
      if (f.step == 0.0) warn(at, "NC4024", "$FOR with step 0 loops forever (PROG-206929163)");
      const bool run = f.step > 0.0 ? *start <= *end : (f.step < 0.0 ? *start >= *end : true);
      if (!run) {
        auto k = matching_end(file, here + 1, at);
        if (!k) return false;
        pc.ordinal = *k + 1;
        return true;
      }
      control.push_back(std::move(f));
      return true;
    }
    case ControlKind::while_: {
      auto v = eval(b, c.expr);
      if (!v) return false;
      const bool reentry = !control.empty() && control.back().open == here &&
                           control.back().file == file && control.back().kind == FrameKind::while_;
      if (is_true(*v)) {
        if (!reentry)
          control.push_back({FrameKind::while_, file, here, 0xFFFFFFFFu, {}, 0, 0, b.loc.line});
        return true;
      }
      std::uint32_t end = 0;
      if (reentry && control.back().end != 0xFFFFFFFFu) {
        end = control.back().end;
      } else {
        auto k = matching_end(file, here + 1, at);
        if (!k) return false;
        end = *k;
      }
      if (reentry) control.pop_back();
      pc.ordinal = end + 1;
      return true;
    }
    case ControlKind::do_:
      control.push_back({FrameKind::do_, file, here, 0xFFFFFFFFu, {}, 0, 0, b.loc.line});
      return true;
    case ControlKind::repeat:
      control.push_back({FrameKind::repeat, file, here, 0xFFFFFFFFu, {}, 0, 0, b.loc.line});
      return true;
    case ControlKind::endfor:
    case ControlKind::endwhile:
    case ControlKind::enddo:
    case ControlKind::until: {
      const FrameKind want = c.kind == ControlKind::endfor     ? FrameKind::for_
                             : c.kind == ControlKind::endwhile ? FrameKind::while_
                             : c.kind == ControlKind::enddo    ? FrameKind::do_
                                                               : FrameKind::repeat;
      const std::size_t base = calls.empty() ? 0 : calls.back().control_depth;
      if (control.size() <= base || control.back().kind != want || control.back().file != file) {
        return fail(at, c.kind == ControlKind::endwhile ? "20237" : "NC4025",
                    "loop end without a matching loop start");
      }
      ControlFrame& f = control.back();
      f.end = here;
      if (want == FrameKind::while_) {
        pc.ordinal = f.open;
        return true;
      }
      if (want == FrameKind::for_) {
        VarError err;
        auto value = vars.read(f.counter, err);
        if (!value || !vars.write(f.counter, *value + f.step, err)) {
          return fail(at, err.id, err.message);
        }
        const double v = *value + f.step;
        const bool run = f.step > 0.0 ? v <= f.end_value : (f.step < 0.0 ? v >= f.end_value : true);
        if (run) {
          pc.ordinal = f.open + 1;
        } else {
          control.pop_back();
        }
        return true;
      }
      auto v = eval(b, c.expr);
      if (!v) return false;
      const bool again = want == FrameKind::do_ ? is_true(*v) : !is_true(*v);
      if (again) {
        pc.ordinal = f.open + 1;
      } else {
        control.pop_back();
      }
      return true;
    }
    case ControlKind::break_:
    case ControlKind::continue_: {
      const std::size_t base = calls.empty() ? 0 : calls.back().control_depth;
      const bool brk = c.kind == ControlKind::break_;
      for (;;) {
        if (control.size() <= base) {
          return fail(at, brk ? "20243" : "20244",
                      brk ? "$BREAK outside a loop or $SWITCH" : "$CONTINUE outside a loop");
        }
        ControlFrame& f = control.back();
        if (f.end == 0xFFFFFFFFu) {
          auto k = matching_end(file, pc.ordinal, at);
          if (!k) return false;
          f.end = *k;
        }
        if (brk) {
          pc.ordinal = f.end + 1;
          control.pop_back();
          return true;
        }
        if (!is_loop(f.kind)) {  // $CONTINUE inside a $SWITCH: leave the switch first
          pc.ordinal = f.end + 1;
          control.pop_back();
          continue;
        }
        pc.ordinal = f.end;  // the loop end block does the step / the test
        return true;
      }
    }
    case ControlKind::goto_:
      return jump_to_label(b, c.target);
  }
  return true;
}

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
std::uint64_t Interpreter::Impl::state_fingerprint(std::size_t& cost) const {
  std::uint64_t h = vars.fingerprint(cost);
  h = mix(h, (std::uint64_t{pc.file} << 32) | pc.ordinal);
  h = mix(h, unit_start);
  for (const ControlFrame& f : control) {
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
  for (const CallFrame& f : calls) {
    h = mix(h, (std::uint64_t{f.ret.file} << 32) | f.ret.ordinal);
    h = mix(h, (std::uint64_t{f.unit_start} << 32) | f.control_depth);
  }
  for (const double v : position)
    h = mix(h, bits(v));
  h = mix(h, static_cast<std::uint64_t>(motion));
  h = mix(h, bits(feed));
  h = mix(h, (std::uint64_t{centre_absolute} << 3) | (std::uint64_t{motion_since_sync} << 2) |
                 (std::uint64_t{spline.has_value()} << 1) | std::uint64_t{kin_id.has_value()});
  if (kin_id) h = mix(h, static_cast<std::uint64_t>(*kin_id));
  const ModalSnapshot& m = modal;
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
                 static_cast<std::uint64_t>(m.trc.approach));
  h = mix(h, bits(m.trc.radius));
  h = mix(h, bits(d_number));
  h = mix(h, files.size());
  // offsets, scaling and path limits (interpreter_offsets.cpp)
  h = mix(h, (std::uint64_t{zero_group} << 8) | (std::uint64_t{mcs_on} << 2) |
                 (std::uint64_t{scale_on} << 1) | std::uint64_t{hsc_saved.has_value()});
  for (const double f : scale_factors)
    h = mix(h, bits(f));
  h = mix(h, bits(vector_vel));
  for (const auto& [code, name] : file_names)
    h = mix(h, code);
  cost += control.size() + calls.size() + kMaxAxes;
  return h;
}

// Brent's cycle detection over decoder states: a state is saved after 1, 2, 4, ... blocks; a
// cycle of length L is found once the period reaches L. States are compared only where the
// block is the saved one, and a costly comparison (many variables) waits until as many
// blocks have been decoded as it costs, so the detection never dominates the decoding.
bool Interpreter::Impl::watch_for_repeat(std::uint32_t block_line) {
  ++decoded;
  if (repeat.credit > 0) --repeat.credit;
  if (pc.file == repeat.pc.file && pc.ordinal == repeat.pc.ordinal && repeat.credit == 0) {
    std::size_t cost = 0;
    const std::uint64_t now = state_fingerprint(cost);
    repeat.credit = cost / 16;
    if (now == repeat.fingerprint) {
      // No motion or time since the saved state: the decoder would loop here forever.
      if (blocks_without_motion >= decoded - repeat.at) {
        const std::uint32_t loop_line = control.empty() ? repeat.line : control.back().line;
        return fail({loop_line, 1}, "NC4901",
                    "endless loop without motion: the decoder returns to this block with the "
                    "same variables and state after " +
                        std::to_string(decoded - repeat.at) + " blocks, so the program cannot end");
      }
      if (!endless_from) endless_from = repeat.line;
    }
  }
  if (decoded - repeat.at >= repeat.period) {
    std::size_t cost = 0;
    repeat.pc = pc;
    repeat.line = block_line;
    repeat.fingerprint = state_fingerprint(cost);
    repeat.at = decoded;
    repeat.period *= 2;
    repeat.credit = cost / 16;
  }
  return true;
}

bool Interpreter::Impl::step() {
  if (!started) {
    started = true;
    find_main_start(*files[0], 0);
    pc = {0, files[0]->main_start};
    unit_start = files[0]->main_start == 0 ? 0 : files[0]->main_start - 1;
  }
  if (finished) return false;
  current_file = pc.file;
  const ast::Block* block = fetch(pc);
  if (block == nullptr || (is_header(block) && pc.ordinal != unit_start)) {
    if (!calls.empty()) return subroutine_return();      // the next % ends a subroutine
    if (spline && !spline_off({line, 1})) return false;  // as at M30 (interpreter_block.cpp)
    emit(line, End{0});
    finished = true;
    return true;
  }
  if (block->has_error) {
    for (auto it = diags.items().rbegin(); it != diags.items().rend(); ++it) {
      if (it->severity == core::Severity::error) {
        error = *it;
        error_reported = true;
        break;
      }
    }
    if (!error) fail(block->loc, "NC4001", "syntax error");
    finished = true;
    return false;
  }
  line = block->loc.line;
  ++pc.ordinal;
  const bool skipped = block->skip && *block->skip >= 1 && *block->skip <= 32 &&
                       (options.skip_levels & (1u << (*block->skip - 1))) != 0;
  // A barrier comes before the block is counted: the block is decoded once, after resume().
  if (!skipped && barrier_before(*block)) {
    --pc.ordinal;
    return true;
  }
  if (!watch_for_repeat(line)) return false;
  if (options.max_blocks_without_motion != 0 &&
      ++blocks_without_motion > options.max_blocks_without_motion) {
    const std::uint32_t loop_line = control.empty() ? line : control.back().line;
    return fail({loop_line, 1}, "NC4903",
                "more than " + std::to_string(options.max_blocks_without_motion) +
                    " blocks decoded without motion or time passing; the loop has not returned "
                    "to an earlier state, so it may end, but later than this limit");
  }
  if (skipped) return true;
  if (block->number && block->number->expr != ast::kNoNode) {
    const core::SourceLoc at = block->number->loc;
    const auto n = eval(*block, block->number->expr);
    if (!n) return false;
    // The range of a literal block number (NC1005), for a computed one too.
    if (!(*n >= 0.0 && *n <= 4294967295.0)) {
      return fail(at, "NC4016",
                  "block number N[...] = " + core::number_text(*n) +
                      " out of range: 0 to 4294967295, as for a literal");
    }
  }
  if (const auto* c = std::get_if<ast::Control>(&block->body)) return run_control(*block, *c);
  if (const auto* h = std::get_if<ast::HashCommand>(&block->body)) return run_hash(*block, *h);
  if (const auto* d = std::get_if<ast::Declaration>(&block->body)) {
    return run_declaration(*block, *d);
  }
  if (std::holds_alternative<ast::ProgramHeader>(block->body)) return true;
  const ast::Block* run = block;
  for (const auto& e : block->exprs) {
    if (e.op == ast::Op::string && vars.macro(e.text) != nullptr) {
      run = expand_macros(*block);
      if (run == nullptr) return false;
      break;
    }
  }
  cycle_call.reset();
  if (!run_words(*run)) return false;
  if (run->trailing_goto) return jump_to_label(*run, run->trailing_goto->target);
  if (cycle_call) {  // G80-G89 / G800-G839: the last action of the block (P-CHAN-00160)
    if (run->call) {
      return fail(run->call->loc, "21542",
                  "a subroutine call in a block that already calls G" +
                      std::to_string(cycle_call->g_code) + "'s subroutine");
    }
    return run_cycle_call();
  }
  if (run->call) return call(*run, *run->call);
  return true;
}

void Interpreter::Impl::emit(std::uint32_t at_line, CommandBody body) {
  pending.push_back(Command{at_line, current_file, std::move(body)});
}

// ---------------------------------------------------------------------------------------------

Interpreter::Interpreter(const core::SourceFile& file, const machines::Machine& machine,
                         Options options)
    : impl_(std::make_unique<Impl>(file, machine, std::move(options), diags_)) {}

Interpreter::~Interpreter() = default;

std::optional<Command> Interpreter::next() {
  Impl& s = *impl_;
  if (open_barrier_) {
    throw std::logic_error("Interpreter::next(): the barrier at line " +
                           std::to_string(open_barrier_->line) +
                           " is not answered; call resume() first");
  }
  // The decoded commands pass through the tool radius compensation (interp/trc.hpp), which
  // holds a plane motion until the next one closes its corner.
  while (s.trc_out.empty()) {
    while (s.pending.empty()) {
      if (s.finished || !s.step()) break;
    }
    if (s.pending.empty()) {
      if (!s.error) s.trc_filter.finish(s.trc_out);
      break;
    }
    Command raw = std::move(s.pending.front());
    s.pending.pop_front();
    if (auto e = s.trc_filter.push(std::move(raw), s.trc_out)) {
      s.error = core::Diagnostic{core::Severity::error, file_name(e->file),
                                 core::SourceLoc{e->line, 1}, e->id, e->message};
      s.error_reported = false;
      s.finished = true;
      s.pending.clear();
      break;
    }
  }
  if (!s.trc_out.empty()) {
    Command c = std::move(s.trc_out.front());
    s.trc_out.pop_front();
    if (std::holds_alternative<Barrier>(c.body)) open_barrier_ = c;
    return c;
  }
  if (s.error && !error_) {
    error_ = s.error;
    if (!s.error_reported) diags_.add(*s.error);
  }
  return std::nullopt;
}

// --- operator
void Interpreter::record_ve_writes(bool on) {
  impl_->vars.record_ve_writes(on);
}

std::map<std::string, double> Interpreter::take_ve_writes() {
  return impl_->vars.take_ve_writes();
}

std::optional<std::uint32_t> Interpreter::endless_from() const {
  return impl_->endless_from;
}

const std::string& Interpreter::file_name(std::uint16_t file) const {
  return impl_->files.at(file)->file->name();
}

const core::SourceFile& Interpreter::source_file(std::uint16_t file) const {
  return *impl_->files.at(file)->file;
}

Interpreter::Footprint Interpreter::footprint() const {
  const Impl& s = *impl_;
  std::size_t indexed = 0;
  for (const auto& f : s.files)
    indexed += f->blocks->indexed_blocks();
  return {s.control.size(),
          s.calls.size(),
          s.pending.size(),
          indexed,
          s.jump_memo.size() + s.goto_memo.size(),
          s.vars.p_count()};
}

}  // namespace ncsim::interp
