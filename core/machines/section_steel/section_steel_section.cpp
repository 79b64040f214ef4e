#include "core/machines/section_steel/section_steel_section.h"

#include "core/job/drive_fields.h"
#include "core/job/field_table.h"

#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_outline.h"

#include <cmath>

namespace cutcell::section_steel {
namespace {

// end_cut.setup: 1 (as loaded) or 2 (turned over); anything else is refused by value.
int readSetup(SectionReader& c) {
    const json::Value* v = c.get("setup");
    if (!v) return 1;
    const double x = v->isNumber() ? v->asNumber() : std::nan("");
    if (!(x >= 1 && x <= kLastSetup && x == std::floor(x)))
        throw JobError(c.key("setup") + " = " + (v->isNumber() ? num(x) : v->typeName()) +
                       " is not a setup: 1 (the section as loaded) or " +
                       std::to_string(kLastSetup) +
                       " (turned over 180 deg about its long axis), range [1, " +
                       std::to_string(kLastSetup) + "]");
    return static_cast<int>(x);
}

// The keys of a limits_deg[] row (min below max and the park position within: checkSteelSpec()).
// clang-format off
const RowField<ArmJointLimit> kLimitFields[] = {
    {.key = "min_deg", .unit = "deg", .label = "min", .lo = -360, .hi = 360,
     .check = FieldCheck::Range, .decimals = 1,
     .number = [](ArmJointLimit& l) -> double& { return l.min_deg; }},
    {.key = "max_deg", .unit = "deg", .label = "max", .lo = -360, .hi = 360,
     .check = FieldCheck::Range, .decimals = 1,
     .number = [](ArmJointLimit& l) -> double& { return l.max_deg; }},
};
// clang-format on

template <size_t N>
void readLimits(SectionReader& parent, const std::array<ArmJointLimit, N>& fallback,
                std::array<ArmJointLimit, N>& out) {
    out = fallback;
    const json::Value* v = parent.get("limits_deg");
    if (!v) return;
    const std::string k = parent.key("limits_deg");
    if (!v->isArray() || v->asArray().size() != N)
        throw JobError(k + " must be an array of " + std::to_string(N) +
                       " objects {min_deg, max_deg}, one per joint");
    readRows<ArmJointLimit>(v->asArray(), k, kLimitFields, out);
}

template <size_t N> json::Array writeLimits(const std::array<ArmJointLimit, N>& l) {
    return writeRows<ArmJointLimit>(kLimitFields, l);
}

template <size_t N>
void readNumbers(SectionReader& parent, const char* key, const char* unit,
                 std::array<double, N>& out) {
    const json::Value* v = parent.get(key);
    if (!v) return;
    const std::string k = parent.key(key);
    if (!v->isArray() || v->asArray().size() != N)
        throw JobError(k + " must be an array of " + std::to_string(N) + " numbers (" + unit + ")");
    for (size_t i = 0; i < N; ++i) {
        const json::Value& e = v->asArray()[i];
        if (!e.isNumber() || !std::isfinite(e.asNumber()))
            throw JobError(k + "[" + std::to_string(i) + "] must be a finite number (" + unit +
                           "), found " + e.typeName());
        out[i] = e.asNumber();
    }
}

template <size_t N> json::Array writeNumbers(const std::array<double, N>& a) {
    json::Array out;
    for (double v : a)
        out.emplace_back(v);
    return out;
}

void readDrives(SectionReader& m, const std::string& leaf, SectionSteelSpec& s) {
    const json::Value* v = m.get(leaf);
    if (!v) return;
    const std::string k = m.key(leaf);
    if (!v->isArray() || v->asArray().size() != kSteelAxes)
        throw JobError(k + " must be an array of 8 rows (axes 0..2 path arm, 3..7 groove arm)");
    for (size_t i = 0; i < kSteelAxes; ++i) {
        SectionReader row(v->asArray()[i], rowKey(k, i));
        readRowFields(row, pidGainFields(), s.controller[i]);
        readRowFields(row, jointPlantFields(), s.plant[i]);
        row.finish();
    }
}

// A drive's row holds its PID's keys, then its plant's.
json::Value writeDrives(const SectionSteelSpec& s) {
    json::Array drives;
    for (size_t i = 0; i < kSteelAxes; ++i) {
        json::Object row;
        writeRowFields(pidGainFields(), s.controller[i], row);
        writeRowFields(jointPlantFields(), s.plant[i], row);
        drives.emplace_back(std::move(row));
    }
    return drives;
}

// piece: {order, drawing, phase, mark, steel_grade, quantity}: marks of at most 64 printable
// characters (as a DSTV header field holds them), a whole quantity in [1, 1e6].
constexpr int kMaxMarkLength = 64;
constexpr int kMaxQuantity = 1'000'000;

PieceMarks readPieceMarks(SectionReader p) {
    PieceMarks m;
    m.order = p.string("order", "");
    m.drawing = p.string("drawing", "");
    m.phase = p.string("phase", "");
    m.mark = p.string("mark", "");
    m.steel_grade = p.string("steel_grade", "");
    m.quantity = p.integer("quantity", "pieces", 1, 1, kMaxQuantity);
    p.finish();
    return m;
}

json::Object writePieceMarks(const PieceMarks& m) {
    json::Object o;
    const std::pair<const char*, const std::string*> marks[] = {{"order", &m.order},
                                                                {"drawing", &m.drawing},
                                                                {"phase", &m.phase},
                                                                {"mark", &m.mark},
                                                                {"steel_grade", &m.steel_grade}};
    for (const auto& [key, value] : marks)
        if (!value->empty()) o.emplace_back(key, *value);
    o.emplace_back("quantity", m.quantity);
    return o;
}

void checkPieceMarks(IssueChecker& c, const PieceMarks& m) {
    const std::pair<const char*, const std::string*> marks[] = {{"order", &m.order},
                                                                {"drawing", &m.drawing},
                                                                {"phase", &m.phase},
                                                                {"mark", &m.mark},
                                                                {"steel_grade", &m.steel_grade}};
    for (const auto& [key, value] : marks) {
        const std::string k = std::string("piece.") + key;
        if (value->size() > static_cast<size_t>(kMaxMarkLength))
            c.add(k, messageC("%s has %zu bytes: at most %d", k.c_str(), value->size(),
                              kMaxMarkLength));
        for (const char ch : *value)
            if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) {
                c.add(k, k + " holds a control character (marks are printable text)");
                break;
            }
    }
    if (m.quantity < 1 || m.quantity > kMaxQuantity)
        c.add("piece.quantity", messageC("piece.quantity = %d pieces is outside [1, %d] pieces",
                                         m.quantity, kMaxQuantity));
}

using Field = SectionField<SectionSteelSpec>;
using S = SectionSteelSpec;
constexpr FieldCheck kRange = FieldCheck::Range, kPositive = FieldCheck::Positive;
constexpr FieldChoices kGrooves{"none", "V", "Y", "K"};

// The keys of the section after `section` (read first, by hand: a catalogue designation or a
// user-defined profile), once each; the file is written in this order. A groove's angle and
// root face depend on its type and the section's thickness: checked in checkSteelSpec().
// One entry per key, kept as a table.
// clang-format off
const Field kFields[] = {
    {.key = "end_cut.mitre_vertical_deg", .unit = "deg", .label = "About the vertical axis (z)",
     .lo = -45, .hi = 45, .check = kRange, .decimals = 2,
     .number = [](S& s) -> double& { return s.cut.mitre_vertical_deg; }},
    {.key = "end_cut.mitre_horizontal_deg", .unit = "deg", .label = "About the horizontal axis (y)",
     .lo = -45, .hi = 45, .check = kRange, .decimals = 2,
     .number = [](S& s) -> double& { return s.cut.mitre_horizontal_deg; }},
    {.key = "end_cut.flanges.groove", .unit = "", .label = "Flange groove", .choices = kGrooves,
     .getChoice = [](const S& s) { return static_cast<int>(s.cut.flanges.type); },
     .setChoice = [](S& s, int i) { s.cut.flanges.type = static_cast<GrooveType>(i); }},
    {.key = "end_cut.flanges.angle_deg", .unit = "deg", .label = "Flange bevel angle",
     .decimals = 2, .number = [](S& s) -> double& { return s.cut.flanges.angle_deg; }},
    {.key = "end_cut.flanges.root_face_mm", .unit = "mm", .label = "Flange root face",
     .decimals = 2, .number = [](S& s) -> double& { return s.cut.flanges.root_face_mm; }},
    {.key = "end_cut.web.groove", .unit = "", .label = "Web groove", .choices = kGrooves,
     .getChoice = [](const S& s) { return static_cast<int>(s.cut.web.type); },
     .setChoice = [](S& s, int i) { s.cut.web.type = static_cast<GrooveType>(i); }},
    {.key = "end_cut.web.angle_deg", .unit = "deg", .label = "Web bevel angle", .decimals = 2,
     .number = [](S& s) -> double& { return s.cut.web.angle_deg; }},
    {.key = "end_cut.web.root_face_mm", .unit = "mm", .label = "Web root face", .decimals = 2,
     .number = [](S& s) -> double& { return s.cut.web.root_face_mm; }},
    // 1 (as loaded) or 2 (turned over); anything else is refused by value.
    {.key = "end_cut.setup", .unit = "", .label = "Setup",
     .readCustom = [](SectionReader& r, const std::string&, S& s) { s.cut.setup = readSetup(r); },
     .writeCustom = [](const S& s) -> json::Value { return s.cut.setup; }},
    {.key = "motion.speed_mm_s", .unit = "mm/s", .label = "Cutting speed along the outline",
     .lo = 0.1, .hi = 100,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.speed_mm_s; }},
    {.key = "motion.ramp_s", .unit = "s", .label = "Ramp to and from the speed", .lo = 0, .hi = 10,
     .check = kRange, .decimals = 2, .number = [](S& s) -> double& { return s.ramp_s; }},
    {.key = "motion.knot_spacing_mm", .unit = "mm", .label = "Knot spacing", .lo = 0.1, .hi = 50,
     .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.knot_spacing_mm; }},
    {.key = "motion.reorient_deg_s", .unit = "deg/s", .label = "Torch turn at the toes", .lo = 1,
     .hi = 360, .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.reorient_deg_s; }},
    {.key = "motion.blend_mm", .unit = "mm", .label = "Bevel blend per face", .lo = 0.1, .hi = 100,
     .check = kRange, .decimals = 1, .number = [](S& s) -> double& { return s.blend_mm; }},
    {.key = "motion.torch_length_mm", .unit = "mm", .label = "Torch length (collision check)",
     .lo = 0, .hi = 1000,
     .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.torch_length_mm; }},
    {.key = "motion.torch_radius_mm", .unit = "mm", .label = "Torch body radius",
     .lo = 0, .hi = 100,
     .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.torch_radius_mm; }},
    {.key = "motion.max_lean_deg", .unit = "deg", .label = "Largest lean along the cut edge",
     .lo = 0, .hi = 60,
     .check = kRange, .decimals = 1, .number = [](S& s) -> double& { return s.max_lean_deg; }},
    {.key = "path_arm.base_y_mm", .unit = "mm", .label = "Base y", .lo = -5000,
     .hi = 5000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.path_base_y_mm; }},
    {.key = "path_arm.base_z_mm", .unit = "mm", .label = "Base z (above the table)", .lo = -5000,
     .hi = 5000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.path_base_z_mm; }},
    {.key = "path_arm.links_mm", .unit = "mm", .label = "Path arm links",
     .readCustom = [](SectionReader& r, const std::string& leaf, S& s) {
         readNumbers(r, leaf.c_str(), "mm", s.path_links_mm);
     },
     .writeCustom = [](const S& s) -> json::Value { return writeNumbers(s.path_links_mm); }},
    {.key = "path_arm.limits_deg", .unit = "deg", .label = "Path arm joint limits",
     .readCustom = [](SectionReader& r, const std::string&, S& s) {
         readLimits(r, s.path_limits, s.path_limits);
     },
     .writeCustom = [](const S& s) -> json::Value { return writeLimits(s.path_limits); }},
    {.key = "groove_arm.base_x_mm", .unit = "mm", .label = "Base x (past the cut)", .lo = -5000,
     .hi = 5000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.groove_base_x_mm; }},
    {.key = "groove_arm.base_y_mm", .unit = "mm", .label = "Base y", .lo = -5000,
     .hi = 5000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.groove_base_y_mm; }},
    {.key = "groove_arm.base_z_mm", .unit = "mm", .label = "Base z", .lo = -5000,
     .hi = 5000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.groove_base_z_mm; }},
    {.key = "groove_arm.limits_deg", .unit = "deg", .label = "Groove arm joint limits",
     .readCustom = [](SectionReader& r, const std::string&, S& s) {
         readLimits(r, s.groove_limits, s.groove_limits);
     },
     .writeCustom = [](const S& s) -> json::Value { return writeLimits(s.groove_limits); }},
    {.key = "park_deg", .unit = "deg", .label = "Park position",
     .readCustom = [](SectionReader& r, const std::string& leaf, S& s) {
         readNumbers(r, leaf.c_str(), "deg", s.park_deg);
     },
     .writeCustom = [](const S& s) -> json::Value { return writeNumbers(s.park_deg); }},
    {.key = "drives", .unit = "", .label = "Drives", .readCustom = readDrives,
     .writeCustom = writeDrives},
};
// clang-format on

} // namespace

