#include "program/move_builder.hpp"

#include <string>

#include "core/diagnostic.hpp"
#include "interp/cs_select.hpp"
#include "interp/trace.hpp"

namespace ncsim::program {
namespace {

planner::Transition to_planner(interp::Transition t) {
  switch (t) {
    case interp::Transition::accelerate_at_start:
      return planner::Transition::accelerate_at_start;
    case interp::Transition::stop_at_end:
      return planner::Transition::stop_at_end;
    case interp::Transition::decel_at_end:
      return planner::Transition::decel_at_end;
    case interp::Transition::decel_after_end:
      return planner::Transition::decel_after_end;
  }
  return planner::Transition::accelerate_at_start;
}

planner::SlopeType to_planner(interp::SlopeType s) {
  switch (s) {
    case interp::SlopeType::step:
      return planner::SlopeType::step;
    case interp::SlopeType::trapez:
      return planner::SlopeType::trapez;
    case interp::SlopeType::sin2:
      return planner::SlopeType::sin2;
    case interp::SlopeType::hsc:
      return planner::SlopeType::hsc;
  }
  return planner::SlopeType::step;
}

const char* contour_name(interp::ContourKind k) {
  switch (k) {
    case interp::ContourKind::dev:
      return "DEV";
    case interp::ContourKind::dist:
      return "DIST";
    case interp::ContourKind::dist_soft:
      return "DIST_SOFT";
    case interp::ContourKind::dist_master:
      return "DIST_MASTER";
    case interp::ContourKind::pos:
      return "POS";
    case interp::ContourKind::ptp:
      return "PTP";
  }
  return "?";
}

}  // namespace

std::shared_ptr<const planner::AxisWeights> axis_weights(const interp::DynamicsWeights& w,
                                                         std::span<const std::uint8_t> axes,
                                                         bool rapid) {
  planner::AxisWeights out;
  bool any = false;
  for (std::size_t k = 0; k < axes.size() && k < planner::kMaxAxes; ++k) {
    const std::uint8_t m = axes[k];
    out.v[k] = rapid ? w.v_rapid : w.v_feed[m];
    out.a[k] = rapid ? w.a_rapid[m] : w.a_feed[m];
    out.j[k] = out.a[k] / (rapid ? w.ramp_rapid : w.ramp_feed[m]);
    any = any || out.v[k] != 1.0 || out.a[k] != 1.0 || out.j[k] != 1.0;
  }
  return any ? std::make_shared<const planner::AxisWeights>(out) : nullptr;
}

void MoveBuilder::check_soft_limits(const interp::Command& c) const {
  core::DiagnosticList limits;
  interp::add_soft_limit_errors(c, parts_.machine, parts_.errors.file_name(c.file), limits);
  if (!limits.items().empty()) {
    const core::Diagnostic& d = limits.items().front();
    parts_.errors.raise_in(c.file, c.line, d.id, d.message);
  }
}

planner::Move MoveBuilder::to_move(const interp::Motion& m, std::uint32_t line) {
  const machines::Machine& machine = parts_.machine;
  const AxisLayout& layout = parts_.layout;
  const std::uint16_t file = parts_.errors.file();
  // check's NC4601, refused here before the block moves (one rule; issue 34 item 22)
  if (refuse_soft_limits_ && m.frame == interp::CoordFrame{}) {
    check_soft_limits(interp::Command{line, file, m});
  } else if (refuse_soft_limits_) {  // under a #CS chain: in MCS, as check does (issue 33)
    if (const auto in_mcs =
            interp::command_in_mcs(interp::Command{line, file, m}, parts_.frames.active(), machine))
      check_soft_limits(*in_mcs);
  }
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    if (layout.slot[i] < 0 && (((m.programmed >> i) & 1u) != 0 || m.end[i] != m.start[i])) {
      parts_.errors.not_supported(line, "motion of axis " + machine.axes[i].name +
                                            " (spindle / conveyor axes are not path-interpolated)");
    }
  }
  planner::Move mv;
  mv.axis_count = layout.count();
  mv.path_axes = layout.path_axes;
  mv.start = parts_.frames.to_mcs(m.frame, m.start, line);
  mv.end = parts_.frames.to_mcs(m.frame, m.end, line);
  mv.rapid = m.kind == interp::MotionKind::rapid;
  mv.feed = m.feed;
  mv.block_time = m.block_time;
  mv.end_feed = m.end_feed;
  if (m.arc) parts_.frames.arc_to_mcs(m, line, mv);
  set_modal(m.modal, mv, line);
  mv.line = line;
  mv.file = file;  // a block held for its ball goes out after later commands: it keeps its own
  if (mv.transformed) parts_.trafo.check_workspace(mv, line);
  if (m.frame.space == interp::Space::pcs1) pcs1_share(mv);
  return mv;
}

void MoveBuilder::pcs1_share(planner::Move& mv) const {
  // Under #TRAFO ON reserved on the joints, else the PCS1 velocity split on the axes
  // (sync-feed, docs/conveyor.md S-5).
  if (mv.transformed)
    parts_.trafo.reserve_belt_share(mv);
  else if (mv.arc || mv.spline)
    mv.belt = parts_.belt.belt();  // their tangent turns: the symmetric limit both ways
  else
    parts_.belt.split(mv);
}

void MoveBuilder::check_vertex(const interp::SplinePoint& p, std::uint32_t line) const {
  const machines::Machine& machine = parts_.machine;
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    if (parts_.layout.slot[i] < 0 && ((p.programmed >> i) & 1u) != 0) {
      parts_.errors.not_supported(line, "spline point on axis " + machine.axes[i].name +
                                            " (spindle / conveyor axes are not path-interpolated)");
    }
  }
  // check's NC4601 for a vertex, refused before the section moves on (issue 34 item 22)
  if (refuse_soft_limits_ && p.frame == interp::CoordFrame{})
    check_soft_limits(interp::Command{line, parts_.errors.file(), p});
}

void MoveBuilder::set_modal(const interp::ModalSnapshot& s, planner::Move& mv, std::uint32_t line) {
  mv.transition = to_planner(s.transition);
  mv.exact_stop = s.exact_stop;
  if (s.contouring) {
    switch (s.contour.kind) {
      case interp::ContourKind::dev:
        mv.contour = planner::Contour::tolerance;
        mv.path_dev = s.contour.path_dev;
        break;
      case interp::ContourKind::dist:  // isg-language.md §5.3 (PROG-475180811)
        mv.contour = planner::Contour::distance;
        mv.pre_dist = s.contour.pre_dist;
        mv.post_dist = s.contour.post_dist;
        break;
      default:
        parts_.errors.not_supported(line, std::string("#CONTOUR MODE ") +
                                              contour_name(s.contour.kind) +
                                              " (only DEV and DIST are interpolated)");
    }
  }
  mv.transvelmin = s.transvelmin;
  mv.slope = to_planner(s.slope);
  if (s.weights != weights_src_) {  // G127..G233: converted once per change
    weights_src_ = s.weights;
    const std::span<const std::uint8_t> axes = parts_.layout.axes;
    weights_feed_ = s.weights ? axis_weights(*s.weights, axes, false) : nullptr;
    weights_rapid_ = s.weights ? axis_weights(*s.weights, axes, true) : nullptr;
  }
  mv.weights = mv.rapid ? weights_rapid_ : weights_feed_;
  mv.transformed = s.kinematics_on;  // X, Y, Z are the TCP (program/trafo_path)
}

}  // namespace ncsim::program
