#pragma once
// The cross-section outline of a section lying on the cutting table: y across, z up, the
// section's underside on the table (z = 0), the bar along x. I/H: web vertical, centred on
// y = 0; U: web outer face at y = -b/2, flanges towards +y; L: vertical leg's outer face at
// y = -b/2, horizontal leg on the table. The outline runs counter-clockwise (material on its
// left) from the right end of the table face round to its left end: straight faces and the
// root fillets (arcs); the face on the table is not part of it (the torch cannot get there).
// Turned over (setup 2, end_cut.setup): the same section turned 180 deg about its long axis,
// (y, z) -> (-y, h - z): I/H look the same, U has its web at y = +b/2, an L stands on the toe
// of its vertical leg with the horizontal leg on top; the face that lay on the table (the
// underside of the bottom flange / horizontal leg) is now in the outline, on top.
#include "core/machines/section_steel/section_catalogue.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cutcell::section_steel {

using Vec2 = Eigen::Vector2d;

enum class FaceKind { Flange, Web, Toe, Fillet, Leg };
const char* toString(FaceKind k);

struct OutlineSegment {
    std::string name; // "top flange, upper face", "root fillet web/top flange +y", ...
    FaceKind kind = FaceKind::Flange;
    double thickness_mm = 0; // of the plate this face belongs to
    bool arc = false;
    Vec2 p0{0, 0}, p1{0, 0};           // ends
    Vec2 centre{0, 0};                 // arc
    double radius = 0, a0 = 0, a1 = 0; // arc angles (rad) from p0 to p1 (a1 - a0 = +-pi/2)
    Vec2 n0{0, 0}, n1{0, 0};           // outward normals at the ends (equal on a line)
    double length = 0;
    // Which side of the plate: one-sided grooves (V, Y) are made from the upper faces of
    // flanges and legs and the +y face of the web.
    bool groove_side = false;
    // Turned over: the face that lay on the table in setup 1 (now on top).
    bool former_table_face = false;
};

struct OutlinePoint {
    Vec2 p{0, 0}, tangent{0, 0}, normal{0, 0}; // normal: outward (away from the material)
    size_t segment = 0;
};

class SectionOutline {
  public:
    explicit SectionOutline(const SectionDims& d, bool turnedOver = false);
    const SectionDims& dims() const { return dims_; }
    bool turnedOver() const { return turned_; }
    const std::vector<OutlineSegment>& segments() const { return segments_; }
    double length() const { return length_; }
    // Area enclosed by the outline and the table face (mm^2), arcs exact.
    double area() const;
    // The point at arc length s (clamped), with its tangent and outward normal.
    OutlinePoint at(double s) const;
    // The point of segment i at arc length s (clamped to the segment): at a boundary between
    // two faces at(s) gives the next face (its normal already turned), this one the face asked.
    OutlinePoint onSegment(size_t i, double s) const;
    // Arc length where segment i begins.
    double segmentStart(size_t i) const { return starts_[i]; }
    // The closed material polygon (fillets as 8-sided arcs), counter-clockwise.
    const std::vector<Vec2>& polygon() const { return polygon_; }
    bool contains(const Vec2& q) const; // strictly inside the material
    // Distance of q from the outline (faces and fillets, not the table face).
    double distanceToOutline(const Vec2& q) const;
    // Distance of q from the material (the polygon, table face included); 0 inside.
    double distanceToMaterial(const Vec2& q) const;

  private:
    SectionDims dims_;
    bool turned_ = false;
    std::vector<OutlineSegment> segments_;
    std::vector<double> starts_;
    std::vector<Vec2> polygon_;
    double length_ = 0;
};

// Checks of user-defined dimensions: the message names the key, value, unit and limit.
std::vector<std::pair<std::string, std::string>> checkSectionDims(const SectionDims& d,
                                                                  const std::string& keyPrefix);

} // namespace cutcell::section_steel
