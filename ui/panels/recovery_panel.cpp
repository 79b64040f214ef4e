#include "ui/panels/recovery_panel.h"
#include "ui/shown_number.h"

#include "ui/panels/run_words.h"

#include "ui/forms/number_fields.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace CutCell::ui {

using cutcell::EngineState;
using cutcell::MotionSourceKind;

RecoveryPanel::RecoveryPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("recoveryPanel");
    auto* box = new QGroupBox(tr("Cut recovery"), this);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(box);
    auto* g = new QGridLayout(box);
    where_ = new QLabel(box);
    where_->setObjectName("recoveryWhere");
    where_->setWordWrap(true);
    g->addWidget(where_, 0, 0, 1, 2);
    g->addWidget(new QLabel(tr("Lead-in"), box), 1, 0);
    auto* leadIn = new DecimalField(box);
    leadIn->setFieldName(tr("Lead-in"));
    leadIn_ = leadIn;
    leadIn_->setObjectName("recoveryLeadIn");
    leadIn_->setRange(0, 50);
    leadIn_->setDecimals(1);
    leadIn_->setSuffix(tr(" mm"));
    leadIn_->setValue(5);
    leadIn_->setToolTip(tr("The resumed cut starts this far back along the path from the stop "
                           "point, so the kerf joins (0 .. 50 mm)."));
    g->addWidget(leadIn_, 1, 1);
    resume_ = new QPushButton(tr("Resume from stop"), box);
    resume_->setObjectName("recoveryResume");
    // Each button under its field, the box's width: beside it the German "Ab Halt fortsetzen"
    // was cut at the column's edge.
    g->addWidget(resume_, 2, 0, 1, 2);
    g->addWidget(new QLabel(tr("From point"), box), 3, 0);
    auto* point = new WholeNumberField(box);
    point->setFieldName(tr("From point"));
    point_ = point;
    point_->setObjectName("recoveryPoint");
    point_->setToolTip(tr("Run the rest of the cut from this point of the path."));
    g->addWidget(point_, 3, 1);
    runFrom_ = new QPushButton(tr("Run from point"), box);
    runFrom_->setObjectName("recoveryRunFrom");
    g->addWidget(runFrom_, 4, 0, 1, 2);
    reason_ = new QLabel(box);
    reason_->setObjectName("recoveryReason");
    reason_->setWordWrap(true);
    g->addWidget(reason_, 5, 0, 1, 2);
    unconfirmed_ = new QLabel(box);
    unconfirmed_->setObjectName("recoveryUnconfirmed");
    unconfirmed_->setWordWrap(true);
    unconfirmed_->hide();
    g->addWidget(unconfirmed_, 6, 0, 1, 2);
    confirm_ = new QPushButton(tr("Count the part as good"), box);
    confirm_->setObjectName("recoveryConfirmPart");
    confirm_->setToolTip(tr("The run completed, but part of the path was never cut (Run from "
                            "point). Count the part only if it was finished otherwise."));
    confirm_->hide();
    g->addWidget(confirm_, 7, 0, 1, 2);
    connect(confirm_, &QPushButton::clicked, this, &RecoveryPanel::partConfirmed);
    connect(resume_, &QPushButton::clicked, this,
            [this] { emit startFromRequested(resumePathTime()); });
    connect(runFrom_, &QPushButton::clicked, this,
            [this] { emit startFromRequested(pickedPathTime()); });
    connect(leadIn_, &QDoubleSpinBox::valueChanged, this, [this] { refresh(); });
    refresh();
}

void RecoveryPanel::setProgram(std::shared_ptr<const cutcell::MotionProgram> program) {
    program_ = std::move(program);
    stop_.reset();
    const int points = program_ ? static_cast<int>(program_->point_count) : 0;
    point_->setRange(1, std::max(1, points)); // shown 1-based, as the progress panel does
    point_->setValue(1); // a point of the program before means nothing in this one
    refresh();
}

void RecoveryPanel::setStopPoint(const std::optional<cutcell::RunStopPoint>& stop) {
    stop_ = stop && stop->valid ? stop : std::nullopt;
    if (stop_) point_->setValue(static_cast<int>(stop_->point_index) + 1);
    refresh();
}

void RecoveryPanel::setState(EngineState state, bool homed) {
    if (state == state_ && homed == homed_) return;
    state_ = state;
    homed_ = homed;
    refresh();
}

double RecoveryPanel::timeOfPoint(int point) const {
    return program_ ? (point - 1) * program_->spline.dt() : 0.0; // point 1 = path time 0
}

double RecoveryPanel::leadInTime() const {
    if (!program_ || !(program_->length_mm > 0)) return 0;
    // The cut runs at constant speed between its ramps: length and time are proportional.
    return leadIn_->value() * program_->cut_time_s / program_->length_mm;
}

double RecoveryPanel::resumePathTime() const {
    if (!stop_) return 0;
    return std::clamp(stop_->path_time_s - leadInTime(), 0.0,
                      program_ ? program_->cut_time_s : 0.0);
}

double RecoveryPanel::pickedPathTime() const {
    if (!program_) return 0;
    // The last point is the path's end: nothing left to cut from there.
    return std::clamp(timeOfPoint(point_->value()), 0.0,
                      std::max(0.0, program_->cut_time_s - program_->spline.dt()));
}

QString RecoveryPanel::reason() const {
    if (!program_) return tr("No program loaded.");
    if (program_->source_kind != MotionSourceKind::JointSpline)
        return tr("This machine's motion follows %1, not a path in time: no cut recovery; start "
                  "the cycle again.")
            .arg(program_->source_kind == MotionSourceKind::MasterAxis ? tr("the line")
                                                                       : tr("a control law"));
    if (state_ != EngineState::Ready)
        return tr("Recovery starts from Ready (state now: %1).").arg(stateWord(state_));
    if (!homed_) return tr("Home first: the axes lost their reference.");
    return {};
}

void RecoveryPanel::setUnconfirmedPart(const QString& text) {
    unconfirmed_->setText(tr("Part not counted: %1.").arg(text));
    unconfirmed_->setVisible(!text.isEmpty());
    confirm_->setVisible(!text.isEmpty());
}

void RecoveryPanel::refresh() {
    const QString why = reason();
    const bool ok = why.isEmpty();
    if (stop_ && program_ && program_->source_kind != MotionSourceKind::JointSpline)
        where_->setText(
            tr("Stopped at %1.").arg(stopFigures(program_->terms, *stop_, program_->length_mm)));
    else if (stop_)
        where_->setText(tr("Stopped at point %1 / %2, %3 of %4 mm (path time %5 s). Resume "
                           "starts at %6 s.")
                            .arg(std::min(stop_->point_index + 1, stop_->point_count))
                            .arg(stop_->point_count)
                            .arg(shownNumber(stop_->length_mm, 1))
                            .arg(shownNumber(program_ ? program_->length_mm : 0.0, 1))
                            .arg(shownNumber(stop_->path_time_s, 2))
                            .arg(shownNumber(resumePathTime(), 2)));
    else
        where_->setText(tr("No stopped cut to recover."));
    resume_->setEnabled(ok && stop_.has_value());
    runFrom_->setEnabled(ok);
    leadIn_->setEnabled(stop_.has_value());
    reason_->setText(why);
    reason_->setVisible(!why.isEmpty());
}

} // namespace CutCell::ui
