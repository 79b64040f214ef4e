#include "ui/view3d/cell_scene.h"

#include "ui/view3d/cell_scene_impl.h"
#include "ui/view3d/scene_geometry.h"

#include <vtkCellArray.h>
#include <vtkLightKit.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell::view3d {

namespace {

constexpr int kFacets = 64;
constexpr size_t kMaxDrawnPathPoints = 5000;

vtkSmartPointer<vtkActor> makeActor(vtkPolyData* pd, Rgb c, double opacity = 1.0) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(pd);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* p = actor->GetProperty();
    p->SetColor(c.r, c.g, c.b);
    p->SetOpacity(opacity);
    p->SetDiffuse(0.8);
    p->SetAmbient(0.15);
    p->SetSpecular(0.25);
    p->SetSpecularPower(25);
    return actor;
}

void setPose(vtkActor* actor, const Eigen::Matrix4d& m) {
    vtkMatrix4x4* um = actor->GetUserMatrix();
    if (!um) {
        vtkNew<vtkMatrix4x4> fresh;
        actor->SetUserMatrix(fresh);
        um = fresh;
    }
    toVtkMatrix(m, um);
    um->Modified();
    actor->Modified();
}

unsigned char byte(double v) {
    return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
}

Eigen::Matrix4d scaled(const Pose& frame, double rx, double ry, double rz) {
    Eigen::Matrix4d m = frame.matrix();
    m.block<3, 1>(0, 0) *= rx;
    m.block<3, 1>(0, 1) *= ry;
    m.block<3, 1>(0, 2) *= rz;
    return m;
}

} // namespace

CellScene::CellScene() : d(std::make_unique<Impl>()) {
    d->renderer->GradientBackgroundOn();
    d->renderer->SetBackground(colours::kBackgroundBottom.r, colours::kBackgroundBottom.g,
                               colours::kBackgroundBottom.b);
    d->renderer->SetBackground2(colours::kBackgroundTop.r, colours::kBackgroundTop.g,
                                colours::kBackgroundTop.b);
    d->renderer->AutomaticLightCreationOff();
    vtkNew<vtkLightKit> lights;
    lights->SetKeyLightIntensity(0.85);
    lights->AddLightsToRenderer(d->renderer);
}

CellScene::~CellScene() = default;

vtkRenderer* CellScene::renderer() const {
    return d->renderer;
}
const SceneModel& CellScene::model() const {
    return d->model;
}
bool CellScene::hasScene() const {
    return d->hasScene;
}

void CellScene::setScene(const SceneModel& model) {
    d->model = model;
    d->hasScene = true;
    d->q = model.homeQ;
    d->progress = 0;
    d->stopProgress = -1; // a new plan: the old stop point means nothing on it
    d->torchOn = false;
    d->done = -1;
    d->statusKey = -1;
    d->build();
    d->place();
    d->updateDone(0);
    d->updateStatus();
    d->applyCamera(d->preset);
}

void CellScene::setMachineState(const JointVector& q, double progressFraction, bool torchOn) {
    if (!d->hasScene) return;
    d->q = q;
    d->progress = std::clamp(std::isfinite(progressFraction) ? progressFraction : 0.0, 0.0, 1.0);
    d->torchOn = torchOn;
    d->place();
    const int n = static_cast<int>(d->model.pathWork.size());
    const int count =
        d->progress <= 0 || n == 0 ? 0 : 1 + static_cast<int>(std::lround(d->progress * (n - 1)));
    d->updateDone(std::min(count, n));
    d->updateStatus();
    if (d->preset == ViewPreset::FollowTorch) d->applyCamera(ViewPreset::FollowTorch);
}

void CellScene::setStopMark(double progressFraction) {
    d->stopProgress = std::isfinite(progressFraction) ? std::min(progressFraction, 1.0) : -1.0;
    if (!d->hasScene) return;
    d->placeStopMark();
    d->place();
}

void CellScene::Impl::placeStopMark() {
    if (!stopMark) return;
    const size_t n = model.pathWork.size();
    if (stopProgress < 0 || n == 0) {
        stopMark->VisibilityOff();
        return;
    }
    const size_t i = std::min(
        n - 1, static_cast<size_t>(std::lround(stopProgress * static_cast<double>(n - 1))));
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    local.block<3, 1>(0, 3) = liftedPathPoint(i, 2.4); // over the done part
    workLocal[stopMarkSlot] = local;
    stopMark->VisibilityOn();
}

