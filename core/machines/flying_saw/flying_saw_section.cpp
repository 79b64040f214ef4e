#include "core/machines/flying_saw/flying_saw_section.h"

#include "core/job/field_table.h"
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

std::vector<PieceOrder> readQueue(SectionReader& r) {
    const json::Value* q = r.get("queue");
    if (!q) return {};
    if (!q->isArray())
        throw JobError(r.key("queue") + " must be an array of {length_mm, count}, found " +
                       q->typeName());
    if (q->asArray().empty() || q->asArray().size() > 16)
        throw JobError(r.key("queue") + " has " + std::to_string(q->asArray().size()) +
                       " entries; it must have 1 to 16");
    std::vector<PieceOrder> out;
    for (size_t i = 0; i < q->asArray().size(); ++i) {
        SectionReader e(q->asArray()[i], r.key("queue") + "[" + std::to_string(i) + "]");
        PieceOrder o;
        o.length_mm = e.number("length_mm", "mm");
        o.count = e.integer("count", "pieces", 1, 1, 1000000);
        e.finish();
        out.push_back(o);
    }
    return out;
}

json::Value writeQueue(const FlyingSawSpec& s) {
    json::Array queue;
    for (const PieceOrder& o : s.queue)
        queue.emplace_back(json::Object{{"length_mm", o.length_mm}, {"count", o.count}});
    return queue;
}

using Field = SectionField<FlyingSawSpec>;
using S = FlyingSawSpec;
constexpr FieldCheck kRange = FieldCheck::Range, kPositive = FieldCheck::Positive;
bool isRound(const S& s) {
    return s.shape == TubeShape::Round;
}
bool rectangular(const S& s) {
    return s.shape == TubeShape::Rectangular;
}

