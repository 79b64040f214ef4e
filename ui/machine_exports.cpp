#include "ui/machine_exports.h"

#include "core/job/job_io.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/template_layout.h"
#include "core/machines/profile_cutter/template_pdf.h"
#include "core/machines/profile_cutter/template_svg.h"
#include "ui/forms/job_editor.h"
#include "ui/machine_plan.h"
#include "ui/panels/event_log_panel.h"

#include <QFileDialog>
#include <QMenu>

namespace CutCell::ui {

bool exportCut(ExportKind kind, const cutcell::Job& job, const QString& path, QString* error,
               QString* summary) {
    const auto fail = [&](const QString& why) {
        if (error) *error = QObject::tr("Export to %1 failed: %2").arg(path, why);
        return false;
    };
    try {
        std::string text;
        QString what;
        if (kind == ExportKind::Gcode) {
            if (!isProfileCutterJob(job))
                return fail(QObject::tr("G-code needs machine = \"%1\"; this job has \"%2\"")
                                .arg(kProfileCutterMachine, QString::fromStdString(job.machine)));
            const cutcell::ProfileCut cut = cutcell::computeProfileCut(job);
            if (const std::string travel = cutcell::travelProblem(job, cut); !travel.empty())
                return fail(QString::fromStdString(travel));
            cutcell::GcodeStats st;
            text = cutcell::profileGcode(job, cut, &st);
            what = QObject::tr("G-code (X/A): %1 moves, %2 mm developed, %3 s")
                       .arg(st.moves)
                       .arg(st.length_mm, 0, 'f', 1)
                       .arg(st.time_s, 0, 'f', 1);
        } else {
            const cutcell::TemplateDrawing drawing = cutcell::buildTemplate(job);
            const bool svg = kind == ExportKind::TemplateSvg;
            text = svg ? cutcell::templateSvg(drawing) : cutcell::templatePdf(drawing);
            what = QObject::tr("cutting template (%1, 1:1): %2 x %3 mm")
                       .arg(svg ? "SVG" : "PDF")
                       .arg(drawing.width_mm, 0, 'f', 1)
                       .arg(drawing.height_mm, 0, 'f', 1);
        }
        cutcell::writeFileAtomically(path.toStdString(), text);
        if (summary) *summary = QObject::tr("Exported %1 to %2").arg(what, path);
        return true;
    } catch (const std::exception& e) {
        return fail(QString::fromUtf8(e.what()));
    }
}

void addCutExportActions(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log) {
    struct Item {
        ExportKind kind;
        QString label, filter;
    };
    const Item items[] = {
        {ExportKind::Gcode, QObject::tr("Export &G-code..."),
         QObject::tr("G-code (*.ngc *.nc *.gcode)")},
        {ExportKind::TemplateSvg, QObject::tr("Export template (SVG)..."), "SVG (*.svg)"},
        {ExportKind::TemplatePdf, QObject::tr("Export template (PDF)..."), "PDF (*.pdf)"},
    };
    for (const Item& it : items)
        menu->addAction(it.label, parent, [=] {
            const QString p = QFileDialog::getSaveFileName(parent, it.label, {}, it.filter);
            if (p.isEmpty()) return;
            QString err, summary;
            if (!editor->valid()) {
                log->add(cutcell::Severity::Error,
                         QObject::tr("Export to %1 refused: the job has invalid fields.").arg(p));
                return;
            }
            if (exportCut(it.kind, editor->job(), p, &err, &summary))
                log->add(cutcell::Severity::Info, summary);
            else
                log->add(cutcell::Severity::Error, err);
        });
}

} // namespace CutCell::ui
