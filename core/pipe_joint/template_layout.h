#pragma once
// The unrolled cutting template of a pipe joint (the profile cutter's and the pipe robot's
// export; its axes are the profile cutter's): the cut curve developed on the outer
// surface of the pipe being cut (u = R_w * A along the circumference, v from X along the pipe),
// to print at 1:1, wrap around the pipe and cut by hand. One drawing (mm, origin top left,
// y down) is rendered by both back ends, template_svg and
// core/pipe_joint/template_pdf.
//
// Contents: the cut curve (one full turn for the branch end, a closed loop for the hole), the two
// wrap edges (u = 0 and u = circumference: the template's developed length), quadrant marks at
// every 90 deg of A, a reference line to align with a line scribed round the pipe, the pipe data,
// a 1:1 scale bar with 10 mm ticks, a glue tab beyond the last edge, a mark on the 0 deg line
// (A = 0 of the G-code: the generator under the torch at chuck zero) and the wrap direction.
//
// Wrap rule (the sentence printed on the sheet; tests/profile/template_test.cpp checks it in 3D):
// printed side out, the sheet's top edge toward the end of the pipe given by top_toward; page x
// grows with A, which is then counter-clockwise seen from that end. For this the branch end has
// X growing upward (top = the end being cut) and the hole X growing downward (top = the main
// pipe's fixed end): the other way round the sheet would lie mirrored on the pipe.
#include "core/job/job.h"
#include "core/pipe_joint/developed_cut.h"

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
        bool dashed = false; // trim lines of tiles
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
    double top_mm = 0;           // page y of x_top_mm: page y = top + y_per_x (X - x_top)
    double y_per_x = -1;         // -1: X grows upward (branch end), +1: downward (hole)
    double zero_u_mm = 0;        // page x of the 0 deg line (A = 0)
    double glue_tab_mm = 0;      // width of the glue tab right of the last wrap edge
    double scale_bar_mm = 0;

    // A tile of a larger drawing (template_tiles.h): lines and texts are clipped to this
    // rectangle (page mm); marks and mark_texts (crosses, trim lines, labels) are not.
    struct Rect {
        double x = 0, y = 0, w = 0, h = 0;
    };
    bool clipped = false;
    Rect clip;
    std::vector<Polyline> marks;
    std::vector<Text> mark_texts;
};

// samples: points of the cut curve per turn (the drawing is smoother than the NC grid).
TemplateDrawing buildTemplate(const Job& job, const JointExtras& extras, int samples = 1440);

} // namespace cutcell
