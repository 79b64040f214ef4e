#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/common/c_format.h"
#include "core/common/sin_cos.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace cutcell {

const char* toString(IkStatus s) {
    switch (s) {
    case IkStatus::Ok:
        return "ok";
    case IkStatus::OutOfReach:
        return "out of reach";
    case IkStatus::JointLimit:
        return "joint limit";
    case IkStatus::Singular:
        return "singular";
    case IkStatus::OrientationUnreachable:
        return "orientation out of reach";
    }
    return "?";
}

std::string describe(const IkResult& r) {
    switch (r.status) {
    case IkStatus::Ok:
        return "ok";
    case IkStatus::OutOfReach:
        return messageC("out of reach: the wrist is %.3f mm beyond the arm's reach (joint 3)",
                        r.residual);
    case IkStatus::JointLimit:
        return messageC("joint %d = %.3f deg is past its limit %.3f deg by %.3f deg", r.axis,
                        rad2deg(r.value), rad2deg(r.limit), rad2deg(r.residual));
    case IkStatus::Singular:
        return messageC("singular at joint %d (its angle is undefined here)", r.axis);
    case IkStatus::OrientationUnreachable:
        return messageC("torch axis is %.3f deg off the plane of joint 1 (a 5-DOF arm can only "
                        "tilt its torch within that plane)",
                        rad2deg(r.residual));
    }
    return "?";
}

PipeRobot::PipeRobot(const std::array<DhRow, kAxisCount>& dh) {
    std::vector<DhLink> links;
    for (int i = 0; i < kAxisCount; ++i) {
        const auto& r = dh[static_cast<size_t>(i)];
        offset_[static_cast<size_t>(i)] = deg2rad(r.theta_offset_deg);
        min_[static_cast<size_t>(i)] = deg2rad(r.min_deg);
        max_[static_cast<size_t>(i)] = deg2rad(r.max_deg);
        if (i == 0) continue;
        links.push_back({deg2rad(r.alpha_deg), r.a_mm, r.d_mm, deg2rad(r.theta_offset_deg),
                         deg2rad(r.min_deg), deg2rad(r.max_deg)});
    }
    arm_ = DhChain(std::move(links));
    for (size_t j = 0; j < link_.size(); ++j) {
        const DhLink& l = arm_.link(j);
        link_[j] = {std::cos(l.alpha_rad), std::sin(l.alpha_rad), l.a_mm, l.d_mm,
                    l.theta_offset_rad};
    }
    d0_ = dh[0].d_mm;
    d1_ = dh[1].d_mm;
    a2_ = dh[2].a_mm;
    a3_ = dh[3].a_mm;
    a4_ = dh[4].a_mm;
    d5_ = dh[5].d_mm;
}

bool PipeRobot::withinLimits(int axis, double q) const {
    constexpr double tol = 1e-9;
    return q >= min_[static_cast<size_t>(axis)] - tol && q <= max_[static_cast<size_t>(axis)] + tol;
}

Pose PipeRobot::baseFromWork(double theta0) const {
    const double th = theta0 + offset_[0];
    double c, s;
    sinCos(th, s, c);
    Pose T = Pose::Identity();
    T.linear() << 0, 0, -1, -c, s, 0, s, c, 0;
    T.translation() << d0_, 0, 0;
    return T;
}

Vec3 PipeRobot::workFromBase(double theta0, const Vec3& p) const {
    // baseFromWork: R = [0 0 -1; -c s 0; s c 0], t = (d0, 0, 0).
    const double th = theta0 + offset_[0];
    double c, s;
    sinCos(th, s, c);
    const double vx = p.x() - d0_, vy = p.y(), vz = p.z();
    return Vec3(-c * vy + s * vz, s * vy + c * vz, -vx);
}

