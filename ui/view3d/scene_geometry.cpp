#include "ui/view3d/scene_geometry.h"

#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkFloatArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace cutcell::view3d {

namespace {

// Accumulates points with normals and quads/triangles.
struct MeshBuilder {
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> normals;
    vtkNew<vtkCellArray> polys;
    MeshBuilder() { normals->SetNumberOfComponents(3); }

    vtkIdType add(const Vec3& p, const Vec3& n) {
        normals->InsertNextTuple3(n.x(), n.y(), n.z());
        return points->InsertNextPoint(p.x(), p.y(), p.z());
    }
    void quad(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d) {
        const vtkIdType ids[4] = {a, b, c, d};
        polys->InsertNextCell(4, ids);
    }
    // A ring band between radius r0 at z0 and r1 at z1 with the given outward normal sign.
    void band(double r0, double r1, double z0, double z1, int facets, double sign) {
        const double slope = (r0 - r1) / std::max(1e-9, std::hypot(z1 - z0, r1 - r0));
        const double radial = std::abs(z1 - z0) / std::max(1e-9, std::hypot(z1 - z0, r1 - r0));
        const vtkIdType base = points->GetNumberOfPoints();
        for (int i = 0; i <= facets; ++i) {
            const double a = 2 * kPi * i / facets;
            const double c = std::cos(a), s = std::sin(a);
            const Vec3 n =
                sign * Vec3(radial * c, radial * s, slope * (z1 > z0 ? 1 : -1)).normalized();
            add({r0 * c, r0 * s, z0}, n);
            add({r1 * c, r1 * s, z1}, n);
        }
        for (int i = 0; i < facets; ++i) {
            const vtkIdType a = base + 2 * i;
            if (sign > 0)
                quad(a, a + 2, a + 3, a + 1);
            else
                quad(a, a + 1, a + 3, a + 2);
        }
    }
    // A flat annulus (or disc when rIn = 0) at z facing nz.
    void ring(double rIn, double rOut, double z, double nz, int facets) {
        const vtkIdType base = points->GetNumberOfPoints();
        const Vec3 n(0, 0, nz);
        for (int i = 0; i <= facets; ++i) {
            const double a = 2 * kPi * i / facets;
            const double c = std::cos(a), s = std::sin(a);
            add({rIn * c, rIn * s, z}, n);
            add({rOut * c, rOut * s, z}, n);
        }
        for (int i = 0; i < facets; ++i) {
            const vtkIdType a = base + 2 * i;
            if (nz > 0)
                quad(a, a + 1, a + 3, a + 2);
            else
                quad(a, a + 2, a + 3, a + 1);
        }
    }
    vtkSmartPointer<vtkPolyData> finish() {
        auto pd = vtkSmartPointer<vtkPolyData>::New();
        pd->SetPoints(points);
        pd->SetPolys(polys);
        pd->GetPointData()->SetNormals(normals);
        return pd;
    }
};

} // namespace

vtkSmartPointer<vtkPolyData> makeTube(double outerR, double innerR, double z0, double z1,
                                      int facets) {
    MeshBuilder m;
    m.band(outerR, outerR, z0, z1, facets, +1);
    if (innerR > 0) m.band(innerR, innerR, z0, z1, facets, -1);
    m.ring(innerR, outerR, z0, -1, facets);
    m.ring(innerR, outerR, z1, +1, facets);
    return m.finish();
}

vtkSmartPointer<vtkPolyData> makeFrustum(double r0, double r1, double z0, double z1, int facets,
                                         bool capped) {
    MeshBuilder m;
    m.band(r0, r1, z0, z1, facets, +1);
    if (capped) {
        m.ring(0, r0, z0, z1 > z0 ? -1 : 1, facets);
        m.ring(0, r1, z1, z1 > z0 ? 1 : -1, facets);
    }
    return m.finish();
}

vtkSmartPointer<vtkPolyData> makeBox(double sx, double sy, double sz) {
    vtkNew<vtkCubeSource> cube;
    cube->SetXLength(sx);
    cube->SetYLength(sy);
    cube->SetZLength(sz);
    cube->Update();
    return cube->GetOutput();
}

vtkSmartPointer<vtkPolyData> makeGrid(double x0, double x1, double y0, double y1, double step,
                                      double z) {
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines;
    const auto line = [&](double ax, double ay, double bx, double by) {
        const vtkIdType ids[2] = {pts->InsertNextPoint(ax, ay, z), pts->InsertNextPoint(bx, by, z)};
        lines->InsertNextCell(2, ids);
    };
    for (double x = x0; x <= x1 + 1e-6; x += step)
        line(x, y0, x, y1);
    for (double y = y0; y <= y1 + 1e-6; y += step)
        line(x0, y, x1, y);
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(pts);
    pd->SetLines(lines);
    return pd;
}

vtkSmartPointer<vtkPolyData> makeTriad(double length) {
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetNumberOfComponents(3);
    rgb->SetName("colours");
    const unsigned char cols[3][3] = {{230, 80, 80}, {90, 200, 90}, {90, 140, 240}};
    for (int k = 0; k < 3; ++k) {
        Vec3 e = Vec3::Zero();
        e[k] = length;
        const vtkIdType ids[2] = {pts->InsertNextPoint(0, 0, 0),
                                  pts->InsertNextPoint(e.x(), e.y(), e.z())};
        lines->InsertNextCell(2, ids);
        rgb->InsertNextTypedTuple(cols[k]);
        rgb->InsertNextTypedTuple(cols[k]);
    }
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(pts);
    pd->SetLines(lines);
    pd->GetPointData()->SetScalars(rgb);
    return pd;
}

void toVtkMatrix(const Eigen::Matrix4d& m, vtkMatrix4x4* out) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out->SetElement(r, c, m(r, c));
}

Eigen::Matrix4d segmentMatrix(const Vec3& a, const Vec3& b, double radius) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    m(3, 3) = 1;
    m.block<3, 1>(0, 3) = a;
    const Vec3 d = b - a;
    const double len = d.norm();
    if (len < 1e-9) return m;
    const Vec3 z = d / len;
    const Vec3 x = z.unitOrthogonal();
    const Vec3 y = z.cross(x);
    m.block<3, 1>(0, 0) = x * radius;
    m.block<3, 1>(0, 1) = y * radius;
    m.block<3, 1>(0, 2) = d;
    return m;
}

} // namespace cutcell::view3d
