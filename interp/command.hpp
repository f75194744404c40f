#pragma once
// interp/command: what the interpreter hands to the planner, one value per command.
//
// Purpose: the seam between decode time (interp/) and run time (planner/, ipo/). Every command
// is an immutable value that carries its source line and the modal state it needs, so the
// planner can queue it without looking back at the interpreter. The seam is two-way: a
// `Barrier` command says the interpreter needs run-time state before the next block; the run
// time answers with `Interpreter::resume(RunState)` (interp/interpreter.hpp, docs/interp.md
// "The seam").
// Units inside: mm, s, degrees; feeds in mm/s (converted from the program's mm/min at this
// boundary, docs/interp.md "Units"). Positions are absolute coordinates in the frame the
// command names (`CoordFrame`): MCS, PCS through the active #CS chain, or PCS1 while
// synchronised, each as axis values or, under #TRAFO ON, as Cartesian TCP coordinates. One slot
// per machine axis in machine order (`Machine::axes`); `AxisMask` bit i says axis i was
// programmed in the block.
// Invariants: `line` >= 1 for commands from a block (0 only for the final End of a file
// without M02/M30); a motion's start, end and arc centre are in the one frame it names; arcs
// carry a centre at equal distance (within the P-CHAN-00059/00060 limits, then corrected) from
// start and end.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "machines/machine.hpp"
#include "machines/motion_blocks.hpp"

