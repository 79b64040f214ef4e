#include "ui/machines/profile_cutter/profile_cutter_form.h"
#include "core/machines/profile_cutter/profile_cutter_section.h"
#include "ui/forms/edited_spec.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::Job;

namespace {
// The edited job's section (a scratch one while another machine's job is open).
cutcell::ProfileCutterSpec& spec(Job& j) {
    return editedSpec<cutcell::ProfileCutterSpec>(j);
}
} // namespace

ProfileCutterForm::ProfileCutterForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* note = new QLabel(tr("2-axis NC profile cutter: the pipe turns in the chuck (A), the "
                               "torch rides the X carriage. Stepper axes behind a pulse card."),
                            this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);

    // One row per key: label, unit, decimals and range from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        addSectionRow(form, sectionField(cutcell::profileCutterFields(), key), &spec);
    };
    auto* a = new QGroupBox(tr("A axis (pipe turn)"), this);
    auto* fa = new QFormLayout(a);
    row(fa, "profile_cutter.steps_per_rev_a");
    row(fa, "profile_cutter.pulses_per_step_a");
    mainLayout()->addWidget(a);

    auto* x = new QGroupBox(tr("X axis (torch carriage)"), this);
    auto* fx = new QFormLayout(x);
    row(fx, "profile_cutter.mm_per_pulse_x");
    row(fx, "profile_cutter.x_travel_mm");
    mainLayout()->addWidget(x);

    auto* card = new QGroupBox(tr("Pulse card and torch"), this);
    auto* fc = new QFormLayout(card);
    row(fc, "profile_cutter.max_pulse_rate_hz");
    row(fc, "profile_cutter.pierce_s");
    mainLayout()->addWidget(card);

    auto* hole = new QGroupBox(tr("Hole in the main pipe"), this);
    auto* fh = new QFormLayout(hole);
    autoPosition_ = bindBool("profile_cutter.branch_position_auto", tr("middle of the main pipe"),
                             [](Job& j) -> bool& { return spec(j).branch_position_auto; });
    fh->addRow(tr("Branch position"), autoPosition_);
    // Its own row: the key is written only when not automatic (a custom field of the table).
    const auto& at =
        sectionField(cutcell::profileCutterFields(), "profile_cutter.branch_position_mm");
    position_ = bindDouble(at.key, at.decimals,
                           [](Job& j) -> double& { return spec(j).branch_position_mm; });
    addRow(fh, fieldLabel(at.label), position_, displayUnit(at.unit));
    connect(autoPosition_, &QCheckBox::toggled, position_,
            [this](bool on) { position_->setEnabled(!on); });
    mainLayout()->addWidget(hole);
    mainLayout()->addStretch(1);
}

void ProfileCutterForm::reloadExtra(const Job& job) {
    if (position_)
        position_->setEnabled(!editedSpec<cutcell::ProfileCutterSpec>(job).branch_position_auto);
}

} // namespace CutCell::ui
