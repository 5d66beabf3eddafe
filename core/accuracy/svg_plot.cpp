// SPDX-License-Identifier: MIT
#include "core/accuracy/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lamina::core {
namespace {

constexpr double kLeft = 70.0, kRight = 190.0, kTop = 30.0, kBottom = 50.0;  // margins, px
// Colour-blind-safe palette (Okabe–Ito).
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                "#E69F00", "#56B4E9", "#000000", "#F0E442"};

bool Plottable(double x, double y) {
  return std::isfinite(x) && std::isfinite(y) && x > 0.0 && y > 0.0;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  void Add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(hi > 0.0); }
};

struct Frame {
  double x0, x1, y0, y1;  // log10 of the axis ends
  double width, height;
  double X(double x) const {
    return kLeft + (std::log10(x) - x0) / (x1 - x0) * (width - kLeft - kRight);
  }
  double Y(double y) const {
    return height - kBottom - (std::log10(y) - y0) / (y1 - y0) * (height - kTop - kBottom);
  }
};

std::string AxisNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

std::string TickLabel(double decade) {
  char text[32];
  std::snprintf(text, sizeof text, "1e%d", static_cast<int>(std::lround(std::log10(decade))));
  return text;
}

std::string Text(double x, double y, const std::string& text, const char* anchor,
                 const std::string& extra = "") {
  return "<text x=\"" + AxisNumber(x) + "\" y=\"" + AxisNumber(y) + "\" text-anchor=\"" + anchor +
         "\"" + extra + ">" + Escape(text) + "</text>\n";
}

std::string Line(double x0, double y0, double x1, double y1, const char* style) {
  return "<line x1=\"" + AxisNumber(x0) + "\" y1=\"" + AxisNumber(y0) + "\" x2=\"" +
         AxisNumber(x1) + "\" y2=\"" + AxisNumber(y1) + "\" " + style + "/>\n";
}

std::string Grid(const Frame& f, const std::vector<double>& xt, const std::vector<double>& yt) {
  std::string svg;
  const char* grid = "stroke=\"#ddd\"";
  for (double x : xt) {
    svg += Line(f.X(x), kTop, f.X(x), f.height - kBottom, grid);
    svg += Text(f.X(x), f.height - kBottom + 16, TickLabel(x), "middle");
  }
  for (double y : yt) {
    svg += Line(kLeft, f.Y(y), f.width - kRight, f.Y(y), grid);
    svg += Text(kLeft - 6, f.Y(y) + 4, TickLabel(y), "end");
  }
  return svg;
}

std::string Axes(const LogLogPlot& plot, const Frame& f) {
  std::string svg = "<rect x=\"" + AxisNumber(kLeft) + "\" y=\"" + AxisNumber(kTop) +
                    "\" width=\"" + AxisNumber(f.width - kLeft - kRight) + "\" height=\"" +
                    AxisNumber(f.height - kTop - kBottom) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  svg += Text(f.width / 2.0, 18, plot.title, "middle", " font-weight=\"bold\"");
  svg += Text((kLeft + f.width - kRight) / 2.0, f.height - 12, plot.x_label, "middle");
  const double cy = (kTop + f.height - kBottom) / 2.0;
  svg +=
      Text(16, cy, plot.y_label, "middle", " transform=\"rotate(-90 16 " + AxisNumber(cy) + ")\"");
  return svg;
}

std::string Dashes(const PlotSeries& s) {
  return s.dashed ? " stroke-dasharray=\"6 4\"" : "";
}

std::string SeriesSvg(const PlotSeries& s, const Frame& f, const char* colour) {
  std::string points, marks;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!Plottable(s.x[i], s.y[i])) continue;
    const std::string px = AxisNumber(f.X(s.x[i])), py = AxisNumber(f.Y(s.y[i]));
    points += px + "," + py + " ";
    marks += "<circle cx=\"" + px + "\" cy=\"" + py + "\" r=\"3\" fill=\"" + colour + "\"/>\n";
  }
  return "<polyline fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"1.5\"" +
         Dashes(s) + " points=\"" + points + "\"/>\n" + marks;
}

int Hidden(const PlotSeries& s) {
  int hidden = 0;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
    hidden += !Plottable(s.x[i], s.y[i]);
  return hidden;
}

std::string Legend(const LogLogPlot& plot, const Frame& f) {
  std::string svg;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const double y = kTop + 14.0 + 18.0 * static_cast<double>(i);
    const double x = f.width - kRight + 10.0;
    const char* colour = kColours[i % std::size(kColours)];
    svg += Line(x, y - 4, x + 18, y - 4,
                ("stroke=\"" + std::string(colour) + "\" stroke-width=\"2\"" + Dashes(s)).c_str());
    const int hidden = Hidden(s);
    const std::string extra = hidden > 0 ? " (" + std::to_string(hidden) + " at 0)" : "";
    svg += Text(x + 24, y, s.label + extra, "start");
  }
  return svg;
}

Frame MakeFrame(const LogLogPlot& plot, Range xr, Range yr) {
  if (xr.empty()) xr = {0.1, 10.0};
  if (yr.empty()) yr = {0.1, 10.0};
  const std::vector<double> xt = DecadeTicks(xr.lo, xr.hi), yt = DecadeTicks(yr.lo, yr.hi);
  return {std::log10(xt.front()),          std::log10(xt.back()),
          std::log10(yt.front()),          std::log10(yt.back()),
          static_cast<double>(plot.width), static_cast<double>(plot.height)};
}

}  // namespace

std::vector<double> DecadeTicks(double lo, double hi) {
  int first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (last <= first) last = first + 1;
  std::vector<double> ticks;
  for (int e = first; e <= last; ++e) ticks.push_back(std::pow(10.0, e));
  return ticks;
}

double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!Plottable(x[i], y[i])) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    n += 1;
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double spread = n * sxx - sx * sx;
  if (n < 2 || spread <= 1e-12 * std::max(1.0, n * sxx)) return std::nan("");
  return (n * sxy - sx * sy) / spread;
}

std::string LogLogSvg(const LogLogPlot& plot) {
  Range xr, yr;
  for (const PlotSeries& s : plot.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!Plottable(s.x[i], s.y[i])) continue;
      xr.Add(s.x[i]);
      yr.Add(s.y[i]);
    }
  }
  const Frame f = MakeFrame(plot, xr, yr);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    std::to_string(plot.width) + "\" height=\"" + std::to_string(plot.height) +
                    "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += Grid(f, DecadeTicks(std::pow(10.0, f.x0), std::pow(10.0, f.x1)),
              DecadeTicks(std::pow(10.0, f.y0), std::pow(10.0, f.y1)));
  svg += Axes(plot, f);
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    svg += SeriesSvg(plot.series[i], f, kColours[i % std::size(kColours)]);
  }
  return svg + Legend(plot, f) + "</svg>\n";
}

}  // namespace lamina::core
