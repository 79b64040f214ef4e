#pragma once
// File exports of the cut for the shop floor, as `cutcell-cli export`: the exports the job's
// machine offers (MachineUi::exports(): G-code only where the machine runs an NC program) and
// the wrap-around cutting template (SVG or PDF, 1:1, common to the pipe machines). Files are
// written atomically (writeFileAtomically); errors name the file.
//
// Threading contract: GUI thread only (the computations are short, closed-form).
#include "core/job/job.h"
#include "ui/machine/machine_ui.h"

#include <QString>

#include <functional>

class QMenu;
class QWidget;

namespace CutCell::ui {

class EventLogPanel;
class JobEditor;

// Writes the export; on success *summary says what was written, on failure *error names the
// file and the reason (a machine without this export, an invalid job, a cut off the carriage,
// an I/O error).
// paper: cutting templates only, "single" (one sheet of the template's size), "A4" or "A3"
// (1:1 tiles, core/pipe_joint/template_tiles.h).
bool exportCut(ExportKind kind, const cutcell::Job& job, const QString& path, QString* error,
               QString* summary = nullptr, const QString& paper = QStringLiteral("single"));

// Adds the "Export cut" submenu (object name "exportMenu") to a menu. Its entries are the
// exports of the editor's job's machine, rebuilt when the machine changes: each asks for a
// file, exports the editor's current job and logs the outcome. Each action's data() is its
// ExportKind (int). A template is a submenu of papers (single sheet / A4 / A3): its menu action
// and each entry carry the kind, each entry its paper in the property "cutcellPaper".
// documentPath gives the job's file (the proposed export name follows it; may be empty).
QMenu* addCutExportMenu(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log,
                        std::function<QString()> documentPath = {});

} // namespace CutCell::ui
