#pragma once
// A line chart as plain data - title, axis labels, named series - for the figures CutCell writes
// as files: the core writes it as SVG (lineChartSvg), the CLI draws the very same layout as PNG
// with QPainter (app/cli/chart_png.cpp), so the two files of one figure look alike. Used by the
// comparison of a machine's cutting methods (`cutcell-cli compare`).
#include <string>
#include <vector>

namespace cutcell {

struct ChartSeries {
    std::string name;
    std::string color;        // "#1f77b4"
    std::vector<double> x, y; // same length; a non-finite point breaks the line
    bool markers = false;     // a dot on every point (a few points: one per axis)
};

struct LineChart {
    std::string title, x_label, y_label;
    std::vector<ChartSeries> series;
    // Category labels at x = 0, 1, 2, ... instead of numbers (per-axis figures); empty: numbers.
    std::vector<std::string> x_categories;
};

struct ChartTick {
    double value = 0;
    std::string text;
};

// Where everything goes on a width x height picture (pixels, y down): the plot rectangle, the
// data ranges (padded, 0 inside when the data straddles it) and the ticks with their texts.
struct ChartLayout {
    double width = 0, height = 0;
    double left = 0, top = 0, right = 0, bottom = 0; // the plot rectangle
    double xmin = 0, xmax = 1, ymin = 0, ymax = 1;
    std::vector<ChartTick> xticks, yticks;
    double px(double x) const { return left + (x - xmin) / (xmax - xmin) * (right - left); }
    double py(double y) const { return bottom - (y - ymin) / (ymax - ymin) * (bottom - top); }
};

ChartLayout chartLayout(const LineChart& chart, double width, double height);
// The standard palette, colour i (wraps): blue, orange, green, red, purple, brown, ...
const char* chartColor(int i);
// The chart as a stand-alone SVG document (numbers written locale-independently).
std::string lineChartSvg(const LineChart& chart, int width = 900, int height = 480);

} // namespace cutcell
