// File -> Import <format> (one entry per registered importer): a DSTV piece opens as a new,
// untitled job identical to the core importer's, its report lines reach the report prompt;
// a broken file goes to the error prompt with its line and leaves the document alone.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/import_batch.h"
#include "core/machine/job_importer.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/main_window.h"

#include <QAction>
#include <QLabel>
#include <QTemporaryDir>
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

    // Several files at once (File -> Import with a multiple selection): one job per file in the
    // chosen folder with import-report.csv, the table's rows (a plate refused naming its line),
    // the first imported job opened with its piece marks shown on the Section page.
    void severalFilesImportAsABatchWithItsTable() {
        MainWindow w(nullptr);
        QTemporaryDir out;
        QVERIFY(out.isValid());
        std::vector<cutcell::ImportBatchRow> rows;
        w.setImportBatchPrompts([&out] { return out.path(); },
                                [&rows](const cutcell::ImportBatch& b) { rows = b.rows; });
        const QString pub = QStringLiteral(CUTCELL_SOURCE_DIR "/tests/data/dstv/public/");
        const QStringList files{pub + "tluijken-dstv_P1.nc", pub + "tluijken-dstv_P1565.nc",
                                pub + "dstv-tools_2519.nc1"};
        QString err;
        QVERIFY2(w.importJobs("dstv", files, out.path(), &err), qPrintable(err));
        QCOMPARE(rows.size(), size_t(3));
        QVERIFY(rows[0].imported && rows[2].imported);
        QVERIFY(!rows[1].imported);
        QVERIFY2(QString::fromStdString(rows[1].reason).startsWith("line 10: profile code B"),
                 rows[1].reason.c_str());
        QVERIFY(QFile::exists(out.filePath("tluijken-dstv_P1.json")));
        QVERIFY(QFile::exists(out.filePath("dstv-tools_2519.json")));
        QVERIFY(QFile::exists(out.filePath("import-report.csv")));
        QCOMPARE(w.document()->path(), out.filePath("tluijken-dstv_P1.json"));
        auto* marks = w.findChild<QLabel*>("pieceMarks");
        QVERIFY(marks);
        QVERIFY2(marks->text().contains("B_1") && marks->text().contains("A992") &&
                     marks->text().contains("PROJECT-1"),
                 qPrintable(marks->text()));
    }
};

QTEST_MAIN(TestJobImport)
#include "test_job_import.moc"