namespace {

// Two samples side by side in one SSE2 register: each lane runs the scalar code's IEEE
// operations in the same order, so a lane's result equals tip() of that sample bit for bit.
using Lanes2 = double __attribute__((vector_size(16)));

template <class T> T splat(double v) {
    if constexpr (std::is_same_v<T, double>)
        return v;
    else
        return T{v, v};
}

// The tip of the arm chain: column-major rotation R (R[col * 3 + row]) and position p of the
// frames A_1 ... A_i. Every sum runs left to right, (x0 + x1) + x2, as Eigen's fixed-size
// products do, so the result equals forward(q).translation() exactly, not only to rounding.
// cosSin(i, c, s) gives the cos and sin of joint i's angle (with its offset).
template <class T, class Link, class CosSin>
void tipChain(const Link* link, int joints, CosSin cosSin, T* p) {
    const Link& l0 = link[0];
    T ct, st;
    cosSin(0, ct, st);
    T R[9] = {ct,         st,          splat<T>(0),    -st * l0.ca, ct * l0.ca, splat<T>(l0.sa),
              st * l0.sa, -ct * l0.sa, splat<T>(l0.ca)};
    p[0] = l0.a * ct;
    p[1] = l0.a * st;
    p[2] = splat<T>(l0.d);
    // Unrolled (measured ~15 % faster than the loops at -O2).
#pragma GCC unroll 4
    for (int i = 1; i < joints; ++i) {
        const Link& l = link[i];
        // The last link's angle only turns the frame about the tip's own z axis: with a = 0
        // it does not move the tip, so its sin/cos are skipped. a * cos = 0 either way; only
        // the sign of a zero term could differ.
        if (i < joints - 1 || l.a != 0) {
            cosSin(i, ct, st);
        } else {
            ct = splat<T>(1);
            st = splat<T>(0);
        }
        const T t0 = l.a * ct, t1 = l.a * st, t2 = splat<T>(l.d);
#pragma GCC unroll 3
        for (int r = 0; r < 3; ++r)
            p[r] = ((R[r] * t0 + R[r + 3] * t1) + R[r + 6] * t2) + p[r];
        if (i == joints - 1) break; // the last rotation is not needed for the tip
        const T A[9] = {ct,        st,         splat<T>(0),   -st * l.ca, ct * l.ca, splat<T>(l.sa),
                        st * l.sa, -ct * l.sa, splat<T>(l.ca)};
        T N[9];
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c)
#pragma GCC unroll 3
            for (int r = 0; r < 3; ++r)
                N[c * 3 + r] =
                    (R[r] * A[c * 3] + R[r + 3] * A[c * 3 + 1]) + R[r + 6] * A[c * 3 + 2];
#pragma GCC unroll 9
        for (int k = 0; k < 9; ++k)
            R[k] = N[k];
    }
}

} // namespace

Vec3 PipeRobot::tip(const ArmVector& q) const {
    double p[3];
    tipChain<double>(
        link_.data(), kArmJointCount,
        [&](int i, double& c, double& s) {
            const double th = q[i] + link_[static_cast<size_t>(i)].offset;
            sinCos(th, s, c);
        },
        p);
    return Vec3(p[0], p[1], p[2]);
}

void PipeRobot::tipPair(const ArmVector& qa, const ArmVector& qb, Vec3& a, Vec3& b) const {
    Lanes2 p[3];
    tipChain<Lanes2>(
        link_.data(), kArmJointCount,
        [&](int i, Lanes2& c, Lanes2& s) {
            const double offset = link_[static_cast<size_t>(i)].offset;
            const double tha = qa[i] + offset, thb = qb[i] + offset;
            double ca, sa, cb, sb;
            sinCos(tha, sa, ca);
            sinCos(thb, sb, cb);
            c = Lanes2{ca, cb};
            s = Lanes2{sa, sb};
        },
        p);
    a = Vec3(p[0][0], p[1][0], p[2][0]);
    b = Vec3(p[0][1], p[1][1], p[2][1]);
}

Pose PipeRobot::forward(const ArmVector& q) const {
    return arm_.forward(q.data());
}

void PipeRobot::armFrames(const ArmVector& q, Pose* out6) const {
    arm_.frames(q.data(), out6);
}

IkResult PipeRobot::solve(const Vec3& tip, const Vec3& approach, double roll,
                          const ArmVector* previous) const {
    return solveImpl(tip, approach, nullptr, roll, previous, nullptr);
}

IkResult PipeRobot::solve(const Pose& tool, const ArmVector* previous) const {
    const Vec3 n = tool.linear().col(0);
    return solveImpl(tool.translation(), tool.linear().col(2), &n, 0, previous, nullptr);
}

// The angle equal to `value` modulo 2 pi that lies within the axis limits and nearest to
// `reference`; *ok is false when no such angle exists.
double PipeRobot::nearestWithinLimits(int axis, double value, double reference, bool* ok) const {
    double best = value;
    double bestDist = 1e300;
    *ok = false;
    for (int k = -2; k <= 2; ++k) {
        const double v = value + 2 * kPi * k;
        if (!withinLimits(axis, v)) continue;
        const double dist = std::fabs(v - reference);
        if (dist < bestDist) {
            bestDist = dist;
            best = v;
            *ok = true;
        }
    }
    if (!*ok) {
        // Report the representative nearest the reference.
        best = value + 2 * kPi * std::round((reference - value) / (2 * kPi));
    }
    return best;
}

IkBranches PipeRobot::solveBranches(const Vec3& tip, const Vec3& approach, double roll) const {
    IkBranches all;
    const IkResult chosen = solveImpl(tip, approach, nullptr, roll, nullptr, &all);
    // Refused before any branch (singular base, torch off the joint-1 plane): that reason.
    if (all.count == 0) all.branch[all.count++] = chosen;
    return all;
}

