#pragma once
// The unrolled cutting template of the profile cutter: the cut curve developed on the outer
// surface of the pipe being cut (u = R_w * A along the circumference, v from X along the pipe),
// to print at 1:1, wrap around the pipe and cut by hand. One drawing (mm, origin top left,
// y down) is rendered by both back ends, template_svg and
// core/machines/profile_cutter/template_pdf.
//
// Contents: the cut curve (one full turn for the branch end, a closed loop for the hole), the two
// wrap edges (u = 0 and u = circumference: the template's developed length), quadrant marks at
// every 90 deg of A, a reference line to align with a line scribed round the pipe, the pipe data,
// and a 1:1 scale bar with 10 mm ticks.
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cutcell {

struct TemplateDrawing {
    struct Polyline {
        std::string id; // "cut", "edge", "quadrant", "reference", "scale"
        std::vector<Eigen::Vector2d> points;
        double width_mm = 0.25;
        bool closed = false;
    };
    struct Text {
        Eigen::Vector2d pos; // baseline start (or centre with centred = true)
        double size_mm = 3.5;
        std::string text; // plain ASCII
        bool centred = false;
    };
    double width_mm = 0, height_mm = 0;
    std::vector<Polyline> lines;
    std::vector<Text> texts;
    // Geometry facts of the drawing (for checks and captions).
    double circumference_mm = 0; // 2 pi R_w = distance between the wrap edges
    double origin_u_mm = 0;      // page x of A = a_low_deg
    double a_low_deg = 0;        // A at the left wrap edge
    double x_top_mm = 0;         // X at page y = top of the drawing area
    double top_mm = 0;           // page y of x_top_mm (page y = top + (x_top - X))
    double scale_bar_mm = 0;
};

// samples: points of the cut curve per turn (the drawing is smoother than the NC grid).
TemplateDrawing buildTemplate(const Job& job, int samples = 1440);

} // namespace cutcell
