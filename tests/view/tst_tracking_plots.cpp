// TrackingPlotsWidget and BoundedSeries, offscreen: ring semantics, pause, exports.
#include "plots/bounded_series.h"
#include "plots/tracking_plots_widget.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QFile>
#include <QImage>
#include <QSet>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <cmath>

using cutcell::plots::BoundedSeries;
using cutcell::plots::TrackingPlotsWidget;

namespace {
// Sample i of a synthetic run: distinct, exactly representable values per channel.
void sample(int i, double* j, double* c) {
    for (int k = 0; k < 6; ++k)
        j[k] = 0.125 * (k + 1) + i * 0.5;
    for (int k = 0; k < 3; ++k)
        c[k] = -0.25 * (k + 1) - i;
}

// Waits until the widget's timer has ticked n more times: "nothing happened" is only checked
// after the timer had its chances (a fixed wait may see no tick at all on a slow machine).
void waitForTicks(const TrackingPlotsWidget& w, std::uint64_t n) {
    const std::uint64_t from = w.timerTicks();
    QTRY_VERIFY_WITH_TIMEOUT(w.timerTicks() >= from + n, 10000);
}
} // namespace

class TstTrackingPlots : public QObject {
    Q_OBJECT
  private slots:
    void ringKeepsNewestAndCountsDrops();
    void ringPadsMissingValuesWithNaN();
    void appendStoresWithoutReplot();
    void pausedViewStaysFrozen();
    void csvRoundTrip();
    void csvOfTwoAxisMachine();
    void oneUnitPerPlot();
    void pngIsAValidImage();
    void exportToBadPathNamesThePath();
    void traceVisibilityToggles();
    void clearEmptiesEverything();
    void hiddenWidgetCatchesUpWhenShown();
    void hostDrivenRedrawWaitsForTheHost();
    void readableAtOperatorSizes_data();
    void readableAtOperatorSizes();
    void clearFollowsTheNewDataAgain();
    void flatTraceKeepsANarrowRange();
};

void TstTrackingPlots::ringKeepsNewestAndCountsDrops() {
    BoundedSeries s(2, 5);
    for (int i = 0; i < 12; ++i) {
        const double v[2] = {double(i), -double(i)};
        s.append(i * 0.1, v, 2);
    }
    QCOMPARE(s.size(), 5);
    QCOMPARE(s.dropped(), std::uint64_t(7));
    QCOMPARE(s.appended(), std::uint64_t(12));
    for (int i = 0; i < 5; ++i) { // oldest first: samples 7..11
        QCOMPARE(s.time(i), (7 + i) * 0.1);
        QCOMPARE(s.value(i, 0), double(7 + i));
        QCOMPARE(s.value(i, 1), -double(7 + i));
    }
}

void TstTrackingPlots::ringPadsMissingValuesWithNaN() {
    BoundedSeries s(3, 4);
    const double v[1] = {2.0};
    s.append(0, v, 1);
    QCOMPARE(s.value(0, 0), 2.0);
    QVERIFY(std::isnan(s.value(0, 1)) && std::isnan(s.value(0, 2)));
}

void TstTrackingPlots::appendStoresWithoutReplot() {
    TrackingPlotsWidget w;
    w.show();
    w.setCapacity(100);
    double j[6], c[3];
    for (int i = 0; i < 250; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    QCOMPARE(w.sampleCount(), 100);
    QCOMPARE(w.droppedCount(), std::uint64_t(150));
    QCOMPARE(w.plottedPointCount(), 0); // nothing moved into the plot until the timer ticks
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 100, 2000);
}

void TstTrackingPlots::pausedViewStaysFrozen() {
    TrackingPlotsWidget w;
    w.show();
    double j[6], c[3];
    for (int i = 0; i < 10; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 10, 2000);
    w.setPaused(true);
    for (int i = 10; i < 30; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    waitForTicks(w, 3);
    QCOMPARE(w.plottedPointCount(), 10);
    QCOMPARE(w.sampleCount(), 30);
    w.setPaused(false);
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 30, 2000);
}

