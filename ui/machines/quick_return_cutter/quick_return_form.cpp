#include "ui/machines/quick_return_cutter/quick_return_form.h"

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
    const auto dbl = [this](const char* key, int decimals, auto member) {
        return bindDouble(key, decimals, [member](Job& j) -> double& { return member(spec(j)); });
    };

    auto* mech = new QGroupBox(tr("Mechanism (crank frame, y up)"), this);
    auto* fm = new QFormLayout(mech);
    addRow(fm, tr("Rocker pivot O3x"),
           dbl("mechanism.o3x_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.o3x; }),
           "m");
    addRow(fm, tr("Rocker pivot O3y"),
           dbl("mechanism.o3y_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.o3y; }),
           "m");
    addRow(fm, tr("Crank r2"),
           dbl("mechanism.r2_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.r2; }), "m");
    addRow(fm, tr("A to B on the rocker (AB)"),
           dbl("mechanism.ab_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.ab; }), "m");
    addRow(fm, tr("Link r4"),
           dbl("mechanism.r4_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.r4; }), "m");
    addRow(fm, tr("Slider line Dx"),
           dbl("mechanism.dx_m", 4, [](QuickReturnSpec& s) -> double& { return s.dims.dx; }), "m");
    addRow(fm, tr("Scale offset"),
           dbl("mechanism.scale_offset_m", 4,
               [](QuickReturnSpec& s) -> double& { return s.dims.scale_offset; }),
           "m");
    alsoMark("mechanism", mech);
    mainLayout()->addWidget(mech);

    auto* drive = new QGroupBox(tr("Slider and crank motor"), this);
    auto* fd = new QFormLayout(drive);
    addRow(
        fd, tr("Slider mass m5"),
        dbl("slider.mass_kg", 3, [](QuickReturnSpec& s) -> double& { return s.plant.slider_mass; }),
        "kg");
    addRow(fd, tr("Scale resolution"),
           dbl("slider.scale_resolution_m", 7,
               [](QuickReturnSpec& s) -> double& { return s.scale_resolution; }),
           "m");
    addRow(fd, tr("Crank inertia"),
           dbl("crank_motor.inertia_kg_m2", 5,
               [](QuickReturnSpec& s) -> double& { return s.plant.crank_inertia; }),
           "kg m²");
    addRow(fd, tr("Rocker inertia"),
           dbl("crank_motor.rocker_inertia_kg_m2", 5,
               [](QuickReturnSpec& s) -> double& { return s.plant.rocker_inertia; }),
           "kg m²");
    addRow(fd, tr("Viscous friction"),
           dbl("crank_motor.viscous_nm_s_rad", 4,
               [](QuickReturnSpec& s) -> double& { return s.plant.viscous; }),
           "N m s/rad");
    addRow(fd, tr("Coulomb friction"),
           dbl("crank_motor.coulomb_nm", 3,
               [](QuickReturnSpec& s) -> double& { return s.plant.coulomb; }),
           "N m");
    addRow(fd, tr("Torque limit"),
           dbl("crank_motor.torque_limit_nm", 2,
               [](QuickReturnSpec& s) -> double& { return s.plant.torque_limit; }),
           "N m");
    mainLayout()->addWidget(drive);

    auto* cut = new QGroupBox(tr("Cutting stroke (experiment 2)"), this);
    auto* fc = new QFormLayout(cut);
    addRow(fc, tr("Workpiece length L_d"),
           dbl("cut.workpiece_length_m", 4,
               [](QuickReturnSpec& s) -> double& { return s.workpiece_length; }),
           "m");
    addRow(fc, tr("Stroke L_c"),
           dbl("cut.stroke_length_m", 4,
               [](QuickReturnSpec& s) -> double& { return s.stroke_length; }),
           "m");
    addRow(fc, tr("Cutting velocity v"),
           dbl("cut.velocity_m_s", 4, [](QuickReturnSpec& s) -> double& { return s.velocity; }),
           "m/s");
    addRow(fc, tr("Contact force"),
           dbl("cut.contact_force_n", 1,
               [](QuickReturnSpec& s) -> double& { return s.plant.contact_force; }),
           "N");
    addRow(fc, tr("Strokes"),
           bindInt("cut.strokes", [](Job& j) -> int& { return spec(j).strokes; }), "strokes");
    addRow(fc, tr("Return torque, first half"),
           dbl("cut.return_torque_1_nm", 2,
               [](QuickReturnSpec& s) -> double& { return s.return_torque_1; }),
           "N m");
    addRow(fc, tr("Return torque, second half"),
           dbl("cut.return_torque_2_nm", 2,
               [](QuickReturnSpec& s) -> double& { return s.return_torque_2; }),
           "N m");
    mainLayout()->addWidget(cut);

    auto* track =
        new QGroupBox(tr("Tracking y_d = offset + amplitude sin(ω t) (experiment 1)"), this);
    auto* ft = new QFormLayout(track);
    addRow(
        ft, tr("Offset"),
        dbl("tracking.offset_m", 4, [](QuickReturnSpec& s) -> double& { return s.track_offset; }),
        "m");
    addRow(ft, tr("Amplitude"),
           dbl("tracking.amplitude_m", 4,
               [](QuickReturnSpec& s) -> double& { return s.track_amplitude; }),
           "m");
    addRow(
        ft, tr("ω"),
        dbl("tracking.omega_rad_s", 4, [](QuickReturnSpec& s) -> double& { return s.track_omega; }),
        "rad/s");
    addRow(ft, tr("Duration"),
           dbl("tracking.duration_s", 2,
               [](QuickReturnSpec& s) -> double& { return s.track_duration; }),
           "s");
    addRow(
        ft, tr("MSE window"),
        dbl("tracking.mse_window_s", 2, [](QuickReturnSpec& s) -> double& { return s.mse_window; }),
        "s");
    addRow(ft, tr("MSE scale L"),
           dbl("tracking.mse_scale", 2, [](QuickReturnSpec& s) -> double& { return s.mse_scale; }),
           "");
    mainLayout()->addWidget(track);
    mainLayout()->addStretch(1);
}

QuickReturnControllerForm::QuickReturnControllerForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    using cutcell::quick_return::ControllerKind;
    using cutcell::quick_return::Experiment;
    const auto dbl = [this](const char* key, int decimals, auto member) {
        return bindDouble(key, decimals, [member](Job& j) -> double& { return member(spec(j)); });
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
    addRow(fr, tr("Sample time"),
           dbl("control.sample_time_s", 5,
               [](QuickReturnSpec& s) -> double& { return s.sample_time; }),
           "s");
    addRow(fr, tr("K_ρ"),
           dbl("control.k_rho_m", 4, [](QuickReturnSpec& s) -> double& { return s.k_rho; }),
           "m/rad");
    addRow(fr, tr("Model slider mass"),
           dbl("control.model_mass_kg", 3,
               [](QuickReturnSpec& s) -> double& { return s.gains.model_mass; }),
           "kg");
    addRow(fr, tr("Disturbance amplitude"),
           dbl("control.disturbance_nm", 3,
               [](QuickReturnSpec& s) -> double& { return s.disturbance_amplitude; }),
           "N m");
    addRow(fr, tr("Disturbance frequency"),
           dbl("control.disturbance_hz", 2,
               [](QuickReturnSpec& s) -> double& { return s.disturbance_hz; }),
           "Hz");
    mainLayout()->addWidget(run);

    auto* ffc = new QGroupBox(tr("FFC (Eq. 37-38)"), this);
    auto* ff = new QFormLayout(ffc);
    addRow(ff, tr("ω_n²"),
           dbl("control.ffc.wn2", 1, [](QuickReturnSpec& s) -> double& { return s.gains.ffc_wn2; }),
           "1/s²");
    addRow(ff, tr("ξ"),
           dbl("control.ffc.xi", 3, [](QuickReturnSpec& s) -> double& { return s.gains.ffc_xi; }),
           "1");
    auto* lqt = new QGroupBox(tr("LQT (Eq. 39): Q = diag(q1, q2), R"), this);
    auto* fl = new QFormLayout(lqt);
    addRow(fl, tr("q1"),
           dbl("control.lqt.q1", 1, [](QuickReturnSpec& s) -> double& { return s.gains.lqt_q1; }),
           "1");
    addRow(fl, tr("q2"),
           dbl("control.lqt.q2", 1, [](QuickReturnSpec& s) -> double& { return s.gains.lqt_q2; }),
           "1");
    addRow(fl, tr("R"),
           dbl("control.lqt.r", 4, [](QuickReturnSpec& s) -> double& { return s.gains.lqt_r; }),
           "1");
    auto* smc = new QGroupBox(tr("SMC: s = c e + ė, boundary layer φ"), this);
    auto* fs = new QFormLayout(smc);
    addRow(fs, tr("c"),
           dbl("control.smc.c", 2, [](QuickReturnSpec& s) -> double& { return s.gains.smc_c; }),
           "1/s");
    addRow(fs, tr("η"),
           dbl("control.smc.eta", 2, [](QuickReturnSpec& s) -> double& { return s.gains.smc_eta; }),
           "N");
    addRow(fs, tr("φ"),
           dbl("control.smc.phi", 4, [](QuickReturnSpec& s) -> double& { return s.gains.smc_phi; }),
           "m/s");
    auto* osmc = new QGroupBox(tr("OSMC (Eq. 20-33): Q = [q11 q12; q12 q22], λ, k1, k2"), this);
    auto* fo = new QFormLayout(osmc);
    addRow(
        fo, tr("q11"),
        dbl("control.osmc.q11", 2, [](QuickReturnSpec& s) -> double& { return s.gains.osmc_q11; }),
        "1");
    addRow(
        fo, tr("q12"),
        dbl("control.osmc.q12", 2, [](QuickReturnSpec& s) -> double& { return s.gains.osmc_q12; }),
        "1");
    addRow(
        fo, tr("q22"),
        dbl("control.osmc.q22", 2, [](QuickReturnSpec& s) -> double& { return s.gains.osmc_q22; }),
        "1");
    addRow(fo, tr("λ"),
           dbl("control.osmc.lambda", 2,
               [](QuickReturnSpec& s) -> double& { return s.gains.osmc_lambda; }),
           "1/s");
    addRow(fo, tr("k1"),
           dbl("control.osmc.k1", 2, [](QuickReturnSpec& s) -> double& { return s.gains.osmc_k1; }),
           "1/s");
    addRow(fo, tr("k2"),
           dbl("control.osmc.k2", 3, [](QuickReturnSpec& s) -> double& { return s.gains.osmc_k2; }),
           "N");
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
