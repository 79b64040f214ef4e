// Reading, writing and checking the quick-return cutter's `machine` section.
#include "core/common/c_format.h"
#include "core/job/field_table.h"
#include "core/job/issue_checker.h"
#include "core/machines/quick_return/quick_return_spec.h"

#include <cmath>
#include <stdexcept>

namespace cutcell {

using namespace quick_return;

const QuickReturnSpec& quickReturnSpec(const Job& job) {
    const QuickReturnSpec* s = job.machine_spec.as<QuickReturnSpec>();
    if (!s) throw std::invalid_argument("the job holds no quick-return cutter section");
    return *s;
}

namespace {

using Field = SectionField<QuickReturnSpec>;
using S = QuickReturnSpec;
constexpr FieldCheck kRange = FieldCheck::Range, kPositive = FieldCheck::Positive;

// Every key of the section, once: path, unit, label, physical range, decimals, member. The file
// is written in this order.
// One entry per key, kept as a table.
// clang-format off
const Field kFields[] = {
    {.key = "mechanism.o3x_m", .unit = "m", .label = "Rocker pivot O3x", .lo = -10, .hi = 10,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.dims.o3x; }},
    {.key = "mechanism.o3y_m", .unit = "m", .label = "Rocker pivot O3y", .lo = -10, .hi = 10,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.dims.o3y; }},
    {.key = "mechanism.r2_m", .unit = "m", .label = "Crank r2", .lo = 1e-3, .hi = 10,
     .check = kPositive, .decimals = 4, .number = [](S& s) -> double& { return s.dims.r2; }},
    {.key = "mechanism.ab_m", .unit = "m", .label = "A to B on the rocker (AB)", .lo = 0,
     .hi = 10, .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.dims.ab; }},
    {.key = "mechanism.r4_m", .unit = "m", .label = "Link r4", .lo = 1e-3, .hi = 10,
     .check = kPositive, .decimals = 4, .number = [](S& s) -> double& { return s.dims.r4; }},
    {.key = "mechanism.dx_m", .unit = "m", .label = "Slider line Dx", .lo = -10, .hi = 10,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.dims.dx; }},
    {.key = "mechanism.scale_offset_m", .unit = "m", .label = "Scale offset", .lo = -10,
     .hi = 10, .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.dims.scale_offset; }},
    {.key = "slider.mass_kg", .unit = "kg", .label = "Slider mass m5", .lo = 1e-4, .hi = 1000,
     .check = kPositive, .decimals = 3,
     .number = [](S& s) -> double& { return s.plant.slider_mass; }},
    {.key = "slider.scale_resolution_m", .unit = "m", .label = "Scale resolution", .lo = 0,
     .hi = 0.01, .check = kRange, .decimals = 7,
     .number = [](S& s) -> double& { return s.scale_resolution; }},
    {.key = "crank_motor.inertia_kg_m2", .unit = "kg m^2", .label = "Crank inertia", .lo = 1e-6,
     .hi = 100, .check = kPositive, .decimals = 5,
     .number = [](S& s) -> double& { return s.plant.crank_inertia; }},
    {.key = "crank_motor.rocker_inertia_kg_m2", .unit = "kg m^2", .label = "Rocker inertia",
     .lo = 0, .hi = 100, .check = kRange, .decimals = 5,
     .number = [](S& s) -> double& { return s.plant.rocker_inertia; }},
    {.key = "crank_motor.viscous_nm_s_rad", .unit = "N m s/rad", .label = "Viscous friction",
     .lo = 0, .hi = 1000, .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.plant.viscous; }},
    {.key = "crank_motor.coulomb_nm", .unit = "N m", .label = "Coulomb friction", .lo = 0,
     .hi = 1000, .check = kRange, .decimals = 3,
     .number = [](S& s) -> double& { return s.plant.coulomb; }},
    {.key = "crank_motor.torque_limit_nm", .unit = "N m", .label = "Torque limit", .lo = 1e-3,
     .hi = 10000, .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.plant.torque_limit; }},
    // The stroke's figures are checked against the mechanism in validateQuickReturn() too;
    // these ranges hold whatever the mechanism (the mechanism's links are at most 10 m).
    {.key = "cut.workpiece_length_m", .unit = "m", .label = "Workpiece length L_d", .lo = 1e-3,
     .hi = 20, .check = kPositive, .decimals = 4,
     .number = [](S& s) -> double& { return s.workpiece_length; }},
    {.key = "cut.stroke_length_m", .unit = "m", .label = "Stroke L_c", .lo = 1e-3, .hi = 20,
     .check = kPositive, .decimals = 4, .number = [](S& s) -> double& { return s.stroke_length; }},
    // The cut runs downwards: negative, at least 0.1 mm/s.
    {.key = "cut.velocity_m_s", .unit = "m/s", .label = "Cutting velocity v", .lo = -10,
     .hi = -1e-4, .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.velocity; }},
    {.key = "cut.contact_force_n", .unit = "N", .label = "Contact force", .lo = 0, .hi = 1e5,
     .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.plant.contact_force; }},
    {.key = "cut.strokes", .unit = "strokes", .label = "Strokes", .lo = 1, .hi = 1000,
     .check = kRange, .integer = [](S& s) -> int& { return s.strokes; }},
    {.key = "cut.return_torque_1_nm", .unit = "N m", .label = "Return torque, first half",
     .decimals = 2, .number = [](S& s) -> double& { return s.return_torque_1; }},
    {.key = "cut.return_torque_2_nm", .unit = "N m", .label = "Return torque, second half",
     .decimals = 2, .number = [](S& s) -> double& { return s.return_torque_2; }},
    // Inside the stroke (validateQuickReturn()); within the mechanism's reach whatever it is.
    {.key = "tracking.offset_m", .unit = "m", .label = "Offset", .lo = -20, .hi = 20,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.track_offset; }},
    {.key = "tracking.amplitude_m", .unit = "m", .label = "Amplitude", .lo = -10, .hi = 10,
     .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.track_amplitude; }},
    {.key = "tracking.omega_rad_s", .unit = "rad/s", .label = "ω", .lo = 0, .hi = 100,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.track_omega; }},
    {.key = "tracking.duration_s", .unit = "s", .label = "Duration", .lo = 0.1, .hi = 600,
     .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.track_duration; }},
    {.key = "tracking.mse_window_s", .unit = "s", .label = "MSE window", .decimals = 2,
     .number = [](S& s) -> double& { return s.mse_window; }},
    {.key = "tracking.mse_scale", .unit = "1", .label = "MSE scale L", .lo = 1e-6, .hi = 1e6,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.mse_scale; }},
    {.key = "control.experiment", .unit = "", .label = "Experiment",
     .choices = {"cutting", "tracking"},
     .getChoice = [](const S& s) { return s.experiment == Experiment::Cutting ? 0 : 1; },
     .setChoice =
         [](S& s, int i) { s.experiment = i == 0 ? Experiment::Cutting : Experiment::Tracking; }},
    {.key = "control.controller", .unit = "", .label = "Controller",
     .choices = {"ffc", "lqt", "smc", "osmc"},
     .getChoice = [](const S& s) { return static_cast<int>(s.controller); },
     .setChoice = [](S& s, int i) { s.controller = static_cast<ControllerKind>(i); }},
    {.key = "control.sample_time_s", .unit = "s", .label = "Sample time", .lo = 1e-5,
     .hi = 0.05, .check = kPositive, .decimals = 5,
     .number = [](S& s) -> double& { return s.sample_time; }},
    {.key = "control.jacobian", .unit = "", .label = "Jacobian",
     .choices = {"compensator", "exact"},
     .getChoice = [](const S& s) { return s.jacobian_compensator ? 0 : 1; },
     .setChoice = [](S& s, int i) { s.jacobian_compensator = i == 0; }},
    {.key = "control.k_rho_m", .unit = "m/rad", .label = "K_ρ", .lo = 1e-4, .hi = 10,
     .check = kRange, .decimals = 4, .number = [](S& s) -> double& { return s.k_rho; }},
    {.key = "control.model_mass_kg", .unit = "kg", .label = "Model slider mass", .lo = 1e-4,
     .hi = 1000, .check = kPositive, .decimals = 3,
     .number = [](S& s) -> double& { return s.gains.model_mass; }},
    {.key = "control.disturbance_nm", .unit = "N m", .label = "Disturbance amplitude", .lo = 0,
     .hi = 1000, .check = kRange, .decimals = 3,
     .number = [](S& s) -> double& { return s.disturbance_amplitude; }},
    {.key = "control.disturbance_hz", .unit = "Hz", .label = "Disturbance frequency", .lo = 0,
     .hi = 1000, .check = kRange, .decimals = 2,
     .number = [](S& s) -> double& { return s.disturbance_hz; }},
    {.key = "control.ffc.wn2", .unit = "1/s^2", .label = "ω_n²", .lo = 1e-6, .hi = 1e8,
     .check = kPositive, .decimals = 1, .number = [](S& s) -> double& { return s.gains.ffc_wn2; }},
    {.key = "control.ffc.xi", .unit = "1", .label = "ξ", .lo = 1e-6, .hi = 100,
     .check = kPositive, .decimals = 3, .number = [](S& s) -> double& { return s.gains.ffc_xi; }},
    {.key = "control.lqt.q1", .unit = "1", .label = "q1", .lo = 0, .hi = 1e12, .check = kRange,
     .decimals = 1, .number = [](S& s) -> double& { return s.gains.lqt_q1; }},
    {.key = "control.lqt.q2", .unit = "1", .label = "q2", .lo = 0, .hi = 1e12, .check = kRange,
     .decimals = 1, .number = [](S& s) -> double& { return s.gains.lqt_q2; }},
    {.key = "control.lqt.r", .unit = "1", .label = "R", .lo = 1e-12, .hi = 1e12,
     .check = kPositive, .decimals = 4, .number = [](S& s) -> double& { return s.gains.lqt_r; }},
    {.key = "control.smc.c", .unit = "1/s", .label = "c", .lo = 1e-6, .hi = 1e6,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.gains.smc_c; }},
    {.key = "control.smc.eta", .unit = "N", .label = "η", .lo = 0, .hi = 1e6, .check = kRange,
     .decimals = 2, .number = [](S& s) -> double& { return s.gains.smc_eta; }},
    {.key = "control.smc.phi", .unit = "m/s", .label = "φ", .lo = 1e-9,
     .hi = 1e3, .check = kPositive, .decimals = 4,
     .number = [](S& s) -> double& { return s.gains.smc_phi; }},
    // Q must be positive definite: checked as a whole in validateQuickReturn(). Its entries on
    // q22's scale, so that q11 q22 - q12^2 stays finite (1e300 passed as infinity > 0).
    {.key = "control.osmc.q11", .unit = "1", .label = "q11", .lo = 1e-12, .hi = 1e12,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.gains.osmc_q11; }},
    {.key = "control.osmc.q12", .unit = "1", .label = "q12", .lo = -1e12, .hi = 1e12,
     .check = kRange, .decimals = 2, .number = [](S& s) -> double& { return s.gains.osmc_q12; }},
    {.key = "control.osmc.q22", .unit = "1", .label = "q22", .lo = 1e-12, .hi = 1e12,
     .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.gains.osmc_q22; }},
    {.key = "control.osmc.lambda", .unit = "1/s", .label = "λ", .lo = 1e-6, .hi = 1e6,
     .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.gains.osmc_lambda; }},
    {.key = "control.osmc.k1", .unit = "1/s", .label = "k1", .lo = 1e-6, .hi = 1e8,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.gains.osmc_k1; }},
    {.key = "control.osmc.k2", .unit = "N", .label = "k2", .lo = 0, .hi = 1e6, .check = kRange,
     .decimals = 3, .number = [](S& s) -> double& { return s.gains.osmc_k2; }},
};
// clang-format on

} // namespace

