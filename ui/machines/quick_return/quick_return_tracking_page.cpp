#include "ui/machines/quick_return/quick_return_tracking_page.h"
#include "ui/shown_number.h"

#include "core/machines/quick_return/quick_return_spec.h"
#include "plots/xy_figures_widget.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <array>

namespace CutCell::ui {

namespace qr = cutcell::quick_return;
using cutcell::plots::XyCurve;

namespace {

// One colour per controller, the same in the table's plots and the error plot.
const std::array<QColor, 4> kColours{QColor(200, 120, 0), QColor(120, 60, 180), QColor(30, 140, 60),
                                     QColor(20, 90, 200)};

QString upper(qr::ControllerKind k) {
    return QString::fromUtf8(qr::toString(k)).toUpper();
}

TrackingBatch runAll(const qr::ExperimentSetup& setup,
                     const std::shared_ptr<std::atomic<bool>>& cancel) {
    TrackingBatch b;
    QElapsedTimer clock;
    clock.start();
    b.offGuiThread = QThread::currentThread() != QCoreApplication::instance()->thread();
    for (qr::ControllerKind k : qr::kAllControllers) {
        if (cancel->load()) {
            b.cancelled = true;
            break;
        }
        b.results.push_back(qr::runTracking(setup, k));
    }
    b.seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    return b;
}

} // namespace

QuickReturnTrackingForm::QuickReturnTrackingForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent), watcher_(new QFutureWatcher<TrackingBatch>(this)),
      cancel_(std::make_shared<std::atomic<bool>>(false)) {
    intro_ = new QLabel(this);
    intro_->setWordWrap(true);
    button_ = new QPushButton(tr("Run experiment 1 (FFC, LQT, SMC, OSMC)"), this);
    button_->setObjectName("quickReturnExperiment1");
    status_ = new QLabel(tr("Not run yet."), this);
    status_->setObjectName("quickReturnExperiment1Status");
    status_->setWordWrap(true);
    table_ = new QTableWidget(4, 4, this);
    table_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    table_->setObjectName("quickReturnExperiment1Table");
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    for (int r = 0; r < 4; ++r) {
        table_->setItem(r, 0, new QTableWidgetItem(upper(qr::kAllControllers[size_t(r)])));
        for (int c = 1; c < 4; ++c)
            table_->setItem(r, c, new QTableWidgetItem(QStringLiteral("-")));
    }
    fitTableHeight();
    // Two rows: FFC, LQT, SMC; OSMC and the four errors (twice as wide).
    figures_ = new cutcell::plots::XyFiguresWidget(5, 3, this);
    for (int i = 0; i < 4; ++i)
        figures_->setPanel(i, tr("%1: y and y_d").arg(upper(qr::kAllControllers[size_t(i)])),
                           tr("t (s)"), tr("y (m)"));
    figures_->setPanel(4, tr("Tracking error e = y_d - y"), tr("t (s)"), tr("e (mm)"));
    mainLayout()->addWidget(intro_);
    mainLayout()->addWidget(button_);
    mainLayout()->addWidget(status_);
    mainLayout()->addWidget(table_);
    mainLayout()->addWidget(figures_, 1);
    connect(button_, &QPushButton::clicked, this, [this] { startExperiment(); });
    connect(watcher_, &QFutureWatcher<TrackingBatch>::finished, this,
            &QuickReturnTrackingForm::batchFinished);
    describe(editor->job());
}

QuickReturnTrackingForm::~QuickReturnTrackingForm() {
    // The pool thread stops after the controller it is on; its result is dropped.
    cancel_->store(true);
}

void QuickReturnTrackingForm::reloadExtra(const cutcell::Job& job) {
    describe(job);
}