void TstTrackingPlots::csvRoundTrip() {
    QTemporaryDir dir;
    TrackingPlotsWidget w;
    w.show();
    w.setAxisNames({"A0 chuck", "J1", "J2", "J3", "J4", "J5"});
    double j[6], c[3];
    const int n = 40;
    for (int i = 0; i < n; ++i) {
        sample(i, j, c);
        w.append(i * 0.002, j, 6, c);
    }
    const QString path = dir.filePath("errors.csv");
    QString err;
    QVERIFY2(w.exportCsv(path, &err), qPrintable(err));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.size(), n + 1);
    QCOMPARE(
        lines[0],
        QByteArray("t_s,A0_chuck_err_deg,J1_err_deg,J2_err_deg,J3_err_deg,J4_err_deg,J5_err_deg,"
                   "x_err_mm,y_err_mm,z_err_mm"));
    for (int i = 0; i < n; ++i) {
        const QList<QByteArray> cells = lines[i + 1].split(',');
        QCOMPARE(cells.size(), 10);
        sample(i, j, c);
        QCOMPARE(cells[0].toDouble(), i * 0.002);
        for (int k = 0; k < 6; ++k)
            QCOMPARE(cells[1 + k].toDouble(), j[k]);
        for (int k = 0; k < 3; ++k)
            QCOMPARE(cells[7 + k].toDouble(), c[k]);
    }
}

