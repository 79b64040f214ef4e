#include "ui/job_import.h"

#include "core/job/job_io.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

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

void showImportBatchReport(QWidget* parent, const cutcell::ImportBatch& batch,
                           const QString& folder) {
    QDialog dialog(parent);
    dialog.setWindowTitle(QObject::tr("Import report"));
    auto* layout = new QVBoxLayout(&dialog);
    const int imported = static_cast<int>(batch.rows.size()) - batch.refused;
    layout->addWidget(new QLabel(
        QObject::tr("%1 file(s): %2 imported, %3 refused. The jobs and import-report.csv are in "
                    "%4.")
            .arg(batch.rows.size())
            .arg(imported)
            .arg(batch.refused)
            .arg(folder),
        &dialog));
    // The reason right after the result: a refused row has nothing else to show.
    QStringList headers{QObject::tr("File"), QObject::tr("Result"), QObject::tr("Refused because")};
    for (const std::string& c : batch.columns)
        headers << QString::fromStdString(c);
    auto* table = new QTableWidget(static_cast<int>(batch.rows.size()),
                                   static_cast<int>(headers.size()), &dialog);
    table->setObjectName(QStringLiteral("importBatchTable"));
    table->setHorizontalHeaderLabels(headers);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int r = 0; r < table->rowCount(); ++r) {
        const cutcell::ImportBatchRow& row = batch.rows[static_cast<size_t>(r)];
        int c = 0;
        const auto cell = [&](const QString& text) {
            table->setItem(r, c++, new QTableWidgetItem(text));
        };
        cell(QString::fromStdString(row.file));
        cell(row.imported ? QObject::tr("imported") : QObject::tr("refused"));
        cell(QString::fromStdString(row.reason));
        table->item(r, c - 1)->setToolTip(QString::fromStdString(row.reason));
        for (const std::string& col : batch.columns)
            cell(QString::fromStdString(cutcell::ImportBatch::fact(row, col)));
    }
    table->resizeColumnsToContents();
    table->setColumnWidth(2, std::min(table->columnWidth(2), 360)); // the whole text: tooltip
    layout->addWidget(table);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    layout->addWidget(buttons);
    dialog.resize(1000, 480);
    dialog.exec();
}

} // namespace CutCell::ui
