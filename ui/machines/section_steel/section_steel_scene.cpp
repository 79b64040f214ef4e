#include "ui/machines/section_steel/section_steel_scene.h"
#include "ui/panels/engine_text.h"

#include "core/job/job.h"
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_steel_planner.h"
#include "core/machines/section_steel/section_steel_spec.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutcell::view3d {

using section_steel::EndCut;
using section_steel::SectionSteelSpec;
using section_steel::SteelCell;
using section_steel::SteelPlan;
using section_steel::Vec2;

namespace {

double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

bool insideTriangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
    return cross2(a, b, p) > 1e-12 && cross2(b, c, p) > 1e-12 && cross2(c, a, p) > 1e-12;
}

LinkagePiece bar(const Vec3& a, const Vec3& b, double r, LinkagePiece::Colour c) {
    return {LinkagePiece::Bar, a, b, r, c};
}
LinkagePiece block(const Vec3& centre, const Vec3& size, LinkagePiece::Colour c) {
    return {LinkagePiece::Block, centre, size, 0, c};
}
// A joint: a short cylinder of length len along axis through p.
LinkagePiece joint(const Vec3& p, const Vec3& axis, double r, double len) {
    const Vec3 h = axis.normalized() * (len / 2);
    return bar(p - h, p + h, r, LinkagePiece::Joint);
}

// The torch with its tip at p pointing along t (into the material): body, nozzle and flame.
// An idle torch's flame hides inside its nozzle (the piece count never changes).
void addTorch(std::vector<LinkagePiece>& out, const Vec3& p, const Vec3& t, double length,
              bool cutting) {
    out.push_back(bar(p - t * length, p - t * 40, 16, LinkagePiece::Tool));
    out.push_back(bar(p - t * 40, p - t * 4, 8, LinkagePiece::Tool));
    out.push_back(cutting ? bar(p - t * 4, p + t * 14, 4, LinkagePiece::Flame)
                          : bar(p - t * 20, p - t * 18, 2, LinkagePiece::Flame));
}

} // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec2>& poly) {
    std::vector<std::array<int, 3>> out;
    std::vector<int> idx(poly.size());
    for (size_t i = 0; i < poly.size(); ++i)
        idx[i] = static_cast<int>(i);
    size_t guard = 0;
    while (idx.size() > 3 && guard++ < poly.size() * poly.size()) {
        bool clipped = false;
        for (size_t i = 0; i < idx.size(); ++i) {
            const int ia = idx[(i + idx.size() - 1) % idx.size()], ib = idx[i],
                      ic = idx[(i + 1) % idx.size()];
            const Vec2 &a = poly[static_cast<size_t>(ia)], &b = poly[static_cast<size_t>(ib)],
                       &c = poly[static_cast<size_t>(ic)];
            if (cross2(a, b, c) <= 1e-12) continue; // reflex or flat: not an ear
            bool empty = true;
            for (int j : idx)
                if (j != ia && j != ib && j != ic &&
                    insideTriangle(poly[static_cast<size_t>(j)], a, b, c)) {
                    empty = false;
                    break;
                }
            if (!empty) continue;
            out.push_back({ia, ib, ic});
            idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
            break;
        }
        if (!clipped) idx.erase(idx.begin()); // only collinear leftovers: no area to cover
    }
    if (idx.size() == 3) out.push_back({idx[0], idx[1], idx[2]});
    return out;
}

SurfaceMesh extrudeSection(const SectionSteelSpec& spec, double x0) {
    const EndCut cut(spec);
    const std::vector<Vec2>& poly = cut.outline().polygon();
    const int n = static_cast<int>(poly.size());
    SurfaceMesh m;
    for (const Vec2& v : poly) // back end (x0), then the cut end (on the cut plane)
        m.points.emplace_back(x0, v.x(), v.y());
    for (const Vec2& v : poly)
        m.points.emplace_back(cut.planeX(v.x(), v.y()), v.x(), v.y());
    for (int i = 0; i < n; ++i) { // side faces, outward (the polygon is counter-clockwise)
        const int j = (i + 1) % n;
        m.triangles.push_back({i, j, n + j});
        m.triangles.push_back({i, n + j, n + i});
    }
    for (const auto& t : triangulatePolygon(poly)) {
        m.triangles.push_back({n + t[0], n + t[1], n + t[2]}); // cut face, normal +x
        m.triangles.push_back({t[0], t[2], t[1]});             // back face, normal -x
    }
    return m;
}

