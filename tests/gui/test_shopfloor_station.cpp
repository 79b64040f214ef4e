// The operator station's side of the shop floor (issue 26, app/gui/shopfloor_station.*): a job
// the network queues is validated on the link's thread (a bad one is refused with the job
// reader's own message and never reaches the queue), arrives in the GUI's queue, and becomes
// the job being edited only when the operator opens it (nothing starts it); the queue can be
// cleared from the network; a remote feed hold reaches the run controller.
#include "shopfloor_station.h"

#include "core/job/job_io.h"
#include "ui/forms/job_editor.h"
#include "ui/job_queue.h"
#include "ui/main_window.h"
#include "ui/panels/job_queue_panel.h"

#include <QtTest>

#include <string>
#include <thread>

using CutCell::ui::JobQueue;
using CutCell::ui::JobQueuePanel;
using CutCell::ui::MainWindow;

class TestShopfloorStation : public QObject {
    Q_OBJECT

    // As the link does: the call on another thread, its answer back.
    static std::string fromNetwork(const std::string& text) {
        cutcell::app::StationCommands commands;
        std::string answer;
        std::thread t([&] { answer = commands.queueJob(text, "spBv1.0/shop/NCMD/cell-1"); });
        t.join();
        return answer;
    }
    static std::string shippedJob(const char* file) {
        return cutcell::readTextFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + file);
    }

  private slots:
    void aQueuedJobWaitsForTheOperator() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        MainWindow w(nullptr);
        const std::string before = w.editor()->job().name;
        QCOMPARE(fromNetwork(shippedJob("plasma_hole_job.json")), std::string());
        QTRY_COMPARE(queue->size(), 1);
        QVERIFY(queue->entries()[0].source.contains("shop floor"));
        QVERIFY(queue->entries()[0].source.contains("NCMD/cell-1"));
        // Queued, not opened and not started: the window's job is still its own.
        QCOMPARE(w.editor()->job().name, before);
        JobQueuePanel panel(queue, w.document());
        QCOMPARE(panel.table()->rowCount(), 1);
        QCOMPARE(panel.table()->item(0, 0)->text().toStdString(),
                 cutcell::parseJob(shippedJob("plasma_hole_job.json")).name);
        QString why;
        QVERIFY2(panel.openQueued(0, &why), qPrintable(why));
        QCOMPARE(w.editor()->job().name,
                 cutcell::parseJob(shippedJob("plasma_hole_job.json")).name);
        QVERIFY(w.editor()->job().process.used);
        QCOMPARE(queue->size(), 0);
        QCOMPARE(panel.table()->rowCount(), 0);
    }

    void aBadJobIsRefusedWithTheReadersMessage() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        const std::string bad = R"({"schema": 2, "name": "x", "machine": {"kind": "no_such"}})";
        std::string expected;
        try {
            cutcell::parseJob(bad);
        } catch (const cutcell::JobError& e) {
            expected = e.what();
        }
        QVERIFY(!expected.empty());
        QCOMPARE(fromNetwork(bad), expected);
        // A job that reads but is not valid: the first issue with its key.
        std::string text = shippedJob("default_job.json");
        const auto at = text.find("\"speed_mm_s\": 4.397");
        QVERIFY(at != std::string::npos);
        text.replace(at, 19, "\"speed_mm_s\": 900");
        const std::string answer = fromNetwork(text);
        for (const char* part : {"cut.speed_mm_s", "900", "mm/s", "500"})
            QVERIFY2(answer.find(part) != std::string::npos, answer.c_str());
        QCoreApplication::processEvents();
        QCOMPARE(queue->size(), 0);
    }

    void theNetworkClearsTheQueue() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        QCOMPARE(fromNetwork(shippedJob("default_job.json")), std::string());
        QCOMPARE(fromNetwork(shippedJob("profile_cutter_job.json")), std::string());
        QTRY_COMPARE(queue->size(), 2);
        std::thread t([] { cutcell::app::StationCommands().clearQueue(); });
        t.join();
        QTRY_COMPARE(queue->size(), 0);
    }
};

QTEST_MAIN(TestShopfloorStation)
#include "test_shopfloor_station.moc"
