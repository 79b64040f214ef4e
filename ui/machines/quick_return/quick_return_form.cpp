#include "ui/machines/quick_return/quick_return_form.h"

#include "core/machines/quick_return/quick_return_spec.h"
#include "ui/forms/edited_spec.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::Job;
using cutcell::QuickReturnSpec;

namespace {

QuickReturnSpec& spec(Job& j) {
    return CutCell::ui::editedSpec<QuickReturnSpec>(j); // a scratch spec for another machine's job
}
const QuickReturnSpec* specOf(const Job& j) {
    return j.machine_spec.as<QuickReturnSpec>();
}

} // namespace

QuickReturnMechanismForm::QuickReturnMechanismForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    auto* note = new QLabel(
        tr("Inverted Whitworth quick-return mechanism: the crank (O2, r2) drives the rocker "
           "through O3; the link r4 from B moves the slider with the tool on the line x = Dx. "
           "The crank must turn fully (the loop closes for every angle)."),
        this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);
    // One row per key, its label, unit and decimals from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        addSectionRow(form, sectionField(cutcell::quickReturnFields(), key), &spec);
    };

    auto* mech = new QGroupBox(tr("Mechanism (crank frame, y up)"), this);
    auto* fm = new QFormLayout(mech);
    row(fm, "mechanism.o3x_m");
    row(fm, "mechanism.o3y_m");
    row(fm, "mechanism.r2_m");
    row(fm, "mechanism.ab_m");
    row(fm, "mechanism.r4_m");
    row(fm, "mechanism.dx_m");
    row(fm, "mechanism.scale_offset_m");
    alsoMark("mechanism", mech);
    mainLayout()->addWidget(mech);

    auto* drive = new QGroupBox(tr("Slider and crank motor"), this);
    auto* fd = new QFormLayout(drive);
    row(fd, "slider.mass_kg");
    row(fd, "slider.scale_resolution_m");
    row(fd, "crank_motor.inertia_kg_m2");
    row(fd, "crank_motor.rocker_inertia_kg_m2");
    row(fd, "crank_motor.viscous_nm_s_rad");
    row(fd, "crank_motor.coulomb_nm");
    row(fd, "crank_motor.torque_limit_nm");
    mainLayout()->addWidget(drive);

    auto* cut = new QGroupBox(tr("Cutting stroke (experiment 2)"), this);
    auto* fc = new QFormLayout(cut);
    row(fc, "cut.workpiece_length_m");
    row(fc, "cut.stroke_length_m");
    row(fc, "cut.velocity_m_s");
    row(fc, "cut.contact_force_n");
    row(fc, "cut.strokes");
    row(fc, "cut.return_torque_1_nm");
    row(fc, "cut.return_torque_2_nm");
    mainLayout()->addWidget(cut);

    auto* track =
        new QGroupBox(tr("Tracking y_d = offset + amplitude sin(ω t) (experiment 1)"), this);
    auto* ft = new QFormLayout(track);
    row(ft, "tracking.offset_m");
    row(ft, "tracking.amplitude_m");
    row(ft, "tracking.omega_rad_s");
    row(ft, "tracking.duration_s");
    row(ft, "tracking.mse_window_s");
    row(ft, "tracking.mse_scale");
    mainLayout()->addWidget(track);
    mainLayout()->addStretch(1);
}

QuickReturnControllerForm::QuickReturnControllerForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    using cutcell::quick_return::ControllerKind;
    using cutcell::quick_return::Experiment;
    // One row per key, its label, unit and decimals from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        addSectionRow(form, sectionField(cutcell::quickReturnFields(), key), &spec);
    };

    auto* run = new QGroupBox(tr("Experiment and control law"), this);
    auto* fr = new QFormLayout(run);
    addRow(fr, tr("Experiment"),
           bindChoice(
               "control.experiment",
               {tr("Cutting (constant velocity over the workpiece)"),
                tr("Tracking y_d = offset + amplitude sin(ω t)")},
               [](const Job& j) {
                   const QuickReturnSpec* s = specOf(j);
                   return s && s->experiment == Experiment::Tracking ? 1 : 0;
               },
               [](Job& j, int i) {
                   spec(j).experiment = i == 1 ? Experiment::Tracking : Experiment::Cutting;
               }),
           "");
    QComboBox* controller = nullptr;
    addRow(fr, tr("Controller"),
           controller = bindChoice(
               "control.controller",
               {tr("FFC (feed-forward + PD)"), tr("LQT"), tr("SMC"),
                tr("OSMC (optimal sliding mode)")},
               [](const Job& j) {
                   const QuickReturnSpec* s = specOf(j);
                   return s ? static_cast<int>(s->controller) : 3;
               },
               [](Job& j, int i) { spec(j).controller = static_cast<ControllerKind>(i); }),
           "");
    addRow(fr, tr("Jacobian"),
           bindChoice(
               "control.jacobian", {tr("Compensator (Eq. 33, K_ρ)"), tr("Exact ρ_y of the model")},
               [](const Job& j) {
                   const QuickReturnSpec* s = specOf(j);
                   return s && !s->jacobian_compensator ? 1 : 0;
               },
               [](Job& j, int i) { spec(j).jacobian_compensator = i == 0; }),
           "");
    row(fr, "control.sample_time_s");
    row(fr, "control.k_rho_m");
    row(fr, "control.model_mass_kg");
    row(fr, "control.disturbance_nm");
    row(fr, "control.disturbance_hz");
    mainLayout()->addWidget(run);

    auto* ffc = new QGroupBox(tr("FFC (Eq. 37-38)"), this);
    auto* ff = new QFormLayout(ffc);
    row(ff, "control.ffc.wn2");
    row(ff, "control.ffc.xi");
    auto* lqt = new QGroupBox(tr("LQT (Eq. 39): Q = diag(q1, q2), R"), this);
    auto* fl = new QFormLayout(lqt);
    row(fl, "control.lqt.q1");
    row(fl, "control.lqt.q2");
    row(fl, "control.lqt.r");
    auto* smc = new QGroupBox(tr("SMC: s = c e + ė, boundary layer φ"), this);
    auto* fs = new QFormLayout(smc);
    row(fs, "control.smc.c");
    row(fs, "control.smc.eta");
    row(fs, "control.smc.phi");
    auto* osmc = new QGroupBox(tr("OSMC (Eq. 20-33): Q = [q11 q12; q12 q22], λ, k1, k2"), this);
    auto* fo = new QFormLayout(osmc);
    row(fo, "control.osmc.q11");
    row(fo, "control.osmc.q12");
    row(fo, "control.osmc.q22");
    row(fo, "control.osmc.lambda");
    row(fo, "control.osmc.k1");
    row(fo, "control.osmc.k2");
    gains_[0] = ffc;
    gains_[1] = lqt;
    gains_[2] = smc;
    gains_[3] = osmc;
    for (QGroupBox* g : gains_)
        mainLayout()->addWidget(g);
    connect(controller, &QComboBox::currentIndexChanged, this, [this](int chosen) {
        for (int i = 0; i < 4; ++i)
            gains_[i]->setEnabled(i == chosen);
    });
    mainLayout()->addStretch(1);
}

void QuickReturnControllerForm::reloadExtra(const Job& job) {
    const QuickReturnSpec* s = specOf(job);
    const int chosen = s ? static_cast<int>(s->controller) : -1;
    for (int i = 0; i < 4; ++i)
        if (gains_[i]) gains_[i]->setEnabled(i == chosen);
}

} // namespace CutCell::ui
