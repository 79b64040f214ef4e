#include "core/sim/line_chart.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

// A "nice" step (1, 2 or 5 times a power of ten) giving about `count` intervals over span.
double niceStep(double span, int count) {
    const double raw = span / count;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / p;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

std::vector<ChartTick> ticks(double lo, double hi, int count) {
    const double step = niceStep(hi - lo, count);
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    std::vector<ChartTick> out;
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) {
        const double shown = std::fabs(v) < step * 1e-6 ? 0.0 : v; // no "-0.000"
        out.push_back({shown, formatC("%.*f", decimals, shown)});
    }
    return out;
}

void padded(double* lo, double* hi) {
    if (!(*hi > *lo)) {
        const double mid = std::isfinite(*lo) ? *lo : 0;
        const double half = std::max(std::fabs(mid) * 0.1, 1e-9);
        *lo = mid - half;
        *hi = mid + half;
        return;
    }
    const double pad = 0.05 * (*hi - *lo);
    *lo -= pad;
    *hi += pad;
}

std::string escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

} // namespace

const char* chartColor(int i) {
    static const char* const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    return palette[static_cast<size_t>(i) % std::size(palette)];
}

ChartLayout chartLayout(const LineChart& chart, double width, double height) {
    ChartLayout l;
    l.width = width;
    l.height = height;
    l.left = 80;
    l.top = 40;
    l.right = width - 20;
    l.bottom = height - 55;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (const ChartSeries& s : chart.series)
        for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            xlo = std::min(xlo, s.x[i]), xhi = std::max(xhi, s.x[i]);
            ylo = std::min(ylo, s.y[i]), yhi = std::max(yhi, s.y[i]);
        }
    if (!std::isfinite(xlo)) xlo = 0, xhi = 1, ylo = 0, yhi = 1;
    if (!chart.x_categories.empty()) {
        xlo = -0.5;
        xhi = static_cast<double>(chart.x_categories.size()) - 0.5;
        ylo = std::min(ylo, 0.0); // a per-axis figure starts at 0
    } else if (!(xhi > xlo)) {
        padded(&xlo, &xhi);
    }
    padded(&ylo, &yhi);
    l.xmin = xlo, l.xmax = xhi, l.ymin = ylo, l.ymax = yhi;
    if (chart.x_categories.empty()) {
        l.xticks = ticks(xlo, xhi, 8);
    } else {
        for (size_t i = 0; i < chart.x_categories.size(); ++i)
            l.xticks.push_back({static_cast<double>(i), chart.x_categories[i]});
    }
    l.yticks = ticks(ylo, yhi, 6);
    return l;
}

std::string lineChartSvg(const LineChart& chart, int width, int height) {
    const ChartLayout l = chartLayout(chart, width, height);
    std::string s = formatC("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                            "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\">\n",
                            width, height, width, height);
    s += formatC("<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", width, height);
    s += formatC("<defs><clipPath id=\"plot\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
                 "height=\"%.1f\"/></clipPath></defs>\n",
                 l.left, l.top, l.right - l.left, l.bottom - l.top);
    // Grid and ticks.
    for (const ChartTick& t : l.yticks) {
        const double y = l.py(t.value);
        s += formatC("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\n",
                     l.left, y, l.right, y, t.value == 0 ? "#999" : "#e4e4e4");
        s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"end\">%s</text>\n",
                     l.left - 6, y + 4, escaped(t.text).c_str());
    }
    for (const ChartTick& t : l.xticks) {
        const double x = l.px(t.value);
        s += formatC("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e4e4e4\"/>\n",
                     x, l.top, x, l.bottom);
        s += formatC(
            "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">%s</text>\n", x,
            l.bottom + 17, escaped(t.text).c_str());
    }
    s += formatC("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
                 "stroke=\"#444\"/>\n",
                 l.left, l.top, l.right - l.left, l.bottom - l.top);
    // Series: one polyline per unbroken run of finite points.
    s += "<g clip-path=\"url(#plot)\">\n";
    for (const ChartSeries& c : chart.series) {
        std::string points;
        const auto flush = [&] {
            if (!points.empty())
                s += "<polyline fill=\"none\" stroke=\"" + c.color +
                     "\" stroke-width=\"1.5\" points=\"" + points + "\"/>\n";
            points.clear();
        };
        for (size_t i = 0; i < c.x.size() && i < c.y.size(); ++i) {
            if (!std::isfinite(c.x[i]) || !std::isfinite(c.y[i])) {
                flush();
                continue;
            }
            points += formatC("%.2f %.2f ", l.px(c.x[i]), l.py(c.y[i])); // no commas (locale)
            if (c.markers)
                s += formatC("<circle cx=\"%.2f\" cy=\"%.2f\" r=\"4\" fill=\"%s\"/>\n",
                             l.px(c.x[i]), l.py(c.y[i]), c.color.c_str());
        }
        flush();
    }
    s += "</g>\n";
    // Title, axis labels, legend (top right, inside the plot).
    s += formatC("<text x=\"%.1f\" y=\"24\" font-size=\"16\" text-anchor=\"middle\">%s</text>\n",
                 (l.left + l.right) / 2, escaped(chart.title).c_str());
    s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"13\" text-anchor=\"middle\">%s</text>\n",
                 (l.left + l.right) / 2, l.bottom + 42, escaped(chart.x_label).c_str());
    s += formatC("<text x=\"18\" y=\"%.1f\" font-size=\"13\" text-anchor=\"middle\" "
                 "transform=\"rotate(-90 18 %.1f)\">%s</text>\n",
                 (l.top + l.bottom) / 2, (l.top + l.bottom) / 2, escaped(chart.y_label).c_str());
    const double rowH = 18, boxW = 150;
    const double bx = l.right - boxW - 8, by = l.top + 8;
    s += formatC("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"white\" "
                 "fill-opacity=\"0.85\" stroke=\"#bbb\"/>\n",
                 bx, by, boxW, rowH * static_cast<double>(chart.series.size()) + 6);
    for (size_t i = 0; i < chart.series.size(); ++i) {
        const double y = by + 3 + rowH * (static_cast<double>(i) + 0.5);
        s += formatC("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                     "stroke-width=\"2.5\"/>\n",
                     bx + 8, y, bx + 32, y, chart.series[i].color.c_str());
        s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">%s</text>\n", bx + 40, y + 4,
                     escaped(chart.series[i].name).c_str());
    }
    return s + "</svg>\n";
}

} // namespace cutcell