std::span<const SectionField<SectionSteelSpec>> sectionSteelFields() {
    return kFields;
}

SectionSteelSpec readSteelSection(SectionReader& m) {
    const SectionSteelSpec d = defaultSectionSteelSpec();
    SectionSteelSpec s = d;
    {
        SectionReader sec = m.child("section");
        if (sec.has("designation")) {
            const std::string name = sec.string("designation", "");
            const auto found = findSection(name);
            if (!found)
                throw JobError(sec.key("designation") + " = " + json::quote(name) +
                               " is not in the catalogue (IPE, HEA, HEB, UPN, UPE, L; or give "
                               "family, h_mm, b_mm, tw_mm, tf_mm, r_mm)");
            s.section = *found;
            s.user_defined = false;
        } else {
            s.user_defined = true;
            s.section.designation.clear();
            s.section.family = sec.choice<SectionFamily>(
                "family",
                {{"I", SectionFamily::I}, {"U", SectionFamily::U}, {"L", SectionFamily::L}},
                SectionFamily::I);
            s.section.h_mm = sec.number("h_mm", "mm");
            s.section.b_mm = sec.number("b_mm", "mm");
            s.section.tw_mm = sec.number("tw_mm", "mm");
            s.section.tf_mm = sec.number("tf_mm", "mm");
            s.section.r_mm = sec.number("r_mm", "mm");
            s.section.r2_mm = sec.number("r2_mm", "mm", 0);
        }
        s.length_mm = sec.number("length_mm", "mm", d.length_mm);
        sec.finish();
    }
    if (m.has("piece")) s.piece = readPieceMarks(m.child("piece"));
    s.cut = EndCutSpec{}; // an end cut left out of the file is a square cut, setup 1
    readFields(m, sectionSteelFields(), s);
    return s;
}

