// axes/profile_compensation.cpp: the 3-phase trapezoid of 002_* 2.5 in virtual time
// tau = s / VP (s: base distance since the compensation started).
//
// Over tau_end = L / VP the offset must grow by D. With ramps a1 (first) and a3 (last) and the
// overspeed plateau vk <= VK covering the whole length (002_* 2.5 "auf der ganzen
// Kompensationslaenge"): D = vk (tau_end - k vk), k = (1/a1 + 1/a3) / 2. The largest feasible
// |D| uses vk* = min(VK, tau_end / (2k)); a larger request is cut to it.

#include "axes/profile_compensation.hpp"

#include <algorithm>
#include <cmath>

namespace ncsim::axes {

std::optional<Compensation> Compensation::plan(const CompensationRequest& r) noexcept {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(r.length) || !positive(r.v_process) || !positive(r.v_extra) || !positive(r.acc) ||
      !positive(r.dec) || !std::isfinite(r.difference) || r.difference == 0.0) {
    return std::nullopt;
  }
  Compensation out;
  out.v_process_ = r.v_process;
  const double sign = r.difference > 0.0 ? 1.0 : -1.0;
  // 002_* 2.5 hint 4: D > 0 starts with AK+, D < 0 starts with AK-.
  const double a_first = sign > 0.0 ? r.acc : r.dec;
  const double a_last = sign > 0.0 ? r.dec : r.acc;
  out.dec_ = a_last;
  const double tau_end = r.length / r.v_process;
  const double k = 0.5 * (1.0 / a_first + 1.0 / a_last);
  const double v_star = std::min(r.v_extra, tau_end / (2.0 * k));
  const double d_max = v_star * (tau_end - k * v_star);
  double d = std::abs(r.difference);
  if (d > d_max) {
    d = d_max;
    out.reduced_ = true;
  }
  const double vk = std::min(
      v_star, 2.0 * d / (tau_end + std::sqrt(std::max(0.0, tau_end * tau_end - 4.0 * k * d))));
  const double t1 = vk / a_first;
  const double t3 = vk / a_last;
  const double t2 = std::max(0.0, tau_end - t1 - t3);
  const double c1 = sign * 0.5 * vk * t1;
  const double c2 = c1 + sign * vk * t2;
  out.ramps_[0] = Ramp{0.0, 0.0, 0.0, sign * a_first};
  out.ramps_[1] = Ramp{t1, c1, sign * vk, 0.0};
  out.ramps_[2] = Ramp{t1 + t2, c2, sign * vk, -sign * a_last};
  out.tau_end_ = t1 + t2 + t3;
  out.difference_ = c2 + sign * 0.5 * vk * t3;
  out.ramps_[3] = Ramp{out.tau_end_, out.difference_, 0.0, 0.0};
  return out;
}

CompensationValue Compensation::at(double tau) const noexcept {
  CompensationValue out;
  if (tau >= tau_end_) {
    out.c = difference_;
    out.done = true;
    return out;
  }
  tau = std::max(0.0, tau);
  std::size_t i = 0;
  while (i < 2 && ramps_[i + 1].tau_start <= tau)
    ++i;
  const Ramp& r = ramps_[i];
  const double dt = tau - r.tau_start;
  out.c = r.c + dt * (r.dc + 0.5 * dt * r.ddc);
  out.dc = r.dc + dt * r.ddc;
  out.ddc = r.ddc;
  out.braking = i == 2;
  return out;
}

bool Compensation::stop_at(double tau) noexcept {
  const CompensationValue now = at(tau);
  if (now.done || now.braking) return false;
  // 002_* 2.5 "Kompensationsstop": the phase limits are moved, D becomes what is really
  // compensated when the overspeed has been ramped down with the final ramp.
  const double sign = now.dc >= 0.0 ? 1.0 : -1.0;
  const double t3 = std::abs(now.dc) / dec_;
  ramps_[1] = Ramp{tau, now.c, now.dc, 0.0};
  ramps_[2] = Ramp{tau, now.c, now.dc, -sign * dec_};
  tau_end_ = tau + t3;
  difference_ = now.c + 0.5 * now.dc * t3;
  ramps_[3] = Ramp{tau_end_, difference_, 0.0, 0.0};
  return true;
}

}  // namespace ncsim::axes