void CellScene::Impl::build() {
    renderer->RemoveAllViewProps();
    workActors.clear();
    workLocal.clear();
    arm.clear();
    fixedActors.clear();
    linkageActors.clear();
    pipe = path = doneActor = unreachableActor = stopMark = nullptr;
    torchBody = nozzle = flame = carriage = direction = nullptr;
    donePoly = nullptr;
    donePts = nullptr;
    drawnIndex.clear();
    if (model.linkage) {
        buildLinkage();
        if (!model.pathWork.empty()) buildPath();
    } else {
        buildPipeCell();
    }
    buildFloorAndTexts();
}

void CellScene::Impl::buildLinkage() {
    const std::vector<LinkagePiece> pieces = model.linkage(model.homeQ);
    vtkSmartPointer<vtkPolyData> unitBar = makeFrustum(1, 1, 0, 1, 24, true);
    vtkSmartPointer<vtkPolyData> unitBlock = makeBox(1, 1, 1);
    for (const LinkagePiece& p : pieces) {
        const Rgb c = p.colour == LinkagePiece::Frame   ? colours::kMachine
                      : p.colour == LinkagePiece::Joint ? colours::kArmJoint
                      : p.colour == LinkagePiece::Work  ? colours::kPipe
                      : p.colour == LinkagePiece::Tool  ? colours::kTorchBody
                      : p.colour == LinkagePiece::Flame ? colours::kFlame
                                                        : colours::kArmLink;
        vtkSmartPointer<vtkPolyData> shape = p.kind == LinkagePiece::Bar ? unitBar : unitBlock;
        auto a = makeActor(shape, c);
        if (p.colour == LinkagePiece::Flame) a->GetProperty()->LightingOff();
        renderer->AddActor(a);
        linkageActors.push_back(a);
    }
    for (const auto& mesh : model.workMeshes) {
        if (!mesh) continue;
        vtkNew<vtkPolyData> shape;
        vtkNew<vtkPoints> pts;
        vtkNew<vtkCellArray> tris;
        for (const Vec3& v : mesh->points)
            pts->InsertNextPoint(v.x(), v.y(), v.z());
        for (const auto& t : mesh->triangles) {
            const vtkIdType ids[3] = {t[0], t[1], t[2]};
            tris->InsertNextCell(3, ids);
        }
        shape->SetPoints(pts);
        shape->SetPolys(tris);
        auto a = makeActor(shape, colours::kPipe);
        renderer->AddActor(a);
        fixedActors.push_back(a);
    }
    placeLinkage();
}

void CellScene::Impl::placeLinkage() {
    const std::vector<LinkagePiece> pieces = model.linkage(q);
    for (size_t i = 0; i < std::min(pieces.size(), linkageActors.size()); ++i) {
        const LinkagePiece& p = pieces[i];
        if (p.colour == LinkagePiece::Flame) linkageActors[i]->SetVisibility(torchOn);
        if (p.kind == LinkagePiece::Bar) {
            if ((p.b - p.a).norm() > 1e-9)
                setPose(linkageActors[i], segmentMatrix(p.a, p.b, p.radius_mm));
            continue;
        }
        Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
        m.diagonal().head<3>() = p.b.cwiseMax(1e-3);
        m.block<3, 1>(0, 3) = p.a;
        setPose(linkageActors[i], m);
    }
}

