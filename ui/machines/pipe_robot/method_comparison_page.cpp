#include "ui/machines/pipe_robot/method_comparison_page.h"
#include "ui/panels/engine_text.h"
#include "ui/shown_number.h"

#include "plots/xy_figures_widget.h"

#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace CutCell::ui {

using cutcell::plots::XyCurve;

namespace {

constexpr int kTipRows = 3;
enum Column { StaticColumn, RotatingColumn, RatioColumn };

QColor seriesColour(int i) {
    return QColor(QString::fromLatin1(cutcell::chartColor(i)));
}

QString methodName(cutcell::CutMethod m) {
    return m == cutcell::CutMethod::StaticPipe ? MethodComparisonForm::tr("static pipe")
                                               : MethodComparisonForm::tr("rotating pipe");
}

QString axisLetter(int k) {
    return QString(QChar(u"xyz"[k]));
}

} // namespace

MethodComparisonForm::MethodComparisonForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent), watcher_(new QFutureWatcher<cutcell::MethodComparison>(this)) {
    button_ = new QPushButton(tr("Compare methods"), this);
    button_->setObjectName("compareMethods");
    button_->setToolTip(tr("Plans and simulates the job's cut with the pipe static and with the "
                           "pipe turning (seed 000, Fig. 11-14)."));
    summary_ = new QLabel(tr("Compare the job's cut with the pipe static and with the pipe "
                             "turning: joint errors and the torch tip's error over time."),
                          this);
    summary_->setObjectName("compareSummary");
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* caption = new QLabel(tr("Max |joint error| (deg) and the tip error's range min … max "
                                  "(mm, robot base frame), over every cycle:"),
                               this);
    caption->setWordWrap(true);

    table_ = new QTableWidget(cutcell::kAxisCount + kTipRows, 3, this);
    table_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    table_->setObjectName("compareTable");
    table_->setHorizontalHeaderLabels({tr("Static"), tr("Rotating"), tr("Ratio")});
    table_->horizontalHeaderItem(StaticColumn)->setToolTip(tr("Pipe static"));
    table_->horizontalHeaderItem(RotatingColumn)->setToolTip(tr("Pipe turning"));
    table_->horizontalHeaderItem(RatioColumn)
        ->setToolTip(tr("Rotating / static of the max |error| (n/a where the static figure is "
                        "zero)"));
    QStringList rows;
    for (int i = 0; i < cutcell::kAxisCount; ++i)
        rows << (i == 0 ? tr("Joint 0 (chuck)") : tr("Joint %1").arg(i));
    for (int k = 0; k < kTipRows; ++k)
        rows << tr("Tip %1").arg(axisLetter(k));
    table_->setVerticalHeaderLabels(rows);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->horizontalHeader()->setSectionResizeMode(RatioColumn, QHeaderView::ResizeToContents);
    table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->setWordWrap(false);

    method_ = new QComboBox(this);
    method_->setObjectName("compareMethod");
    method_->addItems({tr("Figures of the static pipe (Fig. 11, 13)"),
                       tr("Figures of the rotating pipe (Fig. 12, 14)")});
    figures_ = new cutcell::plots::XyFiguresWidget(2, Qt::Vertical, this);
    figures_->setObjectName("compareFigures");
    figures_->setMinimumHeight(560);
    figures_->setLegendColumns(0, 3);
    figures_->setLegendColumns(1, 3);
    mainLayout()->addWidget(button_);
    mainLayout()->addWidget(summary_);
    mainLayout()->addWidget(caption);
    mainLayout()->addWidget(table_);
    mainLayout()->addWidget(method_);
    mainLayout()->addWidget(figures_, 1);
    fitTableHeight();
    draw();
    connect(button_, &QPushButton::clicked, this, [this] { startComparison(); });
    connect(method_, &QComboBox::currentIndexChanged, this, [this] { draw(); });
    connect(watcher_, &QFutureWatcher<cutcell::MethodComparison>::finished, this,
            &MethodComparisonForm::finished);
}

void MethodComparisonForm::fitTableHeight() {
    int h = table_->horizontalHeader()->sizeHint().height() + 2 * table_->frameWidth();
    for (int r = 0; r < table_->rowCount(); ++r)
        h += table_->verticalHeader()->sectionSizeHint(r);
    table_->setFixedHeight(h);
}

MethodComparisonForm::~MethodComparisonForm() {
    // The plans stop at the flag; a simulation running ends on its own (a few seconds at most).
    if (cancel_) cancel_->store(true);
    watcher_->waitForFinished();
}

