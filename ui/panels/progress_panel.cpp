#include "ui/panels/progress_panel.h"
#include "ui/shown_number.h"

#include "ui/panels/run_words.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>

#include <algorithm>
#include <cmath>

namespace CutCell::ui {

using cutcell::EngineState;

ProgressPanel::ProgressPanel(QWidget* parent)
    : QWidget(parent), state_(new QLabel(this)), bar_(new QProgressBar(this)),
      percent_(new QLabel(this)), elapsed_(new QLabel(this)), remaining_(new QLabel(this)),
      points_(new QLabel(this)), stop_(new QLabel(this)), cycle_(new QLabel(this)) {
    setObjectName("progressPanel");
    auto* g = new QGridLayout(this);
    g->setContentsMargins(6, 6, 6, 6);
    state_->setObjectName("stateText");
    g->addWidget(state_, 0, 0);
    percent_->setObjectName("percentText");
    percent_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    g->addWidget(percent_, 0, 1);
    bar_->setRange(0, 1000);
    bar_->setTextVisible(false);
    bar_->setMinimumHeight(22);
    g->addWidget(bar_, 1, 0, 1, 2);
    const auto caption = [this](const QString& t) {
        auto* l = new QLabel(t, this);
        l->setObjectName("caption");
        return l;
    };
    // Two figures a row: the times, then the count. Three in a row reached 345 px with a
    // program of 99999 points, past the column's 306 (a count's digits are never elided).
    g->addWidget(caption(tr("Elapsed")), 2, 0);
    g->addWidget(caption(tr("Remaining")), 2, 1);
    for (auto* l : {elapsed_, remaining_, points_})
        l->setObjectName("bigValue");
    g->addWidget(elapsed_, 3, 0);
    g->addWidget(remaining_, 3, 1);
    pointsCaption_ = caption(countCaption(terms_.counts));
    g->addWidget(pointsCaption_, 4, 0);
    g->addWidget(points_, 4, 1);
    // The detail line (approach phase, or where a run stopped) keeps its place (two lines)
    // whether shown or not: nothing jumps.
    stop_->setObjectName("stopText");
    stop_->setWordWrap(true);
    stop_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    stop_->setFixedHeight(QFontMetrics(stop_->font()).lineSpacing() * 2 + 6);
    g->addWidget(stop_, 5, 0, 1, 2);
    cycle_->setObjectName("cycleText");
    cycle_->setWordWrap(true);
    g->addWidget(cycle_, 6, 0, 1, 2);
    clear();
    setCycleFigures(0, 0);
}

QString ProgressPanel::formatDuration(double s) {
    if (!std::isfinite(s) || s < 0) s = 0;
    const auto total = static_cast<long long>(std::llround(s * 10));
    const long long tenths = total % 10, secs = (total / 10) % 60, mins = total / 600;
    return QStringLiteral("%1:%2.%3")
        .arg(mins, 2, 10, QChar('0'))
        .arg(secs, 2, 10, QChar('0'))
        .arg(tenths);
}

void ProgressPanel::setApproachTarget(const cutcell::JointVector& q, int axisCount) {
    approachTarget_ = q;
    axisCount_ = std::clamp(axisCount, 0, cutcell::kMaxAxes);
}

void ProgressPanel::setTerms(const cutcell::RunTerms& terms) {
    terms_ = terms;
    pointsCaption_->setText(countCaption(terms_.counts));
    setCycleFigures(made_, lastCycleS_);
}

void ProgressPanel::beginRun() {
    stopped_ = false;
    lastCut_.reset();
    approachStart_.reset();
    stop_->clear();
    stop_->setToolTip({});
}

void ProgressPanel::markStopped(const QString& how) {
    if (!lastCut_) return; // nothing ran
    stopped_ = true;
    stopHow_ = how;
    // Nothing of this run remains to be done: a frozen countdown read as time still to go.
    remaining_->setText(QStringLiteral("--"));
    const auto& s = *lastCut_;
    cutcell::RunStopPoint at;
    at.valid = true;
    at.progress = std::clamp(s.progress, 0.0, 1.0);
    at.length_mm = at.progress * pathLengthMm_;
    at.elapsed_s = s.elapsed_s;
    at.point_index = s.point_index;
    at.point_count = s.point_count;
    at.made = s.made;
    showStop(at);
}

void ProgressPanel::setStopPoint(const cutcell::RunStopPoint& stop) {
    if (!stopped_ || !stop.valid) return;
    // The engine's own stop point (taken in the cycle of the stop; the telemetry shown last may
    // be up to a display frame older): the same figures as the cut recovery box and summary.json.
    // The figures above the line show it too: the last sample shown may predate the last piece.
    const double p = std::clamp(stop.progress, 0.0, 1.0);
    bar_->setValue(static_cast<int>(std::lround(p * 1000)));
    percent_->setText(QStringLiteral("%1 %").arg(shownNumber(p * 100.0, 1)));
    const auto shown = stop.point_count ? std::min(stop.point_index + 1, stop.point_count) : 0u;
    points_->setText(QStringLiteral("%1 / %2").arg(shown).arg(stop.point_count));
    showStop(stop);
}

void ProgressPanel::showStop(const cutcell::RunStopPoint& at) {
    const QString text =
        tr("Stopped (%1) at %2, %3 after Start")
            .arg(stopHow_, stopFigures(terms_, at, pathLengthMm_), formatDuration(at.elapsed_s));
    stop_->setText(text);
    stop_->setToolTip(text);
}

void ProgressPanel::setCycleFigures(int made, double lastCycleS) {
    made_ = made;
    lastCycleS_ = lastCycleS;
    cycle_->setText(tr("Last cycle %1   %2 %3")
                        .arg(lastCycleS > 0 ? formatDuration(lastCycleS) : QStringLiteral("--"))
                        .arg(madeCaption(terms_.counts))
                        .arg(made));
}

void ProgressPanel::setSample(const cutcell::TelemetrySample& s) {
    const bool inRun = s.state == EngineState::Running || s.state == EngineState::Paused ||
                       s.state == EngineState::Completed;
    if (inRun) {
        if (stopped_) beginRun(); // a new run after a stop
        lastCut_ = s;
        show(s);
        return;
    }
    // After a run (the telemetry reads 0 there): its figures stay until the next Start.
    if (lastCut_) {
        state_->setText(stateWord(s.state));
        if (!stopped_ && lastCut_->state == EngineState::Completed)
            stop_->setText(tr("Last run completed."));
        return;
    }
    show(s);
}

void ProgressPanel::show(const cutcell::TelemetrySample& s) {
    const double p = std::clamp(s.progress, 0.0, 1.0);
    const int value = static_cast<int>(std::lround(p * 1000));
    if (value != bar_->value()) {
        // QProgressBar::setValue() repaints synchronously when the fill moves a pixel: with
        // updates off it is a no-op; re-enabling schedules an update() that joins the tick's
        // single composition.
        bar_->setUpdatesEnabled(false);
        bar_->setValue(value);
        bar_->setUpdatesEnabled(true);
    }
    percent_->setText(QStringLiteral("%1 %").arg(shownNumber(p * 100.0, 1)));
    elapsed_->setText(formatDuration(s.elapsed_s));
    remaining_->setText(formatDuration(s.remaining_s));
    // The engine counts knots passed from 0; the operator reads "point n of N" from 1.
    const auto shown = s.point_count ? std::min(s.point_index + 1, s.point_count) : 0u;
    points_->setText(QStringLiteral("%1 / %2").arg(shown).arg(s.point_count));
    state_->setText(stateWord(s.state));
    // Before the path begins: the approach move, then settling and the arc (the line below
    // the figures says which; the cut's own progress is still 0).
    QString phase;
    if (s.state == EngineState::Running && s.progress <= 0 && axisCount_ > 0) {
        const double d = (s.setpoint.head(axisCount_) - approachTarget_.head(axisCount_)).norm();
        if (!approachStart_ || d > *approachStart_) approachStart_ = d;
        const double f = *approachStart_ > 1e-9 ? 1.0 - d / *approachStart_ : 1.0;
        if (!terms_.path_length)
            phase = f < 0.999
                        ? tr("Approach to the start position: %1 %").arg(shownNumber(f * 100, 0))
                        : tr("At the start position: the run starts");
        else
            phase = f < 0.999
                        ? tr("Approach to the first cut point: %1 %").arg(shownNumber(f * 100, 0))
                        : (s.torch_on ? tr("Arc on: the cut starts")
                                      : tr("At the first cut point: settling, then the arc"));
    }
    if (!stopped_) {
        stop_->setText(phase);
        stop_->setToolTip(phase);
    }
}

void ProgressPanel::setPlannedTotals(std::uint32_t points, double duration_s) {
    plannedPoints_ = points;
    plannedS_ = duration_s;
    if (stopped_) return; // the stop stays until the next Start or another program
    points_->setText(QStringLiteral("0 / %1").arg(points));
    remaining_->setText(formatDuration(duration_s));
}

void ProgressPanel::clear() {
    beginRun();
    bar_->setValue(0);
    percent_->setText(QStringLiteral("%1 %").arg(shownNumber(0.0, 1)));
    elapsed_->setText(formatDuration(0));
    remaining_->setText(formatDuration(0));
    points_->setText(QStringLiteral("0 / 0"));
    state_->setText(tr("Idle"));
}

void ProgressPanel::setProgram(const cutcell::RunTerms& terms, double pathLengthMm) {
    // Another program (File -> New, Open, an edit): the last run's figures and its stop line
    // belong to the one before; the recovery box drops that stop too.
    lastCut_.reset();
    clear();
    setPathLength(pathLengthMm);
    setTerms(terms);
    setPlannedTotals(plannedPoints_, plannedS_);
}

QString ProgressPanel::remainingText() const {
    return remaining_->text();
}
QString ProgressPanel::percentText() const {
    return percent_->text();
}
QString ProgressPanel::pointsText() const {
    return points_->text();
}
QString ProgressPanel::stateText() const {
    return state_->text();
}
QString ProgressPanel::stopText() const {
    return stop_->text();
}
QString ProgressPanel::cycleText() const {
    return cycle_->text();
}

} // namespace CutCell::ui
