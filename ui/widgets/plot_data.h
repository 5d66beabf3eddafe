// SPDX-License-Identifier: MIT
// The data behind the editor's scrolling plots, with no ImGui: series of (time, value) samples
// in fixed-capacity ring buffers, groups of series sharing one time axis, the visible window
// decimated for drawing, tick positions, the y range and CSV export. The drawing is in
// ui/widgets/plot_widget.h.
//
// Units: time is simulated seconds; each series names its own unit ("J", "N", "rad", ...) and
// its values are stored as given.
//
// Capacity: each series keeps its last `capacity` samples (kDefaultPlotCapacity = 20000, 20 s
// at 1 kHz, 5.5 min at 60 Hz); appending is O(1) and, once full, drops the oldest sample.
//
// NaN and infinity: stored as given (the CSV writes them as "nan", "inf", "-inf"), skipped by
// the y range and by the decimation (the drawn line joins across them), never a crash. A row
// whose time is not finite is ignored.
//
// Time going backwards (a simulation Reset, an undo, a new world): PlotGroup::AddRow clears
// every series of the group and starts again from that row, since a plot shows the current run;
// resets() counts these. A row at the same time as the last one replaces it (a paused simulation
// adds no samples however many frames are drawn).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace lamina::ui {

inline constexpr std::size_t kDefaultPlotCapacity = 20000;

struct PlotSample {
  double t = 0.0;  // s
  double y = 0.0;  // in the series' unit
};

/// A named series of samples, oldest first, in a ring buffer of fixed capacity. Times are
/// expected not to decrease (PlotGroup ensures it); the window functions rely on it.
class PlotSeries {
 public:
  PlotSeries(std::string name, std::string unit, std::size_t capacity = kDefaultPlotCapacity);

  const std::string& name() const { return name_; }
  const std::string& unit() const { return unit_; }
  /// "name [unit]", or just the name without a unit.
  std::string Label() const;

  /// O(1); when full the oldest sample is overwritten (and counted in dropped()).
  void Append(double t, double y);
  /// Replaces the newest sample; does nothing when empty.
  void ReplaceLast(double t, double y);
  void Clear();

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return ring_.size(); }
  bool empty() const { return size_ == 0; }
  /// Samples dropped because the buffer was full (since construction or Clear()).
  std::size_t dropped() const { return dropped_; }
  /// The i-th sample, 0 the oldest; i < size().
  const PlotSample& operator[](std::size_t i) const;
  const PlotSample& back() const { return (*this)[size_ - 1]; }

 private:
  std::string name_, unit_;
  std::vector<PlotSample> ring_;
  std::size_t head_ = 0;  // index in ring_ of the oldest sample
  std::size_t size_ = 0, dropped_ = 0;
};

/// A titled set of series sharing the time axis: one row (a time and a value per series) at a
/// time. See the top of this file for what happens when time goes backwards.
class PlotGroup {
 public:
  explicit PlotGroup(std::string title, std::size_t capacity = kDefaultPlotCapacity);

  const std::string& title() const { return title_; }
  /// Adds a series and returns its index. A series added after rows exist starts empty.
  std::size_t AddSeries(std::string name, std::string unit);
  /// Appends one row: values[i] goes to series i; missing values are NaN, extra ones ignored.
  /// Returns false (and stores nothing) when `t` is not finite.
  bool AddRow(double t, std::span<const double> values);
  bool AddRow(double t, std::initializer_list<double> values) {
    return AddRow(t, std::span<const double>(values.begin(), values.size()));
  }
  /// Empties every series (keeps the series).
  void Clear();

  const std::vector<PlotSeries>& series() const { return series_; }
  bool empty() const;
  /// Time of the last row, s; 0 when empty.
  double last_time() const { return last_time_; }
  /// Time of the oldest sample still held by any series, s; 0 when empty.
  double first_time() const;
  /// How many times a row going back in time cleared the group.
  int resets() const { return resets_; }

 private:
  std::string title_;
  std::size_t capacity_;
  std::vector<PlotSeries> series_;
  double last_time_ = 0.0;
  bool has_rows_ = false;
  int resets_ = 0;
};

/// A closed time interval [t0, t1], s.
struct TimeWindow {
  double t0 = 0.0, t1 = 0.0;
};

/// The window a scrolling plot shows for `span` seconds ending at `t_end`; while the data
/// covers less than `span` (the first seconds of a run), the window starts at the oldest sample
/// so that the line grows from the left edge.
TimeWindow ScrollingWindow(const PlotGroup& group, double span, double t_end);

/// Index of the first sample with t >= `t` (size() when none). O(log n).
std::size_t LowerIndex(const PlotSeries& series, double t);

/// Exactly the samples with t0 <= t <= t1, oldest first, NaN values included.
std::vector<PlotSample> SamplesInWindow(const PlotSeries& series, TimeWindow window);

/// The finite samples of `window` for drawing `columns` pixel columns wide: each column keeps
/// at most 4 samples, its first, its minimum, its maximum and its last, in time order, so a
/// one-sample spike is never lost and the line stays continuous. Non-finite values are skipped.
std::vector<PlotSample> DecimatedWindow(const PlotSeries& series, TimeWindow window, int columns);

/// The value of the sample nearest to `t` (NaN when the series is empty), for the hover readout.
double ValueNear(const PlotSeries& series, double t);

/// A value interval; empty while lo > hi.
struct ValueRange {
  double lo = 0.0, hi = 0.0;
  bool empty() const { return lo > hi; }
};
/// The empty range ({+inf, -inf}) to extend.
ValueRange EmptyRange();
/// Extends `range` by the finite y values of `samples`; NaN and infinities are ignored.
void ExtendRange(std::span<const PlotSample> samples, ValueRange* range);
/// The range to draw: `range` with a 5 % margin on both sides; a flat line y gets y ± 10 % |y|
/// (y ± 1 when y is 0) and an empty range gets [-1, 1], so the height is never zero.
ValueRange PaddedRange(ValueRange range);

/// Axis ticks: every multiple of `step` in [lo, hi]; step is 1, 2 or 5 × 10^k.
struct Ticks {
  std::vector<double> values;
  double step = 0.0;
  /// Digits after the point in the labels: just enough to tell the ticks apart.
  int decimals = 0;
  /// Labels like "1.5e-06" for very small or very large values.
  bool scientific = false;
};
/// The smallest 1/2/5 × 10^k step giving at most `max_ticks` ticks (at least 2) in [lo, hi].
/// As the step is at most 2.5 × (hi − lo) / (max_ticks − 1), max_ticks >= 4 gives at least one
/// tick and max_ticks >= 6 at least two. lo == hi gives the single tick lo (labelled with three
/// significant digits); hi < lo or a non-finite bound or width gives no ticks.
Ticks NiceTicks(double lo, double hi, int max_ticks);
/// The label of a tick value, e.g. "0.2", "-4", "1.5e-06".
std::string TickLabel(const Ticks& ticks, double value);

/// Writes the group as CSV: a header `time,<name> [unit],...` and one row per distinct sample
/// time, oldest first, a series without a sample at that time leaving its field empty. Numbers
/// are written in the shortest form that reads back to the same double. The file is written to
/// `path` + ".tmp" and renamed over `path`, so a reader never sees half a file. On failure
/// returns false, sets *error (naming the path) and leaves no file behind.
bool WriteCsv(const PlotGroup& group, const std::string& path, std::string* error);

}  // namespace lamina::ui
