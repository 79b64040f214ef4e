#include "core/machines/quick_return/quick_return_svg.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace cutcell::quick_return {

namespace {

struct Panel {
    double x0, y0, w, h;           // pixels
    double xmin, xmax, ymin, ymax; // data
    double px(double x) const { return x0 + (x - xmin) / (xmax - xmin) * w; }
    double py(double y) const { return y0 + h - (y - ymin) / (ymax - ymin) * h; }
};

std::string polyline(const Panel& p, const std::vector<double>& xs, const std::vector<double>& ys,
                     const char* color, double width = 1.2) {
    std::string s = "<polyline fill=\"none\" stroke=\"" + std::string(color) +
                    formatC("\" stroke-width=\"%.1f\" points=\"", width);
    for (size_t i = 0; i < xs.size(); ++i)
        if (std::isfinite(xs[i]) && std::isfinite(ys[i]))
            s += formatC("%.1f %.1f ", p.px(xs[i]), p.py(ys[i])); // no commas: see locale_test
    return s + "\"/>\n";
}

std::string frame(const Panel& p, const std::string& title, const char* xl, const char* yl) {
    std::string s = formatC("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" "
                            "fill=\"white\" stroke=\"#444\"/>\n",
                            p.x0, p.y0, p.w, p.h);
    s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"13\">%s</text>\n", p.x0, p.y0 - 6,
                 title.c_str());
    s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">%s  [%.3g, %.3g]</text>\n", p.x0,
                 p.y0 + p.h + 16, xl, p.xmin, p.xmax);
    s += formatC("<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">%s  [%.3g, %.3g]</text>\n",
                 p.x0 + p.w * 0.5, p.y0 + p.h + 16, yl, p.ymin, p.ymax);
    if (p.ymin < 0 && p.ymax > 0)
        s += formatC("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#bbb\"/>\n",
                     p.x0, p.py(0), p.x0 + p.w, p.py(0));
    return s;
}

void range(const std::vector<double>& v, double* lo, double* hi) {
    *lo = 1e300;
    *hi = -1e300;
    for (double x : v)
        if (std::isfinite(x)) {
            *lo = std::min(*lo, x);
            *hi = std::max(*hi, x);
        }
    if (!(*hi > *lo)) *hi = *lo + 1;
    const double pad = 0.05 * (*hi - *lo);
    *lo -= pad;
    *hi += pad;
}

std::string mechanism(const Panel& p, const WhitworthDims& d, double q, const char* color) {
    const WhitworthPoints pts = mechanismPoints(d, q);
    if (!pts.closes) return {};
    const double ax = pts.a[0], ay = pts.a[1];
    const double bx = pts.b[0], by = pts.b[1];
    const double sx = pts.slider[0], sy = pts.slider[1];
    std::string s;
    s += polyline(p, {0, ax}, {0, ay}, color, 3);         // crank
    s += polyline(p, {d.o3x, bx}, {d.o3y, by}, color, 2); // rocker
    s += polyline(p, {bx, sx}, {by, sy}, color, 2);       // link
    s += formatC("<rect x=\"%.1f\" y=\"%.1f\" width=\"14\" height=\"10\" fill=\"%s\"/>\n",
                 p.px(sx) - 7, p.py(sy) - 5, color); // slider
    s += formatC("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", p.px(ax), p.py(ay),
                 color);
    return s;
}

} // namespace

