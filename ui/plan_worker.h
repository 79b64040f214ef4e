#pragma once
// Plans cuts off the GUI thread (QtConcurrent) with progress and cancel. A new request
// cancels the one in flight; only the result of the latest request is delivered, on the GUI
// thread, through planned().
//
// Threading contract: the public API and the signals are GUI-thread only; the job's machine plans
// (MachineUi::plan) on a pool thread with its own copy of the job and touches nothing else.
#include "core/job/job.h"
#include "core/machine/machine_module.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <memory>

namespace CutCell::ui {

class PlanWorker : public QObject {
    Q_OBJECT
  public:
    explicit PlanWorker(QObject* parent = nullptr);
    ~PlanWorker() override;

    void request(const cutcell::Job& job);
    void cancel();
    bool busy() const;
    // Blocks until the worker is idle (tests and shutdown only, never in a slot).
    void waitIdle();

  signals:
    void started();
    void progress(double fraction);
    void planned(std::shared_ptr<const cutcell::MachinePlan> plan, const cutcell::Job& job);
    void cancelled();
    void failed(const QString& message);

  private:
    struct Run;
    void launch();
    void finished();

    std::shared_ptr<Run> current_;
    std::unique_ptr<cutcell::Job> pending_;
    QFutureWatcher<void>* watcher_;
};

} // namespace CutCell::ui
