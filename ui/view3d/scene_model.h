#pragma once
// What the 3D view draws, as plain data (no VTK, no Qt): the machine's geometry and the
// planned path, built once per job/plan. The view turns it into actors and moves them with
// the joint vector (CellView::setMachineState).
//
// Frames and units: mm, rad. The world is the machine's base frame {0} (Z up). The work pipe
// is described in its own "work frame" (axis z, z = 0 at the middle of the cut, see
// core/geometry/cut_path.h); where it is in the world depends on its chuck axis:
//   baseFromWork(q) = baseFromWorkAtZero * Rz(q[chuckAxis])
// so the pipe, its path and the mating pipe turn together.
//
// The tool: either drawn from a DH arm (ToolMount::DhArm: q[armFirstAxis ...] drive
// armChain, the tip is the last frame's origin and the torch axis its z axis) or carried by a
// linear axis (ToolMount::LinearCarriage, for the 2-axis profile cutter: tip =
// carriageOrigin + q[carriageAxis] * carriageDirection, torch axis carriageApproach).
#include "core/common/types.h"
#include "core/kinematics/dh_chain.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cutcell {
struct Job; // the machines' scene builders take one
} // namespace cutcell

namespace cutcell::view3d {

enum class ToolMount { DhArm, LinearCarriage };

struct PipeShape {
    double radius_mm = 0; // outer
    double wall_mm = 0;
    double length_mm = 0;
};

// A triangle mesh in the world (mm), e.g. a steel section extruded with its root radii.
struct SurfaceMesh {
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> triangles; // counter-clockwise seen from outside
};

// A rigid piece of a machine drawn as a linkage (SceneModel::linkage), in the world (mm): a bar
// (a cylinder from `a` to `b`) or an axis-aligned block (centre `a`, edge lengths `b`). Flame
// pieces show only while the torch is on.
struct LinkagePiece {
    enum Kind { Bar, Block } kind = Bar;
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    double radius_mm = 10; // Bar
    enum Colour { Frame, Link, Joint, Work, Tool, Flame } colour = Link;
};

struct SceneModel {
    std::string title; // shown in the view's corner (job name)
    int axisCount = 0; // the machine's axes (set by its scene builder)

    // Work pipe (being cut), centred on its work frame's z axis from -length/2 to +length/2.
    PipeShape workPipe;
    double workPipeCentreZ_mm = 0; // centre of the drawn tube along work z
    int chuckAxis = 0;
    Pose baseFromWorkAtZero = Pose::Identity();

    // Mating pipe, drawn ghosted: a tube from its frame's origin along +z (work frame).
    bool hasMatingPipe = false;
    PipeShape matingPipe;
    Pose workFromMating = Pose::Identity();

    // Planned path (work frame) with the torch axis at each point, and whether each point is
    // reachable (1) or not (0). Points are equally spaced in time.
    std::vector<Vec3> pathWork;
    std::vector<Vec3> approachWork;
    std::vector<std::uint8_t> reachable;
    int firstUnreachable = -1;

    // Tool.
    ToolMount mount = ToolMount::DhArm;
    DhChain armChain;         // frames of the arm for drawing (DhArm)
    int armFirstAxis = 1;     // q index of the chain's first joint
    double toolLength_mm = 0; // the torch: from the tip back along its axis
    int carriageAxis = 0;     // q index of the linear axis (LinearCarriage)
    Vec3 carriageOrigin = Vec3::Zero();
    Vec3 carriageDirection = Vec3::UnitX();
    Vec3 carriageApproach = -Vec3::UnitZ();

    // A machine that is a planar linkage (the quick-return cutter): its pieces as a function
    // of the joint vector, computed by the machine's forward kinematics. When set, the view
    // draws these pieces (the same count for every q) instead of the pipe and the tool; the
    // planned path is drawn too when pathWork is set (lifted off the work along -approachWork
    // when there is no work pipe).
    std::function<std::vector<LinkagePiece>(const JointVector&)> linkage;
    // A linkage that also draws what its master axis measures (the flying saw's pipe on the
    // line): the view puts the telemetry's master position (mm) into q[masterSlot] before
    // placing the pieces. -1: none.
    int masterSlot = -1;
    // Fixed work drawn with a linkage (the section-steel line's section), world frame.
    std::vector<std::shared_ptr<const SurfaceMesh>> workMeshes;

    // Direction from the focal point to the camera of the Iso and Follow-torch views.
    Vec3 isoToCamera = Vec3(0.75, -1.0, 0.7);
    // The same for the Follow-torch view when the Iso side has the machine between the camera
    // and the tool (the section steel's arm); zero: the Iso direction.
    Vec3 followToCamera = Vec3::Zero();

    // Where to put the floor (world z) and the default joint vector (first path point).
    double floorZ_mm = 0;
    JointVector homeQ = JointVector::Zero();

    Pose baseFromWork(const JointVector& q) const;
    // Tool pose in the world: translation = torch tip, column 2 = torch axis (into the work).
    Pose toolPose(const JointVector& q) const;
    // Frames 0..n of the arm in the world (frame 0 = base); empty for a carriage.
    std::vector<Pose> armFrames(const JointVector& q) const;
    // Path point i in the world for joint vector q (the pipe may have turned).
    Vec3 pathPointWorld(size_t i, const JointVector& q) const;
    size_t unreachableCount() const;
};

} // namespace cutcell::view3d