void writeSteelSection(const SectionSteelSpec& s, json::Object& out) {
    if (!s.user_defined)
        out.emplace_back("section", json::Object{{"designation", s.section.designation},
                                                 {"length_mm", s.length_mm}});
    else {
        json::Object sec{{"family", toString(s.section.family)},
                         {"h_mm", s.section.h_mm},
                         {"b_mm", s.section.b_mm},
                         {"tw_mm", s.section.tw_mm},
                         {"tf_mm", s.section.tf_mm},
                         {"r_mm", s.section.r_mm}};
        if (s.section.r2_mm > 0) sec.emplace_back("r2_mm", s.section.r2_mm); // optional
        sec.emplace_back("length_mm", s.length_mm);
        out.emplace_back("section", std::move(sec));
    }
    if (!s.piece.empty()) out.emplace_back("piece", writePieceMarks(s.piece));
    for (auto& member : writeFields(sectionSteelFields(), s))
        out.push_back(std::move(member));
}

void checkSteelSpec(IssueChecker& c, const SectionSteelSpec& s, double periodS) {
    for (const auto& [k, m] : checkSectionDims(s.section, "section"))
        c.add(k, m);
    c.positive("section.length_mm", s.length_mm, 50, 24000, "mm");
    checkPieceMarks(c, s.piece);
    checkFields(c, sectionSteelFields(), s);
    const struct {
        const char* key;
        const GrooveSpec& g;
        double thickness;
    } grooves[] = {{"end_cut.flanges", s.cut.flanges, s.section.tf_mm},
                   {"end_cut.web", s.cut.web, s.section.tw_mm}};
    for (const auto& g : grooves) {
        const std::string k = g.key;
        if (g.g.type == GrooveType::None) {
            // Unused without a groove, but still a value of the file: within its physics.
            c.range(k + ".angle_deg", g.g.angle_deg, 0, 90, "deg");
            c.range(k + ".root_face_mm", g.g.root_face_mm, 0, std::max(0.0, g.thickness), "mm");
            continue;
        }
        // ISO 9692-1: bevel angles of V, Y and K preparations lie about 30..60 deg (per side
        // 15..60); the torch tilt is limited by the bevel head.
        c.range(k + ".angle_deg", g.g.angle_deg, 5, 60, "deg");
        if (g.g.type == GrooveType::V && g.g.root_face_mm != 0)
            c.add(k + ".root_face_mm",
                  messageC("%s.root_face_mm = %.6g mm: a V groove has no root face (use Y)",
                           k.c_str(), g.g.root_face_mm));
        if (g.g.type != GrooveType::V)
            c.range(k + ".root_face_mm", g.g.root_face_mm, 0, g.thickness, "mm");
    }
    if (s.cut.setup < 1 || s.cut.setup > kLastSetup)
        c.add("end_cut.setup",
              messageC("end_cut.setup = %d is outside [1, %d]", s.cut.setup, kLastSetup));
    else if (const std::string why = setupTwoProblem(s); !why.empty())
        c.add("end_cut.setup", why);
    for (size_t i = 0; i < 3; ++i)
        c.positive("path_arm.links_mm[" + std::to_string(i) + "]", s.path_links_mm[i], 1, 5000,
                   "mm");
    auto limits = [&](const std::string& arm, const ArmJointLimit* l, size_t n, size_t axis0) {
        for (size_t i = 0; i < n; ++i) {
            const std::string k = rowKey(arm + ".limits_deg", i);
            checkRow<ArmJointLimit>(c, kLimitFields, k, l[i]);
            if (!(l[i].min_deg < l[i].max_deg))
                c.add(k + ".min_deg", messageC("%s.min_deg = %.6g deg must be below max_deg = "
                                               "%.6g deg",
                                               k.c_str(), l[i].min_deg, l[i].max_deg));
            const double park = s.park_deg[axis0 + i];
            if (!(park >= l[i].min_deg && park <= l[i].max_deg))
                c.add("park_deg[" + std::to_string(axis0 + i) + "]",
                      messageC("park_deg[%zu] = %.6g deg is outside %s [%.6g, %.6g] deg", axis0 + i,
                               park, k.c_str(), l[i].min_deg, l[i].max_deg));
        }
    };
    limits("path_arm", s.path_limits.data(), 3, 0);
    limits("groove_arm", s.groove_limits.data(), 5, 3);
    for (size_t i = 0; i < kSteelAxes; ++i) {
        const std::string k = rowKey("drives", i);
        const auto& g = s.controller[i];
        checkRow(c, pidGainFields(), k, g);
        if (g.tau_f > 0 && periodS > 0 && g.tau_f < periodS / 2)
            c.add(k + ".tau_f_s", messageC("drives[%zu].tau_f_s = %.6g s must be >= half the "
                                           "control period (%.6g s)",
                                           i, g.tau_f, periodS / 2));
        checkRow(c, jointPlantFields(), k, s.plant[i]);
    }
}

} // namespace cutcell::section_steel
