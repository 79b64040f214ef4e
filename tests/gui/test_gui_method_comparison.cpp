// The robot's Compare page (seed 000, Fig. 11-14): "Compare methods" runs both methods of the
// default job on a pool thread - the GUI thread keeps turning meanwhile - and fills the table
// with both methods' finite figures and the four figures with their curves.
#include "core/job/default_job.h"
#include "plots/xy_figures_widget.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/machines/pipe_robot/method_comparison_page.h"
#include "ui/main_window.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

#include <cmath>

using CutCell::ui::MainWindow;
using CutCell::ui::MethodComparisonForm;

class TestGuiMethodComparison : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void compareMethodsFillsTheTableOffTheGuiThread() {
        MainWindow w(nullptr);
        w.editor()->setJob(cutcell::defaultJob());
        auto* page = w.findChild<MethodComparisonForm*>();
        QVERIFY2(page, "the robot's Method page holds the comparison");
        QCOMPARE(page->compareButton()->text(), QStringLiteral("Compare methods"));

        // The GUI thread keeps serving its event loop while the comparison runs.
        int ticks = 0;
        QTimer ticker;
        QObject::connect(&ticker, &QTimer::timeout, [&ticks] { ++ticks; });
        ticker.start(20);
        QSignalSpy done(page, &MethodComparisonForm::compared);
        QTest::mouseClick(page->compareButton(), Qt::LeftButton);
        QVERIFY(page->comparing());
        QVERIFY(!page->compareButton()->isEnabled());
        QString why;
        QVERIFY(!page->startComparison(&why)); // one at a time
        QVERIFY(!why.isEmpty());
        QVERIFY(done.wait(240000));
        ticker.stop();
        QCOMPARE(done.takeFirst().at(0).toBool(), true);
        QVERIFY2(ticks >= 1, qPrintable(QString("%1 ticks").arg(ticks)));
        QVERIFY(page->compareButton()->isEnabled());

        // Both methods, every figure finite; the table shows them.
        QVERIFY(page->result().has_value());
        const cutcell::MethodComparison& c = *page->result();
        QVERIFY(c.ok());
        QCOMPARE(c.staticPipe().method, cutcell::CutMethod::StaticPipe);
        QCOMPARE(c.rotatingPipe().method, cutcell::CutMethod::RotatingPipe);
        for (const cutcell::MethodRun& r : c.runs) {
            QVERIFY(r.trace.t_s.size() > 100);
            for (double v : r.trace.joint_max_abs_deg)
                QVERIFY(std::isfinite(v) && v >= 0);
            for (int k = 0; k < 3; ++k) {
                QVERIFY(std::isfinite(r.trace.tip_min_mm[k]));
                QVERIFY(std::isfinite(r.trace.tip_max_mm[k]));
                QVERIFY(r.trace.tip_min_mm[k] <= r.trace.tip_max_mm[k]);
            }
            // The arm moves in both methods: its joints have errors.
            QVERIFY(r.trace.joint_max_abs_deg[2] > 0);
        }
        QTableWidget* table = page->table();
        QCOMPARE(table->rowCount(), cutcell::kAxisCount + 3);
        QCOMPARE(table->columnCount(), 3);
        QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("Static"));
        QCOMPARE(table->horizontalHeaderItem(1)->text(), QStringLiteral("Rotating"));
        for (int row = 0; row < table->rowCount(); ++row)
            for (int column = 0; column < 2; ++column) {
                const QTableWidgetItem* item = table->item(row, column);
                QVERIFY(item);
                QVERIFY2(!item->text().isEmpty() && item->text() != QStringLiteral("n/a"),
                         qPrintable(QString("row %1 column %2").arg(row).arg(column)));
                // A joint's max |e| reads back as the finite number the comparison holds.
                if (row < cutcell::kAxisCount) {
                    bool ok = false;
                    const double shown = QLocale().toDouble(item->text(), &ok);
                    QVERIFY(ok && std::isfinite(shown));
                }
            }
        // Arm joints 2 and 3 move in both methods: their ratio is a number.
        QVERIFY(std::isfinite(c.jointRatio(2)) && c.jointRatio(2) > 0);
        QVERIFY(table->item(2, 2)->text() != QStringLiteral("n/a"));
        // Fig. 11 / 13 (static pipe) and, chosen in the selector, Fig. 12 / 14 (rotating):
        // six joint curves and three tip curves.
        QCOMPARE(page->methodChoice()->currentIndex(), 0);
        for (int m = 0; m < 2; ++m) {
            page->methodChoice()->setCurrentIndex(m);
            QCOMPARE(page->figures()->curveCount(0), cutcell::kAxisCount);
            QCOMPARE(page->figures()->curveCount(1), 3);
            QVERIFY(page->figures()->pointCount(0) > 100);
        }
        QVERIFY(!page->summary()->text().isEmpty());
    }

    void aPageDestroyedWhileComparingWaitsForItsRun() {
        auto editor = std::make_unique<CutCell::ui::JobEditor>();
        editor->setJob(cutcell::defaultJob());
        auto page = std::make_unique<MethodComparisonForm>(editor.get());
        QVERIFY(page->startComparison());
        page.reset(); // cancels the plans and waits: no pool thread outlives the page
        QVERIFY(QThreadPool::globalInstance()->waitForDone(1000));
    }
};

QTEST_MAIN(TestGuiMethodComparison)
#include "test_gui_method_comparison.moc"
