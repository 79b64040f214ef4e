#pragma once
// Kinematics of the seed-000 cell: a pipe chuck (axis 0) and a 5-DOF arm (axes 1..5).
//
// Frames: {0} is the robot base (joint-1 axis = Z0). The work pipe's axis lies on X0,
// reversed, its cut centre at X0 = d0 (seed Eq. 9/23):
//   p0 = (d0 - z, -c0 x + s0 y, s0 x + c0 y)   for a point (x, y, z) of the work frame.
// The tool frame's third column is the torch axis ("approach", into the material); the seed's
// Eq. 24 prints the columns as n a o, but its IK (Eq. 39-42) only works with n o a: this code
// uses n o a.
//
// A 5-DOF arm keeps its torch axis in the vertical plane through Z0 and the tip (the plane of
// joint 1); roll about the torch axis is theta5. Poses off that plane are reported as
// OrientationUnreachable, never solved silently wrong.
//
// Thread safety: const methods may be called from any thread; solve() does not allocate.
#include "core/common/types.h"
#include "core/job/job.h"
#include "core/kinematics/dh_chain.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <array>
#include <string>

namespace cutcell {

using ArmVector = Eigen::Matrix<double, kArmJointCount, 1>;

enum class IkStatus { Ok = 0, OutOfReach, JointLimit, Singular, OrientationUnreachable };
const char* toString(IkStatus s);

struct IkResult {
    IkStatus status = IkStatus::Ok;
    ArmVector q = ArmVector::Zero(); // theta1..theta5, rad
    int axis = -1;                   // offending axis (1..5), -1 if none
    double residual = 0;             // OutOfReach: mm beyond reach; JointLimit: rad past the limit;
                                     // OrientationUnreachable: rad off the joint-1 plane
    double value = 0;                // JointLimit: the joint value (rad)
    double limit = 0;                // JointLimit: the limit that was broken (rad)
    bool ok() const { return status == IkStatus::Ok; }
};

// Every IK branch of a pose (shoulder facing the tip or reaching over, elbow up or down), each
// with its status; a pose refused before any branch gives that one result.
struct IkBranches {
    std::array<IkResult, 4> branch{};
    int count = 0;
};

// One sentence for the user, e.g. "joint 3 = 97.2 deg is past its limit 90 deg by 7.2 deg".
std::string describe(const IkResult& r);

class PipeRobot {
  public:
    explicit PipeRobot(const std::array<DhRow, kAxisCount>& dh);

    const DhChain& arm() const { return arm_; }
    double d0() const { return d0_; }
    double minRad(int axis) const { return min_[static_cast<size_t>(axis)]; }
    double maxRad(int axis) const { return max_[static_cast<size_t>(axis)]; }
    bool withinLimits(int axis, double q) const;

    // Work frame -> base frame for a chuck angle theta0 (rad).
    Pose baseFromWork(double theta0) const;
    // The tip expressed in the work frame: baseFromWork(theta0)^-1 * tipBase, computed as
    // R^T (p - t) (bit for bit the same as the 4x4 inverse, without forming it).
    Vec3 workFromBase(double theta0, const Vec3& tipBase) const;
    // Tool pose (tip, n o a) in the base frame.
    Pose forward(const ArmVector& q) const;
    // Tip only: forward(q).translation() with the link constants (sin/cos of alpha) computed
    // once, no homogeneous 4x4 algebra and no last rotation. The products are summed in the
    // order Eigen uses for the full pose, so the result is the same bit for bit (tested).
    Vec3 tip(const ArmVector& q) const;
    // tip() of two samples at once (commanded and actual), each equal to tip() bit for bit.
    void tipPair(const ArmVector& qa, const ArmVector& qb, Vec3& a, Vec3& b) const;
    // Frames 0..5 of the arm for drawing (6 poses).
    void armFrames(const ArmVector& q, Pose* out6) const;

    // Tip position and torch axis (unit); theta5 is set to `roll` (the torch is axisymmetric).
    // With `previous`, the branch (shoulder side, elbow) nearest to it is chosen and the
    // angles are unwrapped toward it, so a path stays continuous.
    IkResult solve(const Vec3& tip, const Vec3& approach, double roll,
                   const ArmVector* previous = nullptr) const;
    // Every branch of solve(tip, approach, roll) with its status, none chosen (cutcell-cli ik).
    IkBranches solveBranches(const Vec3& tip, const Vec3& approach, double roll) const;
    // Full tool pose: theta5 follows from the n column.
    IkResult solve(const Pose& tool, const ArmVector* previous = nullptr) const;

  private:
    IkResult solveImpl(const Vec3& p, const Vec3& a, const Vec3* n, double roll,
                       const ArmVector* previous, IkBranches* all) const;
    double nearestWithinLimits(int axis, double value, double reference, bool* ok) const;

    // Per arm link: cos/sin of alpha, a, d and the theta offset (for tip()).
    struct LinkConstants {
        double ca, sa, a, d, offset;
    };

    DhChain arm_;
    std::array<LinkConstants, kArmJointCount> link_{};
    double d0_, d1_, a2_, a3_, a4_, d5_;
    std::array<double, kAxisCount> offset_{}, min_{}, max_{};
};

} // namespace cutcell
