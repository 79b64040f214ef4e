#include "core/process/pipe_surface.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutcell {

namespace {

constexpr double kMaxOvalityFraction = 0.10; // O <= 10 % of the nominal diameter
constexpr double kMaxRunoutFraction = 0.10;  // e <= R / 10
constexpr double kMaxTaperMmPerM = 20;       // |taper| <= 20 mm/m (the model's range)
constexpr int kMaxNewtonSteps = 40;
constexpr int kMaxBracketDoublings = 12;

bool finite(double v) {
    return std::isfinite(v);
}

} // namespace

Outcome checkPipeDefects(const PipeDefects& d) {
    if (!finite(d.radius_mm) || d.radius_mm <= 0)
        return Outcome::refuse(
            messageC("radius_mm = %.6g mm is not valid: the pipe radius must be more than 0 mm",
                     d.radius_mm));
    const double dia = 2 * d.radius_mm;
    const double maxOval = kMaxOvalityFraction * dia;
    if (!finite(d.ovality_mm) || d.ovality_mm < 0 || d.ovality_mm > maxOval)
        return Outcome::refuse(messageC("ovality_mm = %.6g mm is outside 0 .. %.6g mm (10 %% of "
                                        "the diameter %.6g mm)",
                                        d.ovality_mm, maxOval, dia));
    const double maxRunout = kMaxRunoutFraction * d.radius_mm;
    if (!finite(d.runout_mm) || d.runout_mm < 0 || d.runout_mm > maxRunout)
        return Outcome::refuse(messageC("runout_mm = %.6g mm is outside 0 .. %.6g mm (a tenth of "
                                        "the radius %.6g mm)",
                                        d.runout_mm, maxRunout, d.radius_mm));
    if (!finite(d.taper_mm_per_m) || std::fabs(d.taper_mm_per_m) > kMaxTaperMmPerM)
        return Outcome::refuse(messageC("taper_mm_per_m = %.6g mm/m is outside -%.6g .. %.6g mm/m",
                                        d.taper_mm_per_m, kMaxTaperMmPerM, kMaxTaperMmPerM));
    if (!finite(d.major_axis_deg))
        return Outcome::refuse(
            messageC("major_axis_deg = %.6g deg is not a finite number", d.major_axis_deg));
    if (!finite(d.runout_deg))
        return Outcome::refuse(
            messageC("runout_deg = %.6g deg is not a finite number", d.runout_deg));
    return Outcome::done();
}

ActualPipeSurface::ActualPipeSurface(const PipeDefects& d) : d_(d) {
    const Outcome o = checkPipeDefects(d);
    if (!o.ok()) throw std::invalid_argument(o.message);
    radius0_ = d.radius_mm;
    taperPerMm_ = d.taper_mm_per_m / 2 / 1000; // diameter per metre -> radius per mm
    cMaj_ = std::cos(deg2rad(d.major_axis_deg));
    sMaj_ = std::sin(deg2rad(d.major_axis_deg));
    cx_ = d.runout_mm * std::cos(deg2rad(d.runout_deg));
    cy_ = d.runout_mm * std::sin(deg2rad(d.runout_deg));
    perfect_ = d.ovality_mm == 0 && d.runout_mm == 0 && d.taper_mm_per_m == 0;
}

double ActualPipeSurface::radiusAt(double z, double phi) const {
    if (perfect_) return radius0_; // bit for bit the nominal cylinder
    // The ray rho * u from the rotation axis meets the ellipse centred at c: in the ellipse's
    // axes (u1, u2), (c1, c2), the quadratic A rho^2 + B rho + C = 0 with C < 0 (the axis is
    // inside the section), whose positive root is the answer. Stable roots: q = -(B + sgn(B)
    // sqrt(disc)) / 2 gives rho = q / A or C / q, whichever is positive.
    const double a = semiMajor(z), b = semiMinor(z);
    const double ux = std::cos(phi), uy = std::sin(phi);
    const double u1 = ux * cMaj_ + uy * sMaj_, u2 = -ux * sMaj_ + uy * cMaj_;
    const double c1 = cx_ * cMaj_ + cy_ * sMaj_, c2 = -cx_ * sMaj_ + cy_ * cMaj_;
    const double ia2 = 1 / (a * a), ib2 = 1 / (b * b);
    const double A = u1 * u1 * ia2 + u2 * u2 * ib2;
    const double B = -2 * (u1 * c1 * ia2 + u2 * c2 * ib2);
    const double C = c1 * c1 * ia2 + c2 * c2 * ib2 - 1;
    const double disc = B * B - 4 * A * C; // > B^2 since A > 0 > C
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    const double r1 = q / A, r2 = C / q;
    return r1 > 0 ? r1 : r2;
}

