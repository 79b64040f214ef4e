// Reading, writing and checking the quick-return cutter's `machine` section.
#include "core/common/c_format.h"
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

QuickReturnSpec readQuickReturnSection(const json::Value& section) {
    SectionReader m(section, "machine");
    m.get("kind");
    QuickReturnSpec s;
    if (m.has("mechanism")) {
        SectionReader r = m.child("mechanism");
        WhitworthDims& d = s.dims;
        d.o3x = r.number("o3x_m", "m", d.o3x);
        d.o3y = r.number("o3y_m", "m", d.o3y);
        d.r2 = r.number("r2_m", "m", d.r2);
        d.ab = r.number("ab_m", "m", d.ab);
        d.r4 = r.number("r4_m", "m", d.r4);
        d.dx = r.number("dx_m", "m", d.dx);
        d.scale_offset = r.number("scale_offset_m", "m", d.scale_offset);
        r.finish();
    }
    if (m.has("slider")) {
        SectionReader r = m.child("slider");
        s.plant.slider_mass = r.number("mass_kg", "kg", s.plant.slider_mass);
        s.scale_resolution = r.number("scale_resolution_m", "m", s.scale_resolution);
        r.finish();
    }
    if (m.has("crank_motor")) {
        SectionReader r = m.child("crank_motor");
        CrankPlantParams& p = s.plant;
        p.crank_inertia = r.number("inertia_kg_m2", "kg m^2", p.crank_inertia);
        p.rocker_inertia = r.number("rocker_inertia_kg_m2", "kg m^2", p.rocker_inertia);
        p.viscous = r.number("viscous_nm_s_rad", "N m s/rad", p.viscous);
        p.coulomb = r.number("coulomb_nm", "N m", p.coulomb);
        p.torque_limit = r.number("torque_limit_nm", "N m", p.torque_limit);
        r.finish();
    }
    if (m.has("cut")) {
        SectionReader r = m.child("cut");
        s.workpiece_length = r.number("workpiece_length_m", "m", s.workpiece_length);
        s.stroke_length = r.number("stroke_length_m", "m", s.stroke_length);
        s.velocity = r.number("velocity_m_s", "m/s", s.velocity);
        s.plant.contact_force = r.number("contact_force_n", "N", s.plant.contact_force);
        s.strokes = r.integer("strokes", "strokes", s.strokes, 1, 1000);
        s.return_torque_1 = r.number("return_torque_1_nm", "N m", s.return_torque_1);
        s.return_torque_2 = r.number("return_torque_2_nm", "N m", s.return_torque_2);
        r.finish();
    }
    if (m.has("tracking")) {
        SectionReader r = m.child("tracking");
        s.track_offset = r.number("offset_m", "m", s.track_offset);
        s.track_amplitude = r.number("amplitude_m", "m", s.track_amplitude);
        s.track_omega = r.number("omega_rad_s", "rad/s", s.track_omega);
        s.track_duration = r.number("duration_s", "s", s.track_duration);
        s.mse_window = r.number("mse_window_s", "s", s.mse_window);
        s.mse_scale = r.number("mse_scale", "1", s.mse_scale);
        r.finish();
    }
    if (m.has("control")) {
        SectionReader r = m.child("control");
        s.experiment = r.choice<Experiment>(
            "experiment", {{"cutting", Experiment::Cutting}, {"tracking", Experiment::Tracking}},
            s.experiment);
        s.controller = r.choice<ControllerKind>("controller",
                                                {{"ffc", ControllerKind::Ffc},
                                                 {"lqt", ControllerKind::Lqt},
                                                 {"smc", ControllerKind::Smc},
                                                 {"osmc", ControllerKind::Osmc}},
                                                s.controller);
        s.sample_time = r.number("sample_time_s", "s", s.sample_time);
        s.jacobian_compensator = r.choice<bool>(
            "jacobian", {{"compensator", true}, {"exact", false}}, s.jacobian_compensator);
        s.k_rho = r.number("k_rho_m", "m/rad", s.k_rho);
        ControllerParams& g = s.gains;
        g.model_mass = r.number("model_mass_kg", "kg", g.model_mass);
        s.disturbance_amplitude = r.number("disturbance_nm", "N m", s.disturbance_amplitude);
        s.disturbance_hz = r.number("disturbance_hz", "Hz", s.disturbance_hz);
        if (r.has("ffc")) {
            SectionReader c = r.child("ffc");
            g.ffc_wn2 = c.number("wn2", "1/s^2", g.ffc_wn2);
            g.ffc_xi = c.number("xi", "1", g.ffc_xi);
            c.finish();
        }
        if (r.has("lqt")) {
            SectionReader c = r.child("lqt");
            g.lqt_q1 = c.number("q1", "1", g.lqt_q1);
            g.lqt_q2 = c.number("q2", "1", g.lqt_q2);
            g.lqt_r = c.number("r", "1", g.lqt_r);
            c.finish();
        }
        if (r.has("smc")) {
            SectionReader c = r.child("smc");
            g.smc_c = c.number("c", "1/s", g.smc_c);
            g.smc_eta = c.number("eta", "N", g.smc_eta);
            g.smc_phi = c.number("phi", "m/s", g.smc_phi);
            c.finish();
        }
        if (r.has("osmc")) {
            SectionReader c = r.child("osmc");
            g.osmc_q11 = c.number("q11", "1", g.osmc_q11);
            g.osmc_q12 = c.number("q12", "1", g.osmc_q12);
            g.osmc_q22 = c.number("q22", "1", g.osmc_q22);
            g.osmc_lambda = c.number("lambda", "1/s", g.osmc_lambda);
            g.osmc_k1 = c.number("k1", "1/s", g.osmc_k1);
            g.osmc_k2 = c.number("k2", "N", g.osmc_k2);
            c.finish();
        }
        r.finish();
    }
    s.gains.gravity = s.plant.gravity;
    m.finish();
    return s;
}

