// The operator station under a decimal-comma locale. ctest runs this with LC_ALL=de_DE.UTF-8,
// where QApplication sets LC_NUMERIC so that printf/strtod use ','. Every file the GUI writes
// (job JSON, G-code, SVG and PDF templates, the plots' CSV) must hold the same text as under the
// C locale: "575.7429", never "575,7429". The reference is written in-process under "C".
#include "core/job/job_io.h"
#include "plots/tracking_plots_widget.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/machine_exports.h"

#include <QtTest>

#include <clocale>
#include <functional>
#include <string>

using CutCell::ui::ExportKind;

namespace {

const QString kProfileJob =
    QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/profile_cutter_job.json");
const QString kRobotJob = QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/default_job.json");

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Runs `write` once under the process's (decimal-comma) locale and once under "C".
void writeBoth(const std::function<void(const QString&)>& write, const QString& localePath,
               const QString& cPath) {
    write(localePath);
    const std::string saved = std::setlocale(LC_NUMERIC, nullptr);
    std::setlocale(LC_NUMERIC, "C");
    write(cPath);
    std::setlocale(LC_NUMERIC, saved.c_str());
}

} // namespace

class TestLocaleExports : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.1f", 1.5);
        QCOMPARE(QByteArray(buf), QByteArray("1,5")); // the trap is armed
    }

    void exportsAreTheCLocaleText() {
        const cutcell::Job job = cutcell::loadJobFile(kProfileJob.toStdString());
        QTemporaryDir dir;
        for (ExportKind kind :
             {ExportKind::Gcode, ExportKind::TemplateSvg, ExportKind::TemplatePdf}) {
            const QString a = dir.filePath(QString("de_%1").arg(int(kind)));
            const QString b = dir.filePath(QString("c_%1").arg(int(kind)));
            writeBoth(
                [&](const QString& p) {
                    QString err;
                    QVERIFY2(CutCell::ui::exportCut(kind, job, p, &err), qPrintable(err));
                },
                a, b);
            const QByteArray de = readAll(a), c = readAll(b);
            QVERIFY(!c.isEmpty());
            QVERIFY2(de == c, qPrintable(QString("export %1 differs under de_DE").arg(int(kind))));
        }
    }

    void savedJobReadsBackExactly() {
        for (const QString& file : {kRobotJob, kProfileJob}) {
            const cutcell::Job job = cutcell::loadJobFile(file.toStdString());
            CutCell::ui::JobEditor editor;
            editor.setJob(job);
            CutCell::ui::JobDocument doc(&editor);
            QTemporaryDir dir;
            QString err;
            const QString de = dir.filePath("de.json"), c = dir.filePath("c.json");
            writeBoth([&](const QString& p) { QVERIFY2(doc.saveAs(p, &err), qPrintable(err)); }, de,
                      c);
            QCOMPARE(readAll(de), readAll(c));
            // And the saved text is a job again, with the same numbers.
            const cutcell::Job back = cutcell::loadJobFile(de.toStdString());
            QCOMPARE(back.main_pipe.radius_mm, job.main_pipe.radius_mm);
            QCOMPARE(back.cut.speed_mm_s, job.cut.speed_mm_s);
            QCOMPARE(back.sim.period_s, job.sim.period_s);
        }
    }

    void plotCsvIsTheCLocaleText() {
        cutcell::plots::TrackingPlotsWidget plots;
        plots.setAxisNames({"A", "X"});
        for (int k = 0; k < 50; ++k) {
            const double e[2] = {0.001 * k + 0.25, -0.5 * k - 0.125};
            const double tip[3] = {0.5, -0.25, 0.125};
            plots.append(0.001 * k, e, 2, tip);
        }
        QTemporaryDir dir;
        const QString de = dir.filePath("de.csv"), c = dir.filePath("c.csv");
        writeBoth(
            [&](const QString& p) {
                QString err;
                QVERIFY2(plots.exportCsv(p, &err), qPrintable(err));
            },
            de, c);
        QVERIFY(!readAll(c).isEmpty());
        QCOMPARE(readAll(de), readAll(c));
    }
};

int main(int argc, char** argv) {
    QApplication app(argc, argv); // sets LC_NUMERIC from the environment
    // The point of the test is a decimal-comma locale; without one it can say nothing: skipped.
    if (std::string(std::setlocale(LC_NUMERIC, nullptr)).rfind("de_DE", 0) != 0) {
        std::puts("SKIP: LC_NUMERIC is not de_DE (localedef -i de_DE -f UTF-8 de_DE.UTF-8)");
        return 77;
    }
    TestLocaleExports test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_locale_exports.moc"
