#include "ui/machine_exports.h"
#include "ui/shown_number.h"

#include "core/job/job_io.h"
#include "core/pipe_joint/template_layout.h"
#include "core/pipe_joint/template_pdf.h"
#include "core/pipe_joint/template_svg.h"
#include "core/pipe_joint/template_tiles.h"
#include "ui/file_places.h"
#include "ui/forms/job_editor.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/panels/event_log_panel.h"

#include <QMenu>

#include <algorithm>

namespace CutCell::ui {

bool exportCut(ExportKind kind, const cutcell::Job& job, const QString& path, QString* error,
               QString* summary, const QString& paperName) {
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
            const auto paper = cutcell::paperByName(paperName.toStdString());
            if (!paper)
                return fail(QObject::tr("paper \"%1\" is not single, A4 or A3").arg(paperName));
            const cutcell::TemplateDrawing drawing =
                cutcell::buildTemplate(job, machine->jointExtras(job));
            const bool svg = kind == ExportKind::TemplateSvg;
            what = QObject::tr("cutting template (%1, 1:1): %2 x %3 mm")
                       .arg(svg ? "SVG" : "PDF")
                       .arg(shownNumber(drawing.width_mm, 1))
                       .arg(shownNumber(drawing.height_mm, 1));
            if (paper->short_mm <= 0) {
                text = svg ? cutcell::templateSvg(drawing) : cutcell::templatePdf(drawing);
            } else {
                const cutcell::TiledTemplate tiles =
                    cutcell::tileTemplate(drawing, *paper, job.name);
                text =
                    svg ? cutcell::templateSvg(tiles)
                        : cutcell::templatePdf(cutcell::templatePages(drawing, *paper, job.name));
                what += QObject::tr(" on %1 sheets of %2 %3 (%4 x %5)")
                            .arg(tiles.tiles.size())
                            .arg(paperName, tiles.landscape ? QObject::tr("landscape")
                                                            : QObject::tr("portrait"))
                            .arg(tiles.rows)
                            .arg(tiles.cols);
            }
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

void fillExportMenu(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log,
                    const std::function<QString()>& documentPath) {
    menu->clear();
    const MachineUi* machine = machineUiFor(editor->job());
    menu->setEnabled(machine != nullptr);
    if (!machine) return;
    const auto addExport = [=](QMenu* into, ExportKind kind, const QString& text,
                               const QString& paper) {
        const QString label = exportLabel(kind);
        QAction* a = into->addAction(text, parent, [=] {
            const cutcell::Job& job = editor->job();
            const QString tail =
                (kind == ExportKind::Gcode ? QString()
                                           : QStringLiteral("_template_") + paper.toLower()) +
                filterSuffix(exportFilter(kind));
            const QString p = askSavePath(
                parent, SaveKind::Export, QString(label).remove('&').remove(QStringLiteral("...")),
                proposedExportPath(documentPath ? documentPath() : QString(),
                                   QString::fromStdString(job.name), tail),
                exportFilter(kind));
            if (p.isEmpty()) return;
            if (!editor->valid()) {
                log->add(cutcell::Severity::Error,
                         QObject::tr("Export to %1 refused: the job has invalid fields.").arg(p));
                return;
            }
            QString err, summary;
            if (exportCut(kind, editor->job(), p, &err, &summary, paper))
                log->add(cutcell::Severity::Info, summary);
            else
                log->add(cutcell::Severity::Error, err);
        });
        a->setData(static_cast<int>(kind));
        a->setProperty("cutcellPaper", paper);
    };
    for (const ExportKind kind : machine->exports()) {
        if (kind != ExportKind::TemplateSvg && kind != ExportKind::TemplatePdf) {
            addExport(menu, kind, exportLabel(kind), QStringLiteral("single"));
            continue;
        }
        // Templates: the paper as a submenu (no modal question before the file dialog).
        QMenu* papers = menu->addMenu(exportLabel(kind).remove("..."));
        papers->menuAction()->setData(static_cast<int>(kind));
        addExport(papers, kind, QObject::tr("&Single sheet (template size)..."),
                  QStringLiteral("single"));
        addExport(papers, kind, QObject::tr("A&4 tiles (1:1, alignment crosses)..."),
                  QStringLiteral("A4"));
        addExport(papers, kind, QObject::tr("A&3 tiles (1:1, alignment crosses)..."),
                  QStringLiteral("A3"));
    }
}

} // namespace

QMenu* addCutExportMenu(QMenu* menu, QWidget* parent, JobEditor* editor, EventLogPanel* log,
                        std::function<QString()> documentPath) {
    QMenu* exports = menu->addMenu(QObject::tr("&Export cut"));
    exports->setObjectName("exportMenu");
    const auto refresh = [=] {
        const QString machine = QString::fromStdString(editor->job().machine);
        if (exports->property("cutcellMachine").toString() == machine) return;
        exports->setProperty("cutcellMachine", machine);
        fillExportMenu(exports, parent, editor, log, documentPath);
    };
    QObject::connect(editor, &JobEditor::jobReset, exports, refresh);
    QObject::connect(editor, &JobEditor::edited, exports, refresh);
    refresh();
    return exports;
}

} // namespace CutCell::ui
