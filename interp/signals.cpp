// interp/signals.cpp: channel synchronisation (docs/lines.md): #SIGNAL [SYN], #WAIT [SYN] and
// #SIGNAL READ (PROG-207409035, PROG-207421579, PROG-913718283) with the manual's ids 20995,
// 20996, 21056, 21344, 21549 and 250008. #SIGNAL / #SIGNAL SYN become a Signal command, #WAIT
// SYN a SignalWait command; #WAIT and #SIGNAL READ are answered through a Barrier before their
// block (seam.cpp), whose answer (RunState::signal) the block then assigns to its P targets.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/number_text.hpp"
#include "grammar/keywords.hpp"
#include "interp/hash_commands.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

using ast::HashKind;

bool waits(HashKind k) {
  return k == HashKind::wait_signal || k == HashKind::wait_signal_syn || k == HashKind::signal_read;
}

bool removes(HashKind k) {
  return k == HashKind::signal_remove || k == HashKind::signal_remove_syn;
}

std::string command_name(HashKind k) {
  switch (k) {
    case HashKind::signal:
      return "#SIGNAL";
    case HashKind::signal_syn:
      return "#SIGNAL SYN";
    case HashKind::wait_signal:
      return "#WAIT";
    case HashKind::wait_signal_syn:
      return "#WAIT SYN";
    case HashKind::signal_remove:
      return "#SIGNAL REMOVE";
    case HashKind::signal_remove_syn:
      return "#SIGNAL REMOVE SYN";
    default:
      return "#SIGNAL READ";
  }
}

}  // namespace

std::optional<double> HashCommands::signal_value(const ast::Block& b, ast::NodeIndex n,
                                                 bool report) {
  if (report) return ip_.eval(b, n);
  return ip_.evaluator.eval(b, n);
}

std::optional<std::uint32_t> HashCommands::signal_integer(const ast::Block& b, const ast::Item& it,
                                                          const char* id, double low, double high,
                                                          const std::string& what, bool report) {
  const std::optional<double> v = signal_value(b, it.value, report);
  if (!v) return std::nullopt;
  if (!(*v >= low && *v <= high) || *v != std::floor(*v)) {
    if (report) {
      ip_.fail(it.loc, id,
               what + " " + core::number_text(*v) + " is outside " + core::number_text(low) +
                   " .. " + core::number_text(high) + " (an integer)");
    }
    return std::nullopt;
  }
  return static_cast<std::uint32_t>(*v);
}

