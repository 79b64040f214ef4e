#pragma once
// Qt mouse and wheel events into a VTK interactor (the trackball camera style): shared by both
// 3D surfaces (VtkGlWidget, VtkGlWindow). `pixelScale` turns Qt's logical coordinates into the
// render window's pixels (device pixel ratio times the render scale).
#include <QMouseEvent>
#include <QWheelEvent>

class vtkRenderWindowInteractor;

namespace cutcell::view3d {

// Each returns whether the event reached the interactor (the surface then asks for a frame).
bool forwardMousePress(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale,
                       bool doubleClick = false);
bool forwardMouseRelease(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale);
bool forwardMouseMove(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale);
bool forwardWheel(vtkRenderWindowInteractor* interactor, QWheelEvent* e, qreal pixelScale);

} // namespace cutcell::view3d