std::string cuttingFiguresSvg(const ExperimentSetup& setup, const CuttingResult& r) {
    const WhitworthDims& d = setup.law.dims;
    const VelocityProfile& prof = setup.law.profile;
    std::vector<double> t, y, dy, yd, dyd, te, ev;
    for (const TracePoint& p : r.trace) {
        t.push_back(p.t);
        y.push_back(p.y);
        dy.push_back(p.dy);
        yd.push_back(p.y_d);
        dyd.push_back(p.cutting ? p.dy_d : NAN);
        const double lo = std::min(prof.y_a, prof.y_b), hi = std::max(prof.y_a, prof.y_b);
        if (p.cutting && p.y >= lo && p.y <= hi) {
            te.push_back(p.t);
            ev.push_back(p.dy_d - p.dy);
        }
    }
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1100\" height=\"800\" "
                    "font-family=\"sans-serif\">\n<rect width=\"1100\" height=\"800\" "
                    "fill=\"#f4f4f4\"/>\n";
    s += formatC("<text x=\"20\" y=\"24\" font-size=\"15\">Quick-return cutter, controller %s: "
                 "%d strokes, velocity error over the work max %.4f m/s, rms %.4f m/s%s</text>\n",
                 toString(r.controller), r.strokes, r.velocity_error_max, r.velocity_error_rms,
                 r.completed ? "" : " (NOT COMPLETED)");
    // Mechanism (crank frame, y as the scale reads minus its offset).
    const double reach = d.r2 + d.ab + std::fabs(d.o3x) + d.r4;
    Panel m{40, 60, 330, 330, -reach, reach, -reach * 1.3, reach * 0.7};
    s += frame(m, "mechanism (crank frame, m)", "x", "y");
    const double lo = std::min(prof.y_a, prof.y_b) - d.scale_offset;
    const double hi = std::max(prof.y_a, prof.y_b) - d.scale_offset;
    s += formatC("<rect x=\"%.1f\" y=\"%.1f\" width=\"30\" height=\"%.1f\" fill=\"#e7c9a0\"/>\n",
                 m.px(d.dx) + 10, m.py(hi), m.py(lo) - m.py(hi)); // the workpiece beside the tool
    const char* colors[] = {"#1f77b4", "#2ca02c", "#d62728", "#9467bd"};
    const StrokeInfo& st = setup.law.stroke;
    for (int i = 0; i < 4; ++i)
        s += mechanism(m, d, st.q_top + st.cut_arc * i / 3.0, colors[i]);
    // Velocity profile.
    Panel v{420, 60, 640, 300, 0, 1, 0, 1};
    range(t, &v.xmin, &v.xmax);
    std::vector<double> both = dy;
    both.insert(both.end(), dyd.begin(), dyd.end());
    range(both, &v.ymin, &v.ymax);
    s += frame(v, "cutting velocity profile: y' (blue), y_d' in the cut (orange)", "t (s)", "m/s");
    s += polyline(v, t, dy, "#1f77b4");
    s += polyline(v, t, dyd, "#ff7f0e");
    // Phase diagram.
    Panel ph{40, 450, 480, 300, 0, 1, 0, 1};
    range(y, &ph.xmin, &ph.xmax);
    ph.ymin = v.ymin;
    ph.ymax = v.ymax;
    s += frame(ph, "phase diagram: y' against y (y_a, y_b dashed)", "y (m)", "y' (m/s)");
    s += polyline(ph, y, dy, "#1f77b4");
    for (double edge : {prof.y_a, prof.y_b})
        s += formatC("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" "
                     "stroke-dasharray=\"4 3\"/>\n",
                     ph.px(edge), ph.y0, ph.px(edge), ph.y0 + ph.h);
    // Velocity error over the work.
    Panel e{580, 450, 480, 300, 0, 1, 0, 1};
    range(te.empty() ? t : te, &e.xmin, &e.xmax);
    range(ev.empty() ? std::vector<double>{0} : ev, &e.ymin, &e.ymax);
    s += frame(e, "velocity error y_d' - y' over the workpiece", "t (s)", "m/s");
    // One polyline per pass over the work (gaps between strokes).
    std::vector<double> px, py;
    for (size_t i = 0; i < te.size(); ++i) {
        if (i > 0 && te[i] - te[i - 1] > 0.05) {
            s += polyline(e, px, py, "#d62728");
            px.clear();
            py.clear();
        }
        px.push_back(te[i]);
        py.push_back(ev[i]);
    }
    s += polyline(e, px, py, "#d62728");
    return s + "</svg>\n";
}

} // namespace cutcell::quick_return
