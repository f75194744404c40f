// interp/interpreter.cpp: the block stream, the decoder's services (fail, warn, eval, emit) and
// the public Interpreter.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/number_text.hpp"
#include "grammar/check.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

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
  offsets.scale_factors.fill(1.0);
  offsets.init_zero_offsets();
  {  // V.G.SIGNAL_READ: FALSE until a #SIGNAL READ found a signal (PROG-913718283)
    Variable v;
    v.values.assign(1, 0.0);
    vars.provide_global("SIGNAL_READ", std::move(v));
  }
  provide_kinematic_params();
  vars.create_cycle_param_on_read(machine.channel.create_cycle_param_on_read);  // P-CHAN-00463
  if (machine.channel.default_feed > 0.0) feed = machine.channel.default_feed;  // P-CHAN-00099
}

void Interpreter::Impl::provide_kinematic_params() {
  // V.G.KIN[id].PARAM[k] (isg-language.md §5.9, tf5290): trafo[j].param[k] (P-CHAN-00263) of
  // the kinematic `id` as the channel list writes it (0.1 um / 0.0001 deg); ids up to the
  // largest configured one, an id not configured reads 0. Read only: a write is NC1002
  // (Variables::write; docs/machines.md "Kinematic 45").
  int max_id = -1;
  for (const machines::TrafoParams& t : machine.channel.trafos)
    if (t.id >= 0 && t.id < kMaxKinVarId) max_id = std::max(max_id, t.id);
  if (max_id < 0) return;
  const std::size_t n = machines::TrafoParams{}.param.size();
  Variable v;
  v.dims = {static_cast<std::uint32_t>(max_id + 1), static_cast<std::uint32_t>(n)};
  v.values.assign(static_cast<std::size_t>(max_id + 1) * n, 0.0);
  for (const machines::TrafoParams& t : machine.channel.trafos) {
    if (t.id < 0 || t.id > max_id) continue;
    for (std::size_t k = 0; k < n; ++k)
      v.values[static_cast<std::size_t>(t.id) * n + k] = t.param[k] * 1e4;  // mm, deg -> list
  }
  vars.provide_global("KIN.PARAM", std::move(v));
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

void Interpreter::Impl::warn(core::SourceLoc loc, std::string id, std::string message,
                             core::Severity severity) {
  diags.add({severity, files[current_file]->file->name(), loc, std::move(id), std::move(message)});
}

std::optional<double> Interpreter::Impl::eval(const ast::Block& b, ast::NodeIndex n) {
  auto v = evaluator.eval(b, n);
  if (!v) fail_eval();
  return v;
}

const ast::Block* Interpreter::Impl::fetch(Pc at) {
  return files[at.file]->blocks->fetch(at.ordinal, diags);
}

bool Interpreter::Impl::end_stream(End end) {
  if (spline && !spline_off({line, 1})) return false;  // as at M30 (interpreter_block.cpp)
  emit(line, end);
  finished = true;
  return true;
}

bool Interpreter::Impl::step() {
  if (!started) {
    started = true;
    subs.find_main_start(*files[0], 0);
    pc = {0, files[0]->main_start};
    unit_start = files[0]->main_start == 0 ? 0 : files[0]->main_start - 1;
  }
  if (finished) return false;
  current_file = pc.file;
  const ast::Block* block = fetch(pc);
  if (block == nullptr || (is_header(block) && pc.ordinal != unit_start)) {
    if (!calls.empty()) return subs.subroutine_return();  // the next % ends a subroutine
    return end_stream(End{0});
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
  if (!skipped && seam.barrier_before(*block)) {
    --pc.ordinal;
    return true;
  }
  if (!repeat.watch(line)) return false;
  // Before the block the decoder came back to: what ran since it was first there are whole
  // repetitions (docs/interp.md "Endless programs").
  if (options.end_when_endless && repeat.endless_on_its_own()) return end_stream(End{0, true});
  if (options.max_blocks_without_motion != 0 &&
      ++blocks_without_motion > options.max_blocks_without_motion) {
    const std::uint32_t loop_line = flow.loop_line(line);
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
  if (const auto* c = std::get_if<ast::Control>(&block->body)) return flow.run(*block, *c);
  if (const auto* h = std::get_if<ast::HashCommand>(&block->body)) return hash.run_hash(*block, *h);
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
  subs.cycle_call.reset();
  if (!run_words(*run)) return false;
  if (run->trailing_goto) return flow.jump_to_label(*run, run->trailing_goto->target);
  if (subs.cycle_call) {  // G80-G89 / G800-G839: the last action of the block (P-CHAN-00160)
    if (run->call) {
      return fail(run->call->loc, "21542",
                  "a subroutine call in a block that already calls " +
                      Subroutines::call_name(*subs.cycle_call) + "'s subroutine");
    }
    return subs.run_cycle_call();
  }
  if (run->call) return subs.call(*run, *run->call);
  return true;
}

// The public Interpreter: commands through the TRC filter, the V.E. writes, the files.

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
  // One result object, returned from one place: the command is moved into it once and the
  // return elides the copy (two named results would cost a move of the command each).
  std::optional<Command> out;
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
    if (s.trc_filter.passes(s.pending.front())) {
      // What push() would put into trc_out unchanged, handed out at once (trc_out is empty).
      out.emplace(std::move(s.pending.front()));
      s.pending.pop_front();
      break;
    }
    auto e = s.trc_filter.push(std::move(s.pending.front()), s.trc_out);
    s.pending.pop_front();
    if (e) {
      s.error = core::Diagnostic{core::Severity::error, file_name(e->file),
                                 core::SourceLoc{e->line, 1}, e->id, e->message};
      s.error_reported = false;
      s.finished = true;
      s.pending.clear();
      break;
    }
  }
  if (!out && !s.trc_out.empty()) {
    out.emplace(std::move(s.trc_out.front()));
    s.trc_out.pop_front();
  }
  if (out) {
    if (std::holds_alternative<Barrier>(out->body)) open_barrier_ = out;
  } else if (s.error && !error_) {
    error_ = s.error;
    if (!s.error_reported) diags_.add(*s.error);
  }
  return out;
}

// The program's own V.E. writes, for the run time's store.
void Interpreter::record_ve_writes(bool on) {
  impl_->vars.record_ve_writes(on);
}

std::map<std::string, double> Interpreter::take_ve_writes() {
  return impl_->vars.take_ve_writes();
}

std::optional<std::uint32_t> Interpreter::endless_from() const {
  return impl_->repeat.endless_from();
}

const std::string& Interpreter::file_name(std::uint16_t file) const {
  return impl_->files.at(file)->file->name();
}

const core::SourceFile& Interpreter::source_file(std::uint16_t file) const {
  return *impl_->files.at(file)->file;
}

void Interpreter::share_first_parse(grammar::ProgramCheck& check) {
  impl_->files[0]->blocks->share_first_parse(check);
}

void Interpreter::parse_rest() {
  impl_->files[0]->blocks->parse_rest();
}

Interpreter::Footprint Interpreter::footprint() const {
  const Impl& s = *impl_;
  std::size_t indexed = 0;
  for (const auto& f : s.files)
    indexed += f->blocks->indexed_blocks();
  return {s.flow.frames().size(), s.calls.size(),  s.pending.size(), indexed,
          s.flow.memo_entries(),  s.vars.p_count()};
}

}  // namespace ncsim::interp
