#pragma once
// program/program_source: the interpreter's command stream as an ipo::Source, and the machine's
// axis lists as the interpolator's Config.
//
// Purpose: the first end-to-end seam interp -> planner -> ipo (`ncsim time`, `ncsim run`).
// Inputs: an interp::Interpreter (pulled lazily), the machine it decodes for.
// Outputs: ipo::Item values (planner::Move / ipo::Dwell) in program order; Config with one
// AxisLimits and one ExactStop per interpolated axis (docs/ipo.md "From program to cycles").
// Method: Motion (rapid, linear, arc) becomes a Move in the interpolated-axis order, in MCS:
// under a #CS chain its points go through the chain's frame here (program_frames.cpp; an arc
// under a rotation becomes an arc in the rotated plane, planner::ArcPlane); a #SPLINE section
// (SplineBegin / SplinePoint / SplineEnd) goes through planner::SplineBuilder and becomes one
// spline Move per curve piece (program_spline.cpp; never chopped into lines); G04 a Dwell;
// #FLUSH / #FLUSH WAIT a ChannelWait (the path stops at the end of the block before it, the
// events before it done; #FLUSH CONTINUE passes: the next block is always there); Tech,
// Message, ProgramStop (M00/M01 do not stop in time/run: no operator), WaitIndp and the
// switching-off forms of #TRAFO / #CAXTRACK pass; #CS selections update the adapter's
// own #CS stack (the interpreter's rules, machines::CsStack); End ends the stream. Barriers are
// answered from the decode-only state (next_decode_only), or, under a scenario
// (answer_barriers_from), their V.E. names from the scenario's VeStore; with `flush` the source
// first hands out a 0 s Dwell, so the path stops and every block before the barrier has run when
// the barrier is answered (the kernel's synchronous V.E. read; docs/ipo.md "Scenario"). Every other
// command is a program error `not supported: <what>` (NC6001) at its line: nothing is skipped
// silently. Errors end the stream like End does, and error() holds the diagnostic: the blocks
// decoded before the faulty one run to their end and the path stops there, then the caller reports
// the error (the channel stops at the faulty block; docs/ipo.md). Memory: one Command.

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/cs_stack.hpp"
#include "machines/machine.hpp"
#include "planner/spline.hpp"
#include "program/channel_event.hpp"
#include "program/trafo.hpp"
#include "scenario/player.hpp"
#include "tracking/caxtrack.hpp"  // --- static-saw
#include "tracking/trafo_sync.hpp"
#include "tracking/x_virtual.hpp"  // --- static-saw

namespace ncsim::ipo {

/// Id of the adapter's `not supported: ...` program errors.
inline constexpr const char* kNotSupportedId = "NC6001";

/// Machine indices of the axes the path interpolator drives, in machine order: linear and
/// rotary axes; spindles, encoder-only axes and the conveyor axis are not interpolated.
std::vector<std::uint8_t> interpolated_axes(const machines::Machine& machine);

/// The interpolator Config of `machine` (docs/ipo.md "Machine limits"): per interpolated axis
/// v_max P-AXIS-00212, v_reference = v_max (no ISG key), v_rapid P-AXIS-00209,
/// A+ = min(P-AXIS-00001, P-AXIS-00008), A- = min(P-AXIS-00002, P-AXIS-00008),
/// J = Dynamics::jerk_feed(), C0 NCSIM-AXIS-020, G00 slope a_rapid = min(P-AXIS-00004,
/// P-AXIS-00008) and j_rapid = a_rapid / P-AXIS-00200 (Dynamics::jerk_rapid); ExactStop window
/// P-AXIS-00236, settling P-AXIS-00532 (0 when not monitored); window P-CHAN-00650 look-ahead
/// blocks; cycle `t_cycle` [s] (no list key: the manuals at hand name none, the cycle is the NC
/// SAF task's; the CLI's default is the seeds' 1 ms, docs/ipo.md "The cycle time").
Config machine_config(const machines::Machine& machine, double t_cycle);

/// The CLI's interpolation cycle when `--cycle-us` is not given [s].
inline constexpr double kDefaultCycle = 0.001;

/// A block's planner weights (planner::AxisWeights) from the interpreter's, for the
/// interpolated machine axes `axes`, of a G00 block when `rapid`; null when all are 100 %.
std::shared_ptr<const planner::AxisWeights> axis_weights(const interp::DynamicsWeights& w,
                                                         std::span<const std::uint8_t> axes,
                                                         bool rapid);

class ProgramSource final : public Source {
 public:
  /// `interp` and `machine` must outlive the source. `t_cycle` [s] is the interpolation cycle the
  /// run's channel steps with: the static unit's joint check (joint_belt_check) asks the planner's
  /// link rules at it. Throws std::invalid_argument when the machine has no interpolated axis or
  /// `t_cycle` is not > 0.
  ProgramSource(interp::Interpreter& interp, const machines::Machine& machine,
                double t_cycle = kDefaultCycle);

