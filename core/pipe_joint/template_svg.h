#pragma once
// The cutting template as SVG at 1:1: width and height in mm and a viewBox in mm, so one user
// unit is one millimetre. The cut curve is the path with id="cut".
//
// Tiles (template_tiles.h) go into ONE SVG file: the pages side by side as the sheets are
// assembled (row by row, 10 mm apart), each a <g id="tile-rR-cC"> with its paper outline and
// its window clipped by a clipPath, so the file shows the whole set and each tile can be cut out
// of it by id. One file, because an export is one file (CLI option, GUI save dialog); the PDF,
// one page per tile, is the one to print.
#include "core/pipe_joint/template_layout.h"
#include "core/pipe_joint/template_tiles.h"

#include <string>

namespace cutcell {

std::string templateSvg(const TemplateDrawing& drawing);
// The tiles of tileTemplate() on one sheet (see above).
std::string templateSvg(const TiledTemplate& tiles);

} // namespace cutcell
