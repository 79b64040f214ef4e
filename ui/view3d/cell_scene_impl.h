#pragma once
// Private to cell_scene*.cpp: the actors of a CellScene.
#include "ui/view3d/cell_scene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <vector>

namespace cutcell::view3d {

// One drawn piece of the arm: a joint (cylinder centred on frame `frame`'s origin, along its
// z) or a link segment between two points derived from the frames.
struct ArmPiece {
    enum Kind { Joint, LinkAlongZ, LinkAlongX } kind = Joint;
    int frame = 0; // Joint: frame i (joint i+1's axis); links: frame i -> i+1
    double radius = 20;
    double height = 60; // joints
    vtkSmartPointer<vtkActor> actor;
};

struct CellScene::Impl {
    vtkNew<vtkRenderer> renderer;
    SceneModel model;
    bool hasScene = false;
    JointVector q = JointVector::Zero();
    double progress = 0;
    bool torchOn = false;
    ViewPreset preset = ViewPreset::Iso;
    Vec3 followTip = Vec3::Zero();
    int done = 0;
    int unreachable = 0;
    int statusKey = -1;
    std::string toolName = "torch"; // the status line's tool (the program's terms)
    CellScene::StatusWords words;
    static constexpr int kTitleFontPx = 15, kStatusFontPx = 13;
    double pixelScale = 1.0; // render pixels per screen pixel (CellScene::setPixelScale)

    // Moved with the work pipe (baseFromWork).
    std::vector<vtkSmartPointer<vtkActor>> workActors;
    std::vector<Eigen::Matrix4d> workLocal; // each work actor's pose in the work frame
    vtkSmartPointer<vtkActor> pipe, path, doneActor, unreachableActor;
    vtkSmartPointer<vtkPolyData> donePoly;
    vtkSmartPointer<vtkPoints> donePts;
    std::vector<size_t> drawnIndex;     // plan point index of each drawn path point (ascending)
    vtkSmartPointer<vtkActor> stopMark; // where the last run stopped (hidden when none)
    size_t stopMarkSlot = 0;            // its index in workActors / workLocal
    double stopProgress = -1;           // < 0: no stop shown
    // Moved with the tool.
    vtkSmartPointer<vtkActor> torchBody, nozzle, flame;
    vtkSmartPointer<vtkActor> carriage;  // LinearCarriage only: the block riding the rail
    vtkSmartPointer<vtkActor> direction; // cutting direction at the tip (arrow)
    std::vector<ArmPiece> arm;
    // Static.
    vtkSmartPointer<vtkActor> grid;
    std::vector<vtkSmartPointer<vtkActor>> fixedActors;
    vtkSmartPointer<vtkTextActor> title, status;

    // Linkage machines (SceneModel::linkage): one actor per piece.
    std::vector<vtkSmartPointer<vtkActor>> linkageActors;

    void build();
    void buildPipeCell();
    void buildLinkage();
    void buildPath(); // planned path, done part, unreachable marks, stop mark (work actors)
    vtkSmartPointer<vtkActor> addWork(vtkSmartPointer<vtkActor> a, const Eigen::Matrix4d& local);
    void placeLinkage();
    void buildFloorAndTexts();
    void place();
    void updateDone(int count);
    void placeStopMark();
    Vec3 liftedPathPoint(size_t i, double mm) const; // off the work pipe's surface, work frame
    void updateStatus();
    void applyCamera(ViewPreset p);
};

} // namespace cutcell::view3d
