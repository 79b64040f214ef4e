// Planning off the GUI thread: results come back on the GUI thread, a newer request
// supersedes an older one (only the latest is delivered), and cancel is honoured.
#include "core/job/default_job.h"
#include "ui/plan_worker.h"

#include <QThread>
#include <QtTest>

using CutCell::ui::PlanWorker;

Q_DECLARE_METATYPE(std::shared_ptr<const cutcell::MachinePlan>)
Q_DECLARE_METATYPE(cutcell::Job)

class TestPlanWorker : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        qRegisterMetaType<std::shared_ptr<const cutcell::MachinePlan>>();
        qRegisterMetaType<cutcell::Job>();
    }

    void plansOnAWorkerAndDeliversOnTheGuiThread() {
        PlanWorker w;
        QThread* deliveredOn = nullptr;
        std::shared_ptr<const cutcell::MachinePlan> result;
        int progressCalls = 0;
        connect(&w, &PlanWorker::progress, this, [&](double f) {
            ++progressCalls;
            QVERIFY(f >= 0 && f <= 1);
        });
        connect(&w, &PlanWorker::planned, this,
                [&](std::shared_ptr<const cutcell::MachinePlan> p, const cutcell::Job&) {
                    deliveredOn = QThread::currentThread();
                    result = std::move(p);
                });
        w.request(cutcell::defaultJob());
        QVERIFY(w.busy());
        QTRY_VERIFY_WITH_TIMEOUT(result != nullptr, 60000);
        QCOMPARE(deliveredOn, QThread::currentThread());
        QVERIFY(result->ok());
        QVERIFY(result->program && result->program->point_count > 0);
        QVERIFY(progressCalls > 0);
        QVERIFY(!w.busy());
    }

    void onlyTheLatestRequestIsDelivered() {
        PlanWorker w;
        QSignalSpy planned(&w, &PlanWorker::planned);
        auto a = cutcell::defaultJob();
        a.name = "first";
        auto b = cutcell::defaultJob();
        b.name = "second";
        b.cut.speed_mm_s = 8;
        w.request(a);
        w.request(b);
        // planned() is emitted in the call that makes the worker idle: once it is idle, every
        // delivery has happened (a superseded request's would have come first).
        QTRY_VERIFY_WITH_TIMEOUT(!w.busy(), 60000);
        QCOMPARE(planned.count(), 1);
        QCOMPARE(planned.at(0).at(1).value<cutcell::Job>().name, std::string("second"));
        const auto plan = planned.at(0).at(0).value<std::shared_ptr<const cutcell::MachinePlan>>();
        QVERIFY(plan->program &&
                plan->program->cut_time_s < 20); // planned at 8 mm/s, not at the default speed
    }

    void cancelIsHonoured() {
        PlanWorker w;
        QSignalSpy planned(&w, &PlanWorker::planned);
        QSignalSpy cancelled(&w, &PlanWorker::cancelled);
        w.request(cutcell::defaultJob());
        w.cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!w.busy(), 60000);
        QTRY_COMPARE(cancelled.count(), 1);
        QCOMPARE(planned.count(), 0);
    }
};

QTEST_MAIN(TestPlanWorker)
#include "test_plan_worker.moc"
