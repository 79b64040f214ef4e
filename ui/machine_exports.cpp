#include "ui/machine_exports.h"

#include "core/machines/profile_cutter/template_layout.h"
#include "core/machines/profile_cutter/template_pdf.h"
#include "core/machines/profile_cutter/template_svg.h"
#include "core/job/job_io.h"
#include "ui/forms/job_editor.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/panels/event_log_panel.h"

#include <QFileDialog>
#include <QMenu>

#include <algorithm>

namespace CutCell::ui {

bool exportCut(ExportKind kind, const cutcell::Job& job, const QString& path, QString* error,
               QString* summary) {
    const auto fail = [&](const QString& why) {
        if (error) *error = QObject::tr("Export to %1 failed: %2").arg(path, why);
        return false;
    };
    const MachineUi* machine = machineUiFor(job);
    if (!machine)
        return fail(QObject::tr("no machine module for machine = \"%1\"")
                        .arg(QString::fromStdString(job.machine)));
    const auto offered = machine->exports();
    if (std::find(offered.begin(), offered.end(), kind) == offered.end())
        return fail(QObject::tr("the %1 offers no \"%2\" export")
                        .arg(machine->title(), exportLabel(kind).remove('&').remove("...")));
    try {
        std::string text;
        QString what;
        if (kind == ExportKind::TemplateSvg || kind == ExportKind::TemplatePdf) {
            const cutcell::TemplateDrawing drawing = cutcell::buildTemplate(job);
            const bool svg = kind == ExportKind::TemplateSvg;
            text = svg ? cutcell::templateSvg(drawing) : cutcell::templatePdf(drawing);
            what = QObject::tr("cutting template (%1, 1:1): %2 x %3 mm")
                       .arg(svg ? "SVG" : "PDF")
                       .arg(drawing.width_mm, 0, 'f', 1)
                       .arg(drawing.height_mm, 0, 'f', 1);
        } else {
            text = machine->exportText(kind, job, &what);
        }
        cutcell::writeFileAtomically(path.toStdString(), text);
        if (summary) *summary = QObject::tr("Exported %1 to %2").arg(what, path);
        return true;
    } catch (const std::exception& e) {
        return fail(QString::fromUtf8(e.what()));
    }
}

namespace {

void fillExportMenu(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log) {
    menu->clear();
    const MachineUi* machine = machineUiFor(editor->job());
    menu->setEnabled(machine != nullptr);
    if (!machine) return;
    for (const ExportKind kind : machine->exports()) {
        const QString label = exportLabel(kind);
        QAction* a = menu->addAction(label, parent, [=] {
            const QString p = QFileDialog::getSaveFileName(parent, label, {}, exportFilter(kind));
            if (p.isEmpty()) return;
            if (!editor->valid()) {
                log->add(cutcell::Severity::Error,
                         QObject::tr("Export to %1 refused: the job has invalid fields.").arg(p));
                return;
            }
            QString err, summary;
            if (exportCut(kind, editor->job(), p, &err, &summary))
                log->add(cutcell::Severity::Info, summary);
            else
                log->add(cutcell::Severity::Error, err);
        });
        a->setData(static_cast<int>(kind));
    }
}

} // namespace

QMenu* addCutExportMenu(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log) {
    QMenu* exports = menu->addMenu(QObject::tr("&Export cut"));
    exports->setObjectName("exportMenu");
    const auto refresh = [=] {
        const QString machine = QString::fromStdString(editor->job().machine);
        if (exports->property("cutcellMachine").toString() == machine) return;
        exports->setProperty("cutcellMachine", machine);
        fillExportMenu(exports, parent, editor, log);
    };
    QObject::connect(editor, &JobEditor::jobReset, exports, refresh);
    QObject::connect(editor, &JobEditor::edited, exports, refresh);
    refresh();
    return exports;
}

} // namespace CutCell::ui
