// interp/interpreter_block.cpp: the order of a block's parts (run_words), assignments, G04,
// G74, G92, program ends, declarations and string macros. The G codes and addresses are read
// in block_words.cpp, motions and arcs in interpreter_motion.cpp, # commands in
// hash_commands.cpp.
#include <cmath>

#include "core/number_text.hpp"
#include "grammar/block_parser.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"
#include "interp/tech_functions.hpp"

namespace ncsim::interp {
namespace {

std::string unescape(std::string_view s) {
  std::string out;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] == '\\' && k + 1 < s.size()) ++k;
    out.push_back(s[k]);
  }
  return out;
}

std::optional<std::uint8_t> lookup_axis(const machines::Machine& machine, std::string_view name) {
  const machines::AxisParams* a = machine.find_axis(name);
  if (a == nullptr) {
    for (std::size_t i = 0; i < machine.axes.size(); ++i) {
      if (grammar::iequals(machine.axes[i].name, name)) return static_cast<std::uint8_t>(i);
    }
    return std::nullopt;
  }
  const auto i = static_cast<std::size_t>(a - machine.axes.data());
  if (i >= kMaxAxes) return std::nullopt;
  return static_cast<std::uint8_t>(i);
}

}  // namespace

AxisByChar axis_by_char(const machines::Machine& machine) {
  AxisByChar table{};
  for (std::size_t c = 0; c < table.size(); ++c) {
    const char name = static_cast<char>(c);
    table[c] = lookup_axis(machine, std::string_view(&name, 1)).value_or(kNoAxisIndex);
  }
  return table;
}

std::optional<std::uint8_t> Interpreter::Impl::axis_index(std::string_view name) const {
  // Most axis words have a one-letter name: looked up in the table made from the machine.
  if (name.size() == 1 && static_cast<unsigned char>(name[0]) < single_letter_axes.size()) {
    const std::uint8_t i = single_letter_axes[static_cast<unsigned char>(name[0])];
    if (i == kNoAxisIndex) return std::nullopt;
    return i;
  }
  return lookup_axis(machine, name);
}

ModalSnapshot Interpreter::Impl::snapshot() const {
  ModalSnapshot m = modal;
  if (m.synchronised) m.slope = SlopeType::trapez;  // seed 004 §2.1.7: jerk-limited slope
  m.cs_active = cs.active_count() > 0;
  return m;
}

const ast::Block* Interpreter::Impl::expand_macros(const ast::Block& b) {
  // Textual replacement of "NAME" by the macro text (PROG-206014219), repeated for macros in
  // macros up to the recursion limit (decision, docs/interp.md).
  std::string text(b.text);
  for (int pass = 0;; ++pass) {
    std::string out;
    bool changed = false;
    int depth = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
      const char c = text[k];
      if (depth > 0) {
        if (c == '(') ++depth;
        if (c == ')') --depth;
        out.push_back(c);
        continue;
      }
      if (c == ';') {
        out.append(text, k, std::string::npos);
        break;
      }
      if (c == '(') ++depth;
      if (c != '"') {
        out.push_back(c);
        continue;
      }
      std::size_t e = k + 1;
      while (e < text.size() && text[e] != '"')
        e += (text[e] == '\\') ? 2 : 1;
      const std::string name = text.substr(k + 1, std::min(e, text.size()) - k - 1);
      const std::string* m = vars.macro(name);
      if (m != nullptr) {
        out += unescape(*m);
        changed = true;
      } else {
        out.append(text, k, std::min(e + 1, text.size()) - k);
      }
      k = e;
      // A block holds at most 4000 characters (PROG-205952267), also after replacement: stop
      // before a macro that repeats itself grows the text geometrically.
      if (out.size() > grammar::kMaxBlockLength) {
        fail(b.loc, "NC4007",
             "the block is longer than " + std::to_string(grammar::kMaxBlockLength) +
                 " characters after macro replacement");
        return nullptr;
      }
    }
    text = std::move(out);
    if (!changed) break;
    if (pass + 1 >= options.macro_recursion_limit) {
      fail(b.loc, "NC4006",
           "string macros nested deeper than " + std::to_string(options.macro_recursion_limit) +
               " levels");
      return nullptr;
    }
  }
  const ast::Block* expanded = files[current_file]->blocks->parse_text(text, b.loc.line, diags);
  if (expanded == nullptr || expanded->has_error) {
    fail(b.loc, "NC4007", "the block after macro replacement is not valid: " + text);
    return nullptr;
  }
  return expanded;
}

