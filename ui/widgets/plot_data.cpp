// SPDX-License-Identifier: MIT
#include "ui/widgets/plot_data.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>

namespace lamina::ui {

// ---- PlotSeries ----

PlotSeries::PlotSeries(std::string name, std::string unit, std::size_t capacity)
    : name_(std::move(name)), unit_(std::move(unit)), ring_(std::max<std::size_t>(capacity, 1)) {}

std::string PlotSeries::Label() const {
  return unit_.empty() ? name_ : name_ + " [" + unit_ + "]";
}

void PlotSeries::Append(double t, double y) {
  if (size_ == ring_.size()) {
    ring_[head_] = {t, y};
    head_ = (head_ + 1) % ring_.size();
    ++dropped_;
    return;
  }
  ring_[(head_ + size_) % ring_.size()] = {t, y};
  ++size_;
}

void PlotSeries::ReplaceLast(double t, double y) {
  if (size_ > 0) ring_[(head_ + size_ - 1) % ring_.size()] = {t, y};
}

void PlotSeries::Clear() {
  head_ = size_ = dropped_ = 0;
}

const PlotSample& PlotSeries::operator[](std::size_t i) const {
  return ring_[(head_ + i) % ring_.size()];
}

// ---- PlotGroup ----

PlotGroup::PlotGroup(std::string title, std::size_t capacity)
    : title_(std::move(title)), capacity_(capacity) {}

std::size_t PlotGroup::AddSeries(std::string name, std::string unit) {
  series_.emplace_back(std::move(name), std::move(unit), capacity_);
  return series_.size() - 1;
}

bool PlotGroup::AddRow(double t, std::span<const double> values) {
  if (!std::isfinite(t)) return false;
  if (has_rows_ && t < last_time_) {
    Clear();
    ++resets_;
  }
  const bool replace = has_rows_ && t == last_time_;
  for (std::size_t i = 0; i < series_.size(); ++i) {
    const double y = i < values.size() ? values[i] : std::numeric_limits<double>::quiet_NaN();
    if (replace && !series_[i].empty() && series_[i].back().t == t) {
      series_[i].ReplaceLast(t, y);
    } else {
      series_[i].Append(t, y);
    }
  }
  last_time_ = t;
  has_rows_ = true;
  return true;
}

void PlotGroup::Clear() {
  for (PlotSeries& s : series_) s.Clear();
  last_time_ = 0.0;
  has_rows_ = false;
}

bool PlotGroup::empty() const {
  return std::all_of(series_.begin(), series_.end(), [](const PlotSeries& s) { return s.empty(); });
}

double PlotGroup::first_time() const {
  double first = std::numeric_limits<double>::infinity();
  for (const PlotSeries& s : series_) {
    if (!s.empty()) first = std::min(first, s[0].t);
  }
  return std::isfinite(first) ? first : 0.0;
}

// ---- windows ----

TimeWindow ScrollingWindow(const PlotGroup& group, double span, double t_end) {
  const double first = group.empty() ? t_end : group.first_time();
  if (t_end - first < span) return {first, first + span};
  return {t_end - span, t_end};
}

std::size_t LowerIndex(const PlotSeries& series, double t) {
  std::size_t lo = 0, hi = series.size();
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (series[mid].t < t) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

std::vector<PlotSample> SamplesInWindow(const PlotSeries& series, TimeWindow window) {
  std::vector<PlotSample> out;
  for (std::size_t i = LowerIndex(series, window.t0); i < series.size(); ++i) {
    if (series[i].t > window.t1) break;
    out.push_back(series[i]);
  }
  return out;
}

namespace {

// The first, lowest, highest and last finite samples of one pixel column, as series indices.
struct Column {
  std::size_t first = 0, low = 0, high = 0, last = 0;
};

void AddToColumn(const PlotSeries& series, std::size_t i, Column* column) {
  column->last = i;
  if (series[i].y < series[column->low].y) column->low = i;
  if (series[i].y > series[column->high].y) column->high = i;
}

void EmitColumn(const PlotSeries& series, const Column& column, std::vector<PlotSample>* out) {
  std::array<std::size_t, 4> indices = {column.first, column.low, column.high, column.last};
  std::sort(indices.begin(), indices.end());
  const std::size_t* end = std::unique(indices.begin(), indices.end());
  for (const std::size_t* i = indices.begin(); i != end; ++i) out->push_back(series[*i]);
}

int ColumnOf(double t, TimeWindow window, int columns) {
  const double width = window.t1 - window.t0;
  if (!(width > 0.0)) return 0;
  const int c = static_cast<int>(std::floor((t - window.t0) / width * columns));
  return std::clamp(c, 0, columns - 1);
}

}  // namespace

std::vector<PlotSample> DecimatedWindow(const PlotSeries& series, TimeWindow window, int columns) {
  columns = std::max(columns, 1);
  std::vector<PlotSample> out;
  Column column;
  int current = -1;
  for (std::size_t i = LowerIndex(series, window.t0); i < series.size(); ++i) {
    if (series[i].t > window.t1) break;
    if (!std::isfinite(series[i].y)) continue;
    const int c = ColumnOf(series[i].t, window, columns);
    if (c != current) {
      if (current >= 0) EmitColumn(series, column, &out);
      column = {i, i, i, i};
      current = c;
    }
    AddToColumn(series, i, &column);
  }
  if (current >= 0) EmitColumn(series, column, &out);
  return out;
}

double ValueNear(const PlotSeries& series, double t) {
  if (series.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t i = LowerIndex(series, t);
  if (i == 0) return series[0].y;
  if (i == series.size()) return series.back().y;
  const bool before_is_nearer = t - series[i - 1].t <= series[i].t - t;
  return series[before_is_nearer ? i - 1 : i].y;
}

// ---- ranges ----

ValueRange EmptyRange() {
  const double inf = std::numeric_limits<double>::infinity();
  return {inf, -inf};
}

void ExtendRange(std::span<const PlotSample> samples, ValueRange* range) {
  for (const PlotSample& s : samples) {
    if (!std::isfinite(s.y)) continue;
    range->lo = std::min(range->lo, s.y);
    range->hi = std::max(range->hi, s.y);
  }
}

ValueRange PaddedRange(ValueRange range) {
  if (range.empty() || !std::isfinite(range.lo) || !std::isfinite(range.hi)) return {-1.0, 1.0};
  if (range.hi == range.lo) {
    const double half = range.lo != 0.0 ? 0.1 * std::abs(range.lo) : 1.0;
    return {range.lo - half, range.hi + half};
  }
  const double margin = 0.05 * (range.hi - range.lo);
  return {range.lo - margin, range.hi + margin};
}

// ---- ticks ----

namespace {

// The smallest 1, 2, 5 × 10^exponent at least `raw`, as mantissa and exponent.
void NiceStep(double raw, int* mantissa, int* exponent) {
  *exponent = static_cast<int>(std::floor(std::log10(raw)));
  const double scaled = raw / std::pow(10.0, *exponent);
  const double slack = 1.0 + 1e-9;  // 0.2 / 0.1 may come out a hair above 2
  *mantissa = scaled <= slack ? 1 : scaled <= 2 * slack ? 2 : scaled <= 5 * slack ? 5 : 10;
  if (*mantissa == 10) {
    *mantissa = 1;
    ++*exponent;
  }
}

// k × mantissa × 10^exponent, rounded once (so 3 × 0.2 is 0.6, not 0.6000000000000001).
double TickValue(long long k, int mantissa, int exponent) {
  const double units = static_cast<double>(k * mantissa);
  return exponent >= 0 ? units * std::pow(10.0, exponent) : units / std::pow(10.0, -exponent);
}

int DecimalExponent(double v) {
  return v == 0.0 ? 0 : static_cast<int>(std::floor(std::log10(std::abs(v))));
}

void ChooseLabelFormat(int step_exponent, Ticks* ticks) {
  double largest = 0.0;
  for (double v : ticks->values) largest = std::max(largest, std::abs(v));
  const int top = DecimalExponent(largest);
  ticks->scientific = step_exponent < -4 || top >= 6;
  ticks->decimals =
      ticks->scientific ? std::max(0, top - step_exponent) : std::max(0, -step_exponent);
}

}  // namespace

Ticks NiceTicks(double lo, double hi, int max_ticks) {
  Ticks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(hi - lo) || hi < lo) return ticks;
  if (hi == lo) {
    ticks.values = {lo};
    ChooseLabelFormat(DecimalExponent(lo) - 2, &ticks);  // three significant digits
    return ticks;
  }
  int mantissa = 1, exponent = 0;
  NiceStep((hi - lo) / (std::max(max_ticks, 2) - 1), &mantissa, &exponent);
  ticks.step = TickValue(1, mantissa, exponent);
  // 1e-9 of a step of slack: 1e-6 / 5e-7 may come out a hair above 2
  const long long first = static_cast<long long>(std::ceil(lo / ticks.step - 1e-9));
  const long long last = static_cast<long long>(std::floor(hi / ticks.step + 1e-9));
  for (long long k = first; k <= last; ++k)
    ticks.values.push_back(TickValue(k, mantissa, exponent));
  ChooseLabelFormat(exponent, &ticks);
  return ticks;
}

std::string TickLabel(const Ticks& ticks, double value) {
  if (value == 0.0) value = 0.0;  // no "-0"
  std::array<char, 64> text{};
  if (ticks.scientific) {
    std::snprintf(text.data(), text.size(), "%.*e", ticks.decimals, value);
  } else {
    std::snprintf(text.data(), text.size(), "%.*f", ticks.decimals, value);
  }
  return text.data();
}

// ---- CSV ----

namespace {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// The shortest decimal form that reads back to the same double ("nan", "inf" as such).
std::string ShortestNumber(double v) {
  std::array<char, 64> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), v);
  return std::string(text.data(), result.ptr);
}

void WriteCsvHeader(const PlotGroup& group, std::ostream& out) {
  out << "time";
  for (const PlotSeries& s : group.series()) out << ',' << CsvField(s.Label());
  out << '\n';
}

// The earliest time not yet written over all series, given each one's next index.
double NextRowTime(const PlotGroup& group, const std::vector<std::size_t>& next) {
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < next.size(); ++i) {
    if (next[i] < group.series()[i].size()) t = std::min(t, group.series()[i][next[i]].t);
  }
  return t;
}

void WriteCsvRows(const PlotGroup& group, std::ostream& out) {
  std::vector<std::size_t> next(group.series().size(), 0);
  for (double t = NextRowTime(group, next); std::isfinite(t); t = NextRowTime(group, next)) {
    out << ShortestNumber(t);
    for (std::size_t i = 0; i < next.size(); ++i) {
      const PlotSeries& s = group.series()[i];
      out << ',';
      if (next[i] < s.size() && s[next[i]].t == t) out << ShortestNumber(s[next[i]++].y);
    }
    out << '\n';
  }
}

bool Fail(const std::string& message, const std::string& tmp, std::string* error) {
  std::error_code ignored;
  std::filesystem::remove(tmp, ignored);
  if (error) *error = message;
  return false;
}

}  // namespace

bool WriteCsv(const PlotGroup& group, const std::string& path, std::string* error) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return Fail("cannot write " + path + ": " + std::strerror(errno), tmp, error);
    WriteCsvHeader(group, out);
    WriteCsvRows(group, out);
    out.close();
    if (!out) return Fail("cannot write " + path + ": write failed", tmp, error);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) return Fail("cannot write " + path + ": " + ec.message(), tmp, error);
  return true;
}

}  // namespace lamina::ui