std::span<const SectionField<QuickReturnSpec>> quickReturnFields() {
    return kFields;
}

QuickReturnSpec readQuickReturnSection(const json::Value& section) {
    QuickReturnSpec s = readSectionFields(section, quickReturnFields());
    s.gains.gravity = s.plant.gravity;
    return s;
}

json::Value writeQuickReturnSection(const QuickReturnSpec& s, const std::string& kind) {
    json::Object out{{"kind", kind}};
    for (auto& member : writeFields(quickReturnFields(), s))
        out.push_back(std::move(member));
    return out;
}

std::vector<JobIssue> validateQuickReturn(const QuickReturnSpec& s) {
    IssueChecker c;
    const WhitworthDims& d = s.dims;
    checkFields(c, quickReturnFields(), s);
    // The checks whose limits are other values of the section.
    c.range("cut.return_torque_1_nm", s.return_torque_1, 0, s.plant.torque_limit, "N m");
    c.range("cut.return_torque_2_nm", s.return_torque_2, -s.plant.torque_limit, 0, "N m");
    c.positive("tracking.mse_window_s", s.mse_window, 1e-3, s.track_duration, "s");
    const ControllerParams& g = s.gains;
    if (!c.has("control.osmc.q11") && !c.has("control.osmc.q12") &&
        !(g.osmc_q11 * g.osmc_q22 - g.osmc_q12 * g.osmc_q12 > 0))
        c.add("control.osmc.q11",
              messageC("control.osmc: Q = [q11 q12; q12 q22] = [%.6g %.6g; %.6g %.6g] must be "
                       "positive definite",
                       g.osmc_q11, g.osmc_q12, g.osmc_q12, g.osmc_q22));
    if (!c.issues.empty()) return c.issues;

    // The loop must close for every crank angle (the crank turns fully).
    double margin = 0;
    const std::vector<AngleRange> open = openRanges(d, &margin);
    if (!open.empty()) {
        c.add("mechanism",
              messageC("mechanism: the loop (B.1) does not close for crank angles q in %s: "
                       "|Dx - O3x - (r3 + AB) cos(theta3)| > r4 = %.6g m there, so the crank "
                       "cannot turn fully",
                       describeRanges(open).c_str(), d.r4));
        return c.issues;
    }
    if (margin < 0.02) {
        c.add("mechanism.r4_m", messageC("mechanism.r4_m = %.6g m: the link comes within %.4f "
                                         "of horizontal (1 - |cos theta4|), a singular pose; "
                                         "the limit is 0.02",
                                         d.r4, margin));
        return c.issues;
    }
    const StrokeInfo st = strokeInfo(d);
    if (!st.ok) {
        c.add("mechanism",
              messageC("mechanism: no two singular crank angles (rho_y = 0) were found"));
        return c.issues;
    }
    if (std::fabs(st.stroke - s.stroke_length) > 0.002)
        c.add("cut.stroke_length_m",
              messageC("cut.stroke_length_m = %.6g m does not match the mechanism's stroke "
                       "y_min - y_max = %.4f m (tolerance 0.002 m)",
                       s.stroke_length, st.stroke));
    if (!(s.workpiece_length > 0 && s.workpiece_length < st.stroke))
        c.add("cut.workpiece_length_m",
              messageC("cut.workpiece_length_m = %.6g m must be in (0, %.4f) m (the stroke L_c)",
                       s.workpiece_length, st.stroke));
    if (!(s.velocity < 0 && s.velocity >= -10))
        c.add("cut.velocity_m_s",
              messageC("cut.velocity_m_s = %.6g m/s is outside [-10, 0) m/s (the cut runs "
                       "downwards)",
                       s.velocity));
    const double lo = s.track_offset - std::fabs(s.track_amplitude);
    const double hi = s.track_offset + std::fabs(s.track_amplitude);
    if (!(lo > st.y_bottom && hi < st.y_top))
        c.add("tracking.amplitude_m",
              messageC("tracking.amplitude_m = %.6g m about tracking.offset_m = %.6g m: the "
                       "reference spans [%.6g, %.6g] m; it must stay inside the stroke (%.4f, "
                       "%.4f) m",
                       s.track_amplitude, s.track_offset, lo, hi, st.y_bottom, st.y_top));
    return c.issues;
}