bool Interpreter::Impl::run_declaration(const ast::Block& b, const ast::Declaration& d) {
  VarRef ref;
  if (!evaluator.resolve(b, d.variable, ref)) return fail_eval();
  Variable v;
  v.type = d.type;
  std::size_t count = 1;
  for (std::uint32_t k = 0; k < ref.index_count; ++k) {
    if (ref.index[k] < 1.0) return fail(d.loc, "NC4015", "array dimension must be >= 1");
    // Checked before the conversion and the allocation: a dimension beyond
    // the element limit would not fit the integer, a product beyond it asked for gigabytes.
    const double limit = static_cast<double>(kMaxArrayElements / count);
    if (!(ref.index[k] < limit + 1.0)) {
      return fail(d.loc, "NC4015",
                  "array larger than " + std::to_string(kMaxArrayElements) +
                      " elements (dimension " + std::to_string(k + 1) + " is " +
                      core::number_text(ref.index[k]) + ")");
    }
    v.dims.push_back(static_cast<std::uint32_t>(ref.index[k]));
    count *= v.dims.back();
  }
  ref.index_count = 0;
  v.values.assign(count, 0.0);
  if (v.is_string() && d.string_length != ast::kNoNode) {
    auto n = eval(b, d.string_length);
    if (!n) return false;
    if (*n < 1.0 || *n > kMaxStringLength || *n != std::trunc(*n)) {
      return fail(d.loc, "NC4014",
                  "STRING[" + core::number_text(*n) + "]: the length must be 1.." +
                      std::to_string(kMaxStringLength));
    }
    v.max_length = static_cast<std::uint32_t>(*n);
  }
  if (d.init != ast::kNoNode) {
    if (v.is_string()) {
      const ast::ExprNode& n = b.exprs[d.init];
      if (n.op != ast::Op::string) return fail(n.loc, "NC4014", "a STRING needs a \"text\" value");
      v.text = unescape(n.text);
      if (v.text.size() > v.max_length) {
        return fail(n.loc, "NC4014",
                    "the initial text of " + std::to_string(v.text.size()) +
                        " characters is longer than STRING[" + std::to_string(v.max_length) + "]");
      }
    } else {
      std::size_t k = 0;
      for (ast::NodeIndex n = d.init; n != ast::kNoNode && k < count; n = b.exprs[n].next, ++k) {
        auto value = eval(b, n);
        if (!value) return false;
        v.values[k] = *value;
        if (!d.array_init) break;
      }
    }
  }
  VarError err;
  if (!vars.declare(ref, std::move(v), err)) return fail(d.loc, err.id, err.message);
  return true;
}

bool Interpreter::Impl::run_words(const ast::Block& b) {
  // Order within a block (decision, docs/interp.md): assignments, G codes, addresses, the
  // technology functions, then the block's one action, axis-bracket commands, program end.
  if (!run_assignments(b)) return false;
  BlockWords& bw = block_words;  // reused: its vectors keep their capacity across blocks
  if (!word_reader.read(b, bw) || !trc_words.update(bw)) return false;
  if (!bw.weightings.empty()) word_reader.apply_weightings(bw);
  if (bw.g74 && !check_homing(b, bw)) return false;  // before S is emitted
  // Technology functions (interp/tech_functions.hpp): MNS_SNS ones after the block's action.
  const TechWaits waits = resolve_tech(bw.tech, machine.channel.tech);
  for (const Tech& t : bw.tech)
    if (t.sync != machines::TechSync::mns_sns) emit(line, t);
  if (waits.before) emit(line, Dwell{*waits.before, true, false});
  bool ok = true;
  if (bw.g04) {
    ok = run_dwell(b, bw);
  } else if (bw.g74) {
    run_homing(bw);
  } else if (bw.g92) {
    run_set_position(bw);
  } else {
    ok = run_block_motion(b, bw);
  }
  if (!ok || !axis_commands.run(b)) return false;
  if (waits.since) emit(line, Dwell{*waits.since, true, true});
  if (waits.after) {
    for (const Tech& t : bw.tech)
      if (t.sync == machines::TechSync::mns_sns) emit(line, t);
    emit(line, Dwell{*waits.after, true, false});
  }
  return !bw.program_m || run_program_m(b, *bw.program_m);
}

