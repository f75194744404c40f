#include "program/signals.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace ncsim::program {
namespace {

std::string wait_text(const interp::SignalWait& w) {
  std::string out = (w.read ? "#SIGNAL READ signal " : "signal ") + std::to_string(w.id);
  if (w.senders.empty()) return out + " (broadcast)";
  out += " of channel";
  if (w.senders.size() > 1) out += 's';
  for (std::size_t k = 0; k < w.senders.size(); ++k)
    out += (k == 0 ? " " : ", ") + std::to_string(w.senders[k]);
  return out;
}

}  // namespace

SignalHub::SignalHub(std::vector<std::uint8_t> channels, std::vector<std::string> names) {
  std::sort(channels.begin(), channels.end());
  for (std::size_t k = 0; k < channels.size(); ++k) {
    State s;
    s.number = channels[k];
    s.name = k < names.size() ? names[k] : std::string();
    states_.push_back(std::move(s));
  }
}

SignalHub::State& SignalHub::state(std::uint8_t ch) {
  for (State& s : states_)
    if (s.number == ch) return s;
  std::abort();  // the interpreter refused a channel the run does not have (250008)
}

const SignalHub::State& SignalHub::state(std::uint8_t ch) const {
  return const_cast<SignalHub*>(this)->state(ch);
}

std::string SignalHub::channel_name(std::uint8_t ch) const {
  const State& s = state(ch);
  const std::string number = "channel " + std::to_string(ch);
  return number + (s.name.empty() || s.name == number ? "" : " (" + s.name + ")");
}

void SignalHub::remove(std::uint8_t from, const interp::Signal& s) {
  // PROG-207414923: without CH broadcast signals, with CH the signals to those channels; one
  // (the oldest) for ID, all for IDMIN..IDMAX. What another channel sent in this cycle is not
  // seen yet (lock-step), so it stays whatever order the channels step in.
  const auto matches = [&](const Sent& x, std::uint8_t to) {
    return x.to == to && x.id >= s.id && x.id <= s.id_max && (x.cycle < cycle_ || x.from == from);
  };
  const std::vector<std::uint8_t> targets =
      s.receivers.empty() ? std::vector<std::uint8_t>{0} : s.receivers;
  for (const std::uint8_t to : targets) {
    if (s.range) {
      std::erase_if(sent_, [&](const Sent& x) { return matches(x, to); });
      continue;
    }
    const auto it =
        std::find_if(sent_.begin(), sent_.end(), [&](const Sent& x) { return matches(x, to); });
    if (it != sent_.end()) sent_.erase(it);
  }
}

void SignalHub::send(std::uint8_t from, const interp::Signal& s) {
  if (s.remove) return remove(from, s);
  Sent base;
  base.from = from;
  base.id = s.id;
  base.params = s.params;
  base.cycle = cycle_;
  if (s.receivers.empty()) {  // broadcast: used up after COUNT waits, without COUNT never
    base.left = s.count;
    sent_.push_back(base);
    return;
  }
  for (const std::uint8_t to : s.receivers) {  // one signal per receiver (PROG-207409035)
    Sent one = base;
    one.to = to;
    one.left = s.count.value_or(1);
    sent_.push_back(std::move(one));
  }
}

const SignalHub::Sent* SignalHub::find(std::uint8_t from, std::uint8_t to, std::uint32_t id) const {
  for (const Sent& s : sent_) {
    if (s.cycle >= cycle_ || s.id != id) continue;  // not seen before the next cycle
    if (from == 0 ? s.to == 0 : (s.from == from && s.to == to)) return &s;
  }
  return nullptr;
}

std::optional<interp::SignalAnswer> SignalHub::take(std::uint8_t to, const interp::SignalWait& w,
                                                    std::string& order) {
  std::vector<const Sent*> found;
  if (w.senders.empty()) {
    if (const Sent* s = find(0, to, w.id)) found.push_back(s);
  } else {
    for (const std::uint8_t from : w.senders) {
      // 250002: the signals of one sender to one receiver are used in sending order.
      const auto oldest = std::find_if(sent_.begin(), sent_.end(), [&](const Sent& s) {
        return s.cycle < cycle_ && s.from == from && s.to == to;
      });
      if (oldest != sent_.end() && oldest->id != w.id) {
        order = "the oldest signal channel " + std::to_string(from) + " sent to channel " +
                std::to_string(to) + " is " + std::to_string(oldest->id) + ", not " +
                std::to_string(w.id) +
                ": the #WAITs must use one sender's signals in the "
                "order it sent them (250002)";
        return std::nullopt;
      }
      if (oldest != sent_.end()) found.push_back(&*oldest);
    }
  }
  if (found.size() != std::max<std::size_t>(1, w.senders.size())) return std::nullopt;
  interp::SignalAnswer answer;
  answer.received = true;
  for (const Sent* s : found)  // senders in the order the #WAIT names them
    for (const auto& [i, v] : s->params)
      answer.params[i] = v;
  for (const Sent* s : found) {
    Sent& used = sent_[static_cast<std::size_t>(s - sent_.data())];
    if (used.left && --*used.left == 0) used.id = 0;  // used up (ID 0 is never waited for)
  }
  std::erase_if(sent_, [](const Sent& s) { return s.id == 0; });
  return answer;
}

