// The section-steel cutter's cut chart in the job editor: its Section page shows the process
// part (ProcessForm, as the pipe machines' Cut page), its thickness from the section's thickest
// plate, only the kerf's override editable (the cut speed and the other figures read-only with
// the reason: the machine cuts at motion.speed_mm_s); an override edited there is the job's
// process.override.kerf_mm when saved, and the job validates. A job without a process section
// shows it off and is saved without one. The page fits its pane at 1280x720, English and German.
// With CUTCELL_STEEL_PROCESS_SCREENSHOT=<png> the Section page with the chart is saved there.
#include "core/job/job_io.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/machines/section_steel/section_steel_spec.h"
#include "core/process/process_spec.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/forms/process_form.h"
#include "ui/language.h"
#include "ui/machines/section_steel/section_steel_form.h"
#include "ui/main_window.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QScrollArea>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using CutCell::ui::MainWindow;
using CutCell::ui::ProcessForm;
using CutCell::ui::SectionSteelSectionForm;

namespace {

QString jobPath(const char* name) {
    return QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/") + name + ".json";
}

// The process part on the section steel's Section page (not the hidden Cut page's).
ProcessForm* steelProcess(MainWindow& w) {
    auto* page = w.findChild<SectionSteelSectionForm*>();
    return page ? page->findChild<ProcessForm*>() : nullptr;
}

QJsonObject savedMachine(MainWindow& w, const QString& path) {
    if (!w.saveAs(path)) return {};
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object().value("machine").toObject();
}

int sectionTab(MainWindow& w) {
    QTabWidget* tabs = w.parameters()->tabs();
    auto* page = w.findChild<SectionSteelSectionForm*>();
    for (int i = 0; i < tabs->count(); ++i)
        if (auto* scroll = qobject_cast<QScrollArea*>(tabs->widget(i));
            scroll && scroll->widget() == page)
            return i;
    return -1;
}

} // namespace

class TestGuiSectionSteelProcess : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void chartJobShowsItsProcessAndSavesTheOverride() {
        MainWindow w(nullptr);
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QString error;
        QVERIFY2(w.openJob(jobPath("section_steel_plasma_job"), &error), qPrintable(error));
        QVERIFY2(w.editor()->valid(), "the shipped job validates");
        ProcessForm* process = steelProcess(w);
        QVERIFY(process);
        // The tab holding it is shown, the pipes' Cut page not; the job's keys lead to it.
        const int tab = sectionTab(w);
        QVERIFY(tab >= 0);
        QVERIFY(w.parameters()->tabs()->isTabVisible(tab));
        QVERIFY(!w.parameters()->tabShown("Cut"));
        QWidget* kerfField = w.parameters()->fieldFor("process.override.kerf_mm");
        QVERIFY(kerfField && process->isAncestorOf(kerfField));
        QVERIFY(process->isAncestorOf(w.parameters()->fieldFor("process.used")));
        w.parameters()->revealField("process.override.kerf_mm");
        QCOMPARE(w.parameters()->tabs()->currentIndex(), tab);

        // The chart the job names, at the section's thickest plate (the 10.7 mm flange).
        auto* used = process->findChild<QCheckBox*>("processUsed");
        QVERIFY(used && used->isChecked() && used->isEnabled());
        const cutcell::Job& job = w.editor()->job();
        const auto* spec = job.machine_spec.as<cutcell::section_steel::SectionSteelSpec>();
        QVERIFY(spec);
        const double wall = cutcell::section_steel::steelPartThicknessMm(*spec);
        QCOMPARE(wall, 10.7);
        auto* partWall = process->findChild<QCheckBox*>("processPartWall");
        QVERIFY(partWall && partWall->isChecked() && !partWall->toolTip().isEmpty());
        auto* thickness = process->findChild<QDoubleSpinBox*>("processThickness");
        QVERIFY(thickness);
        QCOMPARE(thickness->value(), wall);
        const cutcell::ProcessSettings s =
            cutcell::resolveProcess(job.process, wall, cutcell::activeCutCharts());
        QVERIFY2(s.ok(), s.outcome.message.c_str());
        auto* chart = process->findChild<QLabel*>("processChart");
        QVERIFY(chart);
        QVERIFY2(chart->text().contains(QString::fromStdString(s.chart_name)),
                 qPrintable(chart->text()));
        QVERIFY2(chart->text().contains(QLocale().toString(wall, 'f', 2)),
                 qPrintable(chart->text()));

