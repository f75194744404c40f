// bench/axes_digest: a bit-for-bit fingerprint of the PTP planner, for speed rounds that must
// not change a single plan (issue 36). Prints one FNV-1a digest per set: the axes_bench requests
// (bench/axes_inputs.hpp) planned under each rule, and 200,000 seeded draws over issue 11's
// ranges (jerk/test_random.hpp) under the time-optimal rule. Each digest covers the status, the
// duration, t_brake, the level, the end state and every phase (start time, duration, p, v, a,
// jerk) as raw IEEE bits, so the same digest before and after a change means the same plans.
//   build/release/bench/axes_digest        (Release, -DNCSIM_BENCH=ON)

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

#include "axes/profile.hpp"
#include "bench/axes_inputs.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;

// FNV-1a over the bytes of the values added.
class Digest {
 public:
  void add(double x) noexcept {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (bits >> (8 * i)) & 0xffU;
      hash_ *= 1099511628211ULL;
    }
  }
  void add(ncsim::axes::Result r, const Profile& p) noexcept {
    add(static_cast<double>(r));
    add(p.duration());
    add(p.t_brake());
    add(p.v_level());
    const auto end = p.end_state();
    add(end.p);
    add(end.v);
    add(end.a);
    add(static_cast<double>(p.phases().size()));
    for (const auto& ph : p.phases()) {
      for (const double x : {ph.t_start, ph.duration, ph.p, ph.v, ph.a, ph.j})
        add(x);
    }
  }
  std::uint64_t value() const noexcept { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

}  // namespace

int main() {
  Profile p;
  for (const bool moving : {false, true}) {
    const auto inputs = ncsim::bench::make_axes_inputs(moving, 4096);
    for (const ProfileRule rule : {ProfileRule::manual, ProfileRule::time_optimal}) {
      Digest d;
      for (const auto& in : inputs)
        d.add(ncsim::axes::plan_position(in.start, in.target, in.dyn, p, rule), p);
      std::printf("axes_bench %-7s %-12s %016llx\n", moving ? "moving" : "rest",
                  rule == ProfileRule::manual ? "manual" : "time_optimal",
                  static_cast<unsigned long long>(d.value()));
    }
  }
  std::mt19937_64 rng(7);
  Digest d;
  for (int i = 0; i < 200000; ++i) {
    const auto arrival = i % 2 != 0 ? ncsim::test::Arrival::half : ncsim::test::Arrival::always;
    const auto m = ncsim::test::draw_move(rng, arrival);
    const ncsim::axes::PositionTarget target{m.p1, m.v1};
    d.add(ncsim::axes::plan_position(m.start, target, m.lim, p, ProfileRule::time_optimal), p);
  }
  std::printf("issue 11 draws (200000, seed 7) time_optimal %016llx\n",
              static_cast<unsigned long long>(d.value()));
  return 0;
}
