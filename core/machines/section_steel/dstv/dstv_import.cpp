#include "core/machines/section_steel/dstv/dstv_import.h"

#include "core/common/c_format.h"
#include "core/common/outcome.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/section_steel/dstv/dstv_reader.h"
#include "core/machines/section_steel/section_outline.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_spec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace cutcell::section_steel {
namespace {

using dstv::Contour;
using dstv::ContourPoint;
using dstv::Header;
using dstv::Part;

constexpr double kDimTolMm = 0.5; // header vs catalogue dimensions
constexpr double kPosTolMm = 0.5; // contour corners vs the face's edges
constexpr double kPi = 3.14159265358979323846;

std::string n(double v) {
    return formatC("%g", v);
}

std::string lineOf(int line) {
    return "line " + std::to_string(line) + ": ";
}

ImportError refuse(int line, const std::string& message) {
    return ImportError(lineOf(line) + message);
}

std::string upper(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// Designations as detailing packages write them, tried in turn against the catalogue:
// "IPE300", "HE300A" / "HE 300 B" (-> HEA / HEB), "L100*100*10", "L100X10" (equal angle).
std::vector<std::string> designationCandidates(const std::string& profile) {
    std::string p;
    for (char c : upper(profile))
        if (!std::isspace(static_cast<unsigned char>(c))) p += c == '*' ? 'X' : c;
    std::vector<std::string> out{p};
    if (p.size() > 3 && p.rfind("HE", 0) == 0 && (p.back() == 'A' || p.back() == 'B') &&
        std::isdigit(static_cast<unsigned char>(p[2])))
        out.push_back(std::string("HE") + p.back() + p.substr(2, p.size() - 3));
    if (p.size() > 1 && p[0] == 'L' && std::count(p.begin(), p.end(), 'X') == 1) {
        const size_t x = p.find('X');
        out.push_back(p.substr(0, x) + "X" + p.substr(1, x - 1) + p.substr(x));
    }
    return out;
}

SectionFamily familyOf(const Header& h) {
    if (h.profile_code == "I") return SectionFamily::I;
    if (h.profile_code == "U") return SectionFamily::U;
    if (h.profile_code == "L") return SectionFamily::L;
    static const std::pair<const char*, const char*> kinds[] = {
        {"B", "a plate"},           {"RU", "a round bar"},
        {"RO", "a round tube"},     {"M", "a rectangular tube"},
        {"C", "a C section"},       {"T", "a T section"},
        {"SO", "a special section"}};
    std::string what = "profile code " + h.profile_code;
    for (const auto& [c, k] : kinds)
        if (h.profile_code == c) what += " (" + std::string(k) + ")";
    throw refuse(h.field_line[7], what + ": the section-steel cutter cuts I, U and L sections "
                                         "only (profile code I, U or L)");
}

bool near(double a, double b, double tol) {
    return std::abs(a - b) <= tol;
}

// The section: catalogue entry or the header's dimensions; report lines for what differs.
SectionDims sectionOf(const Header& h, bool* userDefined, std::vector<std::string>& report) {
    const SectionFamily family = familyOf(h);
    std::optional<SectionDims> found;
    for (const std::string& c : designationCandidates(h.profile))
        if ((found = findSection(c))) break;
    SectionDims header;
    header.family = family;
    header.h_mm = h.h_mm;
    header.b_mm = h.b_mm;
    header.tw_mm = h.tw_mm;
    header.tf_mm = h.tf_mm;
    header.r_mm = h.r_mm;
    if (found) {
        if (found->family != family)
            throw refuse(h.field_line[7],
                         "profile code " + h.profile_code + " does not match the profile " +
                             json::quote(h.profile) + " (line " + std::to_string(h.field_line[6]) +
                             "), a catalogue " + toString(found->family) + " section");
        const bool noDims = h.h_mm == 0 && h.b_mm == 0 && h.tf_mm == 0 && h.tw_mm == 0;
        const bool same =
            near(h.h_mm, found->h_mm, kDimTolMm) && near(h.b_mm, found->b_mm, kDimTolMm) &&
            near(h.tf_mm, found->tf_mm, kDimTolMm) && near(h.tw_mm, found->tw_mm, kDimTolMm) &&
            (h.r_mm == 0 || near(h.r_mm, found->r_mm, kDimTolMm));
        if (noDims || same) {
            *userDefined = false;
            if (noDims)
                report.push_back(lineOf(h.field_line[9]) +
                                 "the header gives no dimensions: the catalogue's " +
                                 found->designation + " is used");
            return *found;
        }
        report.push_back(lineOf(h.field_line[9]) + "the header's dimensions (h " + n(h.h_mm) +
                         ", b " + n(h.b_mm) + ", tf " + n(h.tf_mm) + ", tw " + n(h.tw_mm) + ", r " +
                         n(h.r_mm) + " mm) differ from the catalogue's " + found->designation +
                         " (h " + n(found->h_mm) + ", b " + n(found->b_mm) + ", tf " +
                         n(found->tf_mm) + ", tw " + n(found->tw_mm) + ", r " + n(found->r_mm) +
                         " mm): the header's are used (user-defined section)");
    } else {
        report.push_back(lineOf(h.field_line[6]) + "profile " + json::quote(h.profile) +
                         " is not in the catalogue: the header's dimensions are used "
                         "(user-defined " +
                         toString(family) + " section)");
    }
    *userDefined = true;
    // The family's shape checks, named by the header line of the field.
    for (const auto& [key, message] : checkSectionDims(header, "section")) {
        int field = 10;
        if (key == "section.b_mm") field = 11;
        if (key == "section.tf_mm") field = 12;
        if (key == "section.tw_mm") field = 13;
        if (key == "section.r_mm") field = 14;
        throw refuse(h.field_line[static_cast<size_t>(field - 1)],
                     "header field " + std::to_string(field) + " (profile " +
                         json::quote(h.profile) + " as a user-defined " + toString(family) +
                         " section): " + message);
    }
    return header;
}

// Which groove of the spec a face's edge belongs to.
enum class FaceGroup { Web, Flanges };
FaceGroup groupOf(char face) {
    return face == 'v' || face == 'h' ? FaceGroup::Web : FaceGroup::Flanges;
}
const char* groupName(FaceGroup g) {
    return g == FaceGroup::Web ? "web" : "flanges";
}

std::string pointText(const ContourPoint& p) {
    return "(" + n(p.x_mm) + ", " + n(p.y_mm) + ")";
}

std::string prepText(const std::vector<dstv::WeldPrep>& prep) {
    std::string s;
    for (const auto& w : prep)
        s += (s.empty() ? "" : " + ") + n(w.angle_deg) + " deg, blunting " + n(w.blunting_mm) +
             " mm";
    return s;
}

// The groove an end-edge weld preparation asks for (*out), or Refused with the reason.
Outcome grooveOf(const std::vector<dstv::WeldPrep>& prep, double thickness, GrooveSpec* out) {
    GrooveSpec g;
    const double a = std::abs(prep[0].angle_deg);
    const double c = prep[0].blunting_mm;
    if (prep.size() == 2) {
        if (!near(std::abs(prep[1].angle_deg), a, 1e-9) || !near(prep[1].blunting_mm, c, 1e-9))
            return Outcome::refuse("the cutter cuts symmetric K grooves only");
        g.type = GrooveType::K;
    } else {
        g.type = c > 0 ? GrooveType::Y : GrooveType::V;
    }
    g.angle_deg = a;
    g.root_face_mm = c;
    if (!(a >= 5 && a <= 60)) return Outcome::refuse("the bevel head tilts the torch 5..60 deg");
    if (c >= thickness)
        return Outcome::refuse("a blunting of " + n(c) + " mm leaves no bevel in " + n(thickness) +
                               " mm");
    *out = g;
    return Outcome::done();
}

// An end edge whose slope disagrees with the header's saw cut angle: the contour's angle
// (dx = width tan(angle), the header's own convention), to be cut instead where the cutter can.
struct EdgeAngle {
    FaceGroup group;
    int line;
    std::string what;
    double angle_deg;
};

struct FaceGroove {
    char face;
    int line;
    std::optional<GrooveSpec> groove; // nullopt: the face's end edge is square
};

// One AK contour: copes and notches at either end, weld preparations, and the end edge's
// groove (appended to grooves when the end is a straight edge across the face).
void readOuterContour(const Contour& c, const Header& h, const SectionDims& d,
                      std::vector<FaceGroove>& grooves, std::vector<EdgeAngle>& edges,
                      std::vector<std::string>& report) {
    const FaceGroup group = groupOf(c.face);
    const double width = group == FaceGroup::Web ? d.h_mm : d.b_mm;
    const double thickness = group == FaceGroup::Web ? d.tw_mm : d.tf_mm;
    const double cutDeg = group == FaceGroup::Web ? h.web_end_deg : h.flange_end_deg;
    const std::string face = dstv::faceName(c.face);
    const size_t count = c.points.size() - 1; // the last point closes the contour
    const double half = h.length_mm / 2;
    std::vector<size_t> endSide, startSide;
    for (size_t i = 0; i < count; ++i)
        (c.points[i].x_mm > half ? endSide : startSide).push_back(i);
    const auto features = [&](const std::vector<size_t>& idx) {
        bool plain = idx.size() == 2;
        for (size_t i : idx)
            plain = plain && c.points[i].radius_mm == 0 && c.points[i].notch == 0;
        if (plain) {
            const double y0 = std::min(c.points[idx[0]].y_mm, c.points[idx[1]].y_mm);
            const double y1 = std::max(c.points[idx[0]].y_mm, c.points[idx[1]].y_mm);
            plain = near(y0, 0, kPosTolMm) && near(y1, width, kPosTolMm);
        }
        return !plain;
    };
    const auto extent = [&](const std::vector<size_t>& idx) {
        double lo = 1e300, hi = -1e300;
        for (size_t i : idx) {
            lo = std::min(lo, c.points[i].x_mm);
            hi = std::max(hi, c.points[i].x_mm);
        }
        return "x " + n(lo) + " .. " + n(hi) + " mm";
    };
    if (endSide.empty() || startSide.empty()) {
        report.push_back(lineOf(c.line) + "AK contour on " + face + " does not span the piece (" +
                         extent(endSide.empty() ? startSide : endSide) + ", length " +
                         n(h.length_mm) + " mm): not used");
        return;
    }
    const bool endCope = features(endSide);
    if (endCope)
        report.push_back(lineOf(c.line) + "AK cope or notch at the cut end on " + face + " (" +
                         std::to_string(endSide.size()) + " corners, " + extent(endSide) +
                         "): not cut by this machine (it cuts the end in one plane round the "
                         "section)");
    if (features(startSide))
        report.push_back(lineOf(c.line) + "AK cope or notch at the start end on " + face + " (" +
                         std::to_string(startSide.size()) + " corners, " + extent(startSide) +
                         "): not cut by this job (it cuts the end at x = " + n(h.length_mm) +
                         " mm)");
    // The end edge: the two end corners, consecutive on the contour.
    std::optional<size_t> edgeFrom;
    if (!endCope) {
        const size_t a = endSide[0], b = endSide[1];
        if ((a + 1) % count == b) edgeFrom = a;
        if ((b + 1) % count == a) edgeFrom = b;
        const ContourPoint& p0 = c.points[a].y_mm < c.points[b].y_mm ? c.points[a] : c.points[b];
        const ContourPoint& p1 = c.points[a].y_mm < c.points[b].y_mm ? c.points[b] : c.points[a];
        const double dx = p1.x_mm - p0.x_mm;
        const double expect = width * std::tan(cutDeg * kPi / 180);
        if (!near(std::abs(dx), std::abs(expect), 1.0) && width > 0)
            edges.push_back({group, p0.line,
                             "the AK end edge on " + face + " runs from " + pointText(p0) + " to " +
                                 pointText(p1) + " (" + n(dx) + " mm along x) but the header's " +
                                 (group == FaceGroup::Web ? "web" : "flange") + " end cut of " +
                                 n(cutDeg) + " deg gives " + n(expect) + " mm",
                             std::atan(dx / width) * 180 / kPi});
    }
    std::optional<GrooveSpec> groove;
    for (size_t i = 0; i < count; ++i) {
        const ContourPoint& p = c.points[i];
        if (p.prep.empty()) continue;
        const ContourPoint& q = c.points[i + 1];
        const std::string edge = "weld preparation " + prepText(p.prep) + " on the edge " +
                                 pointText(p) + " - " + pointText(q) + " of " + face;
        if (!edgeFrom || i != *edgeFrom) {
            report.push_back(lineOf(p.line) + edge +
                             (endCope ? ": not cut by this machine (the cut end has a cope)"
                                      : ": not cut by this machine (it bevels the cut end's edge "
                                        "only)"));
            continue;
        }
        GrooveSpec g;
        if (const Outcome o = grooveOf(p.prep, thickness, &g); o.ok()) {
            groove = g;
        } else {
            groove.reset();
            report.push_back(lineOf(p.line) + edge + ": not cut (" + o.message + ")");
        }
    }
    if (!endCope) grooves.push_back({c.face, c.line, groove});
}

// The groove of one face group from its faces' end edges.
GrooveSpec mergeGrooves(FaceGroup group, SectionFamily family, const std::vector<FaceGroove>& all,
                        std::vector<std::string>& report) {
    std::vector<const FaceGroove*> faces;
    for (const FaceGroove& f : all)
        if (groupOf(f.face) == group) faces.push_back(&f);
    const FaceGroove* first = nullptr;
    for (const FaceGroove* f : faces)
        if (f->groove && !first) first = f;
    if (!first) return {};
    for (const FaceGroove* f : faces) {
        const bool same = f->groove && f->groove->type == first->groove->type &&
                          f->groove->angle_deg == first->groove->angle_deg &&
                          f->groove->root_face_mm == first->groove->root_face_mm;
        if (!same) {
            report.push_back(lineOf(first->line) + "the " + groupName(group) +
                             " weld preparations differ between " + dstv::faceName(first->face) +
                             " and " + dstv::faceName(f->face) + " (line " +
                             std::to_string(f->line) + "): not cut (the cutter bevels all its " +
                             groupName(group) + " alike)");
            return {};
        }
    }
    if (faces.size() == 1 && group == FaceGroup::Flanges && family != SectionFamily::L)
        report.push_back(lineOf(first->line) + "the flange groove of " +
                         dstv::faceName(first->face) +
                         " is cut on every flange (no AK contour for the other)");
    return *first->groove;
}

std::string holeText(const dstv::Hole& h) {
    std::string what;
    switch (h.kind) {
    case 'g':
        what = "threaded hole " + n(h.diameter_mm) + " mm";
        break;
    case 'l':
        what = "left-hand threaded hole " + n(h.diameter_mm) + " mm";
        break;
    case 'm':
        what = "hole mark";
        break;
    case 's':
        what = "countersink " + n(h.diameter_mm) + " mm";
        break;
    default:
        what = std::string(h.depth_mm > 0 ? "blind hole " : "hole ") + n(h.diameter_mm) + " mm";
    }
    if (h.slot)
        what = "slot " + n(h.diameter_mm) + " mm, " + n(h.slot_width_mm) + " x " +
               n(h.slot_height_mm) + " mm at " + n(h.slot_angle_deg) + " deg";
    return "BO " + what + " on " + dstv::faceName(h.face) + " at x " + n(h.x_mm) + ", y " +
           n(h.y_mm) + " mm: not cut by this machine" +
           (h.extra_values > 0
                ? " (" + std::to_string(h.extra_values) + " more number(s) after the depth ignored)"
                : "");
}

// `raw` as UTF-8: valid sequences kept, any other byte read as Latin-1 (*latin1 set), control
// characters (C0, DEL, C1) as '?'.
std::string utf8Text(const std::string& raw, bool* latin1) {
    std::string out;
    const auto* b = reinterpret_cast<const unsigned char*>(raw.data());
    const size_t n = raw.size();
    for (size_t i = 0; i < n;) {
        const unsigned char c = b[i];
        const size_t len = c < 0x80         ? 1
                           : (c >> 5) == 6  ? 2
                           : (c >> 4) == 14 ? 3
                           : (c >> 3) == 30 ? 4
                                            : 0;
        bool valid = len > 0 && i + len <= n;
        for (size_t k = 1; valid && k < len; ++k)
            valid = (b[i + k] & 0xC0) == 0x80;
        if (valid && len == 2) valid = c >= 0xC2; // no overlong forms
        if (valid) {
            if (len == 1)
                out += c < 0x20 || c == 0x7f ? '?' : static_cast<char>(c);
            else if (len == 2 && c == 0xC2 && b[i + 1] < 0xA0)
                out += '?'; // U+0080..U+009F: C1 controls
            else
                out.append(raw, i, len);
            i += len;
            continue;
        }
        *latin1 = true;
        if (c < 0xA0) {
            out += '?';
        } else {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
        ++i;
    }
    return out;
}

// "3 holes, 1 marking, 2 inner contours": what of the piece the job does not cut.
std::string ignoredText(const Part& part) {
    int inner = 0;
    for (const Contour& c : part.contours)
        inner += c.outer ? 0 : 1;
    std::string out;
    const auto add = [&](int count, const char* one, const char* many) {
        if (count == 0) return;
        out += (out.empty() ? "" : ", ") + std::to_string(count) + " " + (count == 1 ? one : many);
    };
    add(static_cast<int>(part.holes.size()), "hole", "holes");
    add(static_cast<int>(part.markings.size()), "marking", "markings");
    add(inner, "inner contour", "inner contours");
    add(static_cast<int>(part.others.size()), "other block", "other blocks");
    return out.empty() ? "nothing" : out;
}

} // namespace

ImportResult importDstv(const std::string& text) {
    Part part;
    try {
        // The piece's kind first: a plate or a tube is refused by name even where its contours
        // would not read.
        familyOf(dstv::parseDstvHeader(text));
        part = dstv::parseDstv(text);
    } catch (const dstv::DstvError& e) {
        throw ImportError(e.what());
    }
    ImportResult out;
    std::vector<std::string>& report = out.report;
    // The header's texts as UTF-8 (a job file is): older writers use a code page; a byte that
    // is no UTF-8 is read as Latin-1, a control character as '?', and the report says so.
    Header& h = part.header;
    for (const auto& [headerText, field] : {std::pair<std::string*, int>{&h.order, 1},
                                            {&h.drawing, 2},
                                            {&h.phase, 3},
                                            {&h.piece, 4},
                                            {&h.steel_grade, 5},
                                            {&h.profile, 7}}) {
        bool latin1 = false;
        *headerText = utf8Text(*headerText, &latin1);
        if (latin1)
            report.push_back(lineOf(h.field_line[static_cast<size_t>(field - 1)]) + "text " +
                             json::quote(*headerText) + " is not UTF-8: read as Latin-1");
    }
    SectionSteelSpec spec = defaultSectionSteelSpec();
    spec.section = sectionOf(h, &spec.user_defined, report);
    // The end cut at x = length; the cutter mitres +-45 deg about each axis.
    const auto checkedMitre = [&](double deg, int field, const char* key) {
        if (std::abs(deg) > 45)
            throw refuse(h.field_line[static_cast<size_t>(field - 1)],
                         std::string(field == 18 ? "web end cut" : "flange end cut") +
                             " (header field " + std::to_string(field) + ") = " + n(deg) +
                             " deg: the cutter mitres at most 45 deg (" + key + ")");
        return deg;
    };
    // The web's end cut in the cell's sense: DSTV's positive web angle shortens the top of the
    // web face (its y runs up from the underside: x_top - x_bottom = -h tan(angle), as every
    // mitred file here draws its AK), the cell's positive mitre about y lengthens it (cut plane
    // x = (z - h/2) tan, the kept bar at x < 0). The flange angle keeps its sign (unverified:
    // no file here shows a flange mitre's direction against the cell's y).
    const double web = checkedMitre(h.web_end_deg, 18, "end_cut.mitre_horizontal_deg");
    spec.cut.mitre_horizontal_deg = web == 0 ? 0.0 : -web;
    spec.cut.mitre_vertical_deg = checkedMitre(h.flange_end_deg, 20, "end_cut.mitre_vertical_deg");
    report.push_back(lineOf(h.field_line[16]) + "start end (x = 0: web cut " + n(h.web_start_deg) +
                     " deg, flange cut " + n(h.flange_start_deg) +
                     " deg): not cut by this job (it cuts the end at x = " + n(h.length_mm) +
                     " mm)");
    if (h.quantity > 1)
        report.push_back(lineOf(h.field_line[5]) + "quantity " + std::to_string(h.quantity) +
                         ": the job cuts one piece (the quantity is kept in piece.quantity)");
    // The bar's length (the cell's conveyor takes 50 .. 24000 mm) and the piece's marks.
    if (h.length_mm < 50 || h.length_mm > 24000)
        throw refuse(h.field_line[8], "length (header field 9) = " + n(h.length_mm) +
                                          " mm: the cell takes bars of 50 .. 24000 mm "
                                          "(section.length_mm)");
    spec.length_mm = h.length_mm;
    const auto mark = [&](const std::string& v, int field) {
        std::string kept = v;
        if (kept.size() > 64) {
            kept.resize(64);
            while (!kept.empty() && (static_cast<unsigned char>(kept.back()) & 0xC0) == 0x80)
                kept.pop_back(); // a continuation byte: the character it ends is cut whole
            if (!kept.empty() && static_cast<unsigned char>(kept.back()) >= 0xC0) kept.pop_back();
            report.push_back(lineOf(h.field_line[static_cast<size_t>(field - 1)]) + "mark " +
                             json::quote(v) + " cut to " + std::to_string(kept.size()) +
                             " bytes (piece marks hold at most 64)");
        }
        return kept;
    };
    spec.piece.order = mark(h.order, 1);
    spec.piece.drawing = mark(h.drawing, 2);
    spec.piece.phase = mark(h.phase, 3);
    spec.piece.mark = mark(h.piece, 4);
    spec.piece.steel_grade = mark(h.steel_grade, 5);
    spec.piece.quantity = h.quantity;
    std::vector<FaceGroove> grooves;
    std::vector<EdgeAngle> edges;
    for (const Contour& c : part.contours) {
        if (c.outer) {
            readOuterContour(c, h, spec.section, grooves, edges, report);
            continue;
        }
        double lo = 1e300, hi = -1e300;
        for (const ContourPoint& p : c.points) {
            lo = std::min(lo, p.x_mm);
            hi = std::max(hi, p.x_mm);
        }
        report.push_back(lineOf(c.line) + "IK inner contour on " + dstv::faceName(c.face) + " (" +
                         std::to_string(c.points.size() - 1) + " corners, x " + n(lo) + " .. " +
                         n(hi) + " mm): not cut by this machine");
    }
    // Where the contour's end edge disagrees with the header, the contour is the piece's shape:
    // its angle is cut when the cutter can make it (a warning either way).
    for (const FaceGroup g : {FaceGroup::Web, FaceGroup::Flanges}) {
        const EdgeAngle* first = nullptr;
        bool agree = true;
        for (const EdgeAngle& e : edges)
            if (e.group == g) {
                if (!first) first = &e;
                agree = agree && near(e.angle_deg, first->angle_deg, 0.05);
            }
        if (!first) continue;
        double& mitre =
            g == FaceGroup::Web ? spec.cut.mitre_horizontal_deg : spec.cut.mitre_vertical_deg;
        const char* key =
            g == FaceGroup::Web ? "end_cut.mitre_horizontal_deg" : "end_cut.mitre_vertical_deg";
        // The web's slope has its sign (face v's y runs up from the underside, as the cell's z);
        // a flange's is taken from the header's own angle, and a square header gives none.
        double angle = first->angle_deg;
        const bool signKnown = g == FaceGroup::Web || mitre != 0;
        if (g == FaceGroup::Flanges && mitre != 0) angle = std::copysign(angle, mitre);
        std::string verdict;
        if (!agree)
            verdict = "the faces' end edges disagree with each other: the header's " + n(mitre) +
                      " deg is cut";
        else if (std::abs(angle) > 45)
            verdict = "the contour's " + n(std::abs(angle)) +
                      " deg is beyond the cutter's 45 deg: the header's " + n(mitre) +
                      " deg is cut";
        else if (!signKnown)
            verdict = "the flange contour's " + n(std::abs(angle)) +
                      " deg has no direction the header confirms: the header's 0 deg is cut (set " +
                      key + " to cut the contour)";
        else {
            mitre = std::round(angle * 100) / 100;
            verdict = "the contour's " + n(mitre) + " deg is cut (" + key + ")";
        }
        for (const EdgeAngle& e : edges)
            if (e.group == g)
                report.push_back(lineOf(e.line) + "warning: " + e.what + ": " + verdict);
    }
    spec.cut.web = mergeGrooves(FaceGroup::Web, spec.section.family, grooves, report);
    spec.cut.flanges = mergeGrooves(FaceGroup::Flanges, spec.section.family, grooves, report);
    for (const dstv::Hole& hole : part.holes)
        report.push_back(lineOf(hole.line) + holeText(hole));
    for (const dstv::Marking& m : part.markings)
        report.push_back(lineOf(m.line) + "SI marking " + json::quote(m.text) + " on " +
                         dstv::faceName(m.face) + ": not marked by this machine");
    for (const dstv::OtherBlock& b : part.others)
        report.push_back(lineOf(b.line) + b.code + " block (" + dstv::blockTitle(b.code) + ", " +
                         std::to_string(b.data_lines) + " lines): not done by this machine");
    // Report lines in file order.
    std::stable_sort(report.begin(), report.end(), [](const std::string& a, const std::string& b) {
        return std::stoi(a.substr(5)) < std::stoi(b.substr(5));
    });

    Job job = SectionSteelModule().defaultJob();
    const std::string profile = spec.user_defined ? h.profile : spec.section.designation;
    job.name = "DSTV " + (h.piece.empty() ? std::string("piece") : "piece " + h.piece) + " (" +
               profile + ")";
    job.description = "Imported from DSTV: order " + json::quote(h.order) + ", drawing " +
                      json::quote(h.drawing) + ", phase " + json::quote(h.phase) + ", piece " +
                      json::quote(h.piece) + ", steel " + json::quote(h.steel_grade) +
                      ", quantity " + std::to_string(h.quantity) + ", profile " +
                      json::quote(h.profile) + " (" + h.profile_code + "), length " +
                      n(h.length_mm) + " mm, " + n(h.weight_kg_per_m) +
                      " kg/m. The job cuts the end at x = length (web cut " + n(h.web_end_deg) +
                      " deg, flange cut " + n(h.flange_end_deg) +
                      " deg) in the cell of the section-steel cutter.";
    job.machine_spec.set(spec);
    const std::vector<JobIssue> issues = validateJob(job);
    if (!issues.empty())
        throw ImportError("the imported job is not valid: " + issues.front().message);
    out.job = std::move(job);
    out.facts = {{"piece", h.piece},
                 {"section", profile},
                 {"length_mm", n(h.length_mm)},
                 {"quantity", std::to_string(h.quantity)},
                 {"steel", h.steel_grade},
                 {"end cut", "web " + n(spec.cut.mitre_horizontal_deg) + " deg, flange " +
                                 n(spec.cut.mitre_vertical_deg) + " deg"},
                 {"ignored", ignoredText(part)}};
    return out;
}

JobImporter dstvImporter() {
    JobImporter i;
    i.name = "dstv";
    i.title = "DSTV";
    i.description = "DSTV (NC1) structural-steel piece -> section-steel cutter job (its cut end, "
                    "mitres and weld-preparation grooves)";
    i.patterns = {"*.nc", "*.nc1"};
    i.import = importDstv;
    return i;
}

} // namespace cutcell::section_steel