Outcome buildSetup(const QuickReturnSpec& s, ExperimentSetup* setup) {
    ExperimentSetup e;
    e.law.dims = s.dims;
    e.law.stroke = strokeInfo(s.dims);
    if (!e.law.stroke.ok)
        return Outcome::refuse(
            messageC("the mechanism has no full crank turn with two singular points"));
    e.law.profile =
        algorithm1(e.law.stroke.y_top, e.law.stroke.y_bottom, s.workpiece_length, s.velocity);
    if (!e.law.profile.ok)
        return Outcome::refuse(messageC("Algorithm 1: %s", e.law.profile.problem));
    e.law.experiment = s.experiment;
    e.law.controller = s.controller;
    e.law.gains = s.gains;
    e.law.jacobian_compensator = s.jacobian_compensator;
    e.law.k_rho = s.k_rho;
    e.law.track_offset = s.track_offset;
    e.law.track_amplitude = s.track_amplitude;
    e.law.track_omega = s.track_omega;
    e.law.track_duration = s.track_duration;
    e.law.strokes = s.strokes;
    e.law.return_torque_1 = s.return_torque_1;
    e.law.return_torque_2 = s.return_torque_2;
    e.law.torque_limit = s.plant.torque_limit;
    e.law.model = s.plant; // the hold's nominal model
    e.plant = s.plant;
    e.plant.cut_low = std::min(e.law.profile.y_a, e.law.profile.y_b);
    e.plant.cut_high = std::max(e.law.profile.y_a, e.law.profile.y_b);
    e.sample_time = s.sample_time;
    e.scale_resolution = s.scale_resolution;
    e.disturbance_amplitude = s.disturbance_amplitude;
    e.disturbance_hz = s.disturbance_hz;
    e.mse_window = s.mse_window;
    e.mse_scale = s.mse_scale;
    *setup = e;
    return Outcome::done();
}

} // namespace cutcell
