#pragma once
// The cutting template as a one-page PDF 1.4 at 1:1: the page is the template's size (mm -> pt at
// 72/25.4), vector paths and Helvetica text, an uncompressed content stream and an exact xref
// table, so any viewer or printer reads it. PDF 1.4 pages are at most 200 in (5080 mm) a side:
// larger templates are refused with a message naming the size.
#include "core/machines/profile_cutter/template_layout.h"

#include <string>

namespace cutcell {

inline constexpr double kPtPerMm = 72.0 / 25.4;

// Throws std::runtime_error when the page would exceed the PDF page size limit.
std::string templatePdf(const TemplateDrawing& drawing);

} // namespace cutcell
