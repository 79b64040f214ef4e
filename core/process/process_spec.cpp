#include "core/process/process_spec.h"

#include "core/common/c_format.h"

#include <cmath>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace cutcell {
namespace {

// The installed library and every one it replaced: a reference handed out by
// activeCutCharts() (a plan on the worker thread) stays valid when the GUI's editor installs a
// new table; a replaced table is a few kilobytes and is kept until the program ends.
struct ActiveSlot {
    std::mutex mutex;
    std::shared_ptr<const CutChartSet> now;
    std::vector<std::shared_ptr<const CutChartSet>> replaced;
};

ActiveSlot& activeSlot() {
    static ActiveSlot slot;
    return slot;
}

// An override value outside its figure's range: "" when inside.
std::string overrideProblem(CutFigure f, double v) {
    const CutFigureInfo& info = cutFigureInfo(f);
    const bool aboveLo = info.loOpen ? v > info.lo : v >= info.lo;
    if (std::isfinite(v) && aboveLo && v <= info.hi) return {};
    if (info.loOpen)
        return messageC("process.override.%s = %.6g %s is outside its range: above %.6g %s and "
                        "at most %.6g %s",
                        info.key, v, info.unit, info.lo, info.unit, info.hi, info.unit);
    return messageC("process.override.%s = %.6g %s is outside [%.6g, %.6g] %s", info.key, v,
                    info.unit, info.lo, info.hi, info.unit);
}

// process.lead_in / process.lead_out: kind, length_mm (required unless "none"), overlap_mm
// (lead-out only, optional).
LeadSpec readLead(SectionReader& p, const char* name, bool out) {
    LeadSpec lead;
    SectionReader l = p.child(name);
    lead.kind = l.choice<LeadKind>(
        "kind", {{"none", LeadKind::None}, {"line", LeadKind::Line}, {"arc", LeadKind::Arc}},
        LeadKind::None);
    if (!l.has("kind"))
        throw JobError(l.key("kind") + " is required (\"line\", \"arc\" or \"none\")");
    if (lead.used())
        lead.length_mm = l.number("length_mm", "mm");
    else if (l.has("length_mm")) // never read and dropped
        throw JobError(l.key("length_mm") + " is given but " + l.key("kind") +
                       " is \"none\": remove it, or choose \"line\" or \"arc\"");
    if (out) lead.overlap_mm = l.number("overlap_mm", "mm", 0);
    l.finish();
    return lead;
}

void writeLead(const LeadSpec& lead, const char* name, bool out, json::Object& p) {
    if (!lead.used() && lead.overlap_mm == 0) return;
    json::Object l{{"kind", toString(lead.kind)}};
    if (lead.used()) l.emplace_back("length_mm", lead.length_mm);
    if (out && lead.overlap_mm != 0) l.emplace_back("overlap_mm", lead.overlap_mm);
    p.emplace_back(name, std::move(l));
}

void checkLead(IssueChecker& c, const LeadSpec& lead, const std::string& key) {
    if (lead.used()) c.positive(key + ".length_mm", lead.length_mm, 0.1, 100, "mm");
    c.range(key + ".overlap_mm", lead.overlap_mm, 0, 50, "mm");
}

TorchHeightSpec readTorchHeight(SectionReader& p) {
    TorchHeightSpec t;
    t.used = true;
    SectionReader h = p.child("torch_height");
    t.thc = h.boolean("thc", true);
    t.arc_noise_v = h.number("arc_noise_v", "V", 0);
    if (h.has("simulated_pipe")) {
        SectionReader s = h.child("simulated_pipe");
        t.ovality_mm = s.number("ovality_mm", "mm", 0);
        t.major_axis_deg = s.number("major_axis_deg", "deg", 0);
        t.runout_mm = s.number("runout_mm", "mm", 0);
        t.runout_deg = s.number("runout_deg", "deg", 0);
        t.taper_mm_per_m = s.number("taper_mm_per_m", "mm/m", 0);
        s.finish();
    }
    h.finish();
    return t;
}

void writeTorchHeight(const TorchHeightSpec& t, json::Object& p) {
    if (!t.used) return;
    p.emplace_back(
        "torch_height",
        json::Object{{"thc", t.thc},
                     {"arc_noise_v", t.arc_noise_v},
                     {"simulated_pipe", json::Object{{"ovality_mm", t.ovality_mm},
                                                     {"major_axis_deg", t.major_axis_deg},
                                                     {"runout_mm", t.runout_mm},
                                                     {"runout_deg", t.runout_deg},
                                                     {"taper_mm_per_m", t.taper_mm_per_m}}}});
}

} // namespace