double ActualPipeSurface::levelAndGradient(const Vec3& p, Vec3* grad) const {
    // E = sqrt((w1/a)^2 + (w2/b)^2) - 1 with w = p_xy - c in the ellipse's axes; a, b depend
    // on z through the taper (da/dz = db/dz = taperPerMm_). Dimensionless, 0 on the surface.
    const double a = semiMajor(p.z()), b = semiMinor(p.z());
    const double wx = p.x() - cx_, wy = p.y() - cy_;
    const double w1 = wx * cMaj_ + wy * sMaj_, w2 = -wx * sMaj_ + wy * cMaj_;
    const double g = std::sqrt(w1 * w1 / (a * a) + w2 * w2 / (b * b));
    if (grad && g > 0) {
        const double d1 = w1 / (a * a * g), d2 = w2 / (b * b * g);
        const double dz = -(w1 * w1 / (a * a * a) + w2 * w2 / (b * b * b)) * taperPerMm_ / g;
        *grad = Vec3(d1 * cMaj_ - d2 * sMaj_, d1 * sMaj_ + d2 * cMaj_, dz);
    } else if (grad) {
        *grad = Vec3::Zero(); // on the pipe's own axis: no direction
    }
    return g - 1;
}

double ActualPipeSurface::level(const Vec3& p) const {
    // |w| - r(direction of w): the radial distance from the pipe's centre to the surface,
    // which is the normal distance to first order (the section is within 10 % of a circle).
    const double a = semiMajor(p.z()), b = semiMinor(p.z());
    const double wx = p.x() - cx_, wy = p.y() - cy_;
    const double w = std::hypot(wx, wy);
    if (w == 0) return -std::min(a, b);
    const double w1 = (wx * cMaj_ + wy * sMaj_) / w, w2 = (-wx * sMaj_ + wy * cMaj_) / w;
    return w - 1 / std::sqrt(w1 * w1 / (a * a) + w2 * w2 / (b * b));
}

SurfaceHit ActualPipeSurface::alongLine(const Vec3& p, const Vec3& dIn) const {
    SurfaceHit h;
    const double dn = dIn.norm();
    if (!(dn > 0) || !std::isfinite(dn)) return h;
    const Vec3 d = dIn / dn;
    // The angle off the nominal inward normal at p decides whether the line crosses cleanly.
    const double rxy = std::hypot(p.x(), p.y());
    if (!(rxy > 0)) return h;
    const double cosIn = -(p.x() * d.x() + p.y() * d.y()) / rxy;
    if (!(cosIn >= std::cos(deg2rad(kMaxOffNormalDeg)))) return h;

    const auto E = [&](double s, Vec3* g) { return levelAndGradient(p + s * d, g); };
    // A bracket [lo, hi] with E(lo) > 0 (outside) and E(hi) < 0 (inside): the surface lies
    // within the defects' size of the nominal cylinder, /cos off the normal; widened if not.
    const double reach = 0.25 * d_.ovality_mm + d_.runout_mm +
                         std::fabs(taperPerMm_) * (std::fabs(p.z()) + radius0_) +
                         std::fabs(rxy - radius0_) + 1e-6 * radius0_;
    double half = 2 * reach / cosIn;
    double lo = -half, hi = half;
    double Elo = E(lo, nullptr), Ehi = E(hi, nullptr);
    for (int k = 0; k < kMaxBracketDoublings && !(Elo > 0 && Ehi < 0); ++k) {
        half *= 2;
        if (half > radius0_) return h; // not near this point: no crossing of the near side
        lo = -half;
        hi = half;
        Elo = E(lo, nullptr);
        Ehi = E(hi, nullptr);
    }
    if (!(Elo > 0 && Ehi < 0)) return h;

    // Safeguarded Newton: a Newton step that leaves the bracket becomes a bisection; the
    // bracket shrinks with the sign of E at every step.
    double s = std::clamp(0.0, lo, hi);
    for (int it = 1; it <= kMaxNewtonSteps; ++it) {
        Vec3 g;
        const double e = E(s, &g);
        h.iterations = it;
        if (e == 0) break;
        (e > 0 ? lo : hi) = s;
        const double slope = g.dot(d);
        double next = slope != 0 ? s - e / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = std::fabs(next - s);
        s = next;
        if (step <= 1e-13 * (1 + radius0_)) break;
    }
    h.ok = true;
    h.s_mm = s;
    h.point = p + s * d;
    return h;
}

} // namespace cutcell