SceneModel buildSectionSteelScene(const Job& job, const SteelPlan* plan) {
    const SectionSteelSpec* specPtr = job.machine_spec.as<SectionSteelSpec>();
    if (!specPtr) throw std::invalid_argument("the job holds no section-steel machine section");
    const SectionSteelSpec spec = *specPtr;
    const section_steel::SectionDims& d = spec.section;
    const SteelCell cell(spec, plan ? plan->kerf_mm : 0.0); // the arms where the kerf puts them

    SceneModel m;
    const auto words = [](const QString& shown) { return shown.toStdString(); };
    m.title = job.name.empty()
                  ? words(QCoreApplication::translate("SectionSteelScene", "Section-steel cutter"))
                  : job.name;
    if (spec.cut.setup == 2)
        m.title += "  -  " + words(QCoreApplication::translate("SectionSteelScene",
                                                               "setup 2: the section turned over"));
    if (plan && !plan->ok)
        m.title += "  -  " +
                   words(QCoreApplication::translate("SectionSteelScene", "NOT feasible:")) + " " +
                   words(CutCell::ui::engineText(QString::fromStdString(plan->problem)));
    m.axisCount = section_steel::kSteelAxes;
    m.chuckAxis = -1;      // the section lies still; the arms move
    m.toolLength_mm = 550; // the follow-torch view stands 1.8 x this from the cut
    // Look at the cut face (square or mitred) from past the bar end, from above on the side
    // away from the groove arm.
    m.isoToCamera = EndCut(spec).planeNormal().normalized() + Vec3(0, 0.8, 0.75);
    JointVector park = JointVector::Zero();
    for (int i = 0; i < section_steel::kSteelAxes; ++i)
        park[i] = deg2rad(spec.park_deg[static_cast<size_t>(i)]);
    m.homeQ = park;
    const double tableH = 850;
    m.floorZ_mm = -tableH;

    // The planned path: the target of every knot; transitions hold the previous point.
    if (plan && !plan->knots.empty()) {
        Vec3 hold = Vec3::Zero(), holdT = Vec3::UnitX();
        bool have = false;
        for (size_t k = 0; k < plan->knots.size(); ++k) {
            const section_steel::KnotInfo& info = plan->info[k];
            if (info.pass >= 0) {
                const auto& t = plan->passes[static_cast<size_t>(info.pass)].samples[info.sample];
                hold = t.p, holdT = t.t, have = true;
            } else if (!have) { // before the first pass: its first point
                for (size_t j = k; j < plan->knots.size(); ++j)
                    if (plan->info[j].pass >= 0) {
                        const auto& t = plan->passes[static_cast<size_t>(plan->info[j].pass)]
                                            .samples[plan->info[j].sample];
                        hold = t.p, holdT = t.t, have = true;
                        break;
                    }
            }
            m.pathWork.push_back(hold);
            m.approachWork.push_back(holdT);
        }
        m.reachable.assign(m.pathWork.size(), 1);
    }

    const double length = std::max(200.0, spec.length_mm);
    m.workMeshes.push_back(std::make_shared<SurfaceMesh>(extrudeSection(spec, -length)));
    const double width = std::max(d.b_mm, d.h_mm) + 300;
    const Pose pathFrame = cell.path_frame; // world <- the path arm's plane (x: joint axes)
    const Pose grooveBase = cell.groove_base;
    const double torchLength = std::max(60.0, spec.torch_length_mm);
    const double floor = m.floorZ_mm;
    m.linkage = [length, width, pathFrame, grooveBase, cell, park, torchLength,
                 floor](const JointVector& q) {
        std::vector<LinkagePiece> out;
        // The cutting table under the section (a slab on two legs, clear of the cut).
        const double t0 = -length - 50, t1 = -120;
        out.push_back(block({(t0 + t1) / 2, 0, -20}, {t1 - t0, width, 40}, LinkagePiece::Frame));
        for (double x : {t0 + 60, t1 - 60})
            out.push_back(block({x, 0, (floor - 40) / 2}, {60, width * 0.6, -40 - floor},
                                LinkagePiece::Frame));

        // Which arm cuts: the one that has left its park position (as SteelTipModel).
        const double pathMoved = (q.head<3>() - park.head<3>()).cwiseAbs().maxCoeff();
        const double grooveMoved = (q.segment<5>(3) - park.segment<5>(3)).cwiseAbs().maxCoeff();
        const bool pathCuts = pathMoved >= grooveMoved;

        // Path arm: planar 3R in the (square or mitred) cut plane, joint axes along the plane's
        // normal; links 1 and 2 drawn a little in front of the plane, link 3 is the torch's
        // holder in the plane.
        const auto& a = cell.path.lengths();
        const double xo = 90;
        const Vec3 axis = pathFrame.linear().col(0);
        const Vec3 pathBase = pathFrame.translation();
        // Its base hangs from a portal over the bar, behind the cut.
        const double portalX = -420, portalZ = pathBase.z() + 90, half = width / 2 + 250;
        out.push_back(bar(pathBase + axis * (xo + 60), {portalX, pathBase.y(), pathBase.z()}, 40,
                          LinkagePiece::Frame));
        out.push_back(
            block({portalX, 0, portalZ}, {120, 2 * half + 120, 120}, LinkagePiece::Frame));
        for (double y : {-half, half})
            out.push_back(block({portalX, y, (portalZ + floor) / 2}, {120, 120, portalZ - floor},
                                LinkagePiece::Frame));
        double phi = 0;
        Vec3 planar(0, 0, 0); // in the arm's plane: (0, x, y)
        Vec3 joints[3];
        for (int i = 0; i < 3; ++i) {
            joints[i] = pathFrame * planar;
            phi += q[i];
            planar += a[static_cast<size_t>(i)] * Vec3(0, std::cos(phi), std::sin(phi));
        }
        const Vec3 p = pathFrame * planar;
        // The torch direction is link 3's.
        const Vec3 dir = pathFrame.linear() * Vec3(0, std::cos(phi), std::sin(phi));
        const Vec3 ox = axis * xo;
        out.push_back(joint(joints[0] + ox, axis, 55, 120));
        out.push_back(bar(joints[0] + ox, joints[1] + ox, 34, LinkagePiece::Link));
        out.push_back(joint(joints[1] + ox, axis, 45, 110));
        out.push_back(bar(joints[1] + ox, joints[2] + ox, 28, LinkagePiece::Link));
        out.push_back(bar(joints[2] + ox * 0.5, joints[2] + ox, 30, LinkagePiece::Joint));
        out.push_back(joint(joints[2], axis, 32, 60));
        out.push_back(bar(joints[2], p - dir * torchLength, 18, LinkagePiece::Link));
        addTorch(out, p, dir, torchLength, pathCuts);

        // Groove arm: modified-DH frames 0..5 (core FK) in the world; joint i turns about z_i
        // at frame i's origin; the torch tip is frame 5's origin, the torch along x5.
        Pose f[6];
        cell.groove.frames({q[3], q[4], q[5], q[6], q[7]}, f);
        Vec3 o[6], z[6];
        for (int i = 0; i < 6; ++i) {
            const Pose w = grooveBase * f[i];
            o[i] = w.translation();
            z[i] = w.linear().col(2);
        }
        const Vec3 gz = grooveBase.linear().col(2);
        const Vec3 gMount = grooveBase.translation() - gz * 260;
        out.push_back(bar(grooveBase.translation() - gz * 60, gMount, 50, LinkagePiece::Frame));
        out.push_back(block({gMount.x(), gMount.y(), (gMount.z() + 80 + floor) / 2},
                            {140, 140, gMount.z() + 80 - floor}, LinkagePiece::Frame));
        out.push_back(joint(o[1], z[1], 55, 120));
        out.push_back(bar(o[1], o[2], 34, LinkagePiece::Link));
        out.push_back(joint(o[2], z[2], 45, 110));
        out.push_back(bar(o[2], o[3], 28, LinkagePiece::Link));
        out.push_back(joint(o[3], z[3], 34, 90));
        out.push_back(joint(o[4], z[4], 30, 80));
        const Vec3 gt = (grooveBase * f[5]).linear().col(0);
        out.push_back(bar(o[4], o[5] - gt * torchLength, 16, LinkagePiece::Link));
        out.push_back(joint(o[5] - gt * torchLength, z[5], 20, 60)); // bevel head
        addTorch(out, o[5], gt, torchLength, !pathCuts);
        return out;
    };
    return m;
}

} // namespace cutcell::view3d
