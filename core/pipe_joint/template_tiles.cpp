#include "core/pipe_joint/template_tiles.h"
#include "core/common/c_format.h"
#include "core/machine/machine_module.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutcell {
namespace {

constexpr double kCrossArm = 4;  // mm, half the cross; fits in the overlap (kTileOverlapMm / 2)
constexpr double kCrossRing = 2; // mm, radius of the ring round the cross
constexpr double kLabelText = 3; // mm
constexpr double kCheckBar = 50; // mm

const std::vector<Paper>& papers() {
    static const std::vector<Paper> p{{"single", 0, 0}, {"A4", 210, 297}, {"A3", 297, 420}};
    return p;
}

std::string ascii(const std::string& s, size_t maxLen) {
    std::string out;
    for (char ch : s) {
        if (out.size() == maxLen) return out + "...";
        out += (ch >= 32 && ch < 127) ? ch : '?';
    }
    return out;
}

void addCross(TemplateDrawing& page, double x, double y) {
    page.marks.push_back({"cross", {{x - kCrossArm, y}, {x + kCrossArm, y}}, 0.2, false});
    page.marks.push_back({"cross", {{x, y - kCrossArm}, {x, y + kCrossArm}}, 0.2, false});
    TemplateDrawing::Polyline ring{"cross", {}, 0.2, true};
    for (int k = 0; k < 24; ++k) {
        const double t = 2 * kPi * k / 24;
        ring.points.emplace_back(x + kCrossRing * std::cos(t), y + kCrossRing * std::sin(t));
    }
    page.marks.push_back(ring);
}

// Sheet count of one orientation.
struct Grid {
    double pageW, pageH, winW, winH;
    int cols, rows;
};

Grid gridFor(const TemplateDrawing& d, double pageW, double pageH) {
    Grid g{pageW, pageH, pageW - 2 * kTileMarginMm, pageH - 2 * kTileMarginMm - kTileLabelMm, 0, 0};
    g.cols = tilesAlong(d.width_mm, g.winW, kTileOverlapMm);
    g.rows = tilesAlong(d.height_mm, g.winH, kTileOverlapMm);
    return g;
}

TemplateDrawing tilePage(const TemplateDrawing& d, const Grid& g, int r, int c, double x0,
                         double y0, const std::string& jobName) {
    const double m = kTileMarginMm, o = kTileOverlapMm;
    TemplateDrawing page;
    page.width_mm = g.pageW;
    page.height_mm = g.pageH;
    page.circumference_mm = d.circumference_mm;
    page.scale_bar_mm = kCheckBar;
    page.clipped = true;
    page.clip = {m, m, g.winW, g.winH};
    const Eigen::Vector2d shift(m - x0, m - y0);
    for (TemplateDrawing::Polyline l : d.lines) {
        for (auto& p : l.points)
            p += shift;
        page.lines.push_back(std::move(l));
    }
    for (TemplateDrawing::Text t : d.texts) {
        t.pos += shift;
        page.texts.push_back(std::move(t));
    }
    // Crosses at the window corners; trim lines where a neighbour lies left or above.
    for (double x : {m + o / 2, m + g.winW - o / 2})
        for (double y : {m + o / 2, m + g.winH - o / 2})
            addCross(page, x, y);
    if (c > 0)
        page.marks.push_back({"trim", {{m + o / 2, m}, {m + o / 2, m + g.winH}}, 0.2, false, true});
    if (r > 0)
        page.marks.push_back({"trim", {{m, m + o / 2}, {m + g.winW, m + o / 2}}, 0.2, false, true});
    // Label strip: which tile, the job, and a check bar for this sheet's scale.
    const double ly = m + g.winH;
    page.mark_texts.push_back(
        {{m, ly + 4.5},
         kLabelText,
         formatC("row %d, column %d of %d x %d: ", r + 1, c + 1, g.rows, g.cols) +
             ascii(jobName, 40),
         false});
    const double by = ly + 10.5;
    page.marks.push_back({"scale", {{m, by}, {m + kCheckBar, by}}, 0.3, false});
    for (int k = 0; k * 10 <= static_cast<int>(kCheckBar); ++k)
        page.marks.push_back({"scale",
                              {{m + 10.0 * k, by - (k % 5 == 0 ? 3 : 1.5)}, {m + 10.0 * k, by}},
                              0.2,
                              false});
    page.mark_texts.push_back(
        {{m + kCheckBar + 3, by},
         kLabelText,
         formatC("%.0f mm at 1:1 (print at 100 %%); overlap %.0f mm: trim dashes, match crosses",
                 kCheckBar, o),
         false});
    return page;
}

} // namespace

const std::vector<std::string>& paperNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Paper& p : papers())
            n.push_back(p.name);
        return n;
    }();
    return names;
}

std::optional<Paper> paperByName(const std::string& name) {
    for (const Paper& p : papers())
        if (p.name == name) return p;
    return std::nullopt;
}

int tilesAlong(double length_mm, double window_mm, double overlap_mm) {
    if (length_mm <= window_mm) return 1;
    // Tolerance: a length that fits exactly must not ask for one more sheet from rounding.
    return static_cast<int>(std::ceil((length_mm - overlap_mm) / (window_mm - overlap_mm) - 1e-9));
}

TiledTemplate tileTemplate(const TemplateDrawing& d, const Paper& paper,
                           const std::string& jobName) {
    if (paper.short_mm <= 0) throw std::invalid_argument("paper \"single\" is not tiled");
    const Grid portrait = gridFor(d, paper.short_mm, paper.long_mm);
    const Grid landscape = gridFor(d, paper.long_mm, paper.short_mm);
    if (landscape.winH <= kTileOverlapMm || portrait.winW <= kTileOverlapMm)
        throw std::invalid_argument("paper " + paper.name + " is too small for a tile");
    const bool useLandscape = landscape.rows * landscape.cols < portrait.rows * portrait.cols;
    const Grid& g = useLandscape ? landscape : portrait;

    TiledTemplate out;
    out.paper = paper;
    out.landscape = useLandscape;
    out.page_w_mm = g.pageW;
    out.page_h_mm = g.pageH;
    out.window_w_mm = g.winW;
    out.window_h_mm = g.winH;
    out.rows = g.rows;
    out.cols = g.cols;
    const double sx = g.winW - kTileOverlapMm, sy = g.winH - kTileOverlapMm;
    // The tiles cover more than the drawing: centre the drawing in them.
    const double offX = (d.width_mm - (g.cols * sx + kTileOverlapMm)) / 2;
    const double offY = (d.height_mm - (g.rows * sy + kTileOverlapMm)) / 2;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            TemplateTile t;
            t.row = r;
            t.col = c;
            t.x0 = offX + c * sx;
            t.y0 = offY + r * sy;
            t.page = tilePage(d, g, r, c, t.x0, t.y0, jobName);
            out.tiles.push_back(std::move(t));
        }
    return out;
}

std::vector<TemplateDrawing> templatePages(const TemplateDrawing& d, const Paper& paper,
                                           const std::string& jobName) {
    if (paper.short_mm <= 0) return {d};
    std::vector<TemplateDrawing> pages;
    for (TemplateTile& t : tileTemplate(d, paper, jobName).tiles)
        pages.push_back(std::move(t.page));
    return pages;
}

// The papers an export can be written on are the cutting templates' (the only export that
// takes a paper); defined here so that core/machine does not reach into a machine's folder.
const std::vector<std::string>& ExportSettings::papers() {
    return paperNames();
}

} // namespace cutcell