  /// The next Move, Dwell or ChannelWait; false at End or at a program error (error() then
  /// holds it).
  bool next(Item& out) override;
  /// The oldest channel event with tag <= up_to (program/channel_event.hpp).
  bool take_event(std::uint32_t up_to, ChannelEvent& out) override;

  /// The error that ended the stream: the interpreter's, or the adapter's NC6001. Check it
  /// after the interpolator finished: a stream that ends with an error is not a program end.
  const core::Diagnostic* error() const { return error_ ? &*error_ : nullptr; }

  /// Barriers that want V.E. values are answered from `store` (must outlive the source; null:
  /// the decode-only state again). `flush`: the path stops before each such barrier (a 0 s
  /// Dwell is handed out first), so a value written while the blocks before it ran reaches it.
  /// The program's own V.E. assignments are written into `store` as they are decoded
  /// (docs/scenario.md "The program's V.E. writes").
  void answer_barriers_from(scenario::VeStore* store, bool flush) {
    store_ = store;
    flush_ = flush;
    interp_.record_ve_writes(store != nullptr);  // --- operator
  }
  // --- planner: position barriers from run time (docs/ipo.md "Position barriers").
  /// Position barriers are answered from `set_positions`: the channel's set positions after
  /// its last cycle (Channel::axes().command, interpolated order; must outlive the source;
  /// null: the decode-only state). A barrier that asks for an axis an INDP_ASYN motion may
  /// still move (the interpreter asks for such an axis only when the block programs it again)
  /// first stops the path and waits for that motion (a `#WAIT INDP` of those axes: P-CHAN-00451's
  /// implicit synchronisation); the answer then gives those axes where they stand.
  void answer_positions_from(const AxisVec* set_positions) noexcept { positions_ = set_positions; }
  /// --- issue 34 item 22: refuse, before it moves, a block whose programmed target (or arc
  /// extent, spline point) in the MCS without kinematics lies beyond the soft limits, with
  /// `check`'s NC4601 at its line (interp::add_soft_limit_errors), so `time` / `run` and
  /// `check` apply one rule. Off by default (the channel's per-cycle monitor NC5501 / NC5502
  /// alone, as the unit tests of the monitor need); every CLI run turns it on.
  void refuse_beyond_soft_limits(bool on) noexcept { refuse_soft_limits_ = on; }

