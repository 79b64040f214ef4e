#pragma once
// File exports of the cut for the shop floor, as `cutcell-cli export`: the profile cutter's
// G-code (X/A, the profile cutter machine only) and the wrap-around cutting template
// (SVG or PDF, 1:1, any machine). Files are written atomically (writeFileAtomically); errors
// name the file.
//
// Threading contract: GUI thread only (the computations are short, closed-form).
#include "core/job/job.h"

#include <QString>

class QMenu;
class QWidget;

namespace CutCell::ui {

class EventLogPanel;
class JobEditor;

enum class ExportKind { Gcode, TemplateSvg, TemplatePdf };

// Writes the export; on success *summary says what was written, on failure *error names the
// file and the reason (an invalid job, a cut off the carriage, an I/O error).
bool exportCut(ExportKind kind, const cutcell::Job& job, const QString& path, QString* error,
               QString* summary = nullptr);

// Adds "Export G-code...", "Export template (SVG)..." and "Export template (PDF)..." to a
// menu: each asks for a file, exports the editor's current job and logs the outcome.
void addCutExportActions(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log);

} // namespace CutCell::ui
