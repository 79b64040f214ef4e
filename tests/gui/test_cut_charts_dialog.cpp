// The cut-chart editor (ui/panels/cut_charts_dialog.h), offscreen under a German GUI locale: a
// cell typed with a decimal comma is taken, saved atomically to the user's table and read back
// (and installed as the active library); a value out of range is refused with the checker's
// message and the cell keeps its value; Add row / Remove row; an operator sees the table
// read-only with the reason, a setter may edit; the Cut page's "Cut charts…" button stays
// within the page at 1280x720.
#include "core/process/cut_chart_library.h"
#include "core/process/process_spec.h"
#include "core/record/audit.h"
#include "ui/access_control.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/cut_charts_dialog.h"

#include <QDir>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <map>

using cutcell::CutFigure;
using CutCell::ui::AccessControl;
using CutCell::ui::CutChartsDialog;

namespace {

// Users for the access control: "op" an operator, "set" a setter, any password.
class Users : public cutcell::UserAuthenticator {
  public:
    bool hasUsers() const override { return true; }
    std::optional<cutcell::UserLevel> levelOf(const std::string& name) const override {
        const auto it = levels_.find(name);
        if (it == levels_.end()) return std::nullopt;
        return it->second;
    }
    cutcell::LoginAnswer login(const std::string& name, const std::string&) override {
        cutcell::LoginAnswer a;
        if (const auto l = levelOf(name))
            a.level = *l;
        else
            a.outcome = cutcell::Outcome::refuse("no such user", "user");
        return a;
    }
    void logout(const std::string&, const std::string&) override {}

  private:
    std::map<std::string, cutcell::UserLevel> levels_{{"op", cutcell::UserLevel::Operator},
                                                      {"set", cutcell::UserLevel::Setter}};
};

int columnOf(const cutcell::CutChart& c, CutFigure f) {
    for (std::size_t k = 0; k < c.columns.size(); ++k)
        if (c.columns[k] == f) return static_cast<int>(k);
    return -1;
}

} // namespace

class TestCutChartsDialog : public QObject {
    Q_OBJECT
    QTemporaryDir home_;
    std::string dataHome() const { return home_.path().toStdString(); }
    std::string userPath() const { return cutcell::userCutChartsPath(dataHome()); }

  private slots:
    void initTestCase() {
        QVERIFY(home_.isValid());
        // The user's table goes to this test's folder, not to the shared test data home.
        qputenv("XDG_DATA_HOME", home_.path().toLocal8Bit());
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    }
    void init() { std::filesystem::remove(userPath()); }

    void editACellSaveAndReadBack() {
        CutChartsDialog d(dataHome(), nullptr);
        d.show();
        QVERIFY(d.lockReason().isEmpty());
        const cutcell::CutChart& first = cutcell::shippedCutCharts().charts.front();
        QVERIFY(d.showChart(first.process, first.material, first.consumable));
        QTableWidget* rows = d.rowTable();
        QVERIFY(!rows->tabKeyNavigation());
        QCOMPARE(rows->rowCount(), static_cast<int>(first.rows.size()));
        const int speed = columnOf(first, CutFigure::CutSpeedMmMin);
        QVERIFY(speed >= 0);
        QTableWidgetItem* cell = rows->item(1, speed);
        QVERIFY(cell->flags() & Qt::ItemIsEditable);
        cell->setText(QStringLiteral("1234,5")); // a German decimal comma
        QVERIFY2(d.problem().isEmpty(), qPrintable(d.problem()));
        QVERIFY(d.modified());
        QCOMPARE(*d.table().charts[0].rows[1].get(CutFigure::CutSpeedMmMin), 1234.5);
        QCOMPARE(cell->text(), QStringLiteral("1234,5")); // shown in the GUI's form
        QSignalSpy saved(&d, &CutChartsDialog::saved);
        QVERIFY(d.save());
        QCOMPARE(saved.count(), 1);
        QVERIFY(!d.modified());
        const cutcell::CutChartSet back = cutcell::loadCutChartsFile(userPath());
        QCOMPARE(*back.charts[0].rows[1].get(CutFigure::CutSpeedMmMin), 1234.5);
        QVERIFY(back == d.table());
        QVERIFY(cutcell::activeCutCharts() == back); // the forms' table is the new one
        // Nothing but the table in its folder (the temporary file was renamed over).
        const QStringList files =
            QDir(QString::fromStdString(std::filesystem::path(userPath()).parent_path().string()))
                .entryList(QDir::Files | QDir::Hidden);
        QCOMPARE(files, QStringList{QStringLiteral("cut_charts.json")});
        // A new editor shows the user's table.
        CutChartsDialog again(dataHome(), nullptr);
        QVERIFY(again.table() == back);
        QVERIFY(again.findChild<QLabel*>("cutChartsWhere")->text().contains("cut_charts.json"));
        cutcell::setActiveCutCharts(cutcell::shippedCutCharts());
    }