json::Value writeQuickReturnSection(const QuickReturnSpec& s, const std::string& kind) {
    const WhitworthDims& d = s.dims;
    const CrankPlantParams& p = s.plant;
    const ControllerParams& g = s.gains;
    return json::Object{
        {"kind", kind},
        {"mechanism", json::Object{{"o3x_m", d.o3x},
                                   {"o3y_m", d.o3y},
                                   {"r2_m", d.r2},
                                   {"ab_m", d.ab},
                                   {"r4_m", d.r4},
                                   {"dx_m", d.dx},
                                   {"scale_offset_m", d.scale_offset}}},
        {"slider",
         json::Object{{"mass_kg", p.slider_mass}, {"scale_resolution_m", s.scale_resolution}}},
        {"crank_motor", json::Object{{"inertia_kg_m2", p.crank_inertia},
                                     {"rocker_inertia_kg_m2", p.rocker_inertia},
                                     {"viscous_nm_s_rad", p.viscous},
                                     {"coulomb_nm", p.coulomb},
                                     {"torque_limit_nm", p.torque_limit}}},
        {"cut", json::Object{{"workpiece_length_m", s.workpiece_length},
                             {"stroke_length_m", s.stroke_length},
                             {"velocity_m_s", s.velocity},
                             {"contact_force_n", p.contact_force},
                             {"strokes", s.strokes},
                             {"return_torque_1_nm", s.return_torque_1},
                             {"return_torque_2_nm", s.return_torque_2}}},
        {"tracking", json::Object{{"offset_m", s.track_offset},
                                  {"amplitude_m", s.track_amplitude},
                                  {"omega_rad_s", s.track_omega},
                                  {"duration_s", s.track_duration},
                                  {"mse_window_s", s.mse_window},
                                  {"mse_scale", s.mse_scale}}},
        {"control",
         json::Object{{"experiment", toString(s.experiment)},
                      {"controller", toString(s.controller)},
                      {"sample_time_s", s.sample_time},
                      {"jacobian", s.jacobian_compensator ? "compensator" : "exact"},
                      {"k_rho_m", s.k_rho},
                      {"model_mass_kg", g.model_mass},
                      {"disturbance_nm", s.disturbance_amplitude},
                      {"disturbance_hz", s.disturbance_hz},
                      {"ffc", json::Object{{"wn2", g.ffc_wn2}, {"xi", g.ffc_xi}}},
                      {"lqt", json::Object{{"q1", g.lqt_q1}, {"q2", g.lqt_q2}, {"r", g.lqt_r}}},
                      {"smc", json::Object{{"c", g.smc_c}, {"eta", g.smc_eta}, {"phi", g.smc_phi}}},
                      {"osmc", json::Object{{"q11", g.osmc_q11},
                                            {"q12", g.osmc_q12},
                                            {"q22", g.osmc_q22},
                                            {"lambda", g.osmc_lambda},
                                            {"k1", g.osmc_k1},
                                            {"k2", g.osmc_k2}}}}}};
}

