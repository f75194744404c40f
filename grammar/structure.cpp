#include "grammar/structure.hpp"

#include <algorithm>
#include <cmath>

#include "grammar/keywords.hpp"

namespace ncsim::grammar {
namespace {

std::string_view keyword_name(ast::ControlKind k) {
  using K = ast::ControlKind;
  switch (k) {
    case K::if_:
      return "$IF";
    case K::elseif:
      return "$ELSEIF";
    case K::else_:
      return "$ELSE";
    case K::endif:
      return "$ENDIF";
    case K::switch_:
      return "$SWITCH";
    case K::case_:
      return "$CASE";
    case K::default_:
      return "$DEFAULT";
    case K::endswitch:
      return "$ENDSWITCH";
    case K::for_:
      return "$FOR";
    case K::endfor:
      return "$ENDFOR";
    case K::while_:
      return "$WHILE";
    case K::endwhile:
      return "$ENDWHILE";
    case K::do_:
      return "$DO";
    case K::enddo:
      return "$ENDDO";
    case K::repeat:
      return "$REPEAT";
    case K::until:
      return "$UNTIL";
    case K::break_:
      return "$BREAK";
    case K::continue_:
      return "$CONTINUE";
    case K::goto_:
      return "$GOTO";
  }
  return "$";
}

std::string_view closer_of(ast::ControlKind k) {
  using K = ast::ControlKind;
  switch (k) {
    case K::if_:
      return "$ENDIF";
    case K::switch_:
      return "$ENDSWITCH";
    case K::for_:
      return "$ENDFOR";
    case K::while_:
      return "$ENDWHILE";
    case K::do_:
      return "$ENDDO";
    case K::repeat:
      return "$UNTIL";
    default:
      return "";
  }
}

bool is_loop(ast::ControlKind k) {
  using K = ast::ControlKind;
  return k == K::for_ || k == K::while_ || k == K::do_ || k == K::repeat;
}

}  // namespace

void StructureChecker::report(core::DiagnosticList& diags, core::SourceLoc loc, const char* id,
                              std::string message) const {
  diags.add({core::Severity::error, file_.name(), loc, id, std::move(message)});
}

std::vector<std::uint32_t> StructureChecker::open_loops() const {
  std::vector<std::uint32_t> loops;
  for (const Frame& f : frames_) {
    if (f.loop_id != 0) loops.push_back(f.loop_id);
  }
  return loops;
}

void StructureChecker::start_level(bool local) {
  level_open_ = true;
  in_main_ = !local;
  if (!local) main_seen_ = true;
}

void StructureChecker::finish_level(core::DiagnosticList& diags) {
  if (!level_open_) return;
  for (const Frame& f : frames_) {
    report(diags, f.loc, "NC2001",
           std::string(keyword_name(f.kind)) + " is not closed by " +
               std::string(closer_of(f.kind)) + " before the end of the program level");
  }
  // $GOTO (isg-language.md §4.7): the label must exist in the same level; jumping into a loop
  // is error 21480, jumping out of one is allowed.
  for (const GotoInfo& g : gotos_) {
    const auto it = labels_.find(g.label);
    if (it == labels_.end()) {
      report(diags, g.loc, "NC2012",
             "$GOTO target " + g.label + " is not a label of this program level");
      continue;
    }
    const auto& target = it->second.loops;
    const bool prefix = target.size() <= g.loops.size() &&
                        std::equal(target.begin(), target.end(), g.loops.begin());
    if (!prefix) report(diags, g.loc, "21480", "$GOTO " + g.label + " jumps into a loop");
  }
  frames_.clear();
  labels_.clear();
  gotos_.clear();
  level_open_ = false;
}

void StructureChecker::add_goto(const ast::GotoTarget& target) {
  if (target.kind == ast::GotoKind::block_number) {
    gotos_.push_back({"N" + std::to_string(target.number), target.loc, open_loops()});
  } else if (target.kind == ast::GotoKind::name) {
    gotos_.push_back({"[" + to_upper(target.name) + "]", target.loc, open_loops()});
  }
}

// #IF / #ELSE / #ENDIF (isg-language.md §4.8). Returns true when the block was one of them.
bool StructureChecker::preprocessor(const ast::Block& b, core::DiagnosticList& diags) {
  const auto* h = std::get_if<ast::HashCommand>(&b.body);
  if (h == nullptr) return false;
  using H = ast::HashKind;
  if (h->kind != H::pre_if && h->kind != H::pre_else && h->kind != H::pre_endif) return false;
  if (b.number) {
    report(diags, b.number->loc, "20593",
           "a block number is not allowed before #IF, #ELSE or #ENDIF");
  }
  if (h->kind == H::pre_if) {
    pre_ifs_.push_back({h->loc, false, enabled_});
  } else if (pre_ifs_.empty()) {
    report(diags, h->loc, "NC2015",
           std::string(h->kind == H::pre_else ? "#ELSE" : "#ENDIF") + " without #IF");
  } else if (h->kind == H::pre_else) {
    if (pre_ifs_.back().in_else) report(diags, h->loc, "NC2015", "second #ELSE for one #IF");
    pre_ifs_.back().in_else = true;
    enabled_ = false;
  } else {
    enabled_ = pre_ifs_.back().enabled_before;
    pre_ifs_.pop_back();
  }
  return true;
}

void StructureChecker::control(const ast::Block&, const ast::Control& c,
                               core::DiagnosticList& diags) {
  using K = ast::ControlKind;
  Frame* top = frames_.empty() ? nullptr : &frames_.back();
  const auto top_is = [&](K k) { return top != nullptr && top->kind == k; };
  switch (c.kind) {
    case K::if_:
      if (c.target.kind != ast::GotoKind::none) {
        add_goto(c.target);  // one-line `$IF cond $GOTO label` has no $ENDIF (§4.1)
      } else {
        frames_.push_back({K::if_, c.loc});
      }
      break;
    case K::elseif:
      if (!top_is(K::if_) || top->has_else) report(diags, c.loc, "20216", "unexpected $ELSEIF");
      break;
    case K::else_:
      if (!top_is(K::if_) || top->has_else) {
        report(diags, c.loc, "20214", "unexpected $ELSE");
      } else {
        top->has_else = true;
      }
      break;
    case K::endif:
      if (top_is(K::if_)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "20218", "unexpected $ENDIF");
      }
      break;
    case K::switch_:
      frames_.push_back({K::switch_, c.loc});
      break;
    case K::case_:
      if (!top_is(K::switch_)) report(diags, c.loc, "NC2002", "$CASE outside $SWITCH");
      break;
    case K::default_:
      if (!top_is(K::switch_)) {
        report(diags, c.loc, "NC2002", "$DEFAULT outside $SWITCH");
      } else if (top->has_else) {
        report(diags, c.loc, "NC2017", "second $DEFAULT in one $SWITCH");
      } else {
        top->has_else = true;
      }
      break;
    case K::endswitch:
      if (top_is(K::switch_)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "NC2006", "unexpected $ENDSWITCH (no open $SWITCH)");
      }
      break;
    case K::for_:
    case K::while_:
    case K::do_:
    case K::repeat:
      frames_.push_back({c.kind, c.loc, false, next_loop_id_++});
      break;
    case K::endfor:
      if (top_is(K::for_)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "NC2005", "unexpected $ENDFOR (no open $FOR)");
      }
      break;
    case K::endwhile:
      if (top_is(K::while_)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "20237", "unexpected $ENDWHILE");
      }
      break;
    case K::enddo:
      if (top_is(K::do_)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "NC2004", "unexpected $ENDDO (no open $DO)");
      }
      break;
    case K::until:
      if (top_is(K::repeat)) {
        frames_.pop_back();
      } else {
        report(diags, c.loc, "NC2003", "unexpected $UNTIL (no open $REPEAT)");
      }
      break;
    case K::break_: {
      const bool inside = std::any_of(frames_.begin(), frames_.end(), [](const Frame& f) {
        return is_loop(f.kind) || f.kind == K::switch_;
      });
      if (!inside) report(diags, c.loc, "20243", "$BREAK outside a loop or $SWITCH");
      break;
    }
    case K::continue_: {
      const bool inside = std::any_of(frames_.begin(), frames_.end(),
                                      [](const Frame& f) { return is_loop(f.kind); });
      if (!inside) report(diags, c.loc, "20244", "$CONTINUE outside a loop");
      break;
    }
    case K::goto_:
      add_goto(c.target);
      break;
  }
}

