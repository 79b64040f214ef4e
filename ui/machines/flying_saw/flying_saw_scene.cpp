#include "ui/machines/flying_saw/flying_saw_scene.h"

#include "core/machines/flying_saw/flying_saw_module.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cutcell::view3d {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kRingSegments = 24;
constexpr int kDrawnPieces = 2; // cut pieces drawn downstream of the saw

LinkagePiece bar(const Vec3& a, const Vec3& b, double r, LinkagePiece::Colour c) {
    return {LinkagePiece::Bar, a, b, r, c};
}
LinkagePiece block(const Vec3& centre, const Vec3& size, LinkagePiece::Colour c) {
    return {LinkagePiece::Block, centre, size, 0, c};
}

// What the drawing needs of the job and its plan (copied into the linkage's closure).
struct SawGeometry {
    bool round = false;
    double halfW = 0, halfH = 0, wall = 0; // tube (round: halfW = halfH = radius)
    double kerf = 0, bladeR = 0, retract = 0, ringR = 0, axisZ = 0;
    double cornerA = 0;              // blade 1's direction at turntable angle 0 (section plane)
    double xSync = 0;                // carriage position at sync
    double cutDoneMaster = 0;        // master travel from S_k until the blades left the wall
    double windowL = 0, windowR = 0; // the drawn part of the line (world x)
    double railL = 0, railR = 0;
    double rollerR = 0;
    std::vector<double> sync; // S_k, k = 0 (head cut) .. pieces
};

// The tube between world x0 and x1 (clipped to the window): a round bar, or four walls so a
// cut end shows the hollow section. Always the same number of pieces (empty: a speck).
void addTube(const SawGeometry& g, double x0, double x1, std::vector<LinkagePiece>& out) {
    x0 = std::max(x0, g.windowL);
    x1 = std::min(x1, g.windowR);
    const bool empty = !(x1 > x0);
    if (empty) x0 = x1 = g.windowL;
    const double len = x1 - x0, xc = (x0 + x1) / 2, z = g.axisZ;
    if (g.round) {
        out.push_back(empty ? bar({x0, 0, z}, {x0 + 1e-6, 0, z}, 1e-6, LinkagePiece::Work)
                            : bar({x0, 0, z}, {x1, 0, z}, g.halfW, LinkagePiece::Work));
        return;
    }
    const double w = g.wall, a = 2 * g.halfW, b = 2 * g.halfH;
    out.push_back(block({xc, 0, z + g.halfH - w / 2}, {len, a, w}, LinkagePiece::Work));
    out.push_back(block({xc, 0, z - g.halfH + w / 2}, {len, a, w}, LinkagePiece::Work));
    out.push_back(block({xc, -g.halfW + w / 2, z}, {len, w, b - 2 * w}, LinkagePiece::Work));
    out.push_back(block({xc, g.halfW - w / 2, z}, {len, w, b - 2 * w}, LinkagePiece::Work));
}

