// File -> Import <format> (one entry per registered importer): a DSTV piece opens as a new,
// untitled job identical to the core importer's, its report lines reach the report prompt;
// a broken file goes to the error prompt with its line and leaves the document alone.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/job_importer.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/main_window.h"

#include <QAction>
#include <QtTest>

using CutCell::ui::MainWindow;

namespace {
std::string text(const cutcell::Job& j) {
    return cutcell::json::write(cutcell::jobToJson(j));
}
QString dataPath(const char* name) {
    return QStringLiteral(CUTCELL_SOURCE_DIR "/tests/data/dstv/") + name;
}
} // namespace

class TestJobImport : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("CutCellTest");
        QCoreApplication::setApplicationName("test_job_import");
    }

    void importerEntriesAreInTheFileMenu() {
        MainWindow w(nullptr);
        for (const cutcell::JobImporter& i : cutcell::jobImporters()) {
            auto* a = w.findChild<QAction*>(
                QStringLiteral("actionImport_%1").arg(QString::fromStdString(i.name)));
            QVERIFY2(a, i.name.c_str());
            QVERIFY(a->text().contains(QString::fromStdString(i.title)));
        }
        QVERIFY(w.findChild<QAction*>("actionImport_dstv"));
    }

    void importedPieceOpensAsANewJobWithItsReport() {
        MainWindow w(nullptr);
        QStringList report;
        w.setImportReportPrompt(
            [&report](const QString&, const QStringList& lines) { report = lines; });
        const QString path = dataPath("heb200_holes_marks.nc1");
        QString err;
        QVERIFY2(w.importJob("dstv", path, &err), qPrintable(err));
        cutcell::JobImporter dstv;
        QVERIFY(cutcell::findJobImporter("dstv", &dstv));
        const cutcell::ImportResult core = dstv.import(cutcell::readTextFile(path.toStdString()));
        QCOMPARE(text(w.editor()->job()), text(core.job));
        QCOMPARE(report.size(), qsizetype(core.report.size()));
        QVERIFY(report.filter("line 25: BO hole").size() == 1);
        QVERIFY(w.document()->path().isEmpty()); // a new document: Save asks for a file
    }

    void brokenFileIsRefusedWithItsLine() {
        MainWindow w(nullptr);
        const std::string before = text(w.editor()->job());
        QStringList shown;
        w.setErrorPrompt([&shown](const QString& title, const QString& message) {
            shown << title + ": " + message;
        });
        QString err;
        QVERIFY(!w.importJob("dstv", dataPath("broken_bad_number.nc1"), &err));
        QVERIFY2(err.contains("line 11: length (header field 9)"), qPrintable(err));
        QCOMPARE(shown.size(), 1);
        QCOMPARE(text(w.editor()->job()), before);
    }
};

QTEST_MAIN(TestJobImport)
#include "test_job_import.moc"
