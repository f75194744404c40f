#include "interp/block_source.hpp"

#include <cstdlib>
#include <string>

namespace ncsim::interp {
namespace {

void shift(core::SourceLoc& loc, std::uint32_t delta) {
  if (loc.line != 0) loc.line += delta;
}

}  // namespace

void shift_lines(grammar::ast::Block& block, std::uint32_t delta) {
  namespace ast = grammar::ast;
  shift(block.loc, delta);
  if (block.number) shift(block.number->loc, delta);
  if (block.label) shift(block.label->loc, delta);
  if (auto* c = std::get_if<ast::Control>(&block.body)) {
    shift(c->loc, delta);
    shift(c->target.loc, delta);
  } else if (auto* h = std::get_if<ast::HashCommand>(&block.body)) {
    shift(h->loc, delta);
  } else if (auto* d = std::get_if<ast::Declaration>(&block.body)) {
    shift(d->loc, delta);
  }
  for (auto& w : block.words)
    shift(w.loc, delta);
  for (auto& a : block.axis_commands)
    shift(a.loc, delta);
  if (block.call) shift(block.call->loc, delta);
  if (block.trailing_goto) {
    shift(block.trailing_goto->loc, delta);
    shift(block.trailing_goto->target.loc, delta);
  }
  for (auto& i : block.items)
    shift(i.loc, delta);
  for (auto& e : block.exprs)
    shift(e.loc, delta);
}

BlockSource::BlockSource(const core::SourceFile& file)
    : file_(file), parser_(file), reparser_(file), slots_(kCacheSlots) {}

bool BlockSource::parse_next(Slot& slot, core::DiagnosticList& diags) {
  if (parser_done_) return false;
  if (parsed_ % kCheckpointStride == 0) checkpoints_.push_back(parser_.position());
  bool more = false;
  if (check_ == nullptr) {
    more = parser_.next(slot.block, diags);
  } else {
    core::DiagnosticList& found = check_->found();
    const std::size_t before = found.items().size();
    more = parser_.next(slot.block, found);
    for (std::size_t i = before; i < found.items().size(); ++i)
      diags.add(found.items()[i]);
    if (more) check_->feed(slot.block);
  }
  if (!more) {
    parser_done_ = true;
    return false;
  }
  slot.ordinal = parsed_++;
  return true;
}

void BlockSource::parse_rest() {
  core::DiagnosticList ignored;  // the program has stopped: only a shared check still reads
  while (fetch(parsed_, ignored) != nullptr) {
  }
}

void BlockSource::reparse(std::uint32_t ordinal, Slot& slot) {
  if (reparser_next_ > ordinal || ordinal - reparser_next_ >= kCheckpointStride) {
    const std::uint32_t k = ordinal / kCheckpointStride;
    reparser_.seek(checkpoints_[k]);
    reparser_next_ = k * kCheckpointStride;
  }
  core::DiagnosticList ignored;  // reported at the first parse already
  for (; reparser_next_ < ordinal; ++reparser_next_) {
    if (!reparser_.next(skipped_, ignored)) std::abort();  // parsed before: broken invariant
  }
  if (!reparser_.next(slot.block, ignored)) std::abort();
  ++reparser_next_;
  slot.ordinal = ordinal;
}

const grammar::ast::Block* BlockSource::fetch(std::uint32_t ordinal, core::DiagnosticList& diags) {
  Slot& slot = slots_[ordinal & (kCacheSlots - 1)];
  if (slot.ordinal == ordinal) return &slot.block;
  if (ordinal < parsed_) {
    reparse(ordinal, slot);
    return &slot.block;
  }
  while (parsed_ <= ordinal) {
    Slot& target = slots_[parsed_ & (kCacheSlots - 1)];
    target.ordinal = 0xFFFFFFFFu;
    if (!parse_next(target, diags)) return nullptr;
  }
  return &slot.block;
}

const grammar::ast::Block* BlockSource::parse_text(std::string text, std::uint32_t line,
                                                   core::DiagnosticList& diags) {
  auto own = std::make_unique<core::SourceFile>(file_.name(), std::move(text));
  grammar::BlockParser parser(*own);
  core::DiagnosticList local;
  if (!parser.next(scratch_.block, local)) return nullptr;
  for (auto d : local.items()) {
    d.loc.line += line - 1;
    diags.add(std::move(d));
  }
  shift_lines(scratch_.block, line - 1);
  scratch_file_ = std::move(own);
  return &scratch_.block;
}

}  // namespace ncsim::interp