IkResult PipeRobot::solveImpl(const Vec3& p, const Vec3& aIn, const Vec3* n, double roll,
                              const ArmVector* previous, IkBranches* all) const {
    IkResult out;
    const Vec3 a = aIn.normalized();
    const ArmVector ref = previous ? *previous : ArmVector::Zero();
    const double ph = std::hypot(p.x(), p.y());
    double t1;
    if (ph > 1e-9) {
        t1 = std::atan2(p.y(), p.x());
    } else if (std::hypot(a.x(), a.y()) > 1e-9) {
        t1 = std::atan2(a.y(), a.x());
    } else {
        out.status = IkStatus::Singular;
        out.axis = 1;
        return out;
    }

    // Candidates: shoulder facing the tip or reaching over backwards, elbow either way.
    IkResult best;
    double bestCost = 1e300;
    IkResult reachFailure; // out of reach, facing the tip preferred
    bool haveReachFailure = false;
    IkResult limitFailure; // reachable but past a limit or singular, nearest candidate
    double limitCost = 1e300;
    for (int shoulder = 0; shoulder < 2; ++shoulder) {
        const double th1 = t1 + shoulder * kPi;
        const double c1 = std::cos(th1), s1 = std::sin(th1);
        const double lateral = -s1 * a.x() + c1 * a.y();
        if (std::fabs(lateral) > 1e-7) {
            out.status = IkStatus::OrientationUnreachable;
            out.axis = 1;
            out.residual = std::asin(std::min(1.0, std::fabs(lateral)));
            return out;
        }
        const double th234 = std::atan2(c1 * a.x() + s1 * a.y(), -a.z());
        const double s234 = std::sin(th234), c234 = std::cos(th234);
        const double r = c1 * p.x() + s1 * p.y();
        const double h = p.z() - d1_;
        const double rw = r - d5_ * s234 - a4_ * c234;
        const double hw = h + d5_ * c234 - a4_ * s234;
        const double dist = std::hypot(rw, hw);
        const double D = (rw * rw + hw * hw - a2_ * a2_ - a3_ * a3_) / (2 * a2_ * a3_);
        if (D > 1 + 1e-12 || D < -1 - 1e-12) {
            IkResult f;
            f.status = IkStatus::OutOfReach;
            f.axis = 3;
            f.residual = D > 1 ? dist - (a2_ + a3_) : std::fabs(a2_ - a3_) - dist;
            if (!haveReachFailure) reachFailure = f;
            haveReachFailure = true;
            if (all) all->branch[all->count++] = f; // one entry for both elbows
            continue;
        }
        const double c3 = std::clamp(D, -1.0, 1.0);
        double th5 = roll;
        if (n) {
            const Vec3 x4(c1 * c234, s1 * c234, s234), y4(s1, -c1, 0);
            th5 = std::atan2(n->dot(y4), n->dot(x4));
        }
        for (int elbow = -1; elbow <= 1; elbow += 2) {
            const double s3 = elbow * std::sqrt(std::max(0.0, 1 - c3 * c3));
            const double th3 = std::atan2(s3, c3);
            const double th2 = std::atan2(hw, rw) - std::atan2(a3_ * s3, a2_ + a3_ * c3);
            const double th4 = th234 - th2 - th3;
            const double geom[kArmJointCount] = {th1, th2, th3, th4, th5};
            IkResult cand;
            double cost = 0;
            bool allOk = true;
            for (int j = 0; j < kArmJointCount; ++j) {
                const int axis = j + 1;
                bool ok = true;
                const double q = nearestWithinLimits(
                    axis, geom[j] - offset_[static_cast<size_t>(axis)], ref[j], &ok);
                cand.q[j] = q;
                cost += (q - ref[j]) * (q - ref[j]);
                if (!ok && allOk) {
                    allOk = false;
                    cand.status = IkStatus::JointLimit;
                    cand.axis = axis;
                    cand.value = q;
                    const double lo = min_[static_cast<size_t>(axis)],
                                 hi = max_[static_cast<size_t>(axis)];
                    cand.limit = q < lo ? lo : hi;
                    cand.residual = q < lo ? lo - q : q - hi;
                }
            }
            if (allOk && std::fabs(s3) < 1e-9) {
                cand.status = IkStatus::Singular;
                cand.axis = 3;
                allOk = false;
            }
            if (all) all->branch[all->count++] = cand;
            if (allOk) {
                if (cost < bestCost) {
                    bestCost = cost;
                    best = cand;
                }
            } else if (cost < limitCost) {
                limitCost = cost;
                limitFailure = cand;
            }
        }
    }
    if (bestCost < 1e300) return best;
    if (limitCost < 1e300) return limitFailure;
    return reachFailure;
}

} // namespace cutcell
