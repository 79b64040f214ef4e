#pragma once
// Algorithm 1 of seed 004: the cutting stroke's trapezoidal velocity profile with parabolic
// blends. From the stroke ends (the singular points, y_start = the seed's y_min where the cut
// begins, y_end = its y_max), the workpiece length L_d and the signed cutting velocity v:
//   t_c = L_d / |v|,  t_a = t_d = L_c / |v| - t_c,
//   y_a = y_start + v t_a / 2,  y_b = y_a + v t_c   (the workpiece ends),
// with L_c = |y_end - y_start|. The blends accelerate at v / t_a.
namespace cutcell::quick_return {

struct VelocityProfile {
    bool ok = false;
    const char* problem = ""; // when !ok
    double y_start = 0, y_end = 0, v = 0;
    double l_c = 0, l_d = 0;
    double t_a = 0, t_c = 0; // t_d = t_a
    double y_a = 0, y_b = 0;
    double duration() const { return 2 * t_a + t_c; }
};

// L_c given (the algorithm as printed); ok only when 0 < L_d < L_c and v points from y_start
// to y_end.
VelocityProfile algorithm1(double y_start, double y_end, double l_c, double l_d, double v);
// L_c from the stroke ends.
VelocityProfile algorithm1(double y_start, double y_end, double l_d, double v);

struct ProfileSample {
    double y = 0, dy = 0, ddy = 0;
};
// The reference at t seconds after the stroke began (held at y_end after the end).
ProfileSample sampleProfile(const VelocityProfile& p, double t);

} // namespace cutcell::quick_return