void StructureChecker::items(const ast::Block& b, ast::TableId table, std::uint32_t first,
                             std::uint32_t count, core::DiagnosticList& diags) const {
  const KeywordTable& t = keyword_table(table);
  if (t.open) return;
  for (std::uint32_t i = first; i < first + count && i < b.items.size(); ++i) {
    const ast::Item& item = b.items[i];
    if (item.key == ast::kUnknownKeyword && !item.keyword.empty()) {
      report(diags, item.loc, "NC2010",
             "unknown keyword '" + std::string(item.keyword) + "' in this command");
    }
  }
}

void StructureChecker::words(const ast::Block& b, core::DiagnosticList& diags) {
  for (const ast::Word& w : b.words) {
    if (w.kind == ast::WordKind::g) {
      const GClass g_class = classify_g(w.code);
      if (g_class == GClass::supported || g_class == GClass::implicit_call) continue;
      const std::string name = "G" + std::to_string(w.code);
      switch (g_class) {
        case GClass::supported:
        case GClass::implicit_call:  // the interpreter knows the subroutine (docs/interp.md)
          break;
        case GClass::not_supported:
          report(diags, w.loc, "NC1002", "not supported: " + name);
          break;
        case GClass::unknown:
          report(diags, w.loc, "20131", "unknown G function " + name);
          break;
      }
    } else if (w.kind == ast::WordKind::m && w.value != ast::kNoNode) {
      const ast::ExprNode& v = b.exprs[w.value];
      // Only literal values can be judged before running; M[expr] is the interpreter's.
      if (v.op == ast::Op::number) {
        if (v.value < 0 || v.value != std::floor(v.value)) {
          report(diags, w.loc, "NC2009",
                 "unknown M function M" + std::string(v.text) + ": M numbers are whole numbers");
        } else if (const auto code = static_cast<std::uint32_t>(std::min(v.value, 1e9));
                   !known_m_code(code)) {
          report(diags, w.loc, "NC2009", "unknown M function M" + std::to_string(code));
        } else if (in_main_ && (code == 2 || code == 30 || code == 17 || code == 29)) {
          main_has_end_ = true;
        }
      }
    }
  }
  for (const ast::AxisCommand& a : b.axis_commands) {
    const ast::TableId table =
        a.kind == ast::AxisCommandKind::indp_syn || a.kind == ast::AxisCommandKind::indp_asyn
            ? ast::TableId::indp
        : a.kind == ast::AxisCommandKind::mc_move_velocity ? ast::TableId::mc_move_velocity
        : a.kind == ast::AxisCommandKind::mc_touch_probe   ? ast::TableId::mc_touch_probe
                                                           : ast::TableId::mc_other;
    items(b, table, a.first_item, a.item_count, diags);
  }
  if (b.call && b.call->kind == ast::CallKind::local && b.call->target == ast::CallTarget::name) {
    local_calls_.emplace(to_upper(b.call->name), b.call->loc);
  }
  if (b.trailing_goto) add_goto(b.trailing_goto->target);
}