// Every key of the section, once (the file is written in this order). The tube's wall, its
// corner radius and the carriage's wait position are bounded by other values: checked in
// checkFlyingSawSpec().
// One entry per key, kept as a table.
// clang-format off
const Field kFields[] = {
    {.key = "tube.shape", .unit = "", .label = "Tube", .choices = {"round", "rectangular"},
     .getChoice = [](const S& s) { return isRound(s) ? 0 : 1; },
     .setChoice = [](S& s, int i) {
         s.shape = i == 0 ? TubeShape::Round : TubeShape::Rectangular;
     }},
    {.key = "tube.diameter_mm", .unit = "mm", .label = "Diameter D", .lo = 5, .hi = 1000,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.diameter_mm; },
     .when = isRound},
    {.key = "tube.width_mm", .unit = "mm", .label = "Width a (across)", .lo = 5, .hi = 1000,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.width_mm; },
     .when = rectangular},
    {.key = "tube.height_mm", .unit = "mm", .label = "Height b (up)", .lo = 5, .hi = 1000,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.height_mm; },
     .when = rectangular},
    {.key = "tube.corner_radius_mm", .unit = "mm", .label = "Corner radius r", .decimals = 2,
     .number = [](S& s) -> double& { return s.corner_radius_mm; }, .when = rectangular},
    // Within half the tube with the overcut too (checkFlyingSawSpec()); at most half the largest
    // tube whatever the overcut.
    {.key = "tube.wall_mm", .unit = "mm", .label = "Wall", .lo = 0.1, .hi = 500,
     .check = kPositive, .decimals = 2, .number = [](S& s) -> double& { return s.wall_mm; }},
    {.key = "line.speed_m_min", .unit = "m/min", .label = "Line speed", .lo = 0.1, .hi = 300,
     .check = kPositive, .decimals = 3,
     .number = [](S& s) -> double& { return s.line_speed_m_min; }},
    {.key = "line.roller_pulses_per_rev", .unit = "pulses/rev", .label = "Roller encoder",
     .lo = 1, .hi = 10000000, .check = kRange,
     .integer = [](S& s) -> int& { return s.roller_pulses_per_rev; }},
    {.key = "line.roller_diameter_mm", .unit = "mm", .label = "Roller diameter", .lo = 10,
     .hi = 1000, .check = kPositive, .decimals = 4,
     .number = [](S& s) -> double& { return s.roller_diameter_mm; }},
    {.key = "line.filter_alpha", .unit = "", .label = "Master filter gain α", .lo = 1e-4, .hi = 1,
     .check = kPositive, .decimals = 4, .number = [](S& s) -> double& { return s.filter_alpha; }},
    {.key = "cut.queue", .unit = "", .label = "Queue of lengths",
     .readCustom = [](SectionReader& r, const std::string&, S& s) { s.queue = readQueue(r); },
     .writeCustom = writeQueue},
    {.key = "cut.tolerance_mm", .unit = "mm", .label = "Length tolerance ±", .lo = 0.001,
     .hi = 100, .check = kPositive, .decimals = 3,
     .number = [](S& s) -> double& { return s.tolerance_mm; }},
    // Optional: without it the first sync-in follows the line where the run starts.
    {.key = "cut.first_sync_master_mm", .unit = "mm", .label = "First sync-in at",
     .readCustom =
         [](SectionReader& r, const std::string& leaf, S& s) {
             if (r.get(leaf)) s.first_sync_master_mm = r.number(leaf, "mm");
         },
     .writeCustom = [](const S& s) -> json::Value {
         return std::isnan(s.first_sync_master_mm) ? json::Value() : s.first_sync_master_mm;
     }},
    {.key = "carriage.stroke_mm", .unit = "mm", .label = "Stroke", .lo = 10, .hi = 50000,
     .check = kPositive, .decimals = 1, .number = [](S& s) -> double& { return s.stroke_mm; }},
    {.key = "carriage.max_speed_mm_s", .unit = "mm/s", .label = "Speed limit", .lo = 1,
     .hi = 20000, .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.carriage.max_speed_mm_s; }},
    {.key = "carriage.max_accel_mm_s2", .unit = "mm/s^2", .label = "Acceleration limit", .lo = 10,
     .hi = 1e6, .check = kPositive, .decimals = 0,
     .number = [](S& s) -> double& { return s.carriage.max_accel_mm_s2; }},
    {.key = "carriage.max_jerk_mm_s3", .unit = "mm/s^3", .label = "Jerk limit", .lo = 100,
     .hi = 1e9, .check = kPositive, .decimals = 0,
     .number = [](S& s) -> double& { return s.carriage.max_jerk_mm_s3; }},
    {.key = "carriage.wait_position_mm", .unit = "mm", .label = "Wait position", .decimals = 1,
     .number = [](S& s) -> double& { return s.wait_position_mm; }},
    {.key = "saw.settle_s", .unit = "s", .label = "Settle C → D", .lo = 0, .hi = 10,
     .check = kRange, .decimals = 3, .number = [](S& s) -> double& { return s.saw.settle_s; }},
    {.key = "saw.fast_feed_mm_s", .unit = "mm/s", .label = "Fast feed (in air)", .lo = 0.1,
     .hi = 10000,
     .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.saw.fast_feed_mm_s; }},
    {.key = "saw.slow_feed_mm_s", .unit = "mm/s", .label = "Slow feed (through the wall)",
     .lo = 0.1,
     .hi = 10000, .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.saw.slow_feed_mm_s; }},
    {.key = "saw.approach_gap_mm", .unit = "mm", .label = "Fast feed stops before the tube",
     .lo = 0, .hi = 100,
     .check = kRange, .decimals = 2,
     .number = [](S& s) -> double& { return s.saw.approach_gap_mm; }},
    {.key = "saw.overcut_mm", .unit = "mm", .label = "Overcut past the bore", .lo = 0, .hi = 20,
     .check = kRange, .decimals = 2, .number = [](S& s) -> double& { return s.saw.overcut_mm; }},
    {.key = "saw.clearance_mm", .unit = "mm", .label = "Retracted clearance", .lo = 0, .hi = 500,
     .check = kRange, .decimals = 2,
     .number = [](S& s) -> double& { return s.saw.clearance_mm; }},
    {.key = "saw.retract_mm_s", .unit = "mm/s", .label = "Retract speed", .lo = 0.1,
     .hi = 10000, .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.saw.retract_mm_s; }},
    {.key = "saw.turntable_deg_s", .unit = "deg/s", .label = "Turntable speed", .lo = 1,
     .hi = 36000, .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.saw.turntable_deg_s; }},
    {.key = "saw.turntable_deg_s2", .unit = "deg/s^2", .label = "Turntable acceleration",
     .lo = 1, .hi = 1e6, .check = kPositive, .decimals = 0,
     .number = [](S& s) -> double& { return s.saw.turntable_deg_s2; }},
    {.key = "saw.table_points", .unit = "points", .label = "Cam table points", .lo = 8,
     .hi = 1023, .check = kRange, .integer = [](S& s) -> int& { return s.saw.table_points; }},
    {.key = "blade.diameter_mm", .unit = "mm", .label = "Diameter", .lo = 50, .hi = 2000,
     .check = kPositive, .decimals = 1,
     .number = [](S& s) -> double& { return s.blade_diameter_mm; }},
    {.key = "blade.kerf_mm", .unit = "mm", .label = "Kerf", .lo = 0.1, .hi = 20, .check = kPositive,
     .decimals = 2, .number = [](S& s) -> double& { return s.blade_kerf_mm; }},
    {.key = "blade.rpm", .unit = "1/min", .label = "Speed", .lo = 1, .hi = 20000,
     .check = kPositive, .decimals = 0, .number = [](S& s) -> double& { return s.blade_rpm; }},
    {.key = "gauge.enabled", .unit = "", .label = "Length gauge",
     .boolean = [](S& s) -> bool& { return s.gauge_enabled; }},
    {.key = "gauge.delay_pieces", .unit = "pieces", .label = "Gauge delay", .lo = 0, .hi = 10,
     .check = kRange, .integer = [](S& s) -> int& { return s.gauge_delay_pieces; }},
    {.key = "gauge.noise_mm", .unit = "mm", .label = "Gauge noise ±", .lo = 0, .hi = 10,
     .check = kRange, .decimals = 3, .number = [](S& s) -> double& { return s.gauge_noise_mm; }},
    {.key = "gauge.gain", .unit = "", .label = "Correction gain", .lo = 0.01, .hi = 1,
     .check = kPositive, .decimals = 3, .number = [](S& s) -> double& { return s.gauge_gain; }},
    {.key = "line_sim.wander_fraction", .unit = "", .label = "Speed wander", .lo = 0, .hi = 0.5,
     .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.line_sim.wander_fraction; }},
    {.key = "line_sim.wander_hz", .unit = "Hz", .label = "Wander frequency", .lo = 1e-4,
     .hi = 10, .check = kPositive, .decimals = 3,
     .number = [](S& s) -> double& { return s.line_sim.wander_hz; }},
    {.key = "line_sim.step_fraction", .unit = "", .label = "Speed step", .lo = 0, .hi = 0.5,
     .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.line_sim.step_fraction; }},
    {.key = "line_sim.step_interval_s", .unit = "s", .label = "Mean time between steps", .lo = 0.5,
     .hi = 1e5, .check = kPositive, .decimals = 2,
     .number = [](S& s) -> double& { return s.line_sim.step_interval_s; }},
    {.key = "line_sim.step_ramp_s", .unit = "s", .label = "Step ramp", .lo = 0, .hi = 60,
     .check = kRange, .decimals = 3,
     .number = [](S& s) -> double& { return s.line_sim.step_ramp_s; }},
    {.key = "line_sim.noise_mm", .unit = "mm", .label = "Reading noise ±", .lo = 0, .hi = 10,
     .check = kRange, .decimals = 3,
     .number = [](S& s) -> double& { return s.line_sim.noise_mm; }},
    {.key = "line_sim.slip_fraction", .unit = "", .label = "Roller slip", .lo = 0, .hi = 0.2,
     .check = kRange, .decimals = 4,
     .number = [](S& s) -> double& { return s.line_sim.slip_fraction; }},
    {.key = "line_sim.seed", .unit = "", .label = "Random seed",
     .readCustom =
         [](SectionReader& r, const std::string& leaf, S& s) {
             s.line_sim.seed = static_cast<std::uint32_t>(
                 r.integer(leaf, "", static_cast<int>(s.line_sim.seed), 0, 2147483647));
         },
     .writeCustom = [](const S& s) -> json::Value { return static_cast<int>(s.line_sim.seed); }},
};
// clang-format on

} // namespace