std::vector<JobIssue> validateQuickReturn(const QuickReturnSpec& s) {
    IssueChecker c;
    const WhitworthDims& d = s.dims;
    c.positive("mechanism.r2_m", d.r2, 1e-3, 10, "m");
    c.range("mechanism.ab_m", d.ab, 0, 10, "m");
    c.positive("mechanism.r4_m", d.r4, 1e-3, 10, "m");
    c.range("mechanism.o3x_m", d.o3x, -10, 10, "m");
    c.range("mechanism.o3y_m", d.o3y, -10, 10, "m");
    c.range("mechanism.dx_m", d.dx, -10, 10, "m");
    c.range("mechanism.scale_offset_m", d.scale_offset, -10, 10, "m");
    c.positive("slider.mass_kg", s.plant.slider_mass, 1e-4, 1000, "kg");
    c.range("slider.scale_resolution_m", s.scale_resolution, 0, 0.01, "m");
    c.positive("crank_motor.inertia_kg_m2", s.plant.crank_inertia, 1e-6, 100, "kg m^2");
    c.range("crank_motor.rocker_inertia_kg_m2", s.plant.rocker_inertia, 0, 100, "kg m^2");
    c.range("crank_motor.viscous_nm_s_rad", s.plant.viscous, 0, 1000, "N m s/rad");
    c.range("crank_motor.coulomb_nm", s.plant.coulomb, 0, 1000, "N m");
    c.positive("crank_motor.torque_limit_nm", s.plant.torque_limit, 1e-3, 10000, "N m");
    c.range("cut.contact_force_n", s.plant.contact_force, 0, 1e5, "N");
    c.range("cut.return_torque_1_nm", s.return_torque_1, 0, s.plant.torque_limit, "N m");
    c.range("cut.return_torque_2_nm", s.return_torque_2, -s.plant.torque_limit, 0, "N m");
    c.positive("tracking.duration_s", s.track_duration, 0.1, 600, "s");
    c.positive("tracking.mse_window_s", s.mse_window, 1e-3, s.track_duration, "s");
    c.positive("tracking.mse_scale", s.mse_scale, 1e-6, 1e6, "1");
    c.range("tracking.omega_rad_s", s.track_omega, 0, 100, "rad/s");
    c.positive("control.sample_time_s", s.sample_time, 1e-5, 0.05, "s");
    c.range("control.k_rho_m", s.k_rho, 1e-4, 10, "m/rad");
    c.positive("control.model_mass_kg", s.gains.model_mass, 1e-4, 1000, "kg");
    c.range("control.disturbance_nm", s.disturbance_amplitude, 0, 1000, "N m");
    c.range("control.disturbance_hz", s.disturbance_hz, 0, 1000, "Hz");
    const ControllerParams& g = s.gains;
    c.positive("control.ffc.wn2", g.ffc_wn2, 1e-6, 1e8, "1/s^2");
    c.positive("control.ffc.xi", g.ffc_xi, 1e-6, 100, "1");
    c.range("control.lqt.q1", g.lqt_q1, 0, 1e12, "1");
    c.range("control.lqt.q2", g.lqt_q2, 0, 1e12, "1");
    c.positive("control.lqt.r", g.lqt_r, 1e-12, 1e12, "1");
    c.positive("control.smc.c", g.smc_c, 1e-6, 1e6, "1/s");
    c.range("control.smc.eta", g.smc_eta, 0, 1e6, "N");
    c.positive("control.smc.phi", g.smc_phi, 1e-9, 1e3, "m/s");
    c.positive("control.osmc.q22", g.osmc_q22, 1e-12, 1e12, "1");
    if (!(g.osmc_q11 * g.osmc_q22 - g.osmc_q12 * g.osmc_q12 > 0))
        c.add("control.osmc.q11", "control.osmc: Q = [q11 q12; q12 q22] = [" + num(g.osmc_q11) +
                                      " " + num(g.osmc_q12) + "; " + num(g.osmc_q12) + " " +
                                      num(g.osmc_q22) + "] must be positive definite");
    c.positive("control.osmc.lambda", g.osmc_lambda, 1e-6, 1e6, "1/s");
    c.positive("control.osmc.k1", g.osmc_k1, 1e-6, 1e8, "1/s");
    c.range("control.osmc.k2", g.osmc_k2, 0, 1e6, "N");
    if (!c.issues.empty()) return c.issues;

    // The loop must close for every crank angle (the crank turns fully).
    double margin = 0;
    const std::vector<AngleRange> open = openRanges(d, &margin);
    if (!open.empty()) {
        c.add("mechanism", "mechanism: the loop (B.1) does not close for crank angles q in " +
                               describeRanges(open) +
                               ": |Dx - O3x - (r3 + AB) cos(theta3)| > r4 = " + num(d.r4) +
                               " m there, so the crank cannot turn fully");
        return c.issues;
    }
    if (margin < 0.02) {
        c.add("mechanism.r4_m", formatC("mechanism.r4_m = %s m: the link comes within %.4f of "
                                        "horizontal (1 - |cos theta4|), a singular pose; "
                                        "the limit is 0.02",
                                        num(d.r4).c_str(), margin));
        return c.issues;
    }
    const StrokeInfo st = strokeInfo(d);
    if (!st.ok) {
        c.add("mechanism", "mechanism: no two singular crank angles (rho_y = 0) were found");
        return c.issues;
    }
    if (std::fabs(st.stroke - s.stroke_length) > 0.002)
        c.add("cut.stroke_length_m",
              formatC("cut.stroke_length_m = %s m does not match the mechanism's stroke "
                      "y_min - y_max = %.4f m (tolerance 0.002 m)",
                      num(s.stroke_length).c_str(), st.stroke));
    if (!(s.workpiece_length > 0 && s.workpiece_length < st.stroke))
        c.add("cut.workpiece_length_m", "cut.workpiece_length_m = " + num(s.workpiece_length) +
                                            " m must be in (0, " + formatC("%.4f", st.stroke) +
                                            ") m (the stroke L_c)");
    if (!(s.velocity < 0 && s.velocity >= -10))
        c.add("cut.velocity_m_s", "cut.velocity_m_s = " + num(s.velocity) +
                                      " m/s is outside [-10, 0) m/s (the cut runs downwards)");
    const double lo = s.track_offset - std::fabs(s.track_amplitude);
    const double hi = s.track_offset + std::fabs(s.track_amplitude);
    if (!(lo > st.y_bottom && hi < st.y_top))
        c.add("tracking.amplitude_m",
              formatC("tracking: the reference spans [%.4f, %.4f] m; it must stay inside the "
                      "stroke (%.4f, %.4f) m",
                      lo, hi, st.y_bottom, st.y_top));
    return c.issues;
}

bool buildSetup(const QuickReturnSpec& s, ExperimentSetup* setup, std::string* problem) {
    ExperimentSetup e;
    e.law.dims = s.dims;
    e.law.stroke = strokeInfo(s.dims);
    if (!e.law.stroke.ok) {
        *problem = "the mechanism has no full crank turn with two singular points";
        return false;
    }
    e.law.profile =
        algorithm1(e.law.stroke.y_top, e.law.stroke.y_bottom, s.workpiece_length, s.velocity);
    if (!e.law.profile.ok) {
        *problem = std::string("Algorithm 1: ") + e.law.profile.problem;
        return false;
    }
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
    return true;
}

} // namespace cutcell
