// SPDX-License-Identifier: MIT
#include "app/batch_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <stb/stb_easy_font.h>

#include "ui/platform/image_file.h"
#include "ui/widgets/plot_data.h"

namespace lamina::app {

namespace {

constexpr int kWidth = 800;
constexpr int kHeight = 500;
constexpr int kLeft = 90, kRight = 40, kTop = 60, kBottom = 70;  // margins, px
constexpr int kTextScale = 2;  // stb_easy_font's glyphs are ~7 px high

struct Rgb {
  std::uint8_t r, g, b;
};

// an RGBA image, row 0 at the top
class Canvas {
 public:
  Canvas() : pixels_(static_cast<size_t>(kWidth) * kHeight * 4, 255) {}

  void Fill(int x0, int y0, int x1, int y1, Rgb c) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min(x1, kWidth), y1 = std::min(y1, kHeight);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        std::uint8_t* p = &pixels_[(static_cast<size_t>(y) * kWidth + x) * 4];
        p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
      }
    }
  }

  /// Text with its top left at (x, y); `align` 0 left, 1 centre, 2 right of x.
  void Text(int x, int y, const std::string& text, int align = 0) {
    static char buffer[60000];
    const int width = stb_easy_font_width(const_cast<char*>(text.c_str())) * kTextScale;
    x -= align * width / 2;
    const int quads =
        stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr, buffer, sizeof(buffer));
    // 4 vertices per quad, each x, y, z (floats) and a colour (4 bytes)
    for (int q = 0; q < quads; ++q) {
      const float* v0 = reinterpret_cast<const float*>(buffer + q * 64);
      const float* v2 = reinterpret_cast<const float*>(buffer + q * 64 + 32);
      Fill(x + static_cast<int>(v0[0]) * kTextScale, y + static_cast<int>(v0[1]) * kTextScale,
           x + static_cast<int>(v2[0]) * kTextScale, y + static_cast<int>(v2[1]) * kTextScale,
           {20, 20, 20});
    }
  }

  /// The rows bottom-up, as WritePngBottomUp takes them.
  std::vector<std::uint8_t> BottomUp() const {
    std::vector<std::uint8_t> flipped(pixels_.size());
    const size_t row = static_cast<size_t>(kWidth) * 4;
    for (int y = 0; y < kHeight; ++y) {
      std::copy_n(&pixels_[y * row], row, &flipped[(kHeight - 1 - y) * row]);
    }
    return flipped;
  }

 private:
  std::vector<std::uint8_t> pixels_;
};

std::string Label(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", v);
  return buffer;
}

// a histogram's counts: `bins` equal bins over [lo, hi] (the top edge in the last bin)
std::vector<int> Counts(const std::vector<double>& values, double lo, double hi, int bins) {
  std::vector<int> counts(bins, 0);
  for (double v : values) {
    const int b = std::min(bins - 1, static_cast<int>((v - lo) / (hi - lo) * bins));
    ++counts[std::max(0, b)];
  }
  return counts;
}

// ticks of whole runs from 0 to at least `most`: 1/2/5 x 10^k, never a fraction of a run
ui::Ticks CountTicks(int most) {
  ui::Ticks ticks = ui::NiceTicks(0.0, std::max(most, 1), 6);
  if (ticks.step < 1.0) ticks.step = 1.0;
  ticks.values.clear();
  for (double v = 0.0; v < most + ticks.step; v += ticks.step) ticks.values.push_back(v);
  ticks.decimals = 0;
  return ticks;
}

constexpr Rgb kInk{20, 20, 20};
constexpr int kPlotW = kWidth - kLeft - kRight, kPlotH = kHeight - kTop - kBottom;
constexpr int kBase = kTop + kPlotH;  // the x axis, px from the top

void DrawBars(Canvas& canvas, const std::vector<int>& counts, double top) {
  const int bins = static_cast<int>(counts.size());
  for (int b = 0; b < bins; ++b) {
    const int x0 = kLeft + b * kPlotW / bins, x1 = kLeft + (b + 1) * kPlotW / bins;
    const int height = static_cast<int>(std::lround(counts[b] * kPlotH / top));
    canvas.Fill(x0 + 1, kBase - height, x1 - 1, kBase, {70, 120, 180});
  }
}

// the value axis: ticks at 1/2/5 x 10^k within [lo, hi], where the bins put them
void DrawXAxis(Canvas& canvas, double lo, double hi) {
  canvas.Fill(kLeft - 2, kBase, kLeft + kPlotW, kBase + 2, kInk);
  const ui::Ticks ticks = ui::NiceTicks(lo, hi, 7);
  for (double v : ticks.values) {
    const int x = kLeft + static_cast<int>(std::lround((v - lo) / (hi - lo) * kPlotW));
    canvas.Fill(x - 1, kBase + 2, x + 1, kBase + 8, kInk);
    canvas.Text(x, kBase + 14, ui::TickLabel(ticks, v), 1);
  }
}

// the count axis up to `top` runs
void DrawYAxis(Canvas& canvas, const ui::Ticks& ticks, double top) {
  canvas.Fill(kLeft - 2, kTop, kLeft, kBase + 2, kInk);
  for (double v : ticks.values) {
    const int y = kBase - static_cast<int>(std::lround(v * kPlotH / top));
    canvas.Fill(kLeft - 8, y - 1, kLeft - 2, y + 1, kInk);
    canvas.Text(kLeft - 12, y - 6, ui::TickLabel(ticks, v), 2);
  }
}

bool WritePng(const std::string& path, const Canvas& canvas, std::string* error) {
  // through a temporary file and a rename: never half an image under `path`
  const std::string temporary = path + ".tmp";
  if (!ui::WritePngBottomUp(temporary, kWidth, kHeight, canvas.BottomUp()) ||
      std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    *error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace

bool WriteHistogramPng(const std::string& path, const std::vector<double>& values,
                       const std::string& title, std::string* error) {
  if (values.empty()) {
    *error = title + ": no finite values to plot";
    return false;
  }
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  double lo = *lo_it, hi = *hi_it;
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(lo))) lo -= 0.5, hi += 0.5;
  const int bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(values.size()))), 5, 40);
  const std::vector<int> counts = Counts(values, lo, hi, bins);
  const ui::Ticks count_ticks = CountTicks(*std::max_element(counts.begin(), counts.end()));
  const double top = count_ticks.values.back();
  Canvas canvas;
  DrawBars(canvas, counts, top);
  DrawXAxis(canvas, lo, hi);
  DrawYAxis(canvas, count_ticks, top);
  canvas.Text(kWidth / 2, 16, title, 1);
  canvas.Text(kLeft + kPlotW / 2, kHeight - 30,
              "runs per bin; n = " + std::to_string(values.size()) + ", " + std::to_string(bins) +
                  " bins of " + Label((hi - lo) / bins),
              1);
  return WritePng(path, canvas, error);
}

}  // namespace lamina::app
