#pragma once
// The quick-return cutter's part of the job (Job::machine_spec) and what is derived from it.
//
// Its `machine` section (all lengths m, times s, forces N, torques N m):
//   mechanism  { o3x_m, o3y_m, r2_m, ab_m, r4_m, dx_m, scale_offset_m }
//   slider     { mass_kg, scale_resolution_m }
//   crank_motor{ inertia_kg_m2, rocker_inertia_kg_m2, viscous_nm_s_rad, coulomb_nm,
//                torque_limit_nm }
//   cut        { workpiece_length_m (L_d), stroke_length_m (L_c, must match the mechanism),
//                velocity_m_s (v, signed), contact_force_n, strokes, return_torque_1_nm,
//                return_torque_2_nm }
//   tracking   { offset_m, amplitude_m, omega_rad_s, duration_s, mse_window_s, mse_scale }
//   control    { experiment: "cutting"|"tracking", controller: "ffc"|"lqt"|"smc"|"osmc",
//                sample_time_s, jacobian: "compensator"|"exact", k_rho_m, model_mass_kg,
//                disturbance_nm, disturbance_hz,
//                ffc { wn2, xi }, lqt { q1, q2, r }, smc { c, eta, phi },
//                osmc { q11, q12, q22, lambda, k1, k2 } }
#include "core/common/outcome.h"
#include "core/job/field_table.h"
#include "core/job/job.h"
#include "core/job/job_io.h"
#include "core/job/machine_spec.h"
#include "core/json/json.h"
#include "core/machines/quick_return/experiments.h"

namespace cutcell {

inline constexpr const char* kQuickReturnId = "quick_return_cutter";

struct QuickReturnSpec : MachineSpecOf<QuickReturnSpec> {
    quick_return::WhitworthDims dims;
    quick_return::CrankPlantParams plant; // contact and cut window set per experiment
    double scale_resolution = 8.4667e-5;  // m: 300 counts per inch (the seed's strip)
    double workpiece_length = 0.3;        // L_d
    double stroke_length = 0.4667;        // L_c as the job states it
    double velocity = -0.762;             // v (see README: the seed's times fit 0.762 m/s)
    int strokes = 3;
    double return_torque_1 = 8.65, return_torque_2 = -8;
    double track_offset = -0.2, track_amplitude = -0.2, track_omega = 3.141592653589793;
    double track_duration = 10, mse_window = 2, mse_scale = 100;
    quick_return::Experiment experiment = quick_return::Experiment::Cutting;
    quick_return::ControllerKind controller = quick_return::ControllerKind::Osmc;
    quick_return::ControllerParams gains;
    double sample_time = 0.001;
    bool jacobian_compensator = true;
    double k_rho = 0.2162; // m/rad: max |rho_y| on the default mechanism's cutting branch
    double disturbance_amplitude = 0.2, disturbance_hz = 3;
};

// The spec of a quick-return job (throws std::invalid_argument for another machine's job).
const QuickReturnSpec& quickReturnSpec(const Job& job);

// The section I/O and checks (quick_return_section.cpp).
// Every key of the section once, with unit, range and label: reading, writing, the range
// checks and the form's fields come from it (core/job/field_table.h).
std::span<const SectionField<QuickReturnSpec>> quickReturnFields();
QuickReturnSpec readQuickReturnSection(const json::Value& section);
json::Value writeQuickReturnSection(const QuickReturnSpec& s, const std::string& kind);
std::vector<JobIssue> validateQuickReturn(const QuickReturnSpec& s);

// The experiment set-up of a valid spec (stroke, Algorithm 1, law, plant) in *setup; Refused
// with why when the mechanism or the profile cannot be built.
Outcome buildSetup(const QuickReturnSpec& s, quick_return::ExperimentSetup* setup);

} // namespace cutcell