void QuickReturnTrackingForm::describe(const cutcell::Job& job) {
    const auto* spec = job.machine_spec.as<cutcell::QuickReturnSpec>();
    if (!spec) return;
    intro_->setText(tr("Tracking y_d = %1 %2 %3 sin(%4 t) for %5 s without contact force, "
                       "each controller with the job's parameters (Controller page); MSE of "
                       "L e over the last %6 s with L = %7.")
                        .arg(shownNumber(spec->track_offset, 3))
                        .arg(spec->track_amplitude < 0 ? QStringLiteral("-") : QStringLiteral("+"))
                        .arg(shownNumber(std::abs(spec->track_amplitude), 3))
                        .arg(shownNumber(spec->track_omega, 4))
                        .arg(shownNumber(spec->track_duration, 1))
                        .arg(shownNumber(spec->mse_window, 1))
                        .arg(shownNumber(spec->mse_scale, 0)));
    // Two lines a heading: on one line they were cut in a pane of 424 px (1280x720).
    table_->setHorizontalHeaderLabels({tr("Controller"),
                                       tr("MSE,\nlast %1 s").arg(shownNumber(spec->mse_window, 1)),
                                       tr("max |e|\n(mm)"), tr("peak torque\n(N m)")});
    fitTableHeight(); // the headings' two lines
}

void QuickReturnTrackingForm::fitTableHeight() {
    // Exactly the header and the four rows: no empty band below them, no row cut.
    table_->setFixedHeight(table_->horizontalHeader()->sizeHint().height() +
                           4 * table_->verticalHeader()->defaultSectionSize() +
                           2 * table_->frameWidth());
}

bool QuickReturnTrackingForm::running() const {
    return watcher_->isRunning();
}

bool QuickReturnTrackingForm::startExperiment(QString* why) {
    if (running()) {
        if (why) *why = tr("experiment 1 is running");
        return false;
    }
    const cutcell::Job job = editor()->job();
    const auto* spec = job.machine_spec.as<cutcell::QuickReturnSpec>();
    const cutcell::Outcome set =
        spec ? cutcell::buildSetup(*spec, &setup_)
             : cutcell::Outcome::refuse("the job is not for the quick-return cutter");
    if (!set.ok()) {
        status_->setText(tr("Cannot run: %1").arg(QString::fromStdString(set.message)));
        if (why) *why = status_->text();
        return false;
    }
    button_->setEnabled(false);
    status_->setText(tr("Running the four controllers ..."));
    watcher_->setFuture(
        QtConcurrent::run([setup = setup_, cancel = cancel_] { return runAll(setup, cancel); }));
    return true;
}

void QuickReturnTrackingForm::batchFinished() {
    button_->setEnabled(true);
    last_ = watcher_->result();
    if (last_.cancelled) return;
    std::vector<XyCurve> errors;
    for (size_t i = 0; i < last_.results.size(); ++i) {
        const qr::TrackingResult& r = last_.results[i];
        const int row = static_cast<int>(i);
        table_->item(row, 0)->setText(upper(r.controller));
        table_->item(row, 1)->setText(shownNumber(r.mse, 4));
        table_->item(row, 2)->setText(shownNumber(r.max_abs_error * 1000, 3));
        table_->item(row, 3)->setText(shownNumber(r.max_torque, 2));
        XyCurve y{tr("y"), {}, {}, kColours[i]};
        XyCurve yd{tr("y_d"), {}, {}, QColor(220, 60, 30), true};
        XyCurve e{upper(r.controller), {}, {}, kColours[i]};
        for (const qr::TracePoint& p : r.trace) {
            y.x.push_back(p.t), y.y.push_back(p.y);
            yd.x.push_back(p.t), yd.y.push_back(p.y_d);
            e.x.push_back(p.t), e.y.push_back((p.y_d - p.y) * 1000);
        }
        figures_->setCurves(row, {yd, y});
        errors.push_back(e);
    }
    figures_->setCurves(4, errors);
    // The lowest MSE, named: the table says which controller wins with these parameters.
    size_t best = 0;
    for (size_t i = 1; i < last_.results.size(); ++i)
        if (last_.results[i].mse < last_.results[best].mse) best = i;
    if (!last_.results.empty())
        status_->setText(tr("Done in %1 s (off the GUI thread). Lowest MSE: %2 (%3).")
                             .arg(shownNumber(last_.seconds, 2))
                             .arg(upper(last_.results[best].controller))
                             .arg(shownNumber(last_.results[best].mse, 4)));
    emit finished();
}

} // namespace CutCell::ui