const char* toString(LeadKind k) {
    switch (k) {
    case LeadKind::Line:
        return "line";
    case LeadKind::Arc:
        return "arc";
    case LeadKind::None:
        break;
    }
    return "none";
}

const CutChartSet& activeCutCharts() {
    ActiveSlot& slot = activeSlot();
    const std::lock_guard lock(slot.mutex);
    return slot.now ? *slot.now : shippedCutCharts();
}

void setActiveCutCharts(CutChartSet set) {
    checkCutCharts(set);
    auto next = std::make_shared<const CutChartSet>(std::move(set));
    ActiveSlot& slot = activeSlot();
    const std::lock_guard lock(slot.mutex);
    if (slot.now) slot.replaced.push_back(std::move(slot.now));
    slot.now = std::move(next);
}

void readProcess(SectionReader& section, ProcessSpec& spec) {
    spec = ProcessSpec{};
    if (!section.has("process")) return;
    SectionReader p = section.child("process");
    spec.used = true;
    spec.process = p.choice<CutProcess>("process",
                                        {{"plasma", CutProcess::Plasma},
                                         {"oxy_fuel", CutProcess::OxyFuel},
                                         {"laser", CutProcess::Laser}},
                                        CutProcess::Plasma);
    spec.material = p.string("material", "");
    spec.consumable = p.string("consumable", "");
    if (spec.material.empty())
        throw JobError(p.key("material") + " is required (a chart's material)");
    if (spec.consumable.empty())
        throw JobError(p.key("consumable") + " is required (a chart's consumable set)");
    if (p.has("thickness_mm")) spec.thickness_mm = p.number("thickness_mm", "mm");
    if (p.has("override")) {
        SectionReader o = p.child("override");
        for (std::size_t k = 0; k < kCutFigureCount; ++k) {
            const auto f = static_cast<CutFigure>(k);
            const CutFigureInfo& info = cutFigureInfo(f);
            if (f == CutFigure::ThicknessMm || !o.has(info.key)) continue;
            if (!cutFigureApplies(f, spec.process))
                throw JobError(o.key(info.key) + " does not apply to " + toString(spec.process));
            spec.override.set(f, o.number(info.key, info.unit));
        }
        o.finish();
    }
    if (p.has("lead_in")) spec.lead_in = readLead(p, "lead_in", false);
    if (p.has("lead_out")) spec.lead_out = readLead(p, "lead_out", true);
    if (p.has("torch_height")) spec.torch_height = readTorchHeight(p);
    p.finish();
}

void writeProcess(const ProcessSpec& spec, json::Object& section) {
    if (!spec.used) return;
    json::Object p{{"process", toString(spec.process)},
                   {"material", spec.material},
                   {"consumable", spec.consumable}};
    if (spec.thickness_mm) p.emplace_back("thickness_mm", *spec.thickness_mm);
    json::Object o;
    for (std::size_t k = 0; k < kCutFigureCount; ++k)
        if (const auto v = spec.override.figures[k])
            o.emplace_back(cutFigureInfo(static_cast<CutFigure>(k)).key, *v);
    if (!o.empty()) p.emplace_back("override", std::move(o));
    writeLead(spec.lead_in, "lead_in", false, p);
    writeLead(spec.lead_out, "lead_out", true, p);
    writeTorchHeight(spec.torch_height, p);
    section.emplace_back("process", std::move(p));
}

