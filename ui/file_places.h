#pragma once
// Where the operator's files go. The jobs shipped with CutCell (resources/jobs of this build)
// are examples: Save never overwrites one (nor a file that is not writable), it asks for a copy
// in the operator's job folder instead. Save As and every export open in the operator's folders
// with a file name proposed from the job (Documents/CutCell/jobs and .../exports at first, then
// the folder last saved into).
//
// Threading contract: GUI thread only.
#include <QString>

#include <functional>

class QWidget;

namespace CutCell::ui {

// True for a job shipped with CutCell, or any file that cannot be written in place.
bool mustNotOverwrite(const QString& path);

// The folders the save dialogs open in (QSettings "files/jobs_dir", "files/exports_dir").
QString jobsFolder();
QString exportsFolder();

// A file name stem from the job: its file's name, else its name ("Flying saw demo" ->
// "Flying_saw_demo"), else "job". Never a path separator, never empty.
QString fileStem(const QString& documentPath, const QString& jobName);
// Save As: <jobs folder>/<stem>.json ("_copy" added for a shipped job's name).
QString proposedJobPath(const QString& documentPath, const QString& jobName);
// An export: <exports folder>/<stem><tail>, e.g. tail "_plots.png" or ".ngc".
QString proposedExportPath(const QString& documentPath, const QString& jobName,
                           const QString& tail);
// The first suffix a dialog filter offers: "G-code (*.ngc *.nc)" -> ".ngc" ("" if none).
QString filterSuffix(const QString& filter);

// The save dialog, opened on the proposed file (its folder is created first); the folder of the
// chosen file is remembered for the next dialog of that kind. Empty = cancelled.
enum class SaveKind { Job, Export };
QString askSavePath(QWidget* parent, SaveKind kind, const QString& title, const QString& proposed,
                    const QString& filter);
// Tests and unattended runs replace the dialog: it gets the title, the proposed path and the
// filter and returns the chosen path (empty = cancel). An empty function restores the dialog.
using SavePathPrompt =
    std::function<QString(const QString& title, const QString& proposed, const QString& filter)>;
void setSavePathPrompt(SavePathPrompt prompt);

} // namespace CutCell::ui
