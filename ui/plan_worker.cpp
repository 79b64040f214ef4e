#include "ui/plan_worker.h"

#include "ui/machine/machine_ui_registry.h"

#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <stdexcept>

namespace CutCell::ui {

struct PlanWorker::Run {
    cutcell::Job job;
    std::atomic<bool> cancel{false};
    std::atomic<int> lastPermille{-1};
    std::shared_ptr<cutcell::MachinePlan> plan;
    std::string error;
};

PlanWorker::PlanWorker(QObject* parent)
    : QObject(parent), watcher_(new QFutureWatcher<void>(this)) {
    connect(watcher_, &QFutureWatcher<void>::finished, this, &PlanWorker::finished);
}

PlanWorker::~PlanWorker() {
    cancel();
    watcher_->waitForFinished();
}

void PlanWorker::request(const cutcell::Job& job) {
    pending_ = std::make_unique<cutcell::Job>(job);
    if (current_) {
        current_->cancel = true; // finished() launches the pending request
        return;
    }
    launch();
}

void PlanWorker::cancel() {
    pending_.reset();
    if (current_) current_->cancel = true;
}

bool PlanWorker::busy() const {
    return current_ != nullptr;
}

void PlanWorker::waitIdle() {
    while (current_) {
        watcher_->waitForFinished();
        finished();
    }
}

void PlanWorker::launch() {
    auto run = std::make_shared<Run>();
    run->job = std::move(*pending_);
    pending_.reset();
    current_ = run;
    emit started();
    QPointer<PlanWorker> self(this);
    watcher_->setFuture(QtConcurrent::run([run, self] {
        cutcell::PlanOptions opt;
        opt.cancel = &run->cancel;
        // Progress goes back to the GUI thread queued, at most once per 1 %.
        opt.progress = [run, self](double f) {
            const int permille = static_cast<int>(f * 100) * 10;
            if (run->lastPermille.exchange(permille) == permille || !self) return;
            QMetaObject::invokeMethod(
                self.data(),
                [run, self, f] {
                    if (self && self->current_ == run) emit self->progress(f);
                },
                Qt::QueuedConnection);
        };
        try {
            // Each machine plans its own way (the robot's IK and spline, the profile cutter's
            // closed-form cut).
            const MachineUi* machine = machineUiFor(run->job);
            if (!machine)
                throw std::invalid_argument("no machine module for machine = \"" +
                                            run->job.machine + "\"");
            run->plan = std::make_shared<cutcell::MachinePlan>(machine->plan(run->job, opt));
        } catch (const std::exception& e) {
            run->error = e.what();
        }
    }));
}

void PlanWorker::finished() {
    if (!current_) return;
    auto run = std::move(current_);
    current_.reset();
    if (pending_) { // superseded: plan the newer job instead
        launch();
        return;
    }
    if (!run->error.empty())
        emit failed(QString::fromStdString(run->error));
    else if (run->cancel || !run->plan || run->plan->cancelled())
        emit cancelled();
    else
        emit planned(run->plan, run->job);
}

} // namespace CutCell::ui