bool MethodComparisonForm::comparing() const {
    return watcher_->isRunning();
}

bool MethodComparisonForm::startComparison(QString* why) {
    if (comparing()) {
        if (why) *why = tr("a comparison is running");
        return false;
    }
    button_->setEnabled(false);
    summary_->setText(tr("Planning and simulating both methods ..."));
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    // A copy of the job and the flag: the pool thread shares nothing else with the page.
    watcher_->setFuture(QtConcurrent::run([job = editor()->job(), cancel = cancel_] {
        cutcell::PlanOptions options;
        options.cancel = cancel.get();
        return cutcell::runMethodComparison(job, options);
    }));
    return true;
}

void MethodComparisonForm::finished() {
    button_->setEnabled(true);
    result_ = watcher_->result();
    const cutcell::MethodComparison& c = *result_;
    fillTable(c);
    draw();
    QString text;
    if (c.cancelled) {
        text = tr("The comparison was cancelled.");
    } else {
        QStringList parts;
        for (const cutcell::MethodRun& r : c.runs)
            parts << (r.ok ? tr("%1: %2 s simulated at %3 ms per cycle")
                                 .arg(methodName(r.method))
                                 .arg(shownNumber(r.trace.report.simulated_s, 1))
                                 .arg(shownNumber(c.period_s * 1e3, 2))
                           : tr("%1: not simulated - %2")
                                 .arg(methodName(r.method))
                                 .arg(engineText(QString::fromStdString(r.problem))));
        text = parts.join(QStringLiteral("; ")) + QLatin1Char('.');
    }
    summary_->setText(text);
    emit compared(c.ok());
}

void MethodComparisonForm::fillTable(const cutcell::MethodComparison& c) {
    const auto set = [this](int row, int column, const QString& text) {
        auto* item = new QTableWidgetItem(text);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(row, column, item);
    };
    const QString none = tr("n/a");
    const auto ratio = [&none](double v) { return std::isfinite(v) ? shownNumber(v, 2) : none; };
    for (int i = 0; i < cutcell::kAxisCount; ++i) {
        const auto a = static_cast<size_t>(i);
        for (int m = 0; m < 2; ++m) {
            const cutcell::MethodRun& r = c.runs[static_cast<size_t>(m)];
            set(i, m, r.ok ? shownNumber(r.trace.joint_max_abs_deg[a], 4) : none);
        }
        set(i, RatioColumn, ratio(c.jointRatio(i)));
    }
    for (int k = 0; k < kTipRows; ++k) {
        const int row = cutcell::kAxisCount + k;
        for (int m = 0; m < 2; ++m) {
            const cutcell::MethodRun& r = c.runs[static_cast<size_t>(m)];
            set(row, m,
                r.ok ? tr("%1 … %2")
                           .arg(shownNumber(r.trace.tip_min_mm[k], 3))
                           .arg(shownNumber(r.trace.tip_max_mm[k], 3))
                     : none);
        }
        set(row, RatioColumn, ratio(c.tipRatio(k)));
    }
}

void MethodComparisonForm::draw() {
    const int m = std::max(0, method_->currentIndex());
    const QString name =
        methodName(m == 0 ? cutcell::CutMethod::StaticPipe : cutcell::CutMethod::RotatingPipe);
    figures_->setPanel(0, tr("Joint errors, %1").arg(name), tr("t (s)"),
                       tr("commanded - actual (deg)"));
    figures_->setPanel(1, tr("Tip position error, %1").arg(name), tr("t (s)"),
                       tr("FK(actual) - FK(commanded) (mm)"));
    std::vector<XyCurve> joints, tip;
    if (result_ && result_->runs[static_cast<size_t>(m)].ok) {
        const cutcell::CutTrace& trace = result_->runs[static_cast<size_t>(m)].trace;
        const QVector<double> t(trace.t_s.begin(), trace.t_s.end());
        for (int i = 0; i < cutcell::kAxisCount; ++i) {
            const auto& e = trace.joint_error_deg[static_cast<size_t>(i)];
            joints.push_back(
                {tr("joint %1").arg(i), t, QVector<double>(e.begin(), e.end()), seriesColour(i)});
        }
        for (int k = 0; k < kTipRows; ++k) {
            const auto& e = trace.tip_error_mm[static_cast<size_t>(k)];
            tip.push_back({axisLetter(k), t, QVector<double>(e.begin(), e.end()), seriesColour(k)});
        }
    }
    figures_->setCurves(0, joints);
    figures_->setCurves(1, tip);
}

} // namespace CutCell::ui