bool Interpreter::Impl::run_assignments(const ast::Block& b) {
  // 1. assignments and macro definitions, left to right, before the block's motion
  //    (decision, docs/interp.md "Order within a block").
  for (const ast::Word& w : b.words) {
    if (w.kind == ast::WordKind::macro_def) {
      vars.define_macro(std::string(w.name), std::string(w.text));
    } else if (w.kind == ast::WordKind::assignment) {
      const ast::ExprNode& value_node = b.exprs[w.value];
      if (value_node.op == ast::Op::string && vars.macro(value_node.text) == nullptr) {
        VarRef ref;
        if (!evaluator.resolve(b, w.target, ref)) return fail_eval();
        VarError err;
        if (!vars.write_string(ref, unescape(value_node.text), err)) {
          return fail(w.loc, err.id, err.message);
        }
        continue;
      }
      auto v = eval(b, w.value);
      if (!v) return false;
      double value = *v;
      if (w.assign != ast::AssignOp::set) {
        auto old = eval(b, w.target);
        if (!old) return false;
        switch (w.assign) {
          case ast::AssignOp::add:
            value = *old + value;
            break;
          case ast::AssignOp::subtract:
            value = *old - value;
            break;
          case ast::AssignOp::multiply:
            value = *old * value;
            break;
          case ast::AssignOp::divide:
            if (value == 0.0) return fail(w.loc, "20396", "division by zero in /=");
            value = *old / value;
            break;
          case ast::AssignOp::set:
            break;
        }
      }
      if (!evaluator.assign(b, w.target, value)) return fail_eval();
    }
  }
  return true;
}

bool Interpreter::Impl::run_dwell(const ast::Block& b, const BlockWords& bw) {
  // G04: time in seconds after the first main axis address or alone (PROG-206132747).
  std::optional<double> t = bw.bare;
  for (std::size_t k = 0; k < bw.axis_words.size(); ++k) {
    if (k == 0 && !bw.bare) {
      t = bw.axis_words[k].second;
    } else if (bw.bare && k == 0) {
      return fail(b.loc, "20013", "G04 with both a time value and an axis address");
    } else {
      warn(b.loc, "20685", "G04: further axis addresses are ignored");
    }
  }
  if (!t) return fail(b.loc, "20013", "G04 without a dwell time");
  if (*t < 0.0) return fail(b.loc, "20013", "negative dwell time");
  if (!(*t <= core::kLongestTime)) return fail(b.loc, "20752", longest_time_text("dwell", *t));
  emit(line, Dwell{*t});
  if (*t > 0.0) blocks_without_motion = 0;  // a 0 s dwell passes no time
  return true;
}

void Interpreter::Impl::run_homing(const BlockWords& bw) {
  Homing h;
  for (const auto& [axis, order] : bw.axis_words) {
    h.axes.emplace_back(axis, static_cast<int>(order));
    offsets.pset_offsets[axis] = 0.0;     // G74 deselects the #PSET preset (PROG-207101835)
    unknown_axes |= AxisMask{1} << axis;  // the reference position: run-time state
    indp_unknown &= ~(AxisMask{1} << axis);
  }
  emit(line, std::move(h));
  blocks_without_motion = 0;
}

void Interpreter::Impl::run_set_position(const BlockWords& bw) {
  SetPosition s;
  for (const auto& [axis, value] : bw.axis_words) {
    const bool rotary = machine.axes[axis].kind == machines::AxisKind::rotary;
    s.values[axis] = value * (rotary ? 1.0 : bw.unit);
    s.axes |= AxisMask{1} << axis;
    position[axis] = s.values[axis];
    unknown_axes &= ~(AxisMask{1} << axis);  // known again: the program says where it is
    indp_unknown &= unknown_axes;
  }
  emit(line, std::move(s));
}

bool Interpreter::Impl::run_program_m(const ast::Block& b, int code) {
  switch (code) {
    case 0:
      emit(line, ProgramStop{false});
      break;
    case 1:
      emit(line, ProgramStop{true});
      break;
    case 17:
    case 29:
      return subs.subroutine_return();
    default:
      if (!calls.empty()) {
        warn(b.loc, "NC4305", "M02/M30 inside a subroutine ends the program (PROG-206828043)");
      }
      if (modal.synchronised && (code == 2 || code == 30)) {
        // Decision (docs/interp.md): a warning, not an error. Seed 004 §2.1.1.2 (l.292) lets a
        // program per workpiece end while the next one takes the synchronisation over
        // (ProgStartFast); without such a program the tool keeps moving with the belt.
        warn(b.loc, "NC4516",
             "M" + std::to_string(code) +
                 " while synchronised with the conveyor: the coupling stays for a following "
                 "program (seed 004 §2.1.1.2); #SYNC OUT first to end decoupled");
      }
      // An open spline section ends with the program as at #SPLINE OFF: its last points run,
      // never dropped (issue 34 item 5; docs/interp.md "Splines").
      if (spline && (code == 2 || code == 30) && !spline_off(b.loc)) return false;
      emit(line, End{code});
      finished = true;
      break;
  }
  return true;
}

}  // namespace ncsim::interp