 private:
  struct Stop {};  ///< thrown by fail() to leave the visit; caught in next()
  /// What a step of pull() did: handed out an item, go on with the next command, the stream
  /// ended, or nothing (release_held: the command goes on its way).
  enum class Pulled : std::uint8_t { item, again, end, none };
  bool pull(Item& out);
  /// The next command: the one held back, else the interpreter's (its V.E. writes to store_).
  std::optional<interp::Command> take_command();
  /// A command that emits nothing and does not stop the path (a held block stays held).
  bool rides_along(const interp::Command& cmd) const noexcept;
  /// Hands out the static unit's held part or the PCS1 block held for its ball when `cmd` does
  /// not continue its path (`cmd` is then held back for the next pull).
  Pulled release_held(std::optional<interp::Command>& cmd, Item& out);
  /// The block's shared INDP_SYN wait goes out when `cmd` is not of that block (held back).
  bool close_syn_wait(std::optional<interp::Command>& cmd, Item& out);
  /// A channel event (or the catch-up / departure motion after #SYNC IN / OUT): queued with
  /// its tag; the path stops where it needs to.
  Pulled route_event(interp::Command& cmd, Item& out);
  /// Every other command: motion, dwell, flush, barrier, frames, splines, end.
  Pulled run_command(interp::Command& cmd, Item& out);
  void motion(const interp::Motion& body, std::uint32_t line);
  /// A barrier answered now (false) or after the path stopped (true: `out` holds the stop).
  bool barrier(const interp::Barrier& body, std::uint32_t line, Item& out);
  /// Answers the open barrier: the decode-only state with the store's V.E. values and, for
  /// the axes waited for (run_time_), the set positions.
  void answer(const interp::Barrier& barrier);
  /// --- planner: state.position of the run_time_ axes from *positions_, in barrier.frame.
  void answer_positions(const interp::Barrier& barrier, interp::RunState& state);
  /// --- planner: keeps indp_running_ current for an event queued.
  void note_indp(const interp::CommandBody& body) noexcept;
  [[noreturn]] void fail(std::uint32_t line, const std::string& what);
  /// --- conveyor-tail: the program error `id` at `line` of source file `file` (a Move's own,
  /// which may be older than file_: a block held for its tolerance ball).
  [[noreturn]] void fail_in(std::uint16_t file, std::uint32_t line, const std::string& id,
                            const std::string& what);
  /// --- issue 34 item 22: the first of check's NC4601 errors of `c` (interp::
  /// add_soft_limit_errors) ends the stream at its line, before the block moves.
  void check_soft_limits(const interp::Command& c);
  planner::Move to_move(const interp::Motion& m, std::uint32_t line);
  /// Dynamics weightings (docs/interp.md "Dynamics weighting"): the interpreter's last, and
  /// the planner's for feed and G00 blocks (interpolated order), made once per change.
  std::shared_ptr<const interp::DynamicsWeights> weights_src_;
  std::shared_ptr<const planner::AxisWeights> weights_feed_;
  std::shared_ptr<const planner::AxisWeights> weights_rapid_;
  /// The modal fields of a Move from the block's snapshot (transition, contour, slope, ...).
  void set_modal(const interp::ModalSnapshot& s, planner::Move& mv, std::uint32_t line);
  /// Interpolated-axis values of machine values `p` given in `frame`, in MCS (program_frames).
  planner::AxisVec to_mcs(const interp::CoordFrame& frame, const interp::AxisValues& p,
                          std::uint32_t line);
  /// --- conveyor-sync: the frame `frame` -> MCS: the #CS chain, then T0 under PCS1.
  machines::Frame frame_to_mcs(const interp::CoordFrame& frame) const;
  /// --- conveyor-sync: the catch-up / departure Motion as a channel event body: `end` holds
  /// the interpolated axes' values in MCS at belt travel 0 (interpolated order, frame MCS).
  interp::CommandBody sync_motion(const interp::CommandBody& motion, std::uint32_t line);
  /// Sets move.arc (and move.arc_plane under a rotated #CS) from the motion's arc, in MCS
  /// (program_frames.cpp).
  void arc_to_mcs(const interp::Motion& m, std::uint32_t line, planner::Move& move);
  /// #CS DEF / ON / OFF / OFF ALL on the adapter's stack (program_frames.cpp).
  void select_cs(const interp::SelectCs& sel, std::uint32_t line);
  /// #SPLINE section (program_spline.cpp): completed pieces are queued as spline Moves.
  void spline_begin(const interp::SplineBegin& b, std::uint32_t line);
  void spline_point(const interp::SplinePoint& p, std::uint32_t line);
  void spline_end(std::uint32_t line);
  void queue_pieces(std::span<const planner::SplinePiece> pieces);
  /// One piece (or a part of it, planner::split_near_cusp) as a Move into emit_path().
  void queue_piece(const planner::SplinePiece& piece);

