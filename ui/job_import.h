#pragma once
// File -> Import...: one entry per registered importer (core/machine/job_importer.h, e.g.
// "Import DSTV..."), so the GUI names no machine and no format. The imported job opens as a new
// document; the importer's report (what the job does not do, line by line) goes to the event
// log and a dialog.
//
// Threading contract: GUI thread only (an import is a short parse).
#include "core/job/job.h"
#include "core/machine/import_batch.h"
#include "core/machine/job_importer.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <string>

class QMenu;
class QWidget;

namespace CutCell::ui {

struct ImportOutcome {
    cutcell::Job job;
    QStringList report;
};

// Reads the file and imports it; false + *error naming the file and (from the importer) the
// line and the field.
bool importJobFile(const std::string& importer, const QString& path, ImportOutcome* out,
                   QString* error);
// "DSTV files (*.nc *.nc1 *.NC *.NC1);;All files (*)" for the file dialog.
QString importFileFilter(const cutcell::JobImporter& importer);
// Adds "Import <title>..." per importer (object name "actionImport_<name>"); a click calls
// onImport with the importer's name.
void addImportActions(QMenu* menu, QWidget* parent,
                      const std::function<void(const std::string&)>& onImport);
// The report in a dialog (title, file, the lines); nothing to show -> a short "nothing left out".
void showImportReport(QWidget* parent, const QString& path, const QStringList& report);
// A batch's table in a dialog: a row per file (imported with the importer's facts, or refused
// with the line and the reason), the folder of the jobs and of import-report.csv.
void showImportBatchReport(QWidget* parent, const cutcell::ImportBatch& batch,
                           const QString& folder);

} // namespace CutCell::ui
