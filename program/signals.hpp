#pragma once
// program/signals: the signals channels exchange at run time (#SIGNAL / #WAIT, docs/lines.md).
//
// Purpose: the one store of sent signals of a run (a line of channels, or one program alone),
// and each channel's view of it. PROG-207409035: a signal goes to each receiver channel (a
// signal of its own each) or, without receivers, to any channel (a broadcast signal); a
// receiver's #WAIT uses it up (after COUNT waits when COUNT is given; a broadcast without COUNT
// is never used up). PROG-207421579: #WAIT waits for the signal of each channel it names, or
// for a broadcast signal of that number without names; the signals of one sender to one
// receiver are used in the order they were sent (250002 otherwise).
// Method: lock-step (docs/lines.md "One cycle for the line"): a signal sent in cycle k is seen
// by every channel from cycle k + 1 on, whatever the order the channels step in. A channel
// whose wait is not answered stands blocked at it; after each cycle the line asks which blocked
// waits can never be answered (stuck()): every channel that could still send is itself blocked
// for good, or has ended. Such a wait is doomed: its channel fails it with the reason (NC6401)
// in its next cycle, naming the other channel and its block.
// Inputs: the run's channel numbers; sends, takes and the blocked / ended states per channel.
// Outputs: answers (SignalAnswer with the senders' parameters), the doomed waits' reasons.
// Invariants: deterministic (signals are kept in sending order; channels scanned by number);
// memory: the signals sent and not yet used (a broadcast without COUNT stays until the end or a
// #SIGNAL REMOVE clears it, PROG-207414923).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "interp/command.hpp"

namespace ncsim::program {

/// Where a channel stands blocked: the wait and its block.
struct SignalBlock {
  interp::SignalWait wait;
  std::uint32_t line = 0;  ///< source line of the #WAIT block
  std::uint16_t file = 0;  ///< interp::Command::file (0: the main program)
};

/// The run-time error id of a wait that can never be answered (docs/diagnostics.md).
inline constexpr const char* kSignalStuckId = "NC6401";

class SignalHub {
 public:
  /// `channels`: the run's channel numbers (1 .. interp::kMaxChannels, distinct), each with
  /// the name shown in messages (`names` may be empty: "channel <n>").
  explicit SignalHub(std::vector<std::uint8_t> channels, std::vector<std::string> names = {});

  /// The start of cycle `k` (0, 1, ...): signals sent before it are seen from now on.
  void begin_cycle(std::uint64_t k) noexcept { cycle_ = k; }
  /// Channel `from` sends `s` (a #SIGNAL REMOVE: clears the signals it names, remove()).
  void send(std::uint8_t from, const interp::Signal& s);
  /// Channel `to` takes what `w` waits for when all of it is there, using it up; nullopt when
  /// something is missing (nothing is used then). `order` is set (250002) when the oldest
  /// signal a sender sent to `to` is another one than `w` asks for.
  std::optional<interp::SignalAnswer> take(std::uint8_t to, const interp::SignalWait& w,
                                           std::string& order);

  /// Channel `ch` stands at `at`, its wait not answered; unblock() when it was.
  void block(std::uint8_t ch, const SignalBlock& at);
  void unblock(std::uint8_t ch) noexcept;
  /// Channel `ch` stands at a wait not answered.
  bool blocked(std::uint8_t ch) const { return state(ch).blocked.has_value(); }
  /// Channel `ch` ended (program end or error) at `line` of `file`: it sends nothing more.
  void end(std::uint8_t ch, std::uint32_t line, std::uint16_t file) noexcept;
  /// After a cycle: marks every blocked wait that can never be answered as doomed (with its
  /// reason); true when one was marked.
  bool mark_stuck();
  /// The reason channel `ch`'s wait is doomed (nullopt: it is not).
  const std::optional<std::string>& doomed(std::uint8_t ch) const;
  /// "channel 2 (sorter)": the number and the name the hub was given ("channel 2" without one,
  /// or when the name is that).
  std::string channel_name(std::uint8_t ch) const;

 private:
  struct Sent {
    std::uint8_t from = 0;
    std::uint8_t to = 0;  ///< 0: broadcast
    std::uint32_t id = 0;
    std::optional<std::uint32_t> left;  ///< waits until used up; nullopt: never (broadcast)
    std::vector<std::pair<std::uint8_t, double>> params;
    std::uint64_t cycle = 0;  ///< sent in this cycle: seen from the next one
  };
  struct State {
    std::uint8_t number = 0;
    std::string name;
    std::optional<SignalBlock> blocked;
    bool ended = false;
    std::uint32_t end_line = 0;
    std::optional<std::string> doomed;
  };
  /// #SIGNAL REMOVE of channel `from` (PROG-207414923).
  void remove(std::uint8_t from, const interp::Signal& s);
  State& state(std::uint8_t ch);
  const State& state(std::uint8_t ch) const;
  /// The signal `to` would take from `from` (0: a broadcast) for `id`; null when none is there.
  const Sent* find(std::uint8_t from, std::uint8_t to, std::uint32_t id) const;
  /// Why `s`'s wait can never be answered, given the channels that can still send (`live`).
  std::string reason(const State& s, const std::vector<bool>& live) const;

  std::vector<State> states_;
  std::vector<Sent> sent_;
  std::vector<bool> live_;  ///< mark_stuck()'s channels that can still send (kept: per cycle)
  std::uint64_t cycle_ = 0;
};

/// One channel's view of the hub: what its ProgramSource and its channel loop use.
class SignalPort {
 public:
  SignalPort(SignalHub& hub, std::uint8_t channel) noexcept : hub_(hub), channel_(channel) {}
  std::uint8_t channel() const noexcept { return channel_; }
  void send(const interp::Signal& s) { hub_.send(channel_, s); }
  /// Takes what `at.wait` asks for: true when it was there (the answer then waits in
  /// collect()); false: the channel stands blocked at `at`. `order`: see SignalHub::take.
  bool take(const SignalBlock& at, std::string& order);
  /// #SIGNAL READ: what `w` asks for when it is there (used up), else nullopt; never blocks.
  std::optional<interp::SignalAnswer> read(const interp::SignalWait& w, std::string& order) {
    return hub_.take(channel_, w, order);
  }
  /// The answer the last successful take() got (once; nullopt after).
  std::optional<interp::SignalAnswer> collect() noexcept;
  /// The channel ended: it sends nothing more.
  void end(std::uint32_t line, std::uint16_t file) noexcept { hub_.end(channel_, line, file); }
  /// Why this channel's wait can never be answered (nullopt: it can, or it is not waiting).
  const std::optional<std::string>& doomed() const { return hub_.doomed(channel_); }

 private:
  SignalHub& hub_;
  std::uint8_t channel_;
  std::optional<interp::SignalAnswer> taken_;
};

}  // namespace ncsim::program
