#include "ui/job_import.h"

#include "core/job/job_io.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

namespace CutCell::ui {

bool importJobFile(const std::string& importer, const QString& path, ImportOutcome* out,
                   QString* error) {
    cutcell::JobImporter i;
    if (!cutcell::findJobImporter(importer, &i)) {
        if (error)
            *error = QObject::tr("No importer \"%1\" in this build.")
                         .arg(QString::fromStdString(importer));
        return false;
    }
    try {
        cutcell::ImportResult r = i.import(cutcell::readTextFile(path.toStdString()));
        if (out) {
            out->job = std::move(r.job);
            out->report.clear();
            for (const std::string& l : r.report)
                out->report << QString::fromStdString(l);
        }
        return true;
    } catch (const std::exception& e) {
        if (error)
            *error = QObject::tr("Cannot import %1: %2").arg(path, QString::fromUtf8(e.what()));
        return false;
    }
}

QString importFileFilter(const cutcell::JobImporter& importer) {
    QStringList patterns;
    for (const std::string& p : importer.patterns) {
        patterns << QString::fromStdString(p);
        const QString upper = QString::fromStdString(p).toUpper();
        if (upper != patterns.back()) patterns << upper;
    }
    return QObject::tr("%1 files (%2);;All files (*)")
        .arg(QString::fromStdString(importer.title), patterns.join(' '));
}

void addImportActions(QMenu* menu, QWidget* parent,
                      const std::function<void(const std::string&)>& onImport) {
    for (const cutcell::JobImporter& i : cutcell::jobImporters()) {
        QAction* a =
            menu->addAction(QObject::tr("Import %1...").arg(QString::fromStdString(i.title)),
                            parent, [onImport, name = i.name] { onImport(name); });
        a->setObjectName(QStringLiteral("actionImport_%1").arg(QString::fromStdString(i.name)));
        a->setToolTip(QString::fromStdString(i.description));
    }
}

void showImportReport(QWidget* parent, const QString& path, const QStringList& report) {
    QMessageBox box(parent);
    box.setIcon(report.isEmpty() ? QMessageBox::Information : QMessageBox::Warning);
    box.setWindowTitle(QObject::tr("Import report"));
    const QString file = QFileInfo(path).fileName();
    if (report.isEmpty()) {
        box.setText(QObject::tr("%1: imported; the job does everything the file asks.").arg(file));
    } else {
        box.setText(QObject::tr("%1: imported. %n thing(s) of the file the job does not do "
                                "(also in the event log):",
                                nullptr, int(report.size()))
                        .arg(file));
        box.setDetailedText(report.join('\n'));
        box.setInformativeText(report.mid(0, 8).join('\n') +
                               (report.size() > 8 ? QStringLiteral("\n...") : QString()));
    }
    box.exec();
}

} // namespace CutCell::ui