std::vector<LinkagePiece> drawSaw(const SawGeometry& g, const JointVector& q) {
    std::vector<LinkagePiece> out;
    const double z = g.axisZ;
    // Fixed: rail and its legs, roller tables, the measuring roller on the tube.
    const double railTop = 200;
    out.push_back(block({(g.railL + g.railR) / 2, 0, railTop - 50}, {g.railR - g.railL, 240, 100},
                        LinkagePiece::Frame));
    for (double x : {g.railL + 80, g.railR - 80})
        out.push_back(
            block({x, 0, (railTop - 100) / 2}, {120, 200, railTop - 100}, LinkagePiece::Frame));
    const double rollerTop = z - g.halfH;
    for (double x : {g.windowL + 150, g.railL - 250, g.railR + 250, g.windowR - 150}) {
        out.push_back(bar({x, -g.halfW - 80, rollerTop - 30}, {x, g.halfW + 80, rollerTop - 30}, 30,
                          LinkagePiece::Joint));
        out.push_back(block({x, 0, (rollerTop - 60) / 2}, {80, 2 * g.halfW + 200, rollerTop - 60},
                            LinkagePiece::Frame));
    }
    const double xr = g.railL - 450, zr = z + g.halfH + g.rollerR;
    out.push_back(bar({xr, -25, zr}, {xr, 25, zr}, g.rollerR, LinkagePiece::Joint));
    out.push_back(bar({xr, 0, zr}, {xr + 260, 0, zr + 180}, 12, LinkagePiece::Frame)); // its arm

    // The tube: the incoming length up to the last cut, then the cut pieces.
    const double m = q[kFlyingSawMasterSlot];
    const auto done = std::upper_bound(g.sync.begin(), g.sync.end(), m - g.cutDoneMaster);
    const int n = static_cast<int>(done - g.sync.begin()) - 1; // last finished cut, -1: none
    const auto joint = [&](int k) { return k < 0 ? kInf : g.xSync + m - g.sync[size_t(k)]; };
    const auto runOut = [&](int k) {
        return std::min(250.0, 0.25 * std::max(0.0, m - g.sync[size_t(k)] - g.cutDoneMaster));
    };
    addTube(g, -kInf, n >= 0 ? joint(n) - g.kerf / 2 : kInf, out);
    for (int i = 0; i < kDrawnPieces; ++i) {
        const int k = n - i;
        if (k < 0) {
            addTube(g, 1, 0, out); // not cut yet: nothing to draw
            continue;
        }
        const double shift = runOut(k);
        addTube(g, joint(k) + g.kerf / 2 + shift, joint(k - 1) - g.kerf / 2 + shift, out);
    }

    // The carriage on the rail, the pillars holding the turntable's ring around the tube.
    const double xc = q[0];
    out.push_back(block({xc, 0, railTop + 40}, {420, 2 * g.ringR + 200, 80}, LinkagePiece::Link));
    for (double side : {-1.0, 1.0})
        out.push_back(block({xc - 60, side * (g.ringR + 60), (railTop + 80 + z) / 2},
                            {140, 70, z - railTop - 80}, LinkagePiece::Link));
    const double xRing = xc - 70;
    for (int i = 0; i < kRingSegments; ++i) {
        const double a0 = 2 * kPi * i / kRingSegments, a1 = 2 * kPi * (i + 1) / kRingSegments;
        out.push_back(bar({xRing, g.ringR * std::cos(a0), z + g.ringR * std::sin(a0)},
                          {xRing, g.ringR * std::cos(a1), z + g.ringR * std::sin(a1)}, 26,
                          LinkagePiece::Frame));
    }
    // Both blades half a turn apart on the turntable, each on its radial feed.
    for (int i = 0; i < 2; ++i) {
        const double psi = g.cornerA - q[1] + i * kPi;
        const Vec3 dir(0, std::cos(psi), std::sin(psi)); // section (across, up) -> world (y, z)
        const double tip = g.retract - q[2 + i];
        const Vec3 centre = Vec3(xc, 0, z) + (tip + g.bladeR) * dir;
        const Vec3 spindle = centre - Vec3(g.kerf / 2 + 4, 0, 0);
        out.push_back(bar(centre - Vec3(g.kerf / 2, 0, 0), centre + Vec3(g.kerf / 2, 0, 0),
                          g.bladeR, LinkagePiece::Tool));
        out.push_back(bar(spindle, spindle - Vec3(55, 0, 0), 28, LinkagePiece::Joint));
        out.push_back(block(spindle - Vec3(85, 0, 0), {60, 90, 90}, LinkagePiece::Joint));
        // The feed arm from the ring to the spindle's motor: shorter as the blade feeds in.
        out.push_back(bar(Vec3(xRing, 0, z) + g.ringR * dir, spindle - Vec3(85, 0, 0), 16,
                          LinkagePiece::Link));
    }
    return out;
}

} // namespace

SceneModel buildFlyingSawScene(const Job& job, const MachinePlan& plan) {
    const FlyingSawSpec& s = flyingSawSpec(job);
    FlyingSawPlan local;
    const FlyingSawPlan* p = nullptr;
    if (plan.ok() && plan.data) p = &static_cast<const FlyingSawPlanData*>(plan.data.get())->plan;
    if (!p) {
        local = planFlyingSaw(s);
        if (!local.ok) throw std::invalid_argument("machine." + local.problem);
        p = &local;
    }
    SawGeometry g;
    const TubeOutline outer = outerOutline(s);
    g.round = outer.round;
    g.halfW = outer.half_width;
    g.halfH = outer.half_height;
    g.wall = s.wall_mm;
    g.kerf = s.blade_kerf_mm;
    g.bladeR = s.blade_diameter_mm / 2;
    g.retract = p->saw.retract_radius;
    g.ringR = g.retract + 2 * g.bladeR + 60;
    g.axisZ = g.ringR + 300;
    g.cornerA = outer.cornerA();
    g.xSync = s.wait_position_mm + p->forward.d1 / 2;
    g.cutDoneMaster = p->line_speed_mm_s * p->saw.turnEnd();
    g.railL = std::min(0.0, s.wait_position_mm) - 300;
    g.railR = s.stroke_mm + 300;
    g.windowL = g.railL - 700;
    g.windowR = g.railR + 700;
    g.rollerR = s.roller_diameter_mm / 2;
    // S_0 as the source takes it (the line starts at 0: the master at start + d1 + 50 mm), then
    // one pitch (length + kerf) per piece of the queue.
    double sync =
        std::isfinite(s.first_sync_master_mm) ? s.first_sync_master_mm : p->forward.d1 + 50;
    g.sync.push_back(sync);
    for (const PieceOrder& o : s.queue)
        for (int i = 0; i < o.count && g.sync.size() < 100000; ++i)
            g.sync.push_back(sync += o.length_mm + s.blade_kerf_mm);

    SceneModel m;
    m.title = job.name.empty() ? "Flying saw" : job.name;
    m.axisCount = 4;
    m.homeQ = JointVector::Zero();
    m.homeQ[0] = s.wait_position_mm;
    m.floorZ_mm = 0;
    m.masterSlot = kFlyingSawMasterSlot;
    m.linkage = [g](const JointVector& q) { return drawSaw(g, q); };
    return m;
}

} // namespace cutcell::view3d
