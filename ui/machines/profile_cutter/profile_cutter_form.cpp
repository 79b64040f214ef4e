#include "ui/machines/profile_cutter/profile_cutter_form.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::Job;

ProfileCutterForm::ProfileCutterForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* note = new QLabel(tr("2-axis NC profile cutter: the pipe turns in the chuck (A), the "
                               "torch rides the X carriage. Stepper axes behind a pulse card."),
                            this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);

    auto* a = new QGroupBox(tr("A axis (pipe turn)"), this);
    auto* fa = new QFormLayout(a);
    addRow(fa, tr("Steps per revolution (n)"),
           bindInt("profile_cutter.steps_per_rev_a",
                   [](Job& j) -> int& { return j.profile_cutter.steps_per_rev_a; }),
           tr("steps/rev"));
    addRow(fa, tr("Pulses per step"),
           bindInt("profile_cutter.pulses_per_step_a",
                   [](Job& j) -> int& { return j.profile_cutter.pulses_per_step_a; }),
           tr("pulses/step"));
    mainLayout()->addWidget(a);

    auto* x = new QGroupBox(tr("X axis (torch carriage)"), this);
    auto* fx = new QFormLayout(x);
    addRow(fx, tr("Travel per pulse"),
           bindDouble("profile_cutter.mm_per_pulse_x", 5,
                      [](Job& j) -> double& { return j.profile_cutter.mm_per_pulse_x; }),
           tr("mm/pulse"));
    addRow(fx, tr("Carriage travel"),
           bindDouble("profile_cutter.x_travel_mm", 1,
                      [](Job& j) -> double& { return j.profile_cutter.x_travel_mm; }),
           "mm");
    mainLayout()->addWidget(x);

    auto* card = new QGroupBox(tr("Pulse card and torch"), this);
    auto* fc = new QFormLayout(card);
    addRow(fc, tr("Max. pulse rate per axis"),
           bindDouble("profile_cutter.max_pulse_rate_hz", 0,
                      [](Job& j) -> double& { return j.profile_cutter.max_pulse_rate_hz; }),
           "Hz");
    addRow(fc, tr("Pierce dwell"),
           bindDouble("profile_cutter.pierce_s", 2,
                      [](Job& j) -> double& { return j.profile_cutter.pierce_s; }),
           "s");
    mainLayout()->addWidget(card);

    auto* hole = new QGroupBox(tr("Hole in the main pipe"), this);
    auto* fh = new QFormLayout(hole);
    autoPosition_ = bindBool("profile_cutter.branch_position_auto", tr("middle of the main pipe"),
                             [](Job& j) -> bool& { return j.profile_cutter.branch_position_auto; });
    fh->addRow(tr("Branch position"), autoPosition_);
    position_ = bindDouble("profile_cutter.branch_position_mm", 1,
                           [](Job& j) -> double& { return j.profile_cutter.branch_position_mm; });
    addRow(fh, tr("Branch axis at X (S)"), position_, "mm");
    connect(autoPosition_, &QCheckBox::toggled, position_,
            [this](bool on) { position_->setEnabled(!on); });
    mainLayout()->addWidget(hole);
    mainLayout()->addStretch(1);
}

void ProfileCutterForm::reloadExtra(const Job& job) {
    if (position_) position_->setEnabled(!job.profile_cutter.branch_position_auto);
}

} // namespace CutCell::ui