std::span<const SectionField<FlyingSawSpec>> flyingSawFields() {
    return kFields;
}

FlyingSawSpec readFlyingSawSection(const json::Value& section) {
    return readSectionFields(section, flyingSawFields());
}

json::Object writeFlyingSawSection(const FlyingSawSpec& s) {
    return writeFields(flyingSawFields(), s);
}

std::vector<JobIssue> checkFlyingSawSpec(const FlyingSawSpec& s) {
    IssueChecker c;
    checkFields(c, flyingSawFields(), s);
    // The checks whose limits are other values of the section.
    if (s.shape == TubeShape::Rectangular)
        c.range("tube.corner_radius_mm", s.corner_radius_mm, 0,
                std::min(s.width_mm, s.height_mm) / 2, "mm");
    const double smallest =
        s.shape == TubeShape::Round ? s.diameter_mm : std::min(s.width_mm, s.height_mm);
    // The blade cuts the wall and the overcut past the bore; both inside half the tube.
    const double wallRoom = smallest / 2 - s.saw.overcut_mm - 0.1;
    double overcutHi = 0; // an overcut beyond its own range has its message already
    for (const auto& f : flyingSawFields())
        if (std::string(f.key) == "saw.overcut_mm") overcutHi = f.hi;
    const bool overcutInRange = s.saw.overcut_mm <= overcutHi;
    if (overcutInRange && wallRoom < 0.1 && s.saw.overcut_mm > 0)
        c.add("saw.overcut_mm",
              messageC("saw.overcut_mm = %s mm leaves no wall: the wall (machine.tube.wall_mm = %s "
                       "mm) and the overcut must fit in half the tube's width (%s mm); overcut "
                       "at most %s mm",
                       num(s.saw.overcut_mm).c_str(), num(s.wall_mm).c_str(),
                       num(smallest / 2).c_str(),
                       num(std::max(0.0, smallest / 2 - s.wall_mm - 0.1)).c_str()));
    else if (overcutInRange && !c.has("tube.wall_mm"))
        c.positive("tube.wall_mm", s.wall_mm, 0.1, std::max(0.1, wallRoom), "mm");
    if (s.queue.empty())
        c.add("cut.queue", messageC("cut.queue is empty: at least one length is needed"));
    for (size_t i = 0; i < s.queue.size(); ++i) {
        const std::string k = "cut.queue[" + std::to_string(i) + "]";
        c.positive(k + ".length_mm", s.queue[i].length_mm, 10, 100000, "mm");
        c.range(k + ".count", s.queue[i].count, 1, 1000000, "pieces");
    }
    if (!std::isnan(s.first_sync_master_mm))
        // 10 km of line: a coil's length; a 32-bit line count at 0.05 mm/pulse ends at 107 km.
        c.range("cut.first_sync_master_mm", s.first_sync_master_mm, -1e7, 1e7, "mm");
    c.range("carriage.wait_position_mm", s.wait_position_mm, 0, s.stroke_mm, "mm");
    return c.issues;
}

} // namespace cutcell
