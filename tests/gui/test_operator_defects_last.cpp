// Issue 21's defects 12, 14 and 15 (the rest of them), one case each; each failed on main at
// f3d8811:
// 12. A note that comes (parameters locked at Start, a typing error) never moves the fields
//     under the operator's pointer: the notes sit below them.
// 14. A form's message names the field by its label, not the job file's key, and a speed of
//     0 is told with the field's range, not "must be > 0".
// 15. The keyboard focus is visible (an amber frame), and Tab leaves a table.
#include "core/job/default_job.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/number_fields.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/theme.h"

#include <QAbstractSpinBox>
#include <QImage>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtTest>

using CutCell::ui::MainWindow;

namespace {

// How many pixels of the image are close to the colour (each channel within 16: the E-STOP's
// yellow ring #ffcc00 is not the focus amber #ffb020).
int pixelsNear(const QImage& image, QColor c) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor p = image.pixelColor(x, y);
            if (std::abs(p.red() - c.red()) < 16 && std::abs(p.green() - c.green()) < 16 &&
                std::abs(p.blue() - c.blue()) < 16)
                ++n;
        }
    return n;
}

QWidget* showField(MainWindow& w, const char* key) {
    QWidget* field = w.parameters()->fieldFor(key);
    w.parameters()->revealField(key);
    QApplication::processEvents();
    return field;
}

int yOnWindow(const QWidget* field, const MainWindow& w) {
    return field->mapTo(&w, QPoint(0, 0)).y();
}

} // namespace

class TestOperatorDefectsLast : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { QVERIFY(CutCell::ui::applyDarkIndustrialTheme(*qApp)); }

    void defect12_notesNeverMoveTheFields() {
        MainWindow w(nullptr);
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QWidget* speed = showField(w, "cut.speed_mm_s");
        QVERIFY(speed);
        const int before = yOnWindow(speed, w);
        // Locked (as at Start): the note comes, the field stays where it was.
        w.parameters()->setEditingLocked(true, "Parameters are locked while the machine runs.");
        QTest::qWait(50); // the layouts settle (posted layout requests)
        QCOMPARE(yOnWindow(speed, w), before);
        w.parameters()->setEditingLocked(false, {});
        // A bad value on the page: its note comes, the field stays.
        w.editor()->edit([](cutcell::Job& j) { j.cut.ramp_s = -1; });
        QTRY_VERIFY(!w.editor()->valid());
        QTest::qWait(50); // the layouts settle (posted layout requests)
        QCOMPARE(yOnWindow(speed, w), before);
    }

    void defect14_messagesNameTheFieldAndItsRange() {
        MainWindow w(nullptr);
        w.editor()->edit([](cutcell::Job& j) { j.cut.speed_mm_s = 0; });
        QTRY_VERIFY(!w.editor()->valid());
        QWidget* speed = w.parameters()->fieldFor("cut.speed_mm_s");
        const QString tip = speed->toolTip();
        QVERIFY2(tip.contains(speed->accessibleName()) && !speed->accessibleName().isEmpty(),
                 qPrintable(tip));
        QVERIFY2(!tip.contains("cut.speed_mm_s"), qPrintable(tip));
        QVERIFY2(!tip.contains("must be > 0"), qPrintable(tip));
        QVERIFY2(tip.contains("[0.1, 500] mm/s"), qPrintable(tip));
        // In German, in German with the German number form.
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        MainWindow de(nullptr);
        de.editor()->edit([](cutcell::Job& j) { j.cut.speed_mm_s = 0; });
        QTRY_VERIFY(!de.editor()->valid());
        const QString tipDe = de.parameters()->fieldFor("cut.speed_mm_s")->toolTip();
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        QVERIFY2(tipDe.contains("0,1") && tipDe.contains("500") && !tipDe.contains("outside"),
                 qPrintable(tipDe));
    }

    void defect15_theFocusIsVisible() {
        // The application's style sheet on two buttons and a field, as in the window.
        QWidget box;
        auto* layout = new QVBoxLayout(&box);
        auto* a = new QPushButton("Enable", &box);
        auto* b = new QPushButton("Home", &box);
        auto* field = new CutCell::ui::DecimalField(&box);
        layout->addWidget(a);
        layout->addWidget(b);
        layout->addWidget(field);
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        a->setFocus();
        QTRY_VERIFY(a->hasFocus());
        const QImage unfocused = b->grab().toImage();
        const QImage fieldBefore = field->grab().toImage();
        b->setFocus();
        QTRY_VERIFY(b->hasFocus());
        const QImage focused = b->grab().toImage();
        const QColor amber(0xff, 0xb0, 0x20);
        QCOMPARE(pixelsNear(unfocused, amber), 0);
        // The frame all round: at least the button's perimeter.
        QVERIFY2(pixelsNear(focused, amber) >= b->width() + b->height(),
                 qPrintable(QString::number(pixelsNear(focused, amber))));
        field->setFocus();
        QTRY_VERIFY(field->hasFocus());
        QCOMPARE(pixelsNear(fieldBefore, amber), 0);
        QVERIFY(pixelsNear(field->grab().toImage(), amber) >= field->width());
        // The E-STOP's yellow ring turns white.
        MainWindow w(nullptr);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QPushButton* estop = w.controls()->eStopButton();
        const int whiteBefore = pixelsNear(estop->grab().toImage(), Qt::white);
        estop->setFocus();
        QTRY_VERIFY(estop->hasFocus());
        QVERIFY(pixelsNear(estop->grab().toImage(), Qt::white) > whiteBefore + estop->width());
    }

    void defect15_tabLeavesATable() {
        MainWindow w(nullptr);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        int tables = 0;
        for (QTableWidget* t : w.findChildren<QTableWidget*>()) {
            ++tables;
            QVERIFY2(!t->tabKeyNavigation(), t->parentWidget()->metaObject()->className());
        }
        QVERIFY(tables >= 4); // the robot's two, the saw's queue, the crank's, the alarms
        // The DH table: Tab from its last field goes on to the next widget outside it.
        QTableWidget* dh = nullptr;
        for (QTableWidget* t : w.findChildren<QTableWidget*>())
            if (t->rowCount() == 6 && t->columnCount() == 6) dh = t;
        QVERIFY(dh);
        for (int i = 0; i < w.parameters()->tabs()->count(); ++i)
            if (w.parameters()->tabs()->widget(i)->isAncestorOf(dh))
                w.parameters()->tabs()->setCurrentIndex(i);
        QApplication::processEvents();
        // Its cells are fields (the table itself takes no focus): start in the first one.
        QWidget* cell = dh->cellWidget(0, 0);
        QVERIFY(cell);
        QWidget* start = cell->focusProxy() ? cell->focusProxy() : cell;
        start->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY(dh->isAncestorOf(QApplication::focusWidget()));
        bool left = false;
        for (int n = 0; n < 60 && !left; ++n) { // 36 cells, then out
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
            QWidget* f = QApplication::focusWidget();
            left = f && f != dh && !dh->isAncestorOf(f);
        }
        QVERIFY2(left, "Tab never left the DH table (60 presses)");
    }
};

QTEST_MAIN(TestOperatorDefectsLast)
#include "test_operator_defects_last.moc"