    void aBadValueIsRefusedWithTheCheckersMessage() {
        CutChartsDialog d(dataHome(), nullptr);
        const cutcell::CutChart& first = cutcell::shippedCutCharts().charts.front();
        QVERIFY(d.showChart(first.process, first.material, first.consumable));
        const int speed = columnOf(first, CutFigure::CutSpeedMmMin);
        QTableWidgetItem* cell = d.rowTable()->item(1, speed);
        const QString was = cell->text();
        cell->setText(QStringLiteral("200000"));
        QVERIFY2(d.problem().contains("(charts[0]) rows[1]: cut_speed_mm_min = 200000 mm/min is "
                                      "outside (0, 100000] mm/min"),
                 qPrintable(d.problem()));
        QCOMPARE(cell->text(), was);
        QVERIFY(!d.modified());
        QVERIFY(d.table() == cutcell::shippedCutCharts());
        cell->setText(QStringLiteral("1.234,5")); // ambiguous: held, never taken
        QVERIFY(!d.problem().isEmpty());
        QCOMPARE(cell->text(), was);
        // The last row of a chart stays; a row added after the last one is 1 mm thicker.
        d.rowTable()->setCurrentCell(d.rowTable()->rowCount() - 1, 0);
        d.addRow();
        QVERIFY2(d.problem().isEmpty(), qPrintable(d.problem()));
        QCOMPARE(d.rowTable()->rowCount(), static_cast<int>(first.rows.size()) + 1);
        QCOMPARE(d.table().charts[0].rows.back().thicknessMm(),
                 first.rows.back().thicknessMm() + 1);
        d.rowTable()->setCurrentCell(d.rowTable()->rowCount() - 1, 0);
        d.removeRow();
        QVERIFY(d.table() == cutcell::shippedCutCharts());
        QVERIFY(!std::filesystem::exists(userPath())); // nothing saved
    }

    void readOnlyForAnOperator() {
        Users users;
        AccessControl access(&users, nullptr, QStringLiteral("desk"));
        QCOMPARE(AccessControl::current(), &access);
        QVERIFY(access.logIn("op", "pw").ok());
        CutChartsDialog d(dataHome(), &access);
        QVERIFY2(d.lockReason().contains(CutCell::ui::userLevelText(cutcell::UserLevel::Setter)),
                 qPrintable(d.lockReason()));
        auto* lock = d.findChild<QLabel*>("cutChartsLock");
        QVERIFY(!lock->isHidden());
        QVERIFY(lock->text().contains(d.lockReason()));
        QTableWidgetItem* cell = d.rowTable()->item(0, 1);
        QVERIFY(!(cell->flags() & Qt::ItemIsEditable));
        for (const char* name : {"cutChartsSave", "cutChartsAddRow", "cutChartsRemoveRow"})
            QVERIFY2(!d.findChild<QPushButton*>(name)->isEnabled(), name);
        const QString was = cell->text();
        cell->setText(QStringLiteral("1")); // even programmatically: refused
        QCOMPARE(cell->text(), was);
        QVERIFY(!d.modified());
        QVERIFY(!d.save());
        QVERIFY(!std::filesystem::exists(userPath()));
        // A setter may edit (the dialog follows the log-in).
        access.logOut();
        QVERIFY(access.logIn("set", "pw").ok());
        QVERIFY(d.lockReason().isEmpty());
        QVERIFY(d.findChild<QLabel*>("cutChartsLock")->isHidden());
        QVERIFY(d.rowTable()->item(0, 1)->flags() & Qt::ItemIsEditable);
        QVERIFY(d.findChild<QPushButton*>("cutChartsAddRow")->isEnabled());
    }

    void theCutPageButtonFitsAt1280x720() {
        CutCell::ui::MainWindow w(nullptr);
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* button = w.findChild<QPushButton*>("processEditCharts");
        QVERIFY(button);
        QTabWidget* tabs = w.parameters()->tabs();
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->widget(i)->isAncestorOf(button)) tabs->setCurrentIndex(i);
        QCoreApplication::processEvents();
        QVERIFY(button->isVisible());
        QScrollArea* area = nullptr;
        for (QWidget* p = button->parentWidget(); p && !area; p = p->parentWidget())
            area = qobject_cast<QScrollArea*>(p);
        QVERIFY(area);
        const int right = button->mapTo(area->viewport(), QPoint(button->width(), 0)).x();
        QVERIFY2(right <= area->viewport()->width(),
                 qPrintable(QStringLiteral("button ends at %1 of %2 px")
                                .arg(right)
                                .arg(area->viewport()->width())));
        QVERIFY2(area->widget()->width() <= area->viewport()->width(),
                 qPrintable(QStringLiteral("page %1 px in a %2 px viewport")
                                .arg(area->widget()->width())
                                .arg(area->viewport()->width())));
        QVERIFY(button->width() >= button->sizeHint().width());
        qInfo("Cut page viewport %d px, button %d..%d px", area->viewport()->width(),
              button->mapTo(area->viewport(), QPoint(0, 0)).x(), right);
    }
};

QTEST_MAIN(TestCutChartsDialog)
#include "test_cut_charts_dialog.moc"
