#include "ui/machines/quick_return/quick_return_scene.h"

#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/quick_return/whitworth.h"

#include <algorithm>
#include <stdexcept>

namespace cutcell::view3d {

namespace {

// Depths (world y, mm) of the planes the parts move in; the views look from -y, so the frame
// stands behind the moving parts and the link, the slider and the work are in front.
constexpr double kCrankY = 28, kRockerY = 0, kLinkY = -28, kFrameY = 75;

Vec3 world(const std::array<double, 2>& p, double depth) {
    return {p[0] * 1000, depth, p[1] * 1000};
}

LinkagePiece bar(const Vec3& a, const Vec3& b, double r, LinkagePiece::Colour c) {
    return {LinkagePiece::Bar, a, b, r, c};
}
LinkagePiece block(const Vec3& centre, const Vec3& size, LinkagePiece::Colour c) {
    return {LinkagePiece::Block, centre, size, 0, c};
}
// A pin joint at p across the planes [y0, y1].
LinkagePiece pin(const Vec3& p, double y0, double y1, double r) {
    return bar({p.x(), y0, p.z()}, {p.x(), y1, p.z()}, r, LinkagePiece::Joint);
}

} // namespace

SceneModel buildQuickReturnScene(const Job& job) {
    const QuickReturnSpec& spec = quickReturnSpec(job);
    quick_return::ExperimentSetup setup;
    if (const Outcome set = buildSetup(spec, &setup); !set.ok())
        throw std::invalid_argument(set.message);
    const quick_return::WhitworthDims d = spec.dims;
    const quick_return::StrokeInfo& st = setup.law.stroke;
    // Scale readings to the crank frame (mm).
    const double top = (st.y_top - d.scale_offset) * 1000;
    const double bottom = (st.y_bottom - d.scale_offset) * 1000;
    const double cutA = (setup.law.profile.y_a - d.scale_offset) * 1000;
    const double cutB = (setup.law.profile.y_b - d.scale_offset) * 1000;
    // The tool points away from the rocker's pivot, at the workpiece.
    const double side = d.dx < d.o3x ? -1.0 : 1.0;
    const double dxMm = d.dx * 1000;

    SceneModel m;
    m.title = job.name.empty() ? "Quick-return cutter" : job.name;
    m.axisCount = 1;
    m.homeQ = JointVector::Zero();
    m.homeQ[0] = st.q_top;
    m.floorZ_mm = std::min(-d.r2 * 1000, bottom) - 140;
    m.linkage = [d, top, bottom, cutA, cutB, side, dxMm,
                 floor = m.floorZ_mm](const JointVector& q) {
        const quick_return::WhitworthPoints p = quick_return::mechanismPoints(d, q[0]);
        const Vec3 o2 = world(p.o2, kCrankY), a = world(p.a, kCrankY);
        const Vec3 o3 = world(p.o3, kRockerY), b = world(p.b, kRockerY);
        const Vec3 s = world(p.slider, kLinkY);
        const double railTop = top + 60, railBottom = bottom - 60;
        std::vector<LinkagePiece> out;
        // Frame: the bearings' pedestals and the slider's guide rail on its column, behind.
        out.push_back(block({o2.x(), kFrameY, (o2.z() + floor) / 2}, {44, 24, o2.z() - floor},
                            LinkagePiece::Frame));
        out.push_back(block({o3.x(), kFrameY, (o3.z() + floor) / 2}, {44, 24, o3.z() - floor},
                            LinkagePiece::Frame));
        out.push_back(
            bar({dxMm, kLinkY, railBottom}, {dxMm, kLinkY, railTop}, 7, LinkagePiece::Frame));
        out.push_back(block({dxMm, kFrameY, (railTop + floor) / 2}, {30, 24, railTop - floor},
                            LinkagePiece::Frame));
        out.push_back(
            bar({dxMm, kLinkY, railTop}, {dxMm, kFrameY, railTop}, 7, LinkagePiece::Frame));
        out.push_back(
            bar({dxMm, kLinkY, railBottom}, {dxMm, kFrameY, railBottom}, 7, LinkagePiece::Frame));
        // Crank with its pin, rocker with its pins, link.
        out.push_back(pin(o2, kCrankY - 8, kFrameY, 14));
        out.push_back(bar(o2, a, 9, LinkagePiece::Link));
        out.push_back(pin(a, kRockerY - 6, kCrankY, 8));
        out.push_back(pin(o3, kRockerY - 8, kFrameY, 12));
        out.push_back(bar(o3, b, 8, LinkagePiece::Link));
        out.push_back(block(world(p.a, kRockerY), {26, 20, 26}, LinkagePiece::Joint)); // pin block
        out.push_back(pin(b, kLinkY - 6, kRockerY, 7));
        out.push_back(bar(world(p.b, kLinkY), s, 6, LinkagePiece::Link));
        // Slider on the rail, the tool at the workpiece.
        out.push_back(block({dxMm, kLinkY, s.z()}, {46, 40, 60}, LinkagePiece::Link));
        out.push_back(block({dxMm + side * 42, kLinkY, s.z()}, {40, 12, 12}, LinkagePiece::Tool));
        // Workpiece beside the slider line, over the cut window [y_b, y_a].
        const double lo = std::min(cutA, cutB), hi = std::max(cutA, cutB);
        out.push_back(block({dxMm + side * 90, kLinkY, (lo + hi) / 2}, {50, 90, hi - lo},
                            LinkagePiece::Work));
        out.push_back(block({dxMm + side * 90, kLinkY, (lo - 20 + floor) / 2},
                            {70, 110, lo - 20 - floor}, LinkagePiece::Frame)); // its stand
        return out;
    };
    return m;
}

} // namespace cutcell::view3d