        // The kerf's override 1.6 mm, editable.
        auto* kerfBox = process->findChild<QCheckBox*>("override_kerf_mm");
        auto* kerf = process->findChild<QDoubleSpinBox*>("value_kerf_mm");
        QVERIFY(kerfBox && kerf);
        QCOMPARE(kerf, kerfField);
        QVERIFY(kerfBox->isChecked() && kerfBox->isEnabled());
        QVERIFY(kerf->isEnabled());
        QCOMPARE(kerf->value(), 1.6);
        // The cut speed is the machine's own (motion.speed_mm_s): its override read-only, with
        // the reason, as are the figures the machine does not take.
        auto* figures = process->findChild<QTableWidget*>("processFigures");
        QVERIFY(figures);
        for (const char* figure : {"cut_speed_mm_min", "pierce_height_mm", "cut_height_mm"}) {
            auto* box = process->findChild<QCheckBox*>(QStringLiteral("override_%1").arg(figure));
            auto* value =
                process->findChild<QDoubleSpinBox*>(QStringLiteral("value_%1").arg(figure));
            QVERIFY2(box && value, figure);
            QVERIFY2(!box->isChecked() && !box->isEnabled(), figure);
            QVERIFY2(!value->isEnabled(), figure);
            QVERIFY2(!box->toolTip().isEmpty(), figure);
            // The figure's name in the table says it too.
            bool named = false;
            for (int r = 0; r < figures->rowCount(); ++r)
                named = named || (figures->cellWidget(r, 2) == box &&
                                  figures->item(r, 0)->toolTip() == box->toolTip());
            QVERIFY2(named, figure);
        }
        QVERIFY(process->findChild<QCheckBox*>("override_cut_speed_mm_min")
                    ->toolTip()
                    .contains(QStringLiteral("Motion")) ||
                CutCell::ui::shownLanguage() != QLatin1String("en"));

        if (const QByteArray png = qgetenv("CUTCELL_STEEL_PROCESS_SCREENSHOT"); !png.isEmpty()) {
            w.parameters()->tabs()->setCurrentIndex(tab);
            auto* scroll = qobject_cast<QScrollArea*>(w.parameters()->tabs()->widget(tab));
            QTest::qWait(50);
            scroll->ensureWidgetVisible(process);
            QTest::qWait(50);
            QVERIFY(w.parameters()->grab().save(QString::fromLocal8Bit(png)));
        }

        // An override changed on the page is the job's, saved, and the job validates.
        kerf->setValue(1.8);
        QCOMPARE(w.editor()->job().process.override.get(cutcell::CutFigure::KerfMm).value_or(0),
                 1.8);
        QVERIFY(w.editor()->valid());
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("steel_plasma.json");
        const QJsonObject machine = savedMachine(w, path);
        QVERIFY(machine.contains("process"));
        const QJsonObject saved = machine.value("process").toObject();
        QCOMPARE(saved.value("override").toObject().value("kerf_mm").toDouble(), 1.8);
        QCOMPARE(saved.value("material").toString(), QStringLiteral("mild_steel"));
        const cutcell::Job back = cutcell::loadJobFile(path.toStdString());
        const auto issues = cutcell::validateJob(back);
        QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().message.c_str());
        QCOMPARE(back.process.override.get(cutcell::CutFigure::KerfMm).value_or(0), 1.8);
    }

    void jobWithoutProcessShowsItOffAndSavesNone() {
        MainWindow w(nullptr);
        QString error;
        QVERIFY2(w.openJob(jobPath("section_steel_job"), &error), qPrintable(error));
        QVERIFY(!w.editor()->job().process.used);
        ProcessForm* process = steelProcess(w);
        QVERIFY(process);
        auto* used = process->findChild<QCheckBox*>("processUsed");
        QVERIFY(used && !used->isChecked() && used->isEnabled());
        for (const char* name : {"processKind", "processMaterial", "processConsumable",
                                 "processPartWall", "processThickness", "processFigures"}) {
            auto* field = process->findChild<QWidget*>(name);
            QVERIFY2(field && !field->isEnabled(), name);
        }
        auto* chart = process->findChild<QLabel*>("processChart");
        QVERIFY(chart && !chart->text().isEmpty());
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QJsonObject machine = savedMachine(w, dir.filePath("steel.json"));
        QVERIFY(machine.contains("section"));
        QVERIFY(!machine.contains("process"));
    }

    void sectionPageFitsItsPane_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << "en";
        QTest::newRow("de") << "de";
    }
    void sectionPageFitsItsPane() {
        QFETCH(QString, language);
        QVERIFY(CutCell::ui::applyGuiLanguage(language));
        MainWindow w(nullptr);
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QString error;
        QVERIFY2(w.openJob(jobPath("section_steel_plasma_job"), &error), qPrintable(error));
        const int tab = sectionTab(w);
        QVERIFY(tab >= 0);
        w.parameters()->tabs()->setCurrentIndex(tab);
        QTest::qWait(20); // the layouts settle
        auto* scroll = qobject_cast<QScrollArea*>(w.parameters()->tabs()->widget(tab));
        QVERIFY(scroll);
        const int need = scroll->widget()->minimumSizeHint().width();
        const int have = scroll->viewport()->width();
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        QVERIFY2(need <= have,
                 qPrintable(QStringLiteral("needs %1 px, shows %2").arg(need).arg(have)));
    }
};

QTEST_MAIN(TestGuiSectionSteelProcess)
#include "test_gui_section_steel_process.moc"