void CellScene::Impl::buildPipeCell() {
    const SceneModel& m = model;
    const Eigen::Matrix4d I = Eigen::Matrix4d::Identity();

    // Work pipe with its wall.
    const double R = m.workPipe.radius_mm;
    const double rIn = std::max(0.0, R - m.workPipe.wall_mm);
    const double z0 = m.workPipeCentreZ_mm - m.workPipe.length_mm / 2;
    const double z1 = m.workPipeCentreZ_mm + m.workPipe.length_mm / 2;
    pipe = addWork(makeActor(makeTube(R, rIn, z0, z1, kFacets * 2), colours::kPipe), I);
    pipe->GetProperty()->SetSpecular(0.45);
    pipe->GetProperty()->SetSpecularPower(30);

    // Chuck at the end farther from the machine's base (it turns with the pipe).
    const Vec3 e0 = m.baseFromWorkAtZero * Vec3(0, 0, z0);
    const Vec3 e1 = m.baseFromWorkAtZero * Vec3(0, 0, z1);
    const double s = e1.head<2>().norm() > e0.head<2>().norm() ? 1.0 : -1.0;
    const double zEnd = s > 0 ? z1 : z0;
    const double chuckR = R * 1.45 + 15;
    addWork(makeActor(makeFrustum(chuckR, chuckR, zEnd - s * 20, zEnd + s * 70, kFacets, true),
                      colours::kMachine),
            I);
    for (int j = 0; j < 3; ++j) {
        Pose jaw = Pose::Identity();
        jaw.rotate(Eigen::AngleAxisd(2 * kPi * j / 3 + kPi / 2, Vec3::UnitZ()));
        jaw.translate(Vec3(R + 14, 0, zEnd - s * 38));
        addWork(makeActor(makeBox(26, 22, 34), colours::kArmLink), jaw.matrix());
    }
    // Headstock behind the chuck (does not turn), down to the floor.
    const Vec3 axis = m.baseFromWorkAtZero.linear().col(2) * s;
    const Vec3 hc = m.baseFromWorkAtZero * Vec3(0, 0, zEnd + s * 110);
    const double top = hc.z() + chuckR;
    const Vec3 size = axis.cwiseAbs() * 80 + (Vec3::Ones() - axis.cwiseAbs()) * (1.8 * chuckR);
    auto head = makeActor(makeBox(size.x(), size.y(), top - m.floorZ_mm), colours::kMachine);
    head->SetPosition(hc.x(), hc.y(), (top + m.floorZ_mm) / 2);
    renderer->AddActor(head);
    fixedActors.push_back(head);

    // Mating pipe, ghosted as a wireframe: a translucent surface would cost VTK's
    // order-independent translucency pass, ~30 % of the frame on llvmpipe.
    if (m.hasMatingPipe) {
        auto ghost =
            makeActor(makeWireTube(m.matingPipe.radius_mm, m.matingPipe.length_mm, 16, 5, kFacets),
                      colours::kMating, colours::kMatingOpacity);
        ghost->GetProperty()->LightingOff();
        ghost->GetProperty()->SetLineWidth(1.0f);
        addWork(ghost, m.workFromMating.matrix());
    }

    buildPath();

    // Arm: joints on the z axis of frames 0..n-1, links along z (d) then x (a), the last link
    // being the torch itself.
    if (m.mount == ToolMount::DhArm) {
        auto pedestal =
            makeActor(makeFrustum(58, 48, m.floorZ_mm, -40, kFacets, true), colours::kMachine);
        renderer->AddActor(pedestal);
        fixedActors.push_back(pedestal);
        vtkSmartPointer<vtkPolyData> unitJoint = makeFrustum(1, 1, -0.5, 0.5, 32, true);
        vtkSmartPointer<vtkPolyData> unitLink = makeFrustum(1, 1, 0, 1, 24, true);
        const int links = static_cast<int>(m.armChain.size());
        for (int i = 0; i < links; ++i) {
            const double scale = std::max(0.45, 1.0 - 0.12 * i);
            ArmPiece joint{ArmPiece::Joint, i, 42 * scale, 95 * scale,
                           makeActor(unitJoint, colours::kArmJoint)};
            arm.push_back(joint);
            if (i == links - 1) break; // the torch
            const DhLink& l = m.armChain.link(static_cast<size_t>(i));
            if (std::fabs(l.d_mm) > 1e-6)
                arm.push_back({ArmPiece::LinkAlongZ, i, 30 * scale, 0,
                               makeActor(unitLink, colours::kArmLink)});
            if (std::fabs(l.a_mm) > 1e-6)
                arm.push_back({ArmPiece::LinkAlongX, i, 28 * scale, 0,
                               makeActor(unitLink, colours::kArmLink)});
        }
        for (ArmPiece& p : arm)
            renderer->AddActor(p.actor);
    }

    // Torch in the tool frame: tip at the origin, axis +z into the work.
    const double L = m.toolLength_mm;
    carriage = nullptr;
    if (m.mount == ToolMount::LinearCarriage) {
        // A fixed rail along the carriage axis above the torch, and the carriage block on it.
        const Vec3 dir = m.carriageDirection.normalized();
        const Vec3 up = -m.carriageApproach.normalized();
        const Vec3 c = m.carriageOrigin + dir * m.workPipeCentreZ_mm + up * (L + 45);
        const Vec3 railSize =
            dir.cwiseAbs() * (m.workPipe.length_mm + 300) + (Vec3::Ones() - dir.cwiseAbs()) * 40;
        auto rail = makeActor(makeBox(railSize.x(), railSize.y(), railSize.z()), colours::kMachine);
        rail->SetPosition(c.x(), c.y(), c.z());
        renderer->AddActor(rail);
        fixedActors.push_back(rail);
        carriage = makeActor(makeBox(70, 70, 50), colours::kArmLink);
        renderer->AddActor(carriage);
    }
    torchBody = makeActor(makeFrustum(16, 16, -L, -0.3 * L, kFacets, true), colours::kTorchBody);
    nozzle = makeActor(makeFrustum(11, 3.5, -0.3 * L, -3, kFacets, true), colours::kNozzle);
    nozzle->GetProperty()->SetSpecular(0.6);
    flame = makeActor(makeFrustum(5.5, 1.5, -3.5, 1.0, 24, true), colours::kFlame, 1.0);
    flame->GetProperty()->SetAmbient(1.0);
    flame->GetProperty()->SetDiffuse(0.0);
    flame->GetProperty()->LightingOff();
    for (auto* a : {torchBody.Get(), nozzle.Get(), flame.Get()})
        renderer->AddActor(a);
    direction = makeActor(makeFrustum(1, 0, 0, 1, 24, true), colours::kDirection);
    direction->GetProperty()->SetAmbient(0.5);
    renderer->AddActor(direction);
}

