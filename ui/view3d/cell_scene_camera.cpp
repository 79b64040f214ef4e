// Camera presets of the cell view (part of CellScene).
#include "ui/view3d/cell_scene.h"
#include "ui/view3d/cell_scene_impl.h"

#include <vtkCamera.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace cutcell::view3d {

namespace {
// Direction from the focal point to the camera, and the view-up, of each fixed preset.
struct Look {
    Vec3 toCamera;
    Vec3 up;
};
Look lookFor(ViewPreset p, const Vec3& iso) {
    switch (p) {
    case ViewPreset::Front:
        return {Vec3(0, -1, 0), Vec3::UnitZ()};
    case ViewPreset::Top:
        return {Vec3(0, 0, 1), Vec3::UnitY()};
    case ViewPreset::Iso:
    case ViewPreset::FollowTorch:
        break;
    }
    return {iso.normalized(), Vec3::UnitZ()};
}
// The middle of a linkage's tool pieces at q (the origin without any).
Vec3 linkageToolCentre(const SceneModel& model, const JointVector& q) {
    if (!model.linkage) return Vec3::Zero();
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (const LinkagePiece& piece : model.linkage(q))
        if (piece.colour == LinkagePiece::Tool) {
            sum += 0.5 * (piece.a + piece.b);
            ++count;
        }
    return count ? Vec3(sum / count) : Vec3(Vec3::Zero());
}

} // namespace

void CellScene::Impl::applyCamera(ViewPreset p) {
    vtkCamera* cam = renderer->GetActiveCamera();
    if (p == ViewPreset::FollowTorch) {
        // A linkage machine has no tool pose: follow the current point of its path, or without
        // a path (the flying saw) the middle of its tool pieces (the two blades: the cut).
        const size_t n = model.pathWork.size();
        const Vec3 tip =
            torchBody ? Vec3(model.toolPose(q).translation())
            : n > 0
                ? model.pathPointWorld(std::min(n - 1, static_cast<size_t>(std::lround(
                                                           progress * static_cast<double>(n - 1)))),
                                       q)
                : linkageToolCentre(model, q);
        if (preset != ViewPreset::FollowTorch || !hasScene) return;
        double f[3], pos[3];
        cam->GetFocalPoint(f);
        cam->GetPosition(pos);
        const bool fresh = followTip.x() > 1e299; // set by setPreset
        if (fresh) {
            // First frame of the follow mode: close to the tip, from the iso side.
            const Vec3 dir = lookFor(ViewPreset::Iso, model.followToCamera.squaredNorm() > 0
                                                          ? model.followToCamera
                                                          : model.isoToCamera)
                                 .toCamera;
            // Close to the tip, but never inside the tool: a machine without a torch length
            // (the saw: 0 mm) put the camera at the tip and the view was empty. At least a
            // fifth of the scene's extent, so the work around the tip is in view.
            double b[6];
            renderer->ComputeVisiblePropBounds(b);
            const double extent =
                b[0] <= b[1] ? Vec3(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm() : 0.0;
            const double distance = std::max({1.8 * model.toolLength_mm, 0.2 * extent, 150.0});
            const Vec3 c = tip + dir * distance;
            cam->SetFocalPoint(tip.x(), tip.y(), tip.z());
            cam->SetPosition(c.x(), c.y(), c.z());
            cam->SetViewUp(0, 0, 1);
        } else {
            // Keep the user's orbit: move the camera with the tip.
            const Vec3 delta = tip - followTip;
            cam->SetFocalPoint(f[0] + delta.x(), f[1] + delta.y(), f[2] + delta.z());
            cam->SetPosition(pos[0] + delta.x(), pos[1] + delta.y(), pos[2] + delta.z());
        }
        followTip = tip;
        renderer->ResetCameraClippingRange();
        return;
    }
    const Look look = lookFor(p, model.isoToCamera);
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    if (b[0] > b[1]) return; // nothing to frame
    const Vec3 centre((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
    cam->SetFocalPoint(centre.x(), centre.y(), centre.z());
    const Vec3 pos = centre + look.toCamera * 1000.0;
    cam->SetPosition(pos.x(), pos.y(), pos.z());
    cam->SetViewUp(look.up.x(), look.up.y(), look.up.z());
    cam->SetViewAngle(30);
    renderer->ResetCamera(b);
    cam->Zoom(1.15); // ResetCamera leaves a wide margin
    renderer->ResetCameraClippingRange();
}

void CellScene::setPreset(ViewPreset preset) {
    d->preset = preset;
    if (preset == ViewPreset::FollowTorch)
        d->followTip = Vec3(1e300, 0, 0); // forces a fresh framing
    d->applyCamera(preset);
}

ViewPreset CellScene::preset() const {
    return d->preset;
}

void CellScene::resetView() {
    setPreset(ViewPreset::Iso);
}

void CellScene::setPixelScale(double scale) {
    if (!(scale > 0) || scale == d->pixelScale) return;
    d->pixelScale = scale;
    const auto px = [scale](int size) { return std::max(4, static_cast<int>(size * scale + 0.5)); };
    if (d->title) d->title->GetTextProperty()->SetFontSize(px(Impl::kTitleFontPx));
    if (d->status) {
        d->status->GetTextProperty()->SetFontSize(px(Impl::kStatusFontPx));
        d->status->SetPosition(10 * scale, 8 * scale);
    }
}

void CellScene::prepareRender() {
    // A short view (1280x720 screens) has no room for the job title above the machine: the
    // window title names the job; the title comes back when the view is tall enough.
    if (d->title) {
        const int* size = d->renderer->GetSize();
        d->title->SetVisibility(size[1] >= kTitleMinViewHeightPx * d->pixelScale ? 1 : 0);
    }
    double b[6];
    d->renderer->ComputeVisiblePropBounds(b);
    if (b[0] > b[1]) return;
    // Include the floor grid (not part of the bounds used to frame the machine).
    if (d->grid) {
        const double* g = d->grid->GetBounds();
        for (int i = 0; i < 6; i += 2) {
            b[i] = std::min(b[i], g[i]);
            b[i + 1] = std::max(b[i + 1], g[i + 1]);
        }
    }
    d->renderer->ResetCameraClippingRange(b);
}

std::array<double, 6> CellScene::machineBounds() const {
    std::array<double, 6> b{};
    d->renderer->ComputeVisiblePropBounds(b.data());
    return b;
}

} // namespace cutcell::view3d
