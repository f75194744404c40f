#pragma once
// cli/csv_sink: the rows of `ncsim run`'s CSV trajectory (design.md §5), buffered, numbers by
// core::num (core/number_text.hpp); the technology functions as `# tech` comments.

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <string>

#include "channel/channel.hpp"
#include "cli/number_format.hpp"

namespace ncsim::cli {

/// Writes the CSV rows: buffered, numbers by std::to_chars. With --every N the rows of every Nth
/// cycle, and the last cycle of the run whatever its index (`write_last()`): the program end, the
/// last good cycle before a run-time error or the scenario's stop, so the CSV ends where the run
/// did (issue 12: "up to the stop ... never silently cut").
class CsvSink final : public ipo::Sink {
 public:
  CsvSink(std::FILE* f, std::size_t axes, std::uint64_t every, bool detail)
      : f_(f), axes_(axes), every_(every), detail_(detail) {
    buf_.reserve(kFlushAt + 4096);
  }
  void on_joint(const ipo::Joint&) override {}
  void on_cycle(const ipo::Cycle& c) override {
    capture(c);
    if (c.index % every_ != 0) {
      pending_ = true;
      return;
    }
    write_row();
  }
  /// The last cycle seen, when --every skipped it (call once, after the run's last cycle).
  void write_last() {
    if (pending_) write_row();
  }
  void text(const std::string& s) {
    buf_ += s;
    if (buf_.size() >= kFlushAt) flush();
  }
  /// Writes what is buffered; false (errno kept) on a write error, which sticks.
  bool flush() {
    if (!failed_ && f_ != nullptr && !buf_.empty() &&
        std::fwrite(buf_.data(), 1, buf_.size(), f_) != buf_.size()) {
      failed_ = true;
      errno_ = errno;
    }
    buf_.clear();
    return !failed_;
  }
  bool failed() const { return failed_; }
  int error_number() const { return errno_; }
  void set_failed(int e) {
    failed_ = true;
    errno_ = e;
  }
  std::uint64_t rows() const { return rows_; }
  /// The axes whose following error --detail writes (the channel's, read at each on_cycle).
  void set_axes(const channel::AxesState* state) { axes_state_ = state; }
  /// The channel whose conveyor display variables --detail writes (null: none). --- line
  void set_conveyor(const channel::Channel* channel) { conveyor_ = channel; }
  /// The setpoints the axes received (the joints under #TRAFO), read at each on_cycle.
  void set_setpoints(const std::array<axes::Setpoint, planner::kMaxAxes>* set) { set_ = set; }

 private:
  static void append_num(std::string& s, double v) { s += num(v); }
  /// The values of cycle `c`'s row, read from the channel's state while it is that cycle's.
  void capture(const ipo::Cycle& c) {
    row_.t = c.t;
    row_.line = c.line;
    for (std::size_t i = 0; i < axes_; ++i) {
      // The machine axes' setpoints (the channel's; under #TRAFO the joints, not the TCP).
      row_.p[i] = set_ != nullptr ? (*set_)[i].p : c.x[i];
      if (!detail_) continue;
      row_.v[i] = set_ != nullptr ? (*set_)[i].v : c.v[i];
      row_.a[i] = set_ != nullptr ? (*set_)[i].a : c.a[i];
      row_.ferr[i] = axes_state_ != nullptr ? axes_state_->following_error[i] : 0.0;
    }
    if (!detail_) return;
    row_.v_path = c.path.v;
    row_.feed = c.feed;
    // The conveyor display variables with synchro_lag (seed 004 §6,
    // Channel::master_display, tracking/synchro_lag.hpp)
    if (conveyor_ != nullptr) row_.master = conveyor_->master_display();
  }
  void write_row() {
    pending_ = false;
    append_num(buf_, row_.t);
    buf_ += ',';
    buf_ += std::to_string(row_.line);
    for (std::size_t i = 0; i < axes_; ++i) {
      buf_ += ',';
      append_num(buf_, row_.p[i]);
    }
    if (detail_) {
      for (std::size_t i = 0; i < axes_; ++i) {
        buf_ += ',';
        append_num(buf_, row_.v[i]);
        buf_ += ',';
        append_num(buf_, row_.a[i]);
      }
      buf_ += ',';
      append_num(buf_, row_.v_path);
      buf_ += ',';
      append_num(buf_, row_.feed);
      for (std::size_t i = 0; i < axes_; ++i) {
        buf_ += ',';
        append_num(buf_, row_.ferr[i]);
      }
      if (conveyor_ != nullptr) {
        const tracking::MasterDisplay& d = row_.master;
        for (const double v :
             {d.current_pos_master, d.current_v_master, d.current_a_master, d.pos_master_comp,
              d.v_master_comp, d.a_master_comp, d.synchro_lag}) {
          buf_ += ',';
          append_num(buf_, v);
        }
      }
    }
    buf_ += '\n';
    ++rows_;
    if (buf_.size() >= kFlushAt) flush();
  }

  /// One row's values (the columns of the head).
  struct Row {
    double t = 0.0;                                ///< end of the cycle [s]
    std::uint32_t line = 0;                        ///< source line of the active block
    std::array<double, planner::kMaxAxes> p{};     ///< command positions [mm | deg]
    std::array<double, planner::kMaxAxes> v{};     ///< --detail: velocities [mm/s | deg/s]
    std::array<double, planner::kMaxAxes> a{};     ///< --detail: accelerations
    std::array<double, planner::kMaxAxes> ferr{};  ///< --detail: following errors [mm | deg]
    double v_path = 0.0;                           ///< --detail: path velocity [mm/s]
    double feed = 0.0;                             ///< --detail: programmed feed [mm/s]
    tracking::MasterDisplay master{};              ///< --detail on a conveyor machine
  };

  static constexpr std::size_t kFlushAt = 1 << 20;
  std::FILE* f_;
  std::size_t axes_;
  std::uint64_t every_;
  bool detail_;
  const channel::AxesState* axes_state_ = nullptr;
  const channel::Channel* conveyor_ = nullptr;  // the channel's master_display()
  const std::array<axes::Setpoint, planner::kMaxAxes>* set_ = nullptr;
  std::string buf_;
  Row row_;               // the last cycle's values
  bool pending_ = false;  // row_ not written yet (--every skipped it)
  bool failed_ = false;
  int errno_ = 0;
  std::uint64_t rows_ = 0;
};

/// The technology functions output in the channel's last step as comments
/// `# tech t=<s> line=<n> M3` (docs/ipo.md "INDP axes and technology functions").
void write_tech(const channel::Channel& channel, CsvSink& csv);

}  // namespace ncsim::cli
