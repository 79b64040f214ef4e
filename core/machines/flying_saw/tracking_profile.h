#pragma once
// The carriage's five periods of seed 003 (Eq. 1-13), written so that velocity and acceleration
// are continuous at every boundary and the carriage comes back exactly to where it started.
//
// Forward (coupled to the line; parameterised by the master position m, so the same curve
// holds at any line speed and at constant speed V equals the seed's time form with t = m / V):
//   BC acceleration over a master span D1 (= V T1), sigma = (m - m_B) / D1:
//        s = D1 (sigma / 2 - sin(pi sigma) / (2 pi))       ds/dm = sin^2(pi sigma / 2)
//      at constant V this is Eq. 1-3 with Phi / omega = T1; ds/dm goes 0 -> 1 and d2s/dm2 is 0
//      at both ends, so the carriage leaves at rest and arrives with the line's velocity and
//      acceleration (MC_GearInPos: at m = m_C it is at the sync position, geared 1:1);
//   CE synchronous: s = D1 / 2 + (m - m_C);
//   EF deceleration over a master span D3, sigma = (m - m_E) / D3:
//        s = s_E + D3 (sigma / 2 + sin(pi sigma) / (2 pi))  ds/dm = cos^2(pi sigma / 2)
//      (Eq. 4-6 with Phi / omega = T3); at F the carriage is at rest with zero acceleration
//      whatever the line does.
// Continuity condition (derived): Eq. 2/3 give v = V and a = 0 at the end of BC only when
// omega T1 = Phi exactly (sin^2(pi omega T1 / 2 Phi) = 1 and sin(pi omega T1 / Phi) = 0 need
// omega T1 / Phi odd, and = 1 for a monotone ramp); likewise omega T3 = Phi for EF and
// omega_r T4 = Phi_r, omega_r T6 = Phi_r for the reverse periods.
//
// Reverse (in time, the line plays no part): FG, GH, HI at peak speed v_r = k V:
//   FG: s = s_F - v_r (t / 2 - Ta sin(pi t / Ta) / (2 pi))          t in [0, Ta]
//   GH: s = s_G - v_r t                                              t in [0, Ts]
//   HI: s = s_H - v_r (t / 2 + Ta sin(pi t / Ta) / (2 pi))          t in [0, Ta]
// travel back v_r (Ta + Ts). It equals the forward travel s_F = D1/2 + S2 + D3/2 when
//   k = (T1 / 2 + T2 + T3 / 2) / (T4 / 2 + T5 + T6 / 2)        (consistent form)
// The seed's Eq. 13, k = sqrt(T1 (T1 + T2)) / T1, is this form only for T4 = T6 = k T1 and
// T5 = 0 (and T3 = T1); with Eq. 7-12 as printed (T4 = T6 = Phi / omega = T1, a reverse
// synchronous period s5) the carriage ends off its start by V (T1 + T2) - k V (T1 + T5).
#include <string>

namespace cutcell {

struct CarriageLimits {
    double max_speed_mm_s = 3000;
    double max_accel_mm_s2 = 10000;
    double max_jerk_mm_s3 = 200000;
};

// Shortest cosine-ramp time (the seed's sin^2 velocity) from rest to speed v within the
// acceleration (peak v pi / 2T) and jerk (peak v pi^2 / 2T^2, at the ends) limits.
double rampTime(double v, const CarriageLimits& lim);

// The forward stroke, master-parameterised. Positions relative to the wait position.
struct ForwardStroke {
    double d1 = 0; // master span of BC (mm)
    double d3 = 0; // master span of EF (mm)
    // Carriage travel at master distance u from the start of BC, for BC (0 <= u <= d1).
    double accel(double u) const;
    double accelSlope(double u) const;     // ds/dm
    double accelCurvature(double u) const; // d2s/dm2
    // Travel during EF at master distance u from E (0 <= u <= d3), from E.
    double decel(double u) const;
    double decelSlope(double u) const;
    double decelCurvature(double u) const;
};

// The reverse periods FG-GH-HI, in time, back over `distance` (mm) exactly.
struct ReverseProfile {
    double distance = 0;
    double v = 0;  // v_r = k V
    double ta = 0; // T4 = T6
    double ts = 0; // T5
    double duration() const { return 2 * ta + ts; }
    // Travel back so far (0 .. distance), velocity and acceleration (positive backwards).
    double travel(double t) const;
    double speed(double t) const;
    double accel(double t) const;
};

// The fastest reverse within the limits over `distance` (allocation-free: closed form and a
// fixed-count bisection, usable in the engine cycle).
ReverseProfile fastestReverse(double distance, const CarriageLimits& lim);

// The seed as printed: the carriage's end position relative to its start after Eq. 1-12 with
// Eq. 13's k (T3 = T4 = T6 = T1). 0 only when T5 = sqrt(T1 (T1 + T2)) - T1.
double seedReturnMiss(double V, double T1, double T2, double T5);
double seedK(double T1, double T2); // Eq. 13

} // namespace cutcell