vtkSmartPointer<vtkActor> CellScene::Impl::addWork(vtkSmartPointer<vtkActor> a,
                                                   const Eigen::Matrix4d& local) {
    renderer->AddActor(a);
    workActors.push_back(a);
    workLocal.push_back(local);
    return a;
}

void CellScene::Impl::buildPath() {
    const SceneModel& m = model;
    const Eigen::Matrix4d I = Eigen::Matrix4d::Identity();
    const double R = m.workPipe.radius_mm;
    // Planned path lifted 0.8 mm off the surface so it never hides in it; the done part 1.6 mm,
    // so it is drawn over the planned path. At most kMaxDrawnPathPoints are drawn (a 30 000-point
    // plan is far denser than the screen); a drawn point is red when any plan point it stands
    // for is unreachable, and carries a red marker.
    const size_t n = m.pathWork.size();
    const size_t stride = std::max<size_t>(1, (n + kMaxDrawnPathPoints - 1) / kMaxDrawnPathPoints);
    drawnIndex.clear();
    for (size_t i = 0; i < n; i += stride)
        drawnIndex.push_back(i);
    if (n > 0 && drawnIndex.back() != n - 1) drawnIndex.push_back(n - 1);
    const vtkIdType nd = static_cast<vtkIdType>(drawnIndex.size());
    vtkNew<vtkPoints> pts;
    donePts = vtkSmartPointer<vtkPoints>::New();
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetNumberOfComponents(3);
    rgb->SetName("colours");
    vtkNew<vtkCellArray> polyline;
    vtkNew<vtkCellArray> bad;
    pts->SetNumberOfPoints(nd);
    donePts->SetNumberOfPoints(nd + 1); // + the exact current point
    // Every slot must hold a real point: VTK reads all of them (bounds, the VBO's shift and
    // scale), and garbage there broke the whole frame now and then.
    if (nd > 0) {
        const Vec3 first = liftedPathPoint(drawnIndex.front(), 1.6);
        donePts->SetPoint(nd, first.x(), first.y(), first.z());
    } else {
        donePts->SetPoint(0, 0, 0, 0);
    }
    rgb->SetNumberOfTuples(nd);
    if (nd >= 2) polyline->InsertNextCell(static_cast<int>(nd)); // 0 or 1 point: nothing
    unreachable = 0;
    for (size_t i = 0; i < std::min(n, m.reachable.size()); ++i)
        unreachable += m.reachable[i] ? 0 : 1;
    for (vtkIdType k = 0; k < nd; ++k) {
        const size_t i = drawnIndex[static_cast<size_t>(k)];
        const Vec3 lifted = liftedPathPoint(i, 0.8);
        pts->SetPoint(k, lifted.x(), lifted.y(), lifted.z());
        const Vec3 above = liftedPathPoint(i, 1.6);
        donePts->SetPoint(k, above.x(), above.y(), above.z());
        if (nd >= 2) polyline->InsertCellPoint(k);
        const size_t windowEnd = k + 1 < nd ? drawnIndex[static_cast<size_t>(k) + 1] : n;
        bool ok = true;
        for (size_t j = i; j < std::min(windowEnd, m.reachable.size()); ++j)
            ok = ok && m.reachable[j];
        const Rgb c = ok ? colours::kPath : colours::kUnreachable;
        const unsigned char t[3] = {byte(c.r), byte(c.g), byte(c.b)};
        rgb->SetTypedTuple(k, t);
        if (!ok) bad->InsertNextCell(1, &k);
    }
    vtkNew<vtkPolyData> pathPoly;
    pathPoly->SetPoints(pts);
    pathPoly->SetLines(polyline);
    pathPoly->GetPointData()->SetScalars(rgb);
    path = makeActor(pathPoly, colours::kPath);
    path->GetMapper()->ScalarVisibilityOn();
    path->GetMapper()->SetColorModeToDirectScalars();
    path->GetProperty()->LightingOff();
    path->GetProperty()->SetLineWidth(2.5f);
    addWork(path, I);

    donePoly = vtkSmartPointer<vtkPolyData>::New();
    donePoly->SetPoints(donePts);
    donePoly->SetLines(vtkNew<vtkCellArray>());
    doneActor = makeActor(donePoly, colours::kDone);
    doneActor->GetProperty()->LightingOff();
    doneActor->GetProperty()->SetLineWidth(5.0f);
    addWork(doneActor, I);

    vtkNew<vtkPolyData> badPoly;
    badPoly->SetPoints(pts);
    badPoly->SetVerts(bad);
    unreachableActor = makeActor(badPoly, colours::kUnreachable);
    unreachableActor->GetProperty()->SetPointSize(8.0f);
    unreachableActor->GetProperty()->RenderPointsAsSpheresOn();
    unreachableActor->GetProperty()->LightingOff();
    unreachableActor->SetVisibility(unreachable > 0);
    addWork(unreachableActor, I);

    // The stop mark: a small block on the path where the last run stopped (cut recovery).
    const double markMm = std::clamp(R * 0.2, 8.0, 24.0);
    stopMark = addWork(makeActor(makeBox(markMm, markMm, markMm), colours::kStopMark), I);
    stopMark->GetProperty()->LightingOff();
    stopMarkSlot = workActors.size() - 1;
    placeStopMark();
}