void StructureChecker::feed(const ast::Block& b, core::DiagnosticList& diags) {
  if (const auto* h = std::get_if<ast::ProgramHeader>(&b.body)) {
    finish_level(diags);
    if (h->local) {
      if (main_seen_) {
        report(diags, b.loc, "NC2013",
               "local subroutine %L " + std::string(h->name) +
                   " after the main program (local subroutines come first)");
      }
      const auto [it, fresh] = subroutines_.emplace(to_upper(h->name), b.loc);
      if (!fresh) {
        report(diags, b.loc, "NC2018",
               "local subroutine " + std::string(h->name) + " is defined twice");
      }
    }
    start_level(h->local);
    if (!h->local) main_header_ = b.loc;
    return;
  }
  if (!level_open_) start_level(false);
  if (in_main_) main_last_ = b.loc;
  if (preprocessor(b, diags) || !enabled_) return;

  if (b.number && b.number->is_label) {
    const std::string key = "N" + std::to_string(b.number->number);
    const auto [it, fresh] = labels_.emplace(key, LabelInfo{b.number->loc, open_loops()});
    if (!fresh) report(diags, b.number->loc, "NC2011", "label " + key + " is defined twice");
  }
  if (b.label) {
    const std::string key = "[" + to_upper(b.label->name) + "]";
    const auto [it, fresh] = labels_.emplace(key, LabelInfo{b.label->loc, open_loops()});
    if (!fresh) report(diags, b.label->loc, "NC2011", "label " + key + " is defined twice");
  }
  if (const auto* c = std::get_if<ast::Control>(&b.body)) {
    control(b, *c, diags);
  } else if (const auto* h = std::get_if<ast::HashCommand>(&b.body)) {
    items(b, h->table, 0, h->item_count, diags);
  } else {
    words(b, diags);
  }
}

void StructureChecker::finish(core::DiagnosticList& diags) {
  finish_level(diags);
  // isg-language.md §1.2: the main program ends with M02 or M30. Without, the file may have
  // been cut short (a warning: the interpreter ends the program at the file end anyway).
  if (main_seen_ && !main_has_end_ && main_last_.line > 0) {
    diags.add({core::Severity::warning, file_.name(), main_last_, "NC2019",
               "the main program does not end with M02 or M30 (file cut short?)"});
  } else if (main_last_.line == 0) {
    // An empty file, a bare `%`, only comments or only local subroutines: no main program
    // block at all, so no M02/M30 either.
    diags.add({core::Severity::warning, file_.name(), main_header_, "NC2019",
               "the main program has no blocks (empty file?), so no M02 or M30 either"});
  }
  for (const PreIf& p : pre_ifs_)
    report(diags, p.loc, "NC2015", "#IF is not closed by #ENDIF");
  pre_ifs_.clear();
  // LL calls a local subroutine of the same file (isg-language.md §4.9): a name defined by no
  // %L of this file is an error (docs/language.md "LL lookup").
  for (const auto& [name, loc] : local_calls_) {
    if (!subroutines_.contains(name)) {
      report(diags, loc, "NC2014",
             "LL " + name + ": no local subroutine %L " + name + " in this file");
    }
  }
}

}  // namespace ncsim::grammar