std::optional<Signal> HashCommands::signal_parts(const ast::Block& b, const ast::HashCommand& h,
                                                 bool report) {
  const std::string name = command_name(h.kind);
  const auto fail = [&](core::SourceLoc at, const char* id, std::string message) {
    if (report) ip_.fail(at, id, std::move(message));
    return std::optional<Signal>{};
  };
  Signal s;
  s.syn = h.kind == HashKind::signal_syn || h.kind == HashKind::wait_signal_syn ||
          h.kind == HashKind::signal_remove_syn;
  s.remove = removes(h.kind);
  const ast::Item* id_item = nullptr;
  const ast::Item* max_item = nullptr;
  for (std::uint32_t k = 0; k < h.item_count && k < b.items.size(); ++k) {
    const ast::Item& it = b.items[k];
    const std::string key = grammar::to_upper(it.keyword);
    const bool remove_only = key == "IDMIN" || key == "IDMAX";
    if (remove_only != s.remove && (remove_only || key == "COUNT" || key == "P")) {
      return fail(it.loc, "NC4806",
                  key + " is not an item of " + name +
                      (s.remove ? " (it takes ID or IDMIN [IDMAX] and CH, PROG-207414923)"
                                : " (IDMIN and IDMAX belong to #SIGNAL REMOVE)"));
    }
    if (key == "IDMAX") {
      const auto v =
          signal_integer(b, it, "20995", 1.0, kMaxSignalId, "signal number IDMAX", report);
      if (!v) return std::nullopt;
      max_item = &it;
      s.id_max = *v;
    } else if (key == "ID" || key == "IDMIN") {
      s.range = key == "IDMIN";
      if (id_item != nullptr) {
        return fail(it.loc, "21056",
                    "double programming of the signal number in " + name + " (first ID at column " +
                        std::to_string(id_item->loc.column) + ")");
      }
      id_item = &it;
      const auto v = signal_integer(b, it, "20995", 1.0, kMaxSignalId, "signal number ID", report);
      if (!v) return std::nullopt;
      s.id = *v;
    } else if (key == "COUNT") {
      if (waits(h.kind)) {
        return fail(it.loc, "NC4801",
                    "COUNT is the consumption counter of #SIGNAL, not of " + name);
      }
      const auto v = signal_integer(b, it, "NC4802", 1.0, kMaxSignalId, "COUNT", report);
      if (!v) return std::nullopt;
      s.count = *v;
    } else if (key == "CH") {
      const auto v = signal_integer(b, it, "20996", 1.0, kMaxChannels, "channel number CH", report);
      if (!v) return std::nullopt;
      const auto ch = static_cast<std::uint8_t>(*v);
      const auto& run = ip_.options.channels;
      if (run && std::find(run->begin(), run->end(), ch) == run->end()) {
        std::string have;
        for (const std::uint8_t c : *run)
          have += (have.empty() ? "" : ", ") + std::to_string(c);
        return fail(it.loc, "250008",
                    name + " names channel " + std::to_string(ch) +
                        ", which this run does not have (its channels: " + have + ")");
      }
      if (std::find(s.receivers.begin(), s.receivers.end(), ch) == s.receivers.end())
        s.receivers.push_back(ch);
    } else if (key == "P") {
      if (h.kind == HashKind::wait_signal_syn) {
        return fail(it.loc, "21344",
                    "synchronous WAIT with parameters is not allowed: signal parameters are "
                    "evaluated at decoder level only (#WAIT without SYN)");
      }
      ast::Item index = it;
      index.value = it.index;
      const auto i = signal_integer(b, index, "NC4803", 0.0, kSignalParams - 1,
                                    "signal parameter index P[..]", report);
      if (!i) return std::nullopt;
      double value = 0.0;
      if (waits(h.kind)) {  // the target: a variable or P parameter
        VarRef ref;
        if (!ip_.evaluator.resolve(b, it.value, ref)) {
          return fail(it.loc, "NC4804",
                      name + " P[" + std::to_string(*i) +
                          "] = ..: the right-hand side receives the parameter and must be a "
                          "variable or P parameter");
        }
      } else {
        const auto v = signal_value(b, it.value, report);
        if (!v) return std::nullopt;
        value = *v;
      }
      s.params.emplace_back(static_cast<std::uint8_t>(*i), value);
    }
  }
  if (id_item == nullptr) {
    return fail(h.loc, "NC4805",
                name + (s.remove ? " needs the signal number ID=.. or IDMIN=.."
                                 : " needs the signal number ID=.."));
  }
  if (s.remove) {
    if (max_item != nullptr && !s.range) {
      return fail(max_item->loc, "NC4806",
                  "IDMAX is the last number of a range that starts at IDMIN=.., not at ID");
    }
    // IDMIN without IDMAX: every number from IDMIN on (ncsim's reading, docs/lines.md).
    if (max_item == nullptr) s.id_max = s.range ? kMaxSignalId : s.id;
    if (s.id_max < s.id) {
      return fail(max_item->loc, "NC4807",
                  "#SIGNAL REMOVE: IDMAX " + std::to_string(s.id_max) + " is below IDMIN " +
                      std::to_string(s.id));
    }
  }
  return s;
}

std::optional<SignalWait> HashCommands::signal_wait(const ast::Block& b,
                                                    const ast::HashCommand& h) {
  const std::optional<Signal> s = signal_parts(b, h, false);
  if (!s) return std::nullopt;
  return SignalWait{s->id, s->receivers, h.kind == HashKind::signal_read};
}

bool HashCommands::hash_signal(const ast::Block& b, const ast::HashCommand& h) {
  std::optional<Signal> s = signal_parts(b, h, true);
  if (!s) return false;
  if (h.kind == HashKind::signal || h.kind == HashKind::signal_syn || removes(h.kind)) {
    ip_.emit(ip_.line, std::move(*s));
    return true;
  }
  ip_.blocks_without_motion = 0;  // a wait lets time pass
  ++ip_.world_waits;
  if (h.kind == HashKind::wait_signal_syn) {
    ip_.emit(ip_.line, SignalWait{s->id, s->receivers, false});
    return true;
  }
  // #WAIT / #SIGNAL READ: the barrier before this block brought the answer.
  const SignalAnswer& answer = ip_.signal_answer;
  if (h.kind == HashKind::signal_read) {
    VarRef flag;
    flag.cls = ast::VarClass::v_g;
    flag.name = "SIGNAL_READ";
    VarError err;
    ip_.vars.write(flag, answer.received ? 1.0 : 0.0, err);
  }
  if (!answer.received) return true;
  std::size_t k = 0;
  for (std::uint32_t n = 0; n < h.item_count && n < b.items.size(); ++n) {
    const ast::Item& it = b.items[n];
    if (!grammar::iequals(it.keyword, "P")) continue;
    const std::uint8_t i = s->params[k++].first;
    std::optional<double> v = answer.params[i];
    if (!v && ip_.signal_decode_only) v = 0.0;  // check / trace: the parameters are 0
    if (!v) {
      return ip_.fail(it.loc, "21549",
                      command_name(h.kind) + " P[" + std::to_string(i) +
                          "]: the signal received carries no parameter " + std::to_string(i));
    }
    if (!ip_.evaluator.assign(b, it.value, *v)) return ip_.fail_eval();
  }
  return true;
}

}  // namespace ncsim::interp
