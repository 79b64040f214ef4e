#pragma once
// The cutting template as SVG at 1:1: width and height in mm and a viewBox in mm, so one user
// unit is one millimetre. The cut curve is the path with id="cut".
#include "core/machines/profile_cutter/template_layout.h"

#include <string>

namespace cutcell {

std::string templateSvg(const TemplateDrawing& drawing);

} // namespace cutcell