namespace ncsim::interp {

/// Most axes one channel addresses (machine order); the loader rejects machines with more.
inline constexpr std::size_t kMaxAxes = machines::kMaxChannelAxes;
using AxisValues = std::array<double, kMaxAxes>;  ///< [mm | deg] per machine axis
using AxisMask = std::uint32_t;                   ///< bit i: machine axis i

/// The coordinate system a command's coordinates are in (machines/frame.hpp has the chain
/// PCS -> PCS1 -> PCS0 -> MCS -> kinematics -> ACS).
enum class Space : std::uint8_t {
  mcs,  ///< machine coordinates (no #CS active, not synchronised)
  pcs,  ///< programming coordinates inside the active #CS chain (cs_depth >= 1)
  pcs1  ///< co-moving with the conveyor, between #SYNC IN and #SYNC OUT (seed 004 §2.1)
};

/// The frame a motion's coordinates are in.
struct CoordFrame {
  Space space = Space::mcs;
  std::uint8_t cs_depth = 0;  ///< active #CS systems (0..5)
  /// true: X/Y/Z are Cartesian TCP coordinates (#TRAFO ON); false: axis values (ACS; on a
  /// machine without kinematic identical to the Cartesian MCS).
  bool kinematics = false;
  friend bool operator==(const CoordFrame&, const CoordFrame&) = default;
};

/// "MCS", "PCS/CS2", "PCS1", "PCS1/CS1", each with "+KIN" under #TRAFO ON.
std::string frame_name(const CoordFrame& frame);

enum class MotionKind : std::uint8_t { rapid, linear, arc_cw, arc_ccw };
enum class Plane : std::uint8_t { xy, zx, yz };                   ///< G17 / G18 / G19
enum class FeedMode : std::uint8_t { per_minute, inverse_time };  ///< G94 / G93
/// Block transition (isg-language.md §2.4): G08 (default), G09 (this block), G900, G901.
enum class Transition : std::uint8_t {
  accelerate_at_start,
  stop_at_end,
  decel_at_end,
  decel_after_end
};
enum class SlopeType : std::uint8_t { step, trapez, sin2, hsc };  ///< #SLOPE TYPE
enum class ContourKind : std::uint8_t { dev, dist, dist_soft, dist_master, pos, ptp };

/// #CONTOUR MODE parameters (isg-language.md §5.3, PROG-475164939 defaults; the interpreter
/// starts PATH_DEV at the channel's NCSIM-CHAN-620 ncsim.default_path_dev).
struct ContourParams {
  ContourKind kind = ContourKind::dev;
  double path_dev = 1.0;   ///< PATH_DEV [mm]
  double pre_dist = 1.0;   ///< PRE_DIST [mm]
  double post_dist = 1.0;  ///< POST_DIST [mm]
};

/// Tool radius compensation (TRC, docs/trc.md): G40 off / G41 left / G42 right of the contour.
enum class TrcSide : std::uint8_t { off, left, right };
/// Outer-corner transition: G25 linear blocks (default) / G26 a circle (TF5200 "G25/G26").
enum class TrcCorner : std::uint8_t { linear, circle };
/// Selection and deselection: G139 indirect (default) / G138 direct (TF5200 "G138/G139") /
/// G237 perpendicular / G239 direct without a deselection block (TF5200 "G237", "G239").
enum class TrcApproach : std::uint8_t { indirect, direct, perpendicular, no_block };

/// The TRC state a motion was decoded under; the interpreter's TRC filter (interp/trc.hpp)
/// turns the programmed contour into the compensated path from it.
struct ToolRadiusComp {
  TrcSide side = TrcSide::off;
  double radius = 0.0;  ///< [mm] of the D tool (P-TOOL-00004); negative swaps the side
  TrcCorner corner = TrcCorner::linear;
  TrcApproach approach = TrcApproach::indirect;
  bool adapt_feed = false;     ///< G11: F acts on the contour of compensated arcs (G10 off)
  double tangfeed_rmin = 0.0;  ///< [mm] #TANGFEED RMIN: G11 only on arcs of this radius or more
};

/// All axes at 100 %.
constexpr AxisValues all_ones() {
  AxisValues v{};
  for (double& x : v)
    x = 1.0;
  return v;
}

/// Dynamics weightings in force, as fractions per machine axis, already limited to what ncsim
/// runs (TF5200 G127/G128 PROG-206573067, G129 PROG-206578955, G130/G131/G230/G231
/// PROG-206590731, G132/G133/G233 PROG-206596619; docs/interp.md "Dynamics weighting").
struct DynamicsWeights {
  AxisValues v_feed = all_ones();     ///< G127 / G128: P-AXIS-00212 v_max, 0.01 .. 1
  double v_rapid = 1.0;               ///< G129: P-AXIS-00209 (G00), 0.01 .. 1
  AxisValues a_feed = all_ones();     ///< G130 / G131: G01/G02/G03 acceleration, 0.01 .. 1
  AxisValues a_rapid = all_ones();    ///< G230 / G231: G00 acceleration, 0.01 .. 1
  AxisValues ramp_feed = all_ones();  ///< G132 / G133: G01/G02/G03 ramp time, 1 .. 100
  double ramp_rapid = 1.0;            ///< G233: G00 ramp time, 1 .. 100
  bool operator==(const DynamicsWeights&) const = default;
};

/// The modal state a motion needs, as it was when the block was decoded.
struct ModalSnapshot {
  Plane plane = Plane::xy;
  bool inch = false;         ///< G70 (values already converted to mm)
  bool incremental = false;  ///< G91 (values already made absolute)
  FeedMode feed_mode = FeedMode::per_minute;
  Transition transition = Transition::accelerate_at_start;
  bool exact_stop = false;  ///< G60 in this block or G360 modal
  bool contouring = false;  ///< G61 in this block or G261 modal
  ContourParams contour;
  SlopeType slope = SlopeType::step;
  std::optional<double> transvelmin;  ///< #TRANSVELMIN ON value [mm/s]
  bool synchronised = false;          ///< between #SYNC IN and #SYNC OUT (PCS1)
  bool cs_active = false;             ///< a #CS system is active (also in Motion::frame)
  bool kinematics_on = false;         ///< #TRAFO ON (also in Motion::frame)
  bool caxtrack = false;              ///< #CAXTRACK ON
  ToolRadiusComp trc;                 ///< G40/G41/G42, D, G25/G26, G138/G139
  /// Dynamics weightings; null: every weight 100 % (shared: one per change, not per block)
  std::shared_ptr<const DynamicsWeights> weights;
};

struct Arc {
  double centre_1 = 0.0;    ///< first plane axis coordinate of the centre [mm], Motion::frame
  double centre_2 = 0.0;    ///< second plane axis coordinate [mm], Motion::frame
  std::uint8_t axis_1 = 0;  ///< machine index of the first plane axis
  std::uint8_t axis_2 = 0;  ///< machine index of the second plane axis
  double radius = 0.0;      ///< [mm]
  bool full_circle = false;
};

struct Motion {
  MotionKind kind = MotionKind::linear;
  CoordFrame frame;    ///< the frame of start, end and the arc centre
  AxisValues start{};  ///< [mm | deg] absolute, in `frame`
  AxisValues end{};    ///< [mm | deg] absolute, in `frame`
  AxisMask programmed = 0;
  double feed = 0.0;                 ///< [mm/s] (G94); 0 for rapid
  std::optional<double> block_time;  ///< G93: machining time of the block [s]
  std::optional<double> end_feed;    ///< E [mm/s]
  std::optional<Arc> arc;            ///< G02/G03
  ModalSnapshot modal;
};

enum class SplineType : std::uint8_t { akima, bspline };
/// A #SPLINE ON ... OFF section (isg-language.md §5.4) streams as SplineBegin, one SplinePoint
/// per vertex block (with its own line and feed), SplineEnd: memory does not grow with the
/// section's length.
/// #SPLINE ON / G151: the section starts at the current position, its first vertex.
struct SplineBegin {
  SplineType type = SplineType::akima;
  CoordFrame frame;    ///< the frame of `start` and of every point of the section
  AxisValues start{};  ///< first vertex [mm | deg]
  ModalSnapshot modal;
};
/// One vertex (Akima) or control point (B-spline) after the start, from a G00/G01 block.
struct SplinePoint {
  std::uint32_t index = 1;  ///< 1 for the first point after the start
  CoordFrame frame;         ///< as SplineBegin::frame
  AxisValues point{};       ///< [mm | deg]
  AxisMask programmed = 0;
  double feed = 0.0;  ///< [mm/s] in force at this point's block
};
/// #SPLINE OFF / G150.
struct SplineEnd {
  SplineType type = SplineType::akima;
  std::uint32_t points = 0;  ///< vertices of the section, start included
};

/// G04, or the wait for a technology function's acknowledgement (TechSync): the path stops
/// before it.
struct Dwell {
  double seconds = 0.0;
  /// A technology function's acknowledgement (`time`'s tech column), not a G04
  bool tech = false;
  /// MVS_SNS's wait after the block's motion: `seconds` count from the functions' output at the
  /// block's start, so only what the motion did not cover is left (docs/interp.md "Technology
  /// functions")
  bool since_output = false;
};

enum class TechKind : std::uint8_t { m, h, s, t, d };
/// M/H/S/T/D technology function passed through to the PLC side.
struct Tech {
  TechKind kind = TechKind::m;
  double value = 0.0;
  /// M/H additional value for the PLC (`M200=1200`: 1200; TF5200 "M/H functions with optional
  /// additional information"), a whole number
  std::optional<double> extra;
  /// Its synchronisation type from the channel list (machines::TechTable); NO_SYNCH is not
  /// output to the PLC
  machines::TechSync sync = machines::TechSync::mos;
};

/// M00 (optional = false) / M01 (optional = true).
struct ProgramStop {
  bool optional = false;
};

enum class IndpKind : std::uint8_t { syn, asyn };
/// X[INDP_SYN ...] / X[INDP_ASYN ...] (isg-language.md §6.1).
struct AxisCommand {
  IndpKind kind = IndpKind::syn;
  std::uint8_t axis = 0;       ///< machine index
  bool rapid = false;          ///< G00 (else G01)
  double target = 0.0;         ///< absolute POS [mm | deg]
  std::optional<double> feed;  ///< FEED [mm/s]
  std::optional<double> time;  ///< TIME [s]
  bool interruptible = false;  ///< INTERRUPTIBLE (TF5264 examples)
  CoordFrame frame;            ///< the frame of `target`
};

// S1[MC_MoveVelocity ...] and S1[MC_TouchProbe ...]: the blocks' inputs, shared with the
// conveyor world (machines/motion_blocks.hpp).
using machines::MoveVelocity;
using machines::ProbeArm;
using machines::ProbeEdge;
using machines::VelocityDirection;

struct SyncIn {
  std::uint8_t conveyor = 0;  ///< machine index of the conveyor axis
  double latch = 0.0;         ///< conveyor position latched by the probe [mm] (RunState::latch)
  double conv_vel = 0.0;      ///< expected conveyor velocity [mm/s] (> 0)
  std::optional<double> feed_cont;  ///< FEED_CONT relative velocity [mm/s] (program: mm/min)
  bool feed_cont_auto = false;
  bool kinematics = false;  ///< given under #TRAFO ON (the axes are joints)
};

struct SyncOut {
  std::optional<double> feed_cont;  ///< FEED_CONT [mm/s] (program: mm/min)
  bool feed_cont_auto = false;
};

/// `base`: only the zero offsets below an active chain changed (G54.., V.G.NP[i]).
enum class CsOp : std::uint8_t { def, on, off, off_all, base };
struct SelectCs {
  CsOp op = CsOp::on;
  std::optional<int> id;
  std::optional<std::array<double, 6>> values;  ///< v1..v3 [mm], phi1..phi3 [deg]
  std::uint8_t active_count = 0;                ///< active systems after the command
  std::array<double, 3> base{};  ///< X/Y/Z zero offsets [mm] the chain sits on (CsStack::base)
};

struct Kinematics {
  std::optional<int> kin_id;  ///< #KIN ID[n]
  bool trafo_on = false;      ///< state after the command
};

struct CaxTrack {
  bool on = false;
  std::optional<std::uint8_t> axis;
  double anglimit = 0.0;  ///< [deg]
  double offset = 0.0;    ///< [deg]
  double angpos = 0.0;    ///< OFF position [deg]
  // The rest of the ON / OFF words (tracking/caxtrack.hpp, docs/caxtrack.md)
  bool angpos_given = false;  ///< OFF: ANGPOS was programmed (else the axis stays)
  double rotmode = 0.0;       ///< ROTMODE as programmed (0 tool, 1 workpiece)
  std::string unsupported;    ///< the first word ncsim does not run (OPTALIGN, ...), "" none
};

/// One parameter a #MACHINE DATA sets, resolved through the machine's parameter table
/// (machines/param_table.hpp) at decode time.
struct MachineSetting {
  std::string_view id;                 ///< parameter id ("P-AXIS-00178"), from the static table
  std::string_view key;                ///< list key ("kenngr.swe_pos"), indices as "[]"
  std::optional<std::uint16_t> index;  ///< `.idx` of an indexed parameter
  double value = 0.0;                  ///< in internal units (ParamSpec::to_internal applied)
  std::string_view unit;               ///< the internal unit ("mm | deg", "s", ...)
};

/// #MACHINE DATA (isg-language.md §5.10, PROG-207492747).
struct MachineData {
  bool syn = false;                  ///< SYN: at interpolator level; else at decode
  std::optional<std::uint8_t> axis;  ///< AX= / AXNR=; set for axis parameters
  std::vector<MachineSetting> settings;
  bool wait = false;
};

/// #MSG mode (PROG-507845131).
/// accepted: a # command ncsim reads without an effect, shown in trace (docs/language.md).
enum class MessageMode : std::uint8_t { immediate, syn, syn_ack, ack, accepted };

struct Message {
  std::string text;
  MessageMode mode = MessageMode::immediate;
};

enum class FlushKind : std::uint8_t { stop, continue_, wait };
struct Flush {
  FlushKind kind = FlushKind::stop;
};

struct WaitIndp {
  AxisMask axes = 0;  ///< 0: ALL
};

/// G74: each axis with its order number; equal numbers home together.
struct Homing {
  std::vector<std::pair<std::uint8_t, int>> axes;
};

/// G92: the programmed values become the current position (offset kept).
struct SetPosition {
  AxisValues values{};
  AxisMask axes = 0;
};

/// Channel numbers a #SIGNAL / #WAIT may name (CH=..), 1 .. kMaxChannels: ncsim's line
/// holds at most this many channels (docs/lines.md; the manual's range is the control's
/// configuration, 20996 / 250008).
inline constexpr std::uint8_t kMaxChannels = 12;
/// Signal parameters P[0] .. P[kSignalParams - 1] (PROG-207421579: index 0 .. 11).
inline constexpr std::uint8_t kSignalParams = 12;
/// Largest signal number ID=.. (a positive 32-bit integer; decision, docs/lines.md).
inline constexpr std::uint32_t kMaxSignalId = 2147483647;

/// #SIGNAL / #SIGNAL SYN (PROG-207409035): signal `id` to each receiver channel, or to any
/// channel (a broadcast signal) without receivers. Decoder level (syn false): sent when the
/// decoder reaches it; SYN: when the interpolator reaches its place in the block stream.
struct Signal {
  bool syn = false;
  std::uint32_t id = 0;                ///< 1 .. kMaxSignalId
  std::optional<std::uint32_t> count;  ///< COUNT: #WAITs until used up (unset: 1; a broadcast
                                       ///< without COUNT is never used up)
  std::vector<std::pair<std::uint8_t, double>> params;  ///< P[idx] = value
  std::vector<std::uint8_t> receivers;                  ///< CH=..; empty: broadcast
  /// #SIGNAL REMOVE (PROG-207414923): clears signals `id` (one, the oldest) or, with `range`,
  /// every signal id .. id_max, broadcast ones (no receivers) or those to `receivers`.
  bool remove = false;
  bool range = false;
  std::uint32_t id_max = 0;
};

/// A wait for signal `id` (PROG-207421579): from every channel of `senders` (each its own
/// signal), or a broadcast signal without senders. #WAIT SYN is this command (a channel
/// event, the path stands at it); #WAIT and #SIGNAL READ are a Barrier asking for it.
struct SignalWait {
  std::uint32_t id = 0;
  std::vector<std::uint8_t> senders;  ///< CH=..; empty: broadcast
  bool read = false;                  ///< #SIGNAL READ: answered at once, received or not
};

/// The run time's answer to a signal barrier (RunState::signal).
struct SignalAnswer {
  bool received = false;  ///< the signal(s) were there (and are used up)
  std::array<std::optional<double>, kSignalParams> params{};  ///< P[idx] the senders gave
};

/// What a Barrier asks the run time for (bits of Barrier::needs).
enum class BarrierNeed : std::uint8_t {
  external = 1,     ///< V.E. values the outside world may have written (FLUSH V.E.READ)
  probe_latch = 2,  ///< the conveyor position latched by MC_TouchProbe (before #SYNC IN)
  position = 4,     ///< actual positions of Barrier::axes in Barrier::frame
  signal = 8        ///< #WAIT / #SIGNAL READ at decoder level: Barrier::signal
};

/// The interpreter stops before the block at `Command::line` until the run time answers with
/// Interpreter::resume(RunState). The run time must first execute every command before the
/// barrier (a barrier is a flush): the values it answers are those at that point.
struct Barrier {
  std::uint8_t needs = 0;             ///< BarrierNeed bits
  std::vector<std::string> external;  ///< V.E. names the block reads ("PART" for V.E.PART)
  std::optional<std::uint8_t> probe;  ///< the conveyor axis whose latch is wanted
  CoordFrame frame;                   ///< the frame the positions are wanted in
  AxisMask axes = 0;                  ///< axes whose actual position is wanted
  std::optional<SignalWait> signal;   ///< the signal the block waits for or reads
  bool wants(BarrierNeed n) const { return (needs & static_cast<std::uint8_t>(n)) != 0; }
};

struct End {
  int code = 30;  ///< 2 or 30; 0: end of file without M02/M30
  /// Options::end_when_endless: the decoder ended the program where it came back to an
  /// earlier state after motion, with no run-time answer between (docs/interp.md)
  bool endless = false;
};

using CommandBody = std::variant<Motion, SplineBegin, SplinePoint, SplineEnd, Dwell, Tech,
                                 ProgramStop, AxisCommand, MoveVelocity, ProbeArm, SyncIn, SyncOut,
                                 SelectCs, Kinematics, CaxTrack, MachineData, Message, Flush,
                                 WaitIndp, Homing, SetPosition, Signal, SignalWait, Barrier, End>;

struct Command {
  std::uint32_t line = 0;  ///< 1-based source line of the block
  std::uint16_t file =
      0;  ///< 0: the main program; else a global subroutine (Interpreter::file_name)
  CommandBody body;
};

}  // namespace ncsim::interp