ProcessSettings resolveProcess(const ProcessSpec& spec, double partWall_mm,
                               const CutChartSet& charts) {
    ProcessSettings s;
    s.thickness_from_part = !spec.thickness_mm.has_value();
    s.thickness_mm = spec.thickness_mm.value_or(partWall_mm);
    const CutPick pick =
        pickCutRow(charts, spec.process, spec.material, spec.consumable, s.thickness_mm);
    if (pick.chart) {
        s.chart_name = pick.chart->name();
        s.chart_source = pick.chart->source;
        s.typical_values = pick.chart->typical_values;
        s.life_pierces = pick.chart->life_pierces;
        s.life_arc_minutes = pick.chart->life_arc_minutes;
        s.volts_per_mm = pick.chart->volts_per_mm;
    }
    if (!pick.ok()) {
        s.outcome = pick.outcome;
        // The part's wall picked the row: say so, the operator may not have typed a thickness.
        if (s.thickness_from_part && s.outcome.key == "process.thickness_mm")
            s.outcome.message = "the part's wall " + s.outcome.message +
                                " (set process.thickness_mm to cut another row)";
        return s;
    }
    s.chart_row = pick.row;
    s.effective = pick.row;
    for (std::size_t k = 0; k < kCutFigureCount; ++k)
        if (const auto v = spec.override.figures[k]) s.effective.figures[k] = *v;
    return s;
}

void checkProcess(IssueChecker& c, const ProcessSpec& spec, double partWall_mm) {
    if (!spec.used) return;
    if (spec.thickness_mm) c.positive("process.thickness_mm", *spec.thickness_mm, 0.1, 300, "mm");
    for (std::size_t k = 0; k < kCutFigureCount; ++k)
        if (const auto v = spec.override.figures[k]) {
            const auto f = static_cast<CutFigure>(k);
            const std::string problem = overrideProblem(f, *v);
            if (!problem.empty())
                c.add(std::string("process.override.") + cutFigureInfo(f).key, problem);
        }
    checkLead(c, spec.lead_in, "process.lead_in");
    checkLead(c, spec.lead_out, "process.lead_out");
    if (spec.torch_height.used)
        c.range("process.torch_height.arc_noise_v", spec.torch_height.arc_noise_v, 0, 10, "V");
    if (c.has("process.thickness_mm")) return;
    const ProcessSettings s = resolveProcess(spec, partWall_mm);
    if (!s.ok()) c.add(s.outcome.key, s.outcome.message);
    if (s.ok()) {
        const std::string problem = leadHeightProblem(spec, s);
        if (!problem.empty()) c.add(leadHeightKey(spec, s), problem);
    }
}

std::string leadHeightKey(const ProcessSpec& spec, const ProcessSettings& s) {
    if (!spec.lead_in.used() && !spec.lead_out.used()) return {};
    if (!s.effective.get(CutFigure::PierceHeightMm)) return "process.override.pierce_height_mm";
    if (!s.effective.get(CutFigure::CutHeightMm)) return "process.override.cut_height_mm";
    return {};
}

std::string leadHeightProblem(const ProcessSpec& spec, const ProcessSettings& s) {
    const std::string key = leadHeightKey(spec, s);
    if (key.empty()) return {};
    const bool pierce = key == "process.override.pierce_height_mm";
    const CutFigureInfo& info =
        cutFigureInfo(pierce ? CutFigure::PierceHeightMm : CutFigure::CutHeightMm);
    const bool in = spec.lead_in.used();
    return messageC("process.%s.kind = \"%s\" needs the %s height: the chart '%s' gives no %s; "
                    "set %s (%s, [%.6g, %.6g] %s)",
                    in ? "lead_in" : "lead_out",
                    toString(in ? spec.lead_in.kind : spec.lead_out.kind),
                    pierce ? "pierce" : "cut", s.chart_name.c_str(), info.key, key.c_str(),
                    info.unit, info.lo, info.hi, info.unit);
}

void checkNoTorchHeight(IssueChecker& c, const ProcessSpec& spec, const char* machine) {
    if (spec.torch_height.used)
        c.add("process.torch_height",
              messageC("process.torch_height: the %s has no torch height control (the pipe "
                       "robot has); remove it",
                       machine));
}

} // namespace cutcell