void TstTrackingPlots::csvOfTwoAxisMachine() {
    QTemporaryDir dir;
    TrackingPlotsWidget w;
    w.show();
    w.setAxisCount(2);
    w.setAxisNames({"X", "A"});
    const double j[2] = {0.5, -0.5};
    w.append(0.0, j, 2, nullptr); // no Cartesian error: empty cells
    QString err;
    QVERIFY2(w.exportCsv(dir.filePath("xa.csv"), &err), qPrintable(err));
    QFile f(dir.filePath("xa.csv"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines[0], QByteArray("t_s,X_err_deg,A_err_deg,x_err_mm,y_err_mm,z_err_mm"));
    QCOMPARE(lines[1], QByteArray("0,0.5,-0.5,,,"));
}

void TstTrackingPlots::oneUnitPerPlot() {
    // A rotary and a linear axis: each on a plot of its unit; no tip plot when none is set.
    QTemporaryDir dir;
    TrackingPlotsWidget w;
    w.show();
    w.setAxes({"A", "X", "B"}, {"deg", "mm", "deg"});
    w.setTipTraces({}, {});
    QCOMPARE(w.plotTitles(), QStringList({"error (deg)", "error (mm)"}));
    QCOMPARE(w.plotTraceNames(0), QStringList({"A", "B"}));
    QCOMPARE(w.plotTraceNames(1), QStringList({"X"}));
    const double e[3] = {0.25, -1.5, 0.125};
    w.append(0.0, e, 3, nullptr);
    w.replotNow();
    QCOMPARE(w.plottedPointCount(), 1);
    QString err;
    QVERIFY2(w.exportCsv(dir.filePath("u.csv"), &err), qPrintable(err));
    QFile f(dir.filePath("u.csv"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines[0], QByteArray("t_s,A_err_deg,X_err_mm,B_err_deg"));
    QCOMPARE(lines[1], QByteArray("0,0.25,-1.5,0.125"));
    // A tip trace of its own: a third plot, its column in mm.
    w.setTipTraces({"miss"}, "torch miss (mm)");
    QCOMPARE(w.plotTitles().size(), 3);
    QCOMPARE(w.plotTraceNames(2), QStringList({"miss"}));
    QCOMPARE(w.sampleCount(), 0); // new channels clear the data
}

void TstTrackingPlots::pngIsAValidImage() {
    QTemporaryDir dir;
    TrackingPlotsWidget w;
    w.show();
    w.resize(900, 600);
    double j[6], c[3];
    for (int i = 0; i < 500; ++i) {
        sample(i % 7, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    const QString path = dir.filePath("plots.png");
    QString err;
    QVERIFY2(w.exportPng(path, &err), qPrintable(err));
    QImage img(path);
    QVERIFY(!img.isNull());
    QVERIFY(img.width() >= 800 && img.height() >= 600);
    // Traces were drawn: some pixels carry the first trace's blue.
    int coloured = 0;
    for (int y = 0; y < img.height(); y += 2)
        for (int x = 0; x < img.width(); x += 2) {
            const QColor p = img.pixelColor(x, y);
            if (p.blue() > 150 && p.red() < 90) ++coloured;
        }
    QVERIFY2(coloured > 20, qPrintable(QString::number(coloured)));
}

void TstTrackingPlots::exportToBadPathNamesThePath() {
    TrackingPlotsWidget w;
    w.show();
    const QString bad = QStringLiteral("/nonexistent-dir/x/errors.csv");
    QString err;
    QVERIFY(!w.exportCsv(bad, &err));
    QVERIFY2(err.contains(bad), qPrintable(err));
    QVERIFY(!w.exportPng(QStringLiteral("/nonexistent-dir/x/p.png"), &err));
    QVERIFY2(err.contains(QStringLiteral("p.png")), qPrintable(err));
}

void TstTrackingPlots::traceVisibilityToggles() {
    TrackingPlotsWidget w;
    w.show();
    QVERIFY(w.traceVisible(2));
    w.setTraceVisible(2, false);
    QVERIFY(!w.traceVisible(2));
    QVERIFY(w.traceVisible(3));
    w.setTraceVisible(6 + 1, false); // Cartesian y
    QVERIFY(!w.traceVisible(7));
    w.setTraceVisible(2, true);
    QVERIFY(w.traceVisible(2));
}

void TstTrackingPlots::clearEmptiesEverything() {
    TrackingPlotsWidget w;
    w.show();
    double j[6], c[3];
    for (int i = 0; i < 20; ++i) {
        sample(i, j, c);
        w.append(i, j, 6, c);
    }
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 20, 2000);
    w.clear();
    QCOMPARE(w.sampleCount(), 0);
    QCOMPARE(w.droppedCount(), std::uint64_t(0));
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 0, 2000);
}

void TstTrackingPlots::hiddenWidgetCatchesUpWhenShown() {
    TrackingPlotsWidget w; // never shown yet
    double j[6], c[3];
    for (int i = 0; i < 25; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    waitForTicks(w, 3);
    QCOMPARE(w.plottedPointCount(), 0); // no work for a hidden widget
    w.show();
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 25, 2000);
}

QTEST_MAIN(TstTrackingPlots)
// Host-driven: the timer no longer moves new data into the plots (the host's display frame
// does, with redrawPending), so the plots never cause a window composition of their own.
void TstTrackingPlots::hostDrivenRedrawWaitsForTheHost() {
    TrackingPlotsWidget w;
    w.setHostDrivenRedraw(true);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    double j[6], c[3];
    for (int i = 0; i < 40; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    waitForTicks(w, 3);
    QCOMPARE(w.plottedPointCount(), 0);
    w.redrawPending();
    QCOMPARE(w.plottedPointCount(), 40);
    w.setHostDrivenRedraw(false); // back to the timer
    for (int i = 40; i < 50; ++i) {
        sample(i, j, c);
        w.append(i * 0.01, j, 6, c);
    }
    QTRY_COMPARE_WITH_TIMEOUT(w.plottedPointCount(), 50, 2000);
}

#include "tst_tracking_plots.moc"

void TstTrackingPlots::readableAtOperatorSizes_data() {
    QTest::addColumn<QSize>("size");
    // The plots' share of the window at 1280x720 and at 1600x1000 (issue 21, defect 9).
    QTest::newRow("1280x720") << QSize(560, 300);
    QTest::newRow("1600x1000") << QSize(760, 420);
}

void TstTrackingPlots::readableAtOperatorSizes() {
    // Six rotary axes and the tip's x/y/z, errors of a few 1e-4: the robot's live run.
    QFETCH(QSize, size);
    TrackingPlotsWidget w;
    w.resize(size);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    for (int i = 0; i < 3000; ++i) {
        double j[6], c[3];
        for (int k = 0; k < 6; ++k)
            j[k] = 4e-4 * std::sin(0.01 * i + k);
        for (int k = 0; k < 3; ++k)
            c[k] = 2e-3 * std::cos(0.013 * i + k);
        w.append(i * 1e-3, j, 6, c);
    }
    // Short: one plot at a time under tabs; tall: stacked. Every plot is checked as shown.
    auto* tabs = w.findChild<QTabBar*>("plotTabs");
    QVERIFY(tabs);
    const int views = tabs->isVisible() ? tabs->count() : 1;
    QCOMPARE(tabs->isVisible(), size.height() < 400);
    QList<QCustomPlot*> checked;
    for (int view = 0; view < views; ++view) {
        if (tabs->isVisible()) tabs->setCurrentIndex(view);
        w.replotNow();
        w.replotNow(); // the tick count follows the laid-out height
        for (QCustomPlot* p : w.findChildren<QCustomPlot*>()) {
            if (!p->isVisible()) continue;
            checked << p;
            const QRect data = p->axisRect()->rect();
            QVERIFY2(data.height() > 40, qPrintable(QString::number(data.height())));
            // The legend never lies over the data.
            QVERIFY2(!p->legend->visible() || !p->legend->outerRect().intersects(data),
                     qPrintable(QStringLiteral("legend %1,%2 %3x%4 over the data %5,%6 %7x%8")
                                    .arg(p->legend->outerRect().x())
                                    .arg(p->legend->outerRect().y())
                                    .arg(p->legend->outerRect().width())
                                    .arg(p->legend->outerRect().height())
                                    .arg(data.x())
                                    .arg(data.y())
                                    .arg(data.width())
                                    .arg(data.height())));
            QVERIFY(p->legend->outerRect().bottom() <= p->height());
            // y tick labels do not overlap: consecutive ticks are further apart than a label is
            // high, and a label is at most 8 characters wide.
            const QCPRange range = p->yAxis->range();
            QList<double> shown;
            const QVector<double> ticks = p->yAxis->tickVector();
            for (double t : ticks)
                if (range.contains(t)) shown << p->yAxis->coordToPixel(t);
            QVERIFY2(shown.size() >= 2, qPrintable(QStringLiteral("%1 ticks on a %2 px axis")
                                                       .arg(shown.size())
                                                       .arg(data.height())));
            const int labelHeight = QFontMetrics(p->yAxis->tickLabelFont()).height();
            for (qsizetype k = 1; k < shown.size(); ++k)
                QVERIFY2(std::fabs(shown[k] - shown[k - 1]) > labelHeight,
                         qPrintable(QStringLiteral("ticks %1 px apart, labels %2 px high")
                                        .arg(std::fabs(shown[k] - shown[k - 1]))
                                        .arg(labelHeight)));
            for (const QString& label : p->yAxis->tickVectorLabels())
                QVERIFY2(label.size() <= 8, qPrintable(label));
        }
    }
    QCOMPARE(checked.size(), 2); // the axes' plot and the tip's, each seen once
    QCOMPARE(QSet<QCustomPlot*>(checked.begin(), checked.end()).size(), 2);
}

void TstTrackingPlots::clearFollowsTheNewDataAgain() {
    // Zoomed by hand, then a new run or job: its ranges follow the new data, no Fit needed.
    TrackingPlotsWidget w;
    w.resize(560, 300);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* p = w.findChildren<QCustomPlot*>().value(0);
    QVERIFY(p);
    const QPoint at = p->axisRect()->center();
    QWheelEvent wheel(at, p->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(p, &wheel);
    QVERIFY(!w.autoscale());
    w.clear();
    QVERIFY(w.autoscale());
}

void TstTrackingPlots::flatTraceKeepsANarrowRange() {
    // A run whose errors stay exactly 0 (a crank at rest, a simulated axis): redraw after redraw
    // the y range stays narrow around the line (it grew 12 % a redraw, to +-1e15 on screen).
    TrackingPlotsWidget w;
    w.resize(560, 300);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const double zeros[6] = {0, 0, 0, 0, 0, 0};
    const double tip[3] = {5, 5, 5}; // flat away from 0: the span follows the value
    for (int i = 0; i < 400; ++i) {
        w.append(i * 1e-2, zeros, 6, tip);
        w.replotNow();
    }
    const QList<QCustomPlot*> plots = w.findChildren<QCustomPlot*>();
    QCOMPARE(plots.size(), 2);
    const QCPRange axes = plots[0]->yAxis->range();
    QVERIFY2(axes.contains(0) && axes.size() < 3e-6, qPrintable(QString::number(axes.size())));
    const QCPRange tipRange = plots[1]->yAxis->range();
    QVERIFY2(tipRange.contains(5) && tipRange.size() < 15e-6,
             qPrintable(QString::number(tipRange.size())));
    // The line lies inside the axis, not on its edge.
    QVERIFY(axes.lower < -1e-7 && axes.upper > 1e-7);
    // Small errors that are not flat still fill the plot (the robot's simulated run: ~1e-5 deg).
    for (int i = 400; i < 800; ++i) {
        const double small[6] = {1e-5 * std::sin(0.05 * i), 0, 0, 0, 0, 0};
        w.append(i * 1e-2, small, 6, tip);
    }
    w.replotNow();
    const QCPRange filled = plots[0]->yAxis->range();
    QVERIFY2(filled.size() > 2e-5 && filled.size() < 2.5e-5,
             qPrintable(QString::number(filled.size())));
}
