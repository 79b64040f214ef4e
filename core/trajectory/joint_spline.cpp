#include "core/trajectory/joint_spline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutcell {

JointSpline::JointSpline(std::vector<JointVector> knots, double dt)
    : knots_(std::move(knots)), dt_(dt) {
    const size_t n = knots_.size();
    if (n < 2 || !(dt > 0)) throw std::invalid_argument("JointSpline needs >= 2 knots and dt > 0");
    m_.assign(n, JointVector::Zero());
    const double h = dt;
    // Tridiagonal system for the second derivatives M (clamped: zero end velocities).
    std::vector<double> diag(n), upper(n), lower(n);
    std::vector<JointVector> rhs(n);
    diag[0] = 2;
    upper[0] = 1;
    rhs[0] = 6 / h * ((knots_[1] - knots_[0]) / h);
    for (size_t i = 1; i + 1 < n; ++i) {
        lower[i] = 1;
        diag[i] = 4;
        upper[i] = 1;
        rhs[i] = 6 / (h * h) * (knots_[i + 1] - 2 * knots_[i] + knots_[i - 1]);
    }
    lower[n - 1] = 1;
    diag[n - 1] = 2;
    rhs[n - 1] = 6 / h * (-(knots_[n - 1] - knots_[n - 2]) / h);
    // Thomas algorithm (the matrix is strictly diagonally dominant).
    for (size_t i = 1; i < n; ++i) {
        const double w = lower[i] / diag[i - 1];
        diag[i] -= w * upper[i - 1];
        rhs[i] -= w * rhs[i - 1];
    }
    m_[n - 1] = rhs[n - 1] / diag[n - 1];
    for (size_t i = n - 1; i-- > 0;)
        m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
    c_.resize(n);
    for (size_t i = 0; i < n; ++i)
        c_[i] = knots_[i] / h - m_[i] * h / 6;
}

namespace {
// One expression for the position, shared by evaluate() and position() so both round alike.
// c0 and c1 are the knots' linear coefficients y / h - m h / 6 (precomputed: they hold four
// of the eight lanes' divisions per evaluation).
inline JointVector segmentPosition(const JointVector& c0, const JointVector& c1,
                                   const JointVector& m0, const JointVector& m1, double h,
                                   double u) {
    const double a = h - u; // time to the segment's end
    return m0 * (a * a * a / (6 * h)) + m1 * (u * u * u / (6 * h)) + c0 * a + c1 * u;
}
} // namespace

JointSample JointSpline::evaluateSegment(size_t i, double u) const {
    const double h = dt_;
    const JointVector& y0 = knots_[i];
    const JointVector& y1 = knots_[i + 1];
    const JointVector& m0 = m_[i];
    const JointVector& m1 = m_[i + 1];
    const double a = h - u; // time to the segment's end
    JointSample s;
    s.q = segmentPosition(c_[i], c_[i + 1], m0, m1, h, u);
    s.qd = -m0 * (a * a / (2 * h)) + m1 * (u * u / (2 * h)) + (y1 - y0) / h - (m1 - m0) * h / 6;
    s.qdd = m0 * (a / h) + m1 * (u / h);
    return s;
}

JointSample JointSpline::evaluate(double t) const {
    if (knots_.empty()) return {};
    if (!(t > 0)) {
        JointSample s;
        s.q = knots_.front();
        return s;
    }
    if (t >= duration()) {
        JointSample s;
        s.q = knots_.back();
        return s;
    }
    const size_t i = std::min(static_cast<size_t>(t / dt_), knots_.size() - 2);
    return evaluateSegment(i, t - static_cast<double>(i) * dt_);
}

JointVector JointSpline::position(double t) const {
    if (knots_.empty()) return JointVector::Zero();
    if (!(t > 0)) return knots_.front();
    if (t >= duration()) return knots_.back();
    const size_t i = std::min(static_cast<size_t>(t / dt_), knots_.size() - 2);
    return segmentPosition(c_[i], c_[i + 1], m_[i], m_[i + 1], dt_,
                           t - static_cast<double>(i) * dt_);
}

} // namespace cutcell