void CellScene::Impl::buildFloorAndTexts() {
    const SceneModel& m = model;
    // Floor grid and axes triad around what is drawn.
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    const double margin = 250, step = 50;
    const double gx0 = std::floor((b[0] - margin) / step) * step,
                 gx1 = std::ceil((b[1] + margin) / step) * step;
    const double gy0 = std::floor((b[2] - margin) / step) * step,
                 gy1 = std::ceil((b[3] + margin) / step) * step;
    grid = makeActor(makeGrid(gx0, gx1, gy0, gy1, step, m.floorZ_mm), colours::kGrid);
    grid->GetProperty()->LightingOff();
    grid->SetUseBounds(false); // the camera frames the machine, not the floor
    renderer->AddActor(grid);
    auto triad = makeActor(makeTriad(120), colours::kText);
    triad->GetMapper()->ScalarVisibilityOn();
    triad->GetMapper()->SetColorModeToDirectScalars();
    triad->GetProperty()->LightingOff();
    triad->GetProperty()->SetLineWidth(3.0f);
    triad->SetPosition(gx0 + step, gy0 + step, m.floorZ_mm + 1);
    triad->SetUseBounds(false);
    renderer->AddActor(triad);
    fixedActors.push_back(triad);

    title = vtkSmartPointer<vtkTextActor>::New();
    title->SetInput(m.title.c_str());
    title->GetTextProperty()->SetFontSize(
        std::max(4, static_cast<int>(kTitleFontPx * pixelScale + 0.5)));
    title->GetTextProperty()->SetColor(colours::kText.r, colours::kText.g, colours::kText.b);
    title->GetTextProperty()->SetVerticalJustificationToTop();
    title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    title->SetPosition(0.012, 0.985);
    renderer->AddActor2D(title);
    status = vtkSmartPointer<vtkTextActor>::New();
    status->GetTextProperty()->SetFontSize(
        std::max(4, static_cast<int>(kStatusFontPx * pixelScale + 0.5)));
    status->GetTextProperty()->SetColor(colours::kText.r, colours::kText.g, colours::kText.b);
    status->SetPosition(10 * pixelScale, 8 * pixelScale);
    renderer->AddActor2D(status);
}

