#pragma once
// Meshes of the 3D view, built in their own frames (z is the axis of every round part) and
// placed by actor matrices. Normals are set so the surfaces shade smoothly.
#include "core/common/types.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkPolyData;
class vtkMatrix4x4;

namespace cutcell::view3d {

// A pipe with its wall: outer and inner surfaces and the two end rings, from z0 to z1.
vtkSmartPointer<vtkPolyData> makeTube(double outerR, double innerR, double z0, double z1,
                                      int facets);
// A (truncated) cone from radius r0 at z0 to r1 at z1, closed at both ends when capped.
vtkSmartPointer<vtkPolyData> makeFrustum(double r0, double r1, double z0, double z1, int facets,
                                         bool capped);
// An axis-aligned box centred at the origin.
vtkSmartPointer<vtkPolyData> makeBox(double sx, double sy, double sz);
// Lines on the plane z: a square grid covering [x0, x1] x [y0, y1].
vtkSmartPointer<vtkPolyData> makeGrid(double x0, double x1, double y0, double y1, double step,
                                      double z);
// Three axis lines from the origin (x, y, z) of the given length, coloured by point scalars.
vtkSmartPointer<vtkPolyData> makeTriad(double length);

// Eigen 4x4 (pose.matrix()) -> VTK matrix.
void toVtkMatrix(const Eigen::Matrix4d& m, vtkMatrix4x4* out);
// The matrix that maps the unit cylinder (radius 1, z from 0 to 1) onto the segment a -> b
// with the given radius; degenerate segments get a zero-size matrix.
Eigen::Matrix4d segmentMatrix(const Vec3& a, const Vec3& b, double radius);

} // namespace cutcell::view3d
