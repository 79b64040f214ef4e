#pragma once
// The VTK scene graph of the cell (no window, no Qt): actors built from a SceneModel and moved
// by the joint vector. It works without OpenGL (offscreen tests check transforms and bounds);
// a VtkGlWidget renders its renderer when OpenGL is there.
//
// Threading: GUI thread only (VTK objects are not thread-safe).
#include "ui/view3d/scene_model.h"
#include "ui/view3d/view_style.h"

#include <array>
#include <memory>
#include <string>

class vtkRenderer;

namespace cutcell::view3d {

class CellScene {
  public:
    CellScene();
    ~CellScene();
    CellScene(const CellScene&) = delete;
    CellScene& operator=(const CellScene&) = delete;

    vtkRenderer* renderer() const;
    const SceneModel& model() const;
    bool hasScene() const;

    // Rebuilds every actor; the machine goes to model.homeQ, nothing done, torch off.
    void setScene(const SceneModel& model);
    // Cheap: moves actors (matrices), extends the done part, switches the flame.
    // progressFraction is the fraction of the plan's duration (path points are equally spaced
    // in time); values outside [0, 1] are clamped.
    void setMachineState(const JointVector& q, double progressFraction, bool torchOn);
    // Marks the path point where a run stopped (fraction of the plan's duration, as
    // setMachineState); a negative value removes the mark. Kept across setMachineState, cleared
    // by setScene.
    void setStopMark(double progressFraction);

    void setPreset(ViewPreset preset);
    ViewPreset preset() const;
    void resetView();
    // Called before each render: keeps the near/far planes around what is visible.
    void prepareRender();
    // Render pixels per screen pixel (0.5 while moving at half resolution): the overlay texts
    // and the short-view rule are sized in screen pixels.
    void setPixelScale(double scale);
    // The job title is drawn only in views at least this tall (device pixels).
    static constexpr int kTitleMinViewHeightPx = 360;

    // Scene-graph queries (world frame, mm), read back from the actors' matrices.
    Vec3 torchTipWorld() const;
    Vec3 torchAxisWorld() const;
    Vec3 torchBodyCentreWorld() const;
    Vec3 pipeCentreWorld() const;
    // A point on the work pipe's outer surface: work-frame z and angle about the pipe's axis.
    Vec3 pipeSurfaceWorld(double zWork, double angleRad) const;
    // World bounds of the machine and the pipes (xmin, xmax, ymin, ymax, zmin, zmax).
    std::array<double, 6> machineBounds() const;
    // The process tool the status line names ("torch", "saw", "cutter"), translated by the
    // caller; the line reads "42 %  |  saw ON  |  131 points reachable".
    void setToolName(const std::string& name);
    // The rest of the status line's words in the GUI's language (the Qt side translates):
    // the tool's state and what follows the point count.
    struct StatusWords {
        std::string on = "ON", off = "off";
        std::string reachable = "points reachable", notReachable = "points NOT reachable (red)";
    };
    void setStatusWords(const StatusWords& words);
    std::string statusText() const;
    int doneCount() const;        // path points drawn as done
    int unreachableShown() const; // path points flagged unreachable (drawn red)
    int drawnPathPoints() const;  // points of the drawn polyline (decimated to <= 5000)
    bool flameVisible() const;
    const JointVector& machineQ() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> d;
    friend class CellSceneCamera;
};

} // namespace cutcell::view3d