void SignalHub::block(std::uint8_t ch, const SignalBlock& at) {
  state(ch).blocked = at;
}

void SignalHub::unblock(std::uint8_t ch) noexcept {
  State& s = state(ch);
  s.blocked.reset();
  s.doomed.reset();
}

void SignalHub::end(std::uint8_t ch, std::uint32_t line, std::uint16_t /*file*/) noexcept {
  State& s = state(ch);
  s.ended = true;
  s.end_line = line;
  s.blocked.reset();
}

const std::optional<std::string>& SignalHub::doomed(std::uint8_t ch) const {
  return state(ch).doomed;
}

std::string SignalHub::reason(const State& s, const std::vector<bool>& live) const {
  const interp::SignalWait& w = s.blocked->wait;
  std::string out = channel_name(s.number) + " waits at line " + std::to_string(s.blocked->line) +
                    " for " + wait_text(w) + ", which can never come: ";
  std::vector<std::uint8_t> others = w.senders;
  if (others.empty())
    for (const State& o : states_)
      if (o.number != s.number) others.push_back(o.number);
  if (others.empty()) return out + "no other channel runs that could send it";
  std::string list;
  for (const std::uint8_t ch : others) {
    const State& o = state(ch);
    const auto k = static_cast<std::size_t>(&o - states_.data());
    if (live[k] || (!w.senders.empty() && find(ch, s.number, w.id) != nullptr)) continue;
    list += list.empty() ? "" : "; ";
    list += channel_name(ch);
    if (o.ended) {
      list += " ended after line " + std::to_string(o.end_line);
    } else if (o.blocked) {
      list += " waits itself at line " + std::to_string(o.blocked->line) + " for " +
              wait_text(o.blocked->wait);
    }
  }
  return out + list;
}

bool SignalHub::mark_stuck() {
  if (std::none_of(states_.begin(), states_.end(),
                   [](const State& s) { return s.blocked.has_value(); }))
    return false;  // the common case, every cycle of every run: nothing to decide
  // Channels that can still send: those that run, then those whose wait such a channel (or a
  // signal already sent) can answer, until nothing changes.
  std::vector<bool>& live = live_;  // its storage kept: this runs every cycle a channel waits
  live.assign(states_.size(), false);
  for (std::size_t k = 0; k < states_.size(); ++k)
    live[k] = !states_[k].ended && !states_[k].blocked;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 0; k < states_.size(); ++k) {
      if (live[k] || !states_[k].blocked) continue;
      const State& s = states_[k];
      const interp::SignalWait& w = s.blocked->wait;
      bool answerable = true;
      if (w.senders.empty()) {
        answerable = std::any_of(sent_.begin(), sent_.end(),
                                 [&](const Sent& x) { return x.to == 0 && x.id == w.id; });
        for (std::size_t j = 0; j < states_.size() && !answerable; ++j)
          answerable = j != k && live[j];
      } else {
        for (const std::uint8_t from : w.senders) {
          const bool there = std::any_of(sent_.begin(), sent_.end(), [&](const Sent& x) {
            return x.from == from && x.to == s.number && x.id == w.id;
          });
          const State& o = state(from);
          const bool can = there || live[static_cast<std::size_t>(&o - states_.data())];
          answerable = answerable && can;
        }
      }
      if (answerable) {
        live[k] = true;
        changed = true;
      }
    }
  }
  bool marked = false;
  for (std::size_t k = 0; k < states_.size(); ++k) {
    State& s = states_[k];
    if (live[k] || !s.blocked || s.doomed) continue;
    s.doomed = reason(s, live);
    marked = true;
  }
  return marked;
}

bool SignalPort::take(const SignalBlock& at, std::string& order) {
  taken_ = hub_.take(channel_, at.wait, order);
  if (!taken_) {
    hub_.block(channel_, at);
    return false;
  }
  hub_.unblock(channel_);
  return true;
}

std::optional<interp::SignalAnswer> SignalPort::collect() noexcept {
  std::optional<interp::SignalAnswer> out = std::move(taken_);
  taken_.reset();
  return out;
}

}  // namespace ncsim::program
