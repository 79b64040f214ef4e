#pragma once
// The cutting template as a PDF 1.4 at 1:1: one page of the template's size (mm -> pt at
// 72/25.4), or one page per tile (template_tiles.h), vector paths and Helvetica text,
// uncompressed content streams and an exact xref table, so any viewer or printer reads it. A
// tile's template lines are clipped to its window (re W n). PDF 1.4 pages are at most 200 in
// (5080 mm) a side: larger templates are refused with a message naming the size.
#include "core/pipe_joint/template_layout.h"

#include <string>
#include <vector>

namespace cutcell {

inline constexpr double kPtPerMm = 72.0 / 25.4;

// Throws std::runtime_error when the page would exceed the PDF page size limit.
std::string templatePdf(const TemplateDrawing& drawing);
// One page per drawing, in order (at least one).
std::string templatePdf(const std::vector<TemplateDrawing>& pages);

} // namespace cutcell
