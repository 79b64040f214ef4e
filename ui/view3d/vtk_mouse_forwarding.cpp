#include "ui/view3d/vtk_mouse_forwarding.h"

#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>

namespace cutcell::view3d {
namespace {

unsigned long pressEvent(Qt::MouseButton b) {
    switch (b) {
    case Qt::LeftButton:
        return vtkCommand::LeftButtonPressEvent;
    case Qt::MiddleButton:
        return vtkCommand::MiddleButtonPressEvent;
    case Qt::RightButton:
        return vtkCommand::RightButtonPressEvent;
    default:
        return vtkCommand::NoEvent;
    }
}

unsigned long releaseEvent(Qt::MouseButton b) {
    switch (b) {
    case Qt::LeftButton:
        return vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
        return vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
        return vtkCommand::RightButtonReleaseEvent;
    default:
        return vtkCommand::NoEvent;
    }
}

bool forward(vtkRenderWindowInteractor* interactor, QMouseEvent* e, unsigned long vtkEvent,
             qreal pixelScale, bool doubleClick) {
    if (vtkEvent == vtkCommand::NoEvent) return false;
    const QPointF p = e->position() * pixelScale;
    const Qt::KeyboardModifiers mods = e->modifiers();
    interactor->SetEventInformationFlipY(
        static_cast<int>(p.x()), static_cast<int>(p.y()), (mods & Qt::ControlModifier) ? 1 : 0,
        (mods & Qt::ShiftModifier) ? 1 : 0, 0, doubleClick ? 1 : 0);
    interactor->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
    interactor->InvokeEvent(vtkEvent, e);
    return true;
}

} // namespace

bool forwardMousePress(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale,
                       bool doubleClick) {
    return forward(interactor, e, pressEvent(e->button()), pixelScale, doubleClick);
}

bool forwardMouseRelease(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale) {
    return forward(interactor, e, releaseEvent(e->button()), pixelScale, false);
}

bool forwardMouseMove(vtkRenderWindowInteractor* interactor, QMouseEvent* e, qreal pixelScale) {
    // Only drags move the camera.
    return e->buttons() != Qt::NoButton &&
           forward(interactor, e, vtkCommand::MouseMoveEvent, pixelScale, false);
}

bool forwardWheel(vtkRenderWindowInteractor* interactor, QWheelEvent* e, qreal pixelScale) {
    const int delta = e->angleDelta().y();
    if (delta == 0) return false;
    const QPointF p = e->position() * pixelScale;
    interactor->SetEventInformationFlipY(static_cast<int>(p.x()), static_cast<int>(p.y()));
    interactor->InvokeEvent(
        delta > 0 ? vtkCommand::MouseWheelForwardEvent : vtkCommand::MouseWheelBackwardEvent, e);
    e->accept();
    return true;
}

} // namespace cutcell::view3d