void CellScene::Impl::place() {
    const Pose work = model.baseFromWork(q);
    for (size_t i = 0; i < workActors.size(); ++i)
        setPose(workActors[i], work.matrix() * workLocal[i]);
    if (model.linkage) {
        placeLinkage();
        return;
    }
    if (model.mount == ToolMount::DhArm) {
        const std::vector<Pose> frames = model.armFrames(q);
        for (ArmPiece& p : arm) {
            const Pose& f = frames[static_cast<size_t>(p.frame)];
            if (p.kind == ArmPiece::Joint) {
                setPose(p.actor, scaled(f, p.radius, p.radius, p.height));
                continue;
            }
            const DhLink& l = model.armChain.link(static_cast<size_t>(p.frame));
            const Vec3 a = f.translation();
            const Vec3 mid = a + f.linear().col(2) * l.d_mm; // after Tz(d), before Tx(a)
            const Vec3 b = frames[static_cast<size_t>(p.frame) + 1].translation();
            setPose(p.actor, p.kind == ArmPiece::LinkAlongZ ? segmentMatrix(a, mid, p.radius)
                                                            : segmentMatrix(mid, b, p.radius));
        }
    }
    const Eigen::Matrix4d tool = model.toolPose(q).matrix();
    for (auto* a : {torchBody.Get(), nozzle.Get(), flame.Get()})
        setPose(a, tool);
    if (carriage) { // the block sits on the torch's back end (tool frame -z)
        Eigen::Matrix4d block = tool;
        block.block<3, 1>(0, 3) -= tool.block<3, 1>(0, 2) * (model.toolLength_mm + 25);
        setPose(carriage, block);
    }
    flame->SetVisibility(torchOn);

    // Cutting direction: the path's tangent at the current point, drawn just off the surface.
    const size_t n = model.pathWork.size();
    direction->SetVisibility(n >= 2);
    if (n >= 2) {
        const size_t i = std::min(
            n - 2, static_cast<size_t>(std::lround(progress * static_cast<double>(n - 1))));
        const Vec3 tangent = work.linear() * (model.pathWork[i + 1] - model.pathWork[i]);
        const Vec3 axis = tool.block<3, 1>(0, 2);
        if (tangent.norm() > 1e-12) {
            const Vec3 start =
                Vec3(tool.block<3, 1>(0, 3)) - axis * 6.0 + tangent.normalized() * 6.0;
            setPose(direction, segmentMatrix(start, start + tangent.normalized() * 18.0, 3.0));
        }
    }
}

void CellScene::Impl::updateDone(int count) {
    if (count == done || !donePoly) return;
    done = count;
    vtkNew<vtkCellArray> lines;
    if (count >= 2) {
        // Drawn points already passed, then the exact current point.
        const size_t last = static_cast<size_t>(count) - 1;
        const auto upto =
            std::upper_bound(drawnIndex.begin(), drawnIndex.end(), last) - drawnIndex.begin();
        const bool exact = upto > 0 && drawnIndex[static_cast<size_t>(upto) - 1] == last;
        lines->InsertNextCell(static_cast<int>(upto + (exact ? 0 : 1)));
        for (vtkIdType k = 0; k < upto; ++k)
            lines->InsertCellPoint(k);
        if (!exact) {
            const vtkIdType slot = static_cast<vtkIdType>(drawnIndex.size());
            const Vec3 p = liftedPathPoint(last, 1.6);
            donePts->SetPoint(slot, p.x(), p.y(), p.z());
            donePts->Modified();
            lines->InsertCellPoint(slot);
        }
    }
    donePoly->SetLines(lines);
    donePoly->Modified();
}

