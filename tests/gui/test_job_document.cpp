// Job files from the GUI: a job edited, saved and reopened is identical (jobToJson); the
// title shows the job and its modified state; unsaved changes are asked about; recent files.
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/job_document.h"
#include "ui/main_window.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QtTest>

using CutCell::ui::MainWindow;

namespace {
std::string text(const cutcell::Job& j) {
    return cutcell::json::write(cutcell::jobToJson(j));
}
} // namespace

class TestJobDocument : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("CutCellTest");
        QCoreApplication::setApplicationName("test_job_document");
    }

    void savedAndReopenedIsIdentical() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("edited.json");
        MainWindow w(nullptr);
        // Edits through the widgets, as an operator would.
        qobject_cast<QLineEdit*>(w.parameters()->fieldFor("name"))->setText("x");
        w.editor()->edit([](cutcell::Job& j) { j.name = "Round trip"; });
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.bevel_deg"))->setValue(12.5);
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("robot.dh[2].max_deg"))
            ->setValue(44.5);
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("controller[3].kp_nm_per_rad"))
            ->setValue(999.25);
        w.editor()->edit([](cutcell::Job& j) {
            j.cut.start_phi_auto = false;
            j.cut.start_phi_deg = -45;
        });
        const std::string before = text(w.editor()->job());
        QVERIFY(w.saveAs(path));
        QVERIFY(QFileInfo::exists(path));
        // Atomic write leaves no temporary file behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 1);

        MainWindow other(nullptr);
        QString err;
        QVERIFY2(other.openJob(path, &err), qPrintable(err));
        QCOMPARE(text(other.editor()->job()), before);
        QCOMPARE(other.editor()->job().cut.bevel_deg, 12.5);
        QVERIFY(!other.document()->modified());
        // The widgets show what was loaded.
        QCOMPARE(
            qobject_cast<QDoubleSpinBox*>(other.parameters()->fieldFor("cut.bevel_deg"))->value(),
            12.5);
        // And the core reads the same file to the same job.
        QCOMPARE(text(cutcell::loadJobFile(path.toStdString())), before);
    }

    void titleShowsJobAndModifiedState() {
        QTemporaryDir dir;
        MainWindow w(nullptr);
        QVERIFY(w.windowTitle().contains(QString::fromStdString(cutcell::defaultJob().name)));
        QVERIFY(w.windowTitle().contains("untitled"));
        QVERIFY(!w.isWindowModified());
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"))->setValue(5);
        QVERIFY(w.isWindowModified());
        QVERIFY(w.saveAs(dir.filePath("job_a.json")));
        QVERIFY(!w.isWindowModified());
        QVERIFY(w.windowTitle().contains("job_a.json"));
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"))->setValue(6);
        QVERIFY(w.isWindowModified());
        QVERIFY(w.save());
        QVERIFY(!w.isWindowModified());
        QCOMPARE(cutcell::loadJobFile(dir.filePath("job_a.json").toStdString()).cut.speed_mm_s,
                 6.0);
    }

    void unsavedChangesPrompt() {
        MainWindow w(nullptr);
        int asked = 0;
        int answer = QMessageBox::Cancel;
        w.setSavePrompt([&] {
            ++asked;
            return answer;
        });
        QVERIFY(w.maybeSave()); // nothing to save: no question
        QCOMPARE(asked, 0);
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("angle_deg"))->setValue(80);
        QVERIFY(!w.maybeSave());
        QCOMPARE(asked, 1);
        QVERIFY(!w.close()); // Cancel keeps the window open
        answer = QMessageBox::Discard;
        QVERIFY(w.maybeSave());
    }

    void recentFilesAndBadFiles() {
        QTemporaryDir dir;
        MainWindow w(nullptr);
        w.document()->clearRecentFiles();
        QVERIFY(w.saveAs(dir.filePath("one.json")));
        QVERIFY(w.saveAs(dir.filePath("two.json")));
        QVERIFY(w.openJob(dir.filePath("one.json")));
        const QStringList recent = w.document()->recentFiles();
        QCOMPARE(recent.size(), 2);
        QVERIFY(recent[0].endsWith("one.json"));
        QVERIFY(recent[1].endsWith("two.json"));

        QFile bad(dir.filePath("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{ \"schema\": 1, ");
        bad.close();
        const std::string before = text(w.editor()->job());
        QString err;
        QVERIFY(!w.openJob(bad.fileName(), &err));
        QVERIFY2(err.contains("bad.json"), qPrintable(err));
        QCOMPARE(text(w.editor()->job()), before); // the open job is kept
        QVERIFY(!w.openJob(dir.filePath("missing.json"), &err));
    }

    // Broken JSON and wrong types: the operator gets a dialog (here the test's hook) with the
    // file's message, and the log has it too.
    void fileErrorsGoToADialogAndTheLog_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        QTest::newRow("broken JSON") << QByteArray("{ \"schema\": 1, ") << QString("broken.json");
        QTest::newRow("wrong type")
            << QByteArray(text(cutcell::defaultJob()).c_str())
                   .replace("\"angle_deg\": 90", "\"angle_deg\": \"ninety\"")
            << QString("angle_deg");
    }
    void fileErrorsGoToADialogAndTheLog() {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        MainWindow w(nullptr);
        w.show();
        QStringList shown;
        w.setErrorPrompt([&shown](const QString& title, const QString& message) {
            shown << title + ": " + message;
        });
        QString err;
        QVERIFY(!w.openJob(path, &err));
        QCOMPARE(shown.size(), 1);
        QVERIFY2(shown[0].contains(expected), qPrintable(shown[0]));
        QVERIFY2(shown[0].contains(err), qPrintable(shown[0]));
    }

    void invalidJobOpensWithFieldsMarked() {
        QTemporaryDir dir;
        auto job = cutcell::defaultJob();
        job.cut.speed_mm_s = -3;
        const QString path = dir.filePath("invalid.json");
        cutcell::saveJobFile(job, path.toStdString());
        MainWindow w(nullptr);
        QVERIFY(w.openJob(path));
        QVERIFY(w.parameters()->fieldFor("cut.speed_mm_s")->property("invalid").toBool());
    }
};

QTEST_MAIN(TestJobDocument)
#include "test_job_document.moc"
