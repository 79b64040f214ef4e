#pragma once
// The 1:1 cutting template split over sheets of printer paper (A4, A3): every tile is one page
// of the paper, portrait or landscape (whichever needs fewer sheets), with
//  - a printable area kTileMarginMm from every paper edge: nothing is drawn outside it;
//  - a window of the template (clipped to it) and, below it, a label strip with
//    "row r, column c of R x C", the job name and a 50 mm check bar;
//  - an overlap of kTileOverlapMm between neighbouring windows; a registration cross at each
//    window corner, kTileOverlapMm / 2 in from both edges, so two neighbours share the crosses
//    of their common edge, and a dashed trim line through the crosses on the left and top of
//    every tile that has a neighbour there (trim there, lay it on the neighbour, match crosses).
// Paper "single" gives the template as one page of its own size (templatePdf/templateSvg of the
// drawing, unchanged).
#include "core/pipe_joint/template_layout.h"

#include <optional>
#include <string>
#include <vector>

namespace cutcell {

inline constexpr double kTileMarginMm = 10;  // printable area: this far from the paper edge
inline constexpr double kTileOverlapMm = 10; // shared by neighbouring tiles
inline constexpr double kTileLabelMm = 12;   // label strip under the window

struct Paper {
    std::string name;                 // "single", "A4", "A3"
    double short_mm = 0, long_mm = 0; // 0 for single
};

// The accepted names, for option lists and messages: "single", "A4", "A3".
const std::vector<std::string>& paperNames();
// nullopt for a name not in paperNames().
std::optional<Paper> paperByName(const std::string& name);

struct TemplateTile {
    int row = 0, col = 0;  // 0-based
    double x0 = 0, y0 = 0; // template point at the window's top left corner (drawing mm)
    TemplateDrawing page;  // the page (paper size, mm), ready for templatePdf / templateSvg
};

struct TiledTemplate {
    Paper paper;
    bool landscape = false;
    double page_w_mm = 0, page_h_mm = 0;     // the paper as printed
    double window_w_mm = 0, window_h_mm = 0; // template shown per tile (inside the margins)
    int rows = 0, cols = 0;
    std::vector<TemplateTile> tiles; // row by row
};

// Tiles needed along one side: the least n with n * (window - overlap) + overlap >= length.
int tilesAlong(double length_mm, double window_mm, double overlap_mm);

// Throws std::invalid_argument for paper "single" or one too small for any window.
TiledTemplate tileTemplate(const TemplateDrawing& drawing, const Paper& paper,
                           const std::string& jobName);

// The pages to print: the drawing itself on "single", else one page per tile.
std::vector<TemplateDrawing> templatePages(const TemplateDrawing& drawing, const Paper& paper,
                                           const std::string& jobName);

} // namespace cutcell