Vec3 CellScene::Impl::liftedPathPoint(size_t i, double mm) const {
    const Vec3& p = model.pathWork[i];
    // No pipe (a linkage machine's work): off the surface against the torch.
    if (model.workPipe.radius_mm <= 0 && i < model.approachWork.size())
        return p - mm * model.approachWork[i].normalized();
    const Vec3 radial(p.x(), p.y(), 0);
    return radial.norm() > 1e-9 ? Vec3(p + mm * radial.normalized()) : p;
}

void CellScene::Impl::updateStatus() {
    const int percent = static_cast<int>(std::floor(progress * 100 + 1e-9));
    const int key = percent * 2 + (torchOn ? 1 : 0);
    if (key == statusKey) return;
    statusKey = key;
    char buf[200];
    // Short: at 1280x720 the view is ~500 px wide and a longer line ran past its edge.
    const char* tool = toolName.c_str();
    const char* state = (torchOn ? words.on : words.off).c_str();
    if (model.linkage &&
        model.pathWork.empty()) // no planned path: the machine follows a control law
        std::snprintf(buf, sizeof buf, "%d %%  |  %s %s", percent, tool, state);
    else if (unreachable > 0)
        std::snprintf(buf, sizeof buf, "%d %%  |  %s %s  |  %d %s", percent, tool, state,
                      unreachable, words.notReachable.c_str());
    else
        std::snprintf(buf, sizeof buf, "%d %%  |  %s %s  |  %zu %s", percent, tool, state,
                      model.pathWork.size(), words.reachable.c_str());
    status->SetInput(buf);
}

namespace {
Vec3 apply(vtkActor* a, const Vec3& p) {
    double in[4] = {p.x(), p.y(), p.z(), 1}, out[4];
    a->GetMatrix()->MultiplyPoint(in, out);
    return {out[0], out[1], out[2]};
}
} // namespace

Vec3 CellScene::torchTipWorld() const {
    return d->torchBody ? apply(d->torchBody, Vec3::Zero()) : Vec3::Zero();
}

Vec3 CellScene::torchAxisWorld() const {
    if (!d->torchBody) return Vec3::UnitZ();
    return (apply(d->torchBody, Vec3::UnitZ()) - torchTipWorld()).normalized();
}

Vec3 CellScene::torchBodyCentreWorld() const {
    return d->torchBody ? apply(d->torchBody, Vec3(0, 0, -0.65 * d->model.toolLength_mm))
                        : Vec3::Zero();
}

Vec3 CellScene::pipeCentreWorld() const {
    return d->pipe ? apply(d->pipe, Vec3(0, 0, d->model.workPipeCentreZ_mm)) : Vec3::Zero();
}

Vec3 CellScene::pipeSurfaceWorld(double zWork, double angleRad) const {
    const double R = d->model.workPipe.radius_mm;
    return d->pipe ? apply(d->pipe, Vec3(R * std::cos(angleRad), R * std::sin(angleRad), zWork))
                   : Vec3::Zero();
}

void CellScene::setToolName(const std::string& name) {
    d->toolName = name.empty() ? std::string("tool") : name;
    d->statusKey = -1;
    if (d->hasScene) d->updateStatus();
}

void CellScene::setStatusWords(const StatusWords& words) {
    d->words = words;
    d->statusKey = -1;
    if (d->hasScene) d->updateStatus();
}

std::string CellScene::statusText() const {
    const char* text = d->status ? d->status->GetInput() : nullptr;
    return text ? text : "";
}

int CellScene::doneCount() const {
    return std::max(0, d->done);
}
int CellScene::unreachableShown() const {
    return d->unreachable;
}
int CellScene::drawnPathPoints() const {
    return static_cast<int>(d->drawnIndex.size());
}
bool CellScene::flameVisible() const {
    return d->flame && d->flame->GetVisibility();
}
const JointVector& CellScene::machineQ() const {
    return d->q;
}

} // namespace cutcell::view3d
