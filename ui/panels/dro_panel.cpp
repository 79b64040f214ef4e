#include "ui/panels/dro_panel.h"
#include "ui/shown_number.h"

#include "core/common/types.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace CutCell::ui {

using cutcell::EngineState;

namespace {
// Steps offered (in the axis's unit); the first entry is continuous jog.
constexpr double kSteps[] = {0.0, 0.01, 0.1, 1.0, 10.0};
} // namespace

DroPanel::DroPanel(QWidget* parent)
    : QWidget(parent), grid_(new QGridLayout), step_(new QComboBox(this)),
      axis_(new QComboBox(this)), minus_(new QPushButton(QStringLiteral("-"), this)),
      plus_(new QPushButton(QStringLiteral("+"), this)) {
    setObjectName("droPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 4, 6, 4);
    auto* title = new QLabel(tr("Position: commanded / actual"), this);
    title->setObjectName("caption");
    v->addWidget(title);
    grid_->setHorizontalSpacing(6);
    grid_->setVerticalSpacing(2);
    grid_->setColumnStretch(0, 1);
    v->addLayout(grid_);
    for (int i = 0; i < cutcell::kMaxAxes; ++i) {
        Row& r = rows_[static_cast<size_t>(i)];
        r.name = new QLabel(this);
        r.commanded = new QLabel(this);
        r.actual = new QLabel(this);
        r.name->setMinimumWidth(40);
        r.name->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // long names elide
        r.commanded->setObjectName(QStringLiteral("droCommanded%1").arg(i));
        r.actual->setObjectName(QStringLiteral("droActual%1").arg(i));
        for (QLabel* l : {r.commanded, r.actual}) {
            l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            l->setProperty("dro", true);
        }
        grid_->addWidget(r.name, i, 0);
        grid_->addWidget(r.commanded, i, 1);
        grid_->addWidget(r.actual, i, 2);
    }
    // One jog row: axis, - / +, step.
    auto* jog = new QHBoxLayout;
    axis_->setObjectName("jogAxis");
    axis_->setToolTip(tr("The axis to jog"));
    axis_->setMinimumWidth(60);
    axis_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    axis_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    axis_->setMinimumContentsLength(4);
    jog->addWidget(axis_, 1);
    for (QPushButton* b : {minus_, plus_}) {
        b->setFixedSize(36, 30);
        b->setFocusPolicy(Qt::NoFocus);
        b->setAutoRepeat(false);
        jog->addWidget(b);
    }
    minus_->setObjectName("jogMinus");
    plus_->setObjectName("jogPlus");
    connect(minus_, &QPushButton::pressed, this, [this] { onPressed(-1); });
    connect(plus_, &QPushButton::pressed, this, [this] { onPressed(+1); });
    connect(minus_, &QPushButton::released, this, &DroPanel::onReleased);
    connect(plus_, &QPushButton::released, this, &DroPanel::onReleased);
    step_->setObjectName("jogStep");
    step_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    step_->setMinimumContentsLength(4);
    for (double st : kSteps)
        step_->addItem(st == 0 ? tr("cont.") : QLocale().toString(st, 'g', 3), st);
    step_->setCurrentIndex(3);
    step_->setToolTip(tr("Jog step in the axis unit (deg or mm); cont.: the axis moves while - "
                         "or + is held, up to its limit"));
    jog->addWidget(step_);
    v->addLayout(jog);
    setProgram(nullptr);
}

void DroPanel::setProgram(const std::shared_ptr<const cutcell::MotionProgram>& program,
                          const std::vector<AxisLabel>& labels) {
    axes_ = program ? std::clamp(program->axis_count, 0, cutcell::kMaxAxes) : 0;
    const int chosen = axis_->currentIndex();
    axis_->clear();
    for (int i = 0; i < cutcell::kMaxAxes; ++i) {
        const auto a = static_cast<size_t>(i);
        Row& r = rows_[a];
        const bool shown = i < axes_;
        linear_[a] = shown && program->axis_linear[a];
        for (QWidget* w : {static_cast<QWidget*>(r.name), static_cast<QWidget*>(r.commanded),
                           static_cast<QWidget*>(r.actual)})
            w->setVisible(shown);
        if (!shown) continue;
        // The unit follows the program's linear flag (it decides the conversion); the machine
        // UI's label gives the name the plots and forms use.
        if (a < labels.size() && !labels[a].name.isEmpty())
            names_[a] = labels[a].name;
        else
            names_[a] = program->axis_names[a].empty()
                            ? tr("axis %1").arg(i)
                            : QString::fromStdString(program->axis_names[a]);
        const QString range = tr("%1: %2 .. %3 %4")
                                  .arg(names_[a])
                                  .arg(shownNumber(toDisplay(i, program->min_position[i]), 1))
                                  .arg(shownNumber(toDisplay(i, program->max_position[i]), 1))
                                  .arg(unit(i));
        r.name->setText(QStringLiteral("%1 (%2)").arg(names_[a], unit(i)));
        r.name->setToolTip(range);
        axis_->addItem(names_[a]);
        axis_->setItemData(i, range, Qt::ToolTipRole);
    }
    axis_->setCurrentIndex(std::clamp(chosen, 0, std::max(0, axes_ - 1)));
    refreshEnabled();
}

QString DroPanel::axisName(int axis) const {
    return axis >= 0 && axis < axes_ ? names_[static_cast<size_t>(axis)] : QString();
}

QString DroPanel::unit(int axis) const {
    return axis >= 0 && axis < cutcell::kMaxAxes && linear_[static_cast<size_t>(axis)]
               ? QStringLiteral("mm")
               : QStringLiteral("deg");
}

double DroPanel::toDisplay(int axis, double v) const {
    return linear_[static_cast<size_t>(axis)] ? v : cutcell::rad2deg(v);
}

void DroPanel::setSample(const cutcell::TelemetrySample& s) {
    for (int i = 0; i < axes_; ++i) {
        const auto a = static_cast<size_t>(i);
        commanded_[a] = toDisplay(i, s.setpoint[i]);
        actual_[a] = toDisplay(i, s.actual[i]);
        // A fixed count of digits (the columns do not jitter), in the GUI language's form.
        rows_[a].commanded->setText(shownNumber(commanded_[a], kDecimals));
        rows_[a].actual->setText(shownNumber(actual_[a], kDecimals));
    }
}

double DroPanel::commanded(int axis) const {
    return commanded_[static_cast<size_t>(axis)];
}
double DroPanel::actual(int axis) const {
    return actual_[static_cast<size_t>(axis)];
}
QString DroPanel::commandedText(int axis) const {
    return rows_[static_cast<size_t>(axis)].commanded->text();
}
QString DroPanel::actualText(int axis) const {
    return rows_[static_cast<size_t>(axis)].actual->text();
}

void DroPanel::setState(EngineState state) {
    state_ = state;
    refreshEnabled();
}

void DroPanel::refreshEnabled() {
    // Ready: a new jog; Jogging: the held button must still get its release.
    const bool can = axes_ > 0 && (state_ == EngineState::Ready ||
                                   (continuousHeld_ && state_ == EngineState::Jogging));
    for (QPushButton* b : {minus_, plus_})
        if (!b->isDown()) b->setEnabled(can);
}

void DroPanel::setJogAxis(int axis) {
    axis_->setCurrentIndex(axis);
}

int DroPanel::jogAxis() const {
    return axis_->currentIndex();
}

void DroPanel::setJogStep(double step) {
    for (int k = 0; k < step_->count(); ++k)
        if (std::abs(step_->itemData(k).toDouble() - step) < 1e-12) step_->setCurrentIndex(k);
}

double DroPanel::jogStep() const {
    return step_->currentData().toDouble();
}

void DroPanel::onPressed(int direction) {
    const int axis = axis_->currentIndex();
    if (axis < 0 || axis >= axes_) return;
    const double step = jogStep();
    if (step <= 0) {
        continuousHeld_ = true;
        emit jogContinuousRequested(axis, direction);
        return;
    }
    const double engineStep = linear_[static_cast<size_t>(axis)] ? step : cutcell::deg2rad(step);
    emit jogRequested(axis, direction * engineStep);
}

void DroPanel::onReleased() {
    if (!continuousHeld_) return;
    continuousHeld_ = false;
    emit jogStopRequested();
    refreshEnabled();
}

} // namespace CutCell::ui