  interp::Interpreter& interp_;
  const machines::Machine& machine_;
  double t_cycle_;                  ///< the run's interpolation cycle [s]
  std::vector<std::uint8_t> axes_;  ///< interpolated machine indices
  std::vector<int> slot_;           ///< machine index -> interpolated index, -1: not interpolated
  planner::AxisMask path_axes_ = 0;
  std::optional<core::Diagnostic> error_;
  std::uint32_t line_ = 0;
  std::uint16_t file_ = 0;  ///< Command::file of the last command
  // #CS frames (program_frames.cpp).
  machines::CsStack cs_;
  machines::Frame cs_frame_;            ///< cs_.active_frame(): PCS -> MCS
  std::array<int, 3> xyz_{-1, -1, -1};  ///< machine indices of X, Y, Z (-1: none)
  // #SPLINE (program_spline.cpp): the builder of the open section and its modal Move.
  std::optional<planner::SplineBuilder> spline_;
  planner::Move spline_modal_;
  /// --- belt-jerk: the open section is programmed in PCS1 (its pieces get the belt's share).
  bool spline_pcs1_ = false;
  /// Items of the last command not yet handed out (spline pieces, #CAXTRACK turn blocks, the
  /// static unit's parts: emit_path()); empty before each command is pulled.
  std::deque<Item> queue_;
  /// --- conveyor-tail: pull() handed out a queued item (it carries its own file, next()).
  bool out_queued_ = false;
  // Run-time barrier answers (answer_barriers_from).
  scenario::VeStore* store_ = nullptr;
  bool flush_ = false;
  std::optional<interp::Barrier> open_;  ///< a barrier waiting for the flush's Dwell to pass
  // --- planner: run-time position answers (answer_positions_from).
  const AxisVec* positions_ = nullptr;  ///< the channel's set positions; null: none
  bool refuse_soft_limits_ = false;     ///< refuse_beyond_soft_limits()
  interp::AxisMask indp_running_ = 0;   ///< machine axes an INDP_ASYN motion may still move
  interp::AxisMask run_time_ = 0;       ///< axes the open barrier answers from run time
  // Channel events (program/channel_event.hpp).
  std::deque<ChannelEvent> events_;  ///< not yet taken by the channel
  std::uint32_t tag_ = 0;            ///< tag of the last event queued
  std::uint32_t given_ = 0;          ///< largest tag handed out with an item
  bool end_reached_ = false;         ///< End came after a final ChannelWait
  // --- trafo: #TRAFO ON / OFF (program_kinematics.cpp, docs/ipo.md "Kinematics in run and
  // time").
  /// #KIN ID / #TRAFO: at a switch of #TRAFO a 0 s Dwell goes out first (the path stands at the
  /// switch; true: `out` holds it); #TRAFO ON with another kinematic than the machine's first
  /// is NC6001.
  bool kinematics(const interp::Kinematics& k, std::uint32_t line, Item& out);
  /// A transformed Move whose path leaves the kinematic's workspace: the kinematic's error
  /// (NC3201 / NC3202) at its line.
  void check_workspace(const planner::Move& move, std::uint32_t line);
  [[noreturn]] void fail_with(std::uint32_t line, const std::string& id, const std::string& what);
  /// A transformed G00 / G01 / G02 / G03 Move or spline piece in PCS1: the belt's share (1.1 x
  /// CONV_VEL, the 50653 margin) of the joints wherever the belt can carry the block (forward from
  /// the latch, inside the conveyor workspace): its F capped for the joints' V (and by the
  /// acceleration and jerk shares' bisection; a G00's of its joints' rapid limits, the cap in
  /// Move::feed for planner::path_limits), the a and j shares in Move::belt_joints
  /// (ipo::belt_share, docs/conveyor.md "Machining in PCS1"); NC6211 when the belt alone needs a
  /// joint's V or its share with the path at rest leaves a joint less than 1 % of its A or J.
  void reserve_belt_share(planner::Move& move);
  /// The belt's carry for belt_share (1.1 x CONV_VEL, the conveying direction, the conveyor
  /// workspace); false without a kinematic, a conveyor or a CONV_VEL.
  bool belt_carry(BeltCarry& carry) const;
  /// ipo::belt_share of `path` at `feed` under the carry with the joints' limits `joints`; an
  /// overload is NC6211 at block `at` (its line and file).
  BeltShare belt_share_at(const planner::Segment& path, double feed, const planner::Move& at,
                          std::span<const planner::AxisLimits> joints);
  // --- trafo-pcs1: the tolerance ball between two PCS1 blocks (docs/conveyor.md "Machining in
  // PCS1"): a transformed PCS1 block that ends in a ball (G61 / G261) is held (ball_held_)
  // until the next command; a next Motion gets the ball built as the planner builds it and
  // the ball's share goes into the held block's (reserve_ball_share); anything else releases
  // the held block as it is before that command's items (pull()).
  /// A transformed G01 / G02 / G03 Move in PCS1 (`pcs1`) that ends in a contoured corner.
  bool holds_for_ball(const planner::Move& move, bool pcs1) const;
  /// The ball between `in` and `out` (planner::corner_blend, DEV or DIST): its belt share
  /// (ipo::belt_share at the slower feed of the two) raises in's acceleration and jerk shares where
  /// larger and caps in's feed where lower (the planner runs the ball with in's limits).
  void reserve_ball_share(planner::Move& in, const planner::Move& out);
  std::optional<planner::Move> ball_held_;  ///< the block whose ball waits for the next Motion
  /// Emits ball_held_ (if any): with its ball's share into the next Motion `next`
  /// (reserve_ball_share), or as it is when `next` is null (another command, or the next
  /// Motion's error).
  void ball_release(const planner::Move* next);
  /// The next Motion's error while a block was held: raised after the held block went out.
  std::optional<core::Diagnostic> held_error_;
  std::optional<MachineTrafo> trafo_;  ///< the machine's kinematic, built at the first #TRAFO
  bool trafo_on_ = false;              ///< #TRAFO ON as handed out
  double belt_conv_vel_ = 0.0;         ///< CONV_VEL of the last #SYNC IN [mm/s]
  // --- end trafo
  bool sync_motion_ = false;  ///< --- conveyor-sync: the next Motion is a catch-up / departure
  /// --- sync-feed: the velocity the belt takes of each interpolated axis while synchronised
  /// (ipo::pcs1_belt of the last #SYNC IN's CONV_VEL; planner::Move::belt of PCS1 blocks).
  planner::AxisVec belt_{};
  /// --- belt-split: per interpolated axis, the belt's velocity on it at CONV_VEL, signed
  /// (conveying component x CONV_VEL [mm/s]); 0 off the conveyor.
  planner::AxisVec belt_dir_{};
  /// --- sync-feed: sets belt_ at #SYNC IN, clears it at #SYNC OUT (program_sync.cpp).
  void sync_belt(const interp::CommandBody& body);
  /// --- belt-split: a PCS1 line's Move::belt: belt_ on axes it moves along the conveying
  /// direction, -|belt_dir_| (v_max + CONV_VEL) on axes it moves against it (program_sync.cpp).
  void split_belt(planner::Move& move) const noexcept;
  // --- indp: a block's INDP_SYN commands share one ChannelWait (program_source.cpp).
  std::optional<ChannelWait> syn_wait_;  ///< the wait after the block's INDP_SYN commands
  bool syn_interruptible_ = false;       ///< --- sync-feed: all of them INTERRUPTIBLE so far
  std::optional<interp::Command> held_;  ///< the command that ended that block
  // --- static-saw: #CAXTRACK and the static unit (program_static.cpp)
  /// Every path Move goes out here: #CAXTRACK sets the tracking axis, a synchronised static
  /// unit (P-CHAN-00364) the belt feed; the results are queued.
  void emit_path(planner::Move mv);
  /// #CAXTRACK ON / OFF: 120626 (a main axis), NC9103 (no tracking axis), NC6001 (ROTMODE
  /// other than 0 / 1, OPTALIGN, SCALEFACT, AXNR, START_STROKE, ANGPOS).
  void caxtrack(const interp::CaxTrack& c, std::uint32_t line);
  /// #SYNC IN / #SYNC OUT as the adapter sees them: the static unit's belt feed on / off.
  void static_sync(const interp::CommandBody& body);
  /// A path stop (`what`: G04, #FLUSH) while the static unit is synchronised: NC9101.
  void static_stop(std::uint32_t line, const char* what);
  /// G74: the homed axes stand at P-AXIS-00152 when the channel is done; the next position
  /// barrier takes them from the channel's set positions (docs/homing.md).
  void note_homing(const interp::CommandBody& body) noexcept;
  struct CaxState {
    CaxTrackParams params;
    int slot = -1;                      ///< interpolated slot of the tracking axis
    std::optional<CaxTracker> tracker;  ///< built at the first Move (its start is the axis's)
  };
  std::optional<CaxState> cax_;
  std::optional<double> c_hold_;  ///< after OFF: where tracking left the axis [deg]
  int c_hold_slot_ = -1;
  std::optional<XVirtualParams> xv_;            ///< set while a static unit is synchronised
  std::vector<planner::AxisLimits> xv_limits_;  ///< the planner's limits (NC9100)
  planner::ChannelLimits xv_channel_;           ///< --- static-c1: and its channel's (the joints)
  std::vector<std::string> xv_names_;           ///< interpolated axis names
  std::optional<double> xv_tangent_;            ///< XY tangent at the last block's end [deg]
  /// --- static-blend: the last part of a block that ends in a tolerance ball (G61 / G261),
  /// held until the next path part is known (blend_belt_feed raises both feeds), then queued;
  /// queued as it is before any other command's items (xv_release()).
  std::optional<planner::Move> xv_held_;
  /// --- static-c1: the last part queued with no ball after it, whose joint with the next part
  /// is checked (joint_belt_check).
  std::optional<planner::Move> xv_last_;
  /// Queues xv_held_ (if any) as it is.
  void xv_release();
  // --- end static-saw
};

}  // namespace ncsim::ipo
