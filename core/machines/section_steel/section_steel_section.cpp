#include "core/machines/section_steel/section_steel_section.h"

#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_outline.h"

#include <cmath>

namespace cutcell::section_steel {
namespace {

GrooveSpec readGroove(SectionReader& parent, const char* key) {
    GrooveSpec g;
    if (!parent.has(key)) return g;
    SectionReader r = parent.child(key);
    g.type = r.choice<GrooveType>("groove",
                                  {{"none", GrooveType::None},
                                   {"V", GrooveType::V},
                                   {"Y", GrooveType::Y},
                                   {"K", GrooveType::K}},
                                  GrooveType::None);
    g.angle_deg = r.number("angle_deg", "deg", 30);
    g.root_face_mm = r.number("root_face_mm", "mm", 0);
    r.finish();
    return g;
}

json::Value writeGroove(const GrooveSpec& g) {
    return json::Object{
        {"groove", toString(g.type)}, {"angle_deg", g.angle_deg}, {"root_face_mm", g.root_face_mm}};
}

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

template <size_t N>
void readLimits(SectionReader& parent, const std::array<JointLimit, N>& fallback,
                std::array<JointLimit, N>& out) {
    out = fallback;
    const json::Value* v = parent.get("limits_deg");
    if (!v) return;
    const std::string k = parent.key("limits_deg");
    if (!v->isArray() || v->asArray().size() != N)
        throw JobError(k + " must be an array of " + std::to_string(N) +
                       " objects {min_deg, max_deg}, one per joint");
    for (size_t i = 0; i < N; ++i) {
        SectionReader row(v->asArray()[i], k + "[" + std::to_string(i) + "]");
        out[i].min_deg = row.number("min_deg", "deg");
        out[i].max_deg = row.number("max_deg", "deg");
        row.finish();
    }
}

template <size_t N> json::Array writeLimits(const std::array<JointLimit, N>& l) {
    json::Array a;
    for (const auto& j : l)
        a.emplace_back(json::Object{{"min_deg", j.min_deg}, {"max_deg", j.max_deg}});
    return a;
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

} // namespace

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
    s.cut = EndCutSpec{};
    if (m.has("end_cut")) {
        SectionReader c = m.child("end_cut");
        s.cut.mitre_vertical_deg = c.number("mitre_vertical_deg", "deg", 0);
        s.cut.mitre_horizontal_deg = c.number("mitre_horizontal_deg", "deg", 0);
        s.cut.flanges = readGroove(c, "flanges");
        s.cut.web = readGroove(c, "web");
        s.cut.setup = readSetup(c); // absent in older jobs: 1
        c.finish();
    }
    if (m.has("motion")) {
        SectionReader r = m.child("motion");
        s.speed_mm_s = r.number("speed_mm_s", "mm/s", d.speed_mm_s);
        s.ramp_s = r.number("ramp_s", "s", d.ramp_s);
        s.knot_spacing_mm = r.number("knot_spacing_mm", "mm", d.knot_spacing_mm);
        s.reorient_deg_s = r.number("reorient_deg_s", "deg/s", d.reorient_deg_s);
        s.blend_mm = r.number("blend_mm", "mm", d.blend_mm);
        s.torch_length_mm = r.number("torch_length_mm", "mm", d.torch_length_mm);
        s.torch_radius_mm = r.number("torch_radius_mm", "mm", d.torch_radius_mm);
        s.max_lean_deg = r.number("max_lean_deg", "deg", d.max_lean_deg);
        r.finish();
    }
    if (m.has("path_arm")) {
        SectionReader r = m.child("path_arm");
        s.path_base_y_mm = r.number("base_y_mm", "mm", d.path_base_y_mm);
        s.path_base_z_mm = r.number("base_z_mm", "mm", d.path_base_z_mm);
        readNumbers(r, "links_mm", "mm", s.path_links_mm);
        readLimits(r, d.path_limits, s.path_limits);
        r.finish();
    }
    if (m.has("groove_arm")) {
        SectionReader r = m.child("groove_arm");
        s.groove_base_x_mm = r.number("base_x_mm", "mm", d.groove_base_x_mm);
        s.groove_base_y_mm = r.number("base_y_mm", "mm", d.groove_base_y_mm);
        s.groove_base_z_mm = r.number("base_z_mm", "mm", d.groove_base_z_mm);
        readLimits(r, d.groove_limits, s.groove_limits);
        r.finish();
    }
    readNumbers(m, "park_deg", "deg", s.park_deg);
    if (const json::Value* v = m.get("drives")) {
        const std::string k = m.key("drives");
        if (!v->isArray() || v->asArray().size() != kSteelAxes)
            throw JobError(k + " must be an array of 8 rows (axes 0..2 path arm, 3..7 groove arm)");
        for (size_t i = 0; i < kSteelAxes; ++i) {
            SectionReader row(v->asArray()[i], k + "[" + std::to_string(i) + "]");
            s.controller[i].kp = row.number("kp_nm_per_rad", "N m/rad");
            s.controller[i].ki = row.number("ki_nm_per_rad_s", "N m/(rad s)");
            s.controller[i].kd = row.number("kd_nm_s_per_rad", "N m s/rad");
            s.controller[i].tau_f = row.number("tau_f_s", "s");
            s.plant[i].inertia_kg_m2 = row.number("inertia_kg_m2", "kg m^2");
            s.plant[i].viscous_nm_s_per_rad = row.number("viscous_nm_s_per_rad", "N m s/rad");
            s.plant[i].torque_limit_nm = row.number("torque_limit_nm", "N m");
            row.finish();
        }
    }
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
    out.emplace_back("end_cut", json::Object{{"mitre_vertical_deg", s.cut.mitre_vertical_deg},
                                             {"mitre_horizontal_deg", s.cut.mitre_horizontal_deg},
                                             {"flanges", writeGroove(s.cut.flanges)},
                                             {"web", writeGroove(s.cut.web)},
                                             {"setup", s.cut.setup}});
    out.emplace_back("motion", json::Object{{"speed_mm_s", s.speed_mm_s},
                                            {"ramp_s", s.ramp_s},
                                            {"knot_spacing_mm", s.knot_spacing_mm},
                                            {"reorient_deg_s", s.reorient_deg_s},
                                            {"blend_mm", s.blend_mm},
                                            {"torch_length_mm", s.torch_length_mm},
                                            {"torch_radius_mm", s.torch_radius_mm},
                                            {"max_lean_deg", s.max_lean_deg}});
    out.emplace_back("path_arm", json::Object{{"base_y_mm", s.path_base_y_mm},
                                              {"base_z_mm", s.path_base_z_mm},
                                              {"links_mm", writeNumbers(s.path_links_mm)},
                                              {"limits_deg", writeLimits(s.path_limits)}});
    out.emplace_back("groove_arm", json::Object{{"base_x_mm", s.groove_base_x_mm},
                                                {"base_y_mm", s.groove_base_y_mm},
                                                {"base_z_mm", s.groove_base_z_mm},
                                                {"limits_deg", writeLimits(s.groove_limits)}});
    out.emplace_back("park_deg", writeNumbers(s.park_deg));
    json::Array drives;
    for (size_t i = 0; i < kSteelAxes; ++i)
        drives.emplace_back(json::Object{{"kp_nm_per_rad", s.controller[i].kp},
                                         {"ki_nm_per_rad_s", s.controller[i].ki},
                                         {"kd_nm_s_per_rad", s.controller[i].kd},
                                         {"tau_f_s", s.controller[i].tau_f},
                                         {"inertia_kg_m2", s.plant[i].inertia_kg_m2},
                                         {"viscous_nm_s_per_rad", s.plant[i].viscous_nm_s_per_rad},
                                         {"torque_limit_nm", s.plant[i].torque_limit_nm}});
    out.emplace_back("drives", drives);
}

void checkSteelSpec(IssueChecker& c, const SectionSteelSpec& s, double periodS) {
    for (const auto& [k, m] : checkSectionDims(s.section, "section"))
        c.add(k, m);
    c.positive("section.length_mm", s.length_mm, 50, 24000, "mm");
    c.range("end_cut.mitre_vertical_deg", s.cut.mitre_vertical_deg, -45, 45, "deg");
    c.range("end_cut.mitre_horizontal_deg", s.cut.mitre_horizontal_deg, -45, 45, "deg");
    const struct {
        const char* key;
        const GrooveSpec& g;
        double thickness;
    } grooves[] = {{"end_cut.flanges", s.cut.flanges, s.section.tf_mm},
                   {"end_cut.web", s.cut.web, s.section.tw_mm}};
    for (const auto& g : grooves) {
        if (g.g.type == GrooveType::None) continue;
        const std::string k = g.key;
        // ISO 9692-1: bevel angles of V, Y and K preparations lie about 30..60 deg (per side
        // 15..60); the torch tilt is limited by the bevel head.
        c.range(k + ".angle_deg", g.g.angle_deg, 5, 60, "deg");
        if (g.g.type == GrooveType::V && g.g.root_face_mm != 0)
            c.add(k + ".root_face_mm", k + ".root_face_mm = " + num(g.g.root_face_mm) +
                                           " mm: a V groove has no root face (use Y)");
        if (g.g.type != GrooveType::V)
            c.range(k + ".root_face_mm", g.g.root_face_mm, 0, g.thickness, "mm");
    }
    if (s.cut.setup < 1 || s.cut.setup > kLastSetup)
        c.add("end_cut.setup", "end_cut.setup = " + std::to_string(s.cut.setup) +
                                   " is outside [1, " + std::to_string(kLastSetup) + "]");
    else if (const std::string why = setupTwoProblem(s); !why.empty())
        c.add("end_cut.setup", why);
    c.positive("motion.speed_mm_s", s.speed_mm_s, 0.1, 100, "mm/s");
    c.range("motion.ramp_s", s.ramp_s, 0, 10, "s");
    c.positive("motion.knot_spacing_mm", s.knot_spacing_mm, 0.1, 50, "mm");
    c.positive("motion.reorient_deg_s", s.reorient_deg_s, 1, 360, "deg/s");
    c.range("motion.blend_mm", s.blend_mm, 0.1, 100, "mm");
    c.range("motion.torch_length_mm", s.torch_length_mm, 0, 1000, "mm");
    c.range("motion.torch_radius_mm", s.torch_radius_mm, 0, 100, "mm");
    c.range("motion.max_lean_deg", s.max_lean_deg, 0, 60, "deg");
    c.range("path_arm.base_y_mm", s.path_base_y_mm, -5000, 5000, "mm");
    c.range("path_arm.base_z_mm", s.path_base_z_mm, -5000, 5000, "mm");
    for (size_t i = 0; i < 3; ++i)
        c.positive("path_arm.links_mm[" + std::to_string(i) + "]", s.path_links_mm[i], 1, 5000,
                   "mm");
    c.range("groove_arm.base_x_mm", s.groove_base_x_mm, -5000, 5000, "mm");
    c.range("groove_arm.base_y_mm", s.groove_base_y_mm, -5000, 5000, "mm");
    c.range("groove_arm.base_z_mm", s.groove_base_z_mm, -5000, 5000, "mm");
    auto limits = [&](const std::string& arm, const JointLimit* l, size_t n, size_t axis0) {
        for (size_t i = 0; i < n; ++i) {
            const std::string k = arm + ".limits_deg[" + std::to_string(i) + "]";
            c.range(k + ".min_deg", l[i].min_deg, -360, 360, "deg");
            c.range(k + ".max_deg", l[i].max_deg, -360, 360, "deg");
            if (!(l[i].min_deg < l[i].max_deg))
                c.add(k + ".min_deg", k + ".min_deg = " + num(l[i].min_deg) +
                                          " deg must be below max_deg = " + num(l[i].max_deg) +
                                          " deg");
            const double park = s.park_deg[axis0 + i];
            if (!(park >= l[i].min_deg && park <= l[i].max_deg))
                c.add("park_deg[" + std::to_string(axis0 + i) + "]",
                      "park_deg[" + std::to_string(axis0 + i) + "] = " + num(park) +
                          " deg is outside " + k + " [" + num(l[i].min_deg) + ", " +
                          num(l[i].max_deg) + "] deg");
        }
    };
    limits("path_arm", s.path_limits.data(), 3, 0);
    limits("groove_arm", s.groove_limits.data(), 5, 3);
    for (size_t i = 0; i < kSteelAxes; ++i) {
        const std::string k = "drives[" + std::to_string(i) + "]";
        const auto& g = s.controller[i];
        const auto& p = s.plant[i];
        c.range(k + ".kp_nm_per_rad", g.kp, 0, 1e6, "N m/rad");
        c.range(k + ".ki_nm_per_rad_s", g.ki, 0, 1e8, "N m/(rad s)");
        c.range(k + ".kd_nm_s_per_rad", g.kd, 0, 1e5, "N m s/rad");
        c.positive(k + ".tau_f_s", g.tau_f, 1e-5, 1, "s");
        if (g.tau_f > 0 && periodS > 0 && g.tau_f < periodS / 2)
            c.add(k + ".tau_f_s", k + ".tau_f_s = " + num(g.tau_f) +
                                      " s must be >= half the control period (" + num(periodS / 2) +
                                      " s)");
        c.positive(k + ".inertia_kg_m2", p.inertia_kg_m2, 1e-5, 1e4, "kg m^2");
        c.range(k + ".viscous_nm_s_per_rad", p.viscous_nm_s_per_rad, 0, 1e5, "N m s/rad");
        c.positive(k + ".torque_limit_nm", p.torque_limit_nm, 1e-3, 1e5, "N m");
    }
}

} // namespace cutcell::section_steel
