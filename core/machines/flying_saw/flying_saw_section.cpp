#include "core/machines/flying_saw/flying_saw_section.h"

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

} // namespace

FlyingSawSpec readFlyingSawSection(const json::Value& section) {
    SectionReader m(section, "machine");
    m.get("kind");
    FlyingSawSpec s;
    if (m.has("tube")) {
        SectionReader t = m.child("tube");
        s.shape = t.choice<TubeShape>(
            "shape", {{"round", TubeShape::Round}, {"rectangular", TubeShape::Rectangular}},
            s.shape);
        if (s.shape == TubeShape::Round) {
            s.diameter_mm = t.number("diameter_mm", "mm", s.diameter_mm);
        } else {
            s.width_mm = t.number("width_mm", "mm", s.width_mm);
            s.height_mm = t.number("height_mm", "mm", s.height_mm);
            s.corner_radius_mm = t.number("corner_radius_mm", "mm", s.corner_radius_mm);
        }
        s.wall_mm = t.number("wall_mm", "mm", s.wall_mm);
        t.finish();
    }
    if (m.has("line")) {
        SectionReader l = m.child("line");
        s.line_speed_m_min = l.number("speed_m_min", "m/min", s.line_speed_m_min);
        s.roller_pulses_per_rev =
            l.integer("roller_pulses_per_rev", "pulses/rev", s.roller_pulses_per_rev, 1, 10000000);
        s.roller_diameter_mm = l.number("roller_diameter_mm", "mm", s.roller_diameter_mm);
        s.filter_alpha = l.number("filter_alpha", "", s.filter_alpha);
        l.finish();
    }
    if (m.has("cut")) {
        SectionReader c = m.child("cut");
        if (c.has("queue")) s.queue = readQueue(c);
        s.tolerance_mm = c.number("tolerance_mm", "mm", s.tolerance_mm);
        if (c.has("first_sync_master_mm"))
            s.first_sync_master_mm = c.number("first_sync_master_mm", "mm");
        c.finish();
    }
    if (m.has("carriage")) {
        SectionReader c = m.child("carriage");
        s.stroke_mm = c.number("stroke_mm", "mm", s.stroke_mm);
        s.carriage.max_speed_mm_s = c.number("max_speed_mm_s", "mm/s", s.carriage.max_speed_mm_s);
        s.carriage.max_accel_mm_s2 =
            c.number("max_accel_mm_s2", "mm/s^2", s.carriage.max_accel_mm_s2);
        s.carriage.max_jerk_mm_s3 = c.number("max_jerk_mm_s3", "mm/s^3", s.carriage.max_jerk_mm_s3);
        s.wait_position_mm = c.number("wait_position_mm", "mm", s.wait_position_mm);
        c.finish();
    }
    if (m.has("saw")) {
        SectionReader w = m.child("saw");
        SawSettings& a = s.saw;
        a.settle_s = w.number("settle_s", "s", a.settle_s);
        a.fast_feed_mm_s = w.number("fast_feed_mm_s", "mm/s", a.fast_feed_mm_s);
        a.slow_feed_mm_s = w.number("slow_feed_mm_s", "mm/s", a.slow_feed_mm_s);
        a.approach_gap_mm = w.number("approach_gap_mm", "mm", a.approach_gap_mm);
        a.overcut_mm = w.number("overcut_mm", "mm", a.overcut_mm);
        a.clearance_mm = w.number("clearance_mm", "mm", a.clearance_mm);
        a.retract_mm_s = w.number("retract_mm_s", "mm/s", a.retract_mm_s);
        a.turntable_deg_s = w.number("turntable_deg_s", "deg/s", a.turntable_deg_s);
        a.turntable_deg_s2 = w.number("turntable_deg_s2", "deg/s^2", a.turntable_deg_s2);
        a.table_points = w.integer("table_points", "points", a.table_points, 8, 1023);
        w.finish();
    }
    if (m.has("blade")) {
        SectionReader b = m.child("blade");
        s.blade_diameter_mm = b.number("diameter_mm", "mm", s.blade_diameter_mm);
        s.blade_kerf_mm = b.number("kerf_mm", "mm", s.blade_kerf_mm);
        s.blade_rpm = b.number("rpm", "1/min", s.blade_rpm);
        b.finish();
    }
    if (m.has("gauge")) {
        SectionReader g = m.child("gauge");
        s.gauge_enabled = g.boolean("enabled", s.gauge_enabled);
        s.gauge_delay_pieces = g.integer("delay_pieces", "pieces", s.gauge_delay_pieces, 0, 10);
        s.gauge_noise_mm = g.number("noise_mm", "mm", s.gauge_noise_mm);
        s.gauge_gain = g.number("gain", "", s.gauge_gain);
        g.finish();
    }
    if (m.has("line_sim")) {
        SectionReader l = m.child("line_sim");
        LineSimSpec& v = s.line_sim;
        v.wander_fraction = l.number("wander_fraction", "", v.wander_fraction);
        v.wander_hz = l.number("wander_hz", "Hz", v.wander_hz);
        v.step_fraction = l.number("step_fraction", "", v.step_fraction);
        v.step_interval_s = l.number("step_interval_s", "s", v.step_interval_s);
        v.step_ramp_s = l.number("step_ramp_s", "s", v.step_ramp_s);
        v.noise_mm = l.number("noise_mm", "mm", v.noise_mm);
        v.slip_fraction = l.number("slip_fraction", "", v.slip_fraction);
        v.seed = static_cast<std::uint32_t>(
            l.integer("seed", "", static_cast<int>(v.seed), 0, 2147483647));
        l.finish();
    }
    m.finish();
    return s;
}

json::Object writeFlyingSawSection(const FlyingSawSpec& s) {
    json::Object tube{{"shape", s.shape == TubeShape::Round ? "round" : "rectangular"}};
    if (s.shape == TubeShape::Round) {
        tube.emplace_back("diameter_mm", s.diameter_mm);
    } else {
        tube.emplace_back("width_mm", s.width_mm);
        tube.emplace_back("height_mm", s.height_mm);
        tube.emplace_back("corner_radius_mm", s.corner_radius_mm);
    }
    tube.emplace_back("wall_mm", s.wall_mm);
    json::Array queue;
    for (const PieceOrder& o : s.queue)
        queue.emplace_back(json::Object{{"length_mm", o.length_mm}, {"count", o.count}});
    json::Object cut{{"queue", queue}, {"tolerance_mm", s.tolerance_mm}};
    if (!std::isnan(s.first_sync_master_mm))
        cut.emplace_back("first_sync_master_mm", s.first_sync_master_mm);
    const SawSettings& a = s.saw;
    const LineSimSpec& v = s.line_sim;
    return json::Object{{"tube", tube},
                        {"line", json::Object{{"speed_m_min", s.line_speed_m_min},
                                              {"roller_pulses_per_rev", s.roller_pulses_per_rev},
                                              {"roller_diameter_mm", s.roller_diameter_mm},
                                              {"filter_alpha", s.filter_alpha}}},
                        {"cut", cut},
                        {"carriage", json::Object{{"stroke_mm", s.stroke_mm},
                                                  {"max_speed_mm_s", s.carriage.max_speed_mm_s},
                                                  {"max_accel_mm_s2", s.carriage.max_accel_mm_s2},
                                                  {"max_jerk_mm_s3", s.carriage.max_jerk_mm_s3},
                                                  {"wait_position_mm", s.wait_position_mm}}},
                        {"saw", json::Object{{"settle_s", a.settle_s},
                                             {"fast_feed_mm_s", a.fast_feed_mm_s},
                                             {"slow_feed_mm_s", a.slow_feed_mm_s},
                                             {"approach_gap_mm", a.approach_gap_mm},
                                             {"overcut_mm", a.overcut_mm},
                                             {"clearance_mm", a.clearance_mm},
                                             {"retract_mm_s", a.retract_mm_s},
                                             {"turntable_deg_s", a.turntable_deg_s},
                                             {"turntable_deg_s2", a.turntable_deg_s2},
                                             {"table_points", a.table_points}}},
                        {"blade", json::Object{{"diameter_mm", s.blade_diameter_mm},
                                               {"kerf_mm", s.blade_kerf_mm},
                                               {"rpm", s.blade_rpm}}},
                        {"gauge", json::Object{{"enabled", s.gauge_enabled},
                                               {"delay_pieces", s.gauge_delay_pieces},
                                               {"noise_mm", s.gauge_noise_mm},
                                               {"gain", s.gauge_gain}}},
                        {"line_sim", json::Object{{"wander_fraction", v.wander_fraction},
                                                  {"wander_hz", v.wander_hz},
                                                  {"step_fraction", v.step_fraction},
                                                  {"step_interval_s", v.step_interval_s},
                                                  {"step_ramp_s", v.step_ramp_s},
                                                  {"noise_mm", v.noise_mm},
                                                  {"slip_fraction", v.slip_fraction},
                                                  {"seed", static_cast<int>(v.seed)}}}};
}

std::vector<JobIssue> checkFlyingSawSpec(const FlyingSawSpec& s) {
    IssueChecker c;
    if (s.shape == TubeShape::Round) {
        c.positive("tube.diameter_mm", s.diameter_mm, 5, 1000, "mm");
    } else {
        c.positive("tube.width_mm", s.width_mm, 5, 1000, "mm");
        c.positive("tube.height_mm", s.height_mm, 5, 1000, "mm");
        c.range("tube.corner_radius_mm", s.corner_radius_mm, 0,
                std::min(s.width_mm, s.height_mm) / 2, "mm");
    }
    const double smallest =
        s.shape == TubeShape::Round ? s.diameter_mm : std::min(s.width_mm, s.height_mm);
    c.positive("tube.wall_mm", s.wall_mm, 0.1, std::max(0.1, smallest / 2 - s.saw.overcut_mm - 0.1),
               "mm");
    c.positive("line.speed_m_min", s.line_speed_m_min, 0.1, 300, "m/min");
    c.range("line.roller_pulses_per_rev", s.roller_pulses_per_rev, 1, 10000000, "pulses/rev");
    c.positive("line.roller_diameter_mm", s.roller_diameter_mm, 10, 1000, "mm");
    c.positive("line.filter_alpha", s.filter_alpha, 1e-4, 1, "");
    if (s.queue.empty()) c.add("cut.queue", "cut.queue is empty: at least one length is needed");
    for (size_t i = 0; i < s.queue.size(); ++i) {
        const std::string k = "cut.queue[" + std::to_string(i) + "]";
        c.positive(k + ".length_mm", s.queue[i].length_mm, 10, 100000, "mm");
        c.range(k + ".count", s.queue[i].count, 1, 1000000, "pieces");
    }
    c.positive("cut.tolerance_mm", s.tolerance_mm, 0.001, 100, "mm");
    if (!std::isnan(s.first_sync_master_mm))
        c.range("cut.first_sync_master_mm", s.first_sync_master_mm, -1e9, 1e9, "mm");
    c.positive("carriage.stroke_mm", s.stroke_mm, 10, 50000, "mm");
    c.positive("carriage.max_speed_mm_s", s.carriage.max_speed_mm_s, 1, 20000, "mm/s");
    c.positive("carriage.max_accel_mm_s2", s.carriage.max_accel_mm_s2, 10, 1e6, "mm/s^2");
    c.positive("carriage.max_jerk_mm_s3", s.carriage.max_jerk_mm_s3, 100, 1e9, "mm/s^3");
    c.range("carriage.wait_position_mm", s.wait_position_mm, 0, s.stroke_mm, "mm");
    const SawSettings& a = s.saw;
    c.range("saw.settle_s", a.settle_s, 0, 10, "s");
    c.positive("saw.fast_feed_mm_s", a.fast_feed_mm_s, 0.1, 10000, "mm/s");
    c.positive("saw.slow_feed_mm_s", a.slow_feed_mm_s, 0.1, 10000, "mm/s");
    c.range("saw.approach_gap_mm", a.approach_gap_mm, 0, 100, "mm");
    c.range("saw.overcut_mm", a.overcut_mm, 0, 20, "mm");
    c.range("saw.clearance_mm", a.clearance_mm, 0, 500, "mm");
    c.positive("saw.retract_mm_s", a.retract_mm_s, 0.1, 10000, "mm/s");
    c.positive("saw.turntable_deg_s", a.turntable_deg_s, 1, 36000, "deg/s");
    c.positive("saw.turntable_deg_s2", a.turntable_deg_s2, 1, 1e6, "deg/s^2");
    c.range("saw.table_points", a.table_points, 8, 1023, "points");
    c.positive("blade.diameter_mm", s.blade_diameter_mm, 50, 2000, "mm");
    c.range("blade.kerf_mm", s.blade_kerf_mm, 0, 20, "mm");
    c.positive("blade.rpm", s.blade_rpm, 1, 20000, "1/min");
    c.range("gauge.delay_pieces", s.gauge_delay_pieces, 0, 10, "pieces");
    c.range("gauge.noise_mm", s.gauge_noise_mm, 0, 10, "mm");
    c.positive("gauge.gain", s.gauge_gain, 0.01, 1, "");
    const LineSimSpec& v = s.line_sim;
    c.range("line_sim.wander_fraction", v.wander_fraction, 0, 0.5, "");
    c.positive("line_sim.wander_hz", v.wander_hz, 1e-4, 10, "Hz");
    c.range("line_sim.step_fraction", v.step_fraction, 0, 0.5, "");
    c.positive("line_sim.step_interval_s", v.step_interval_s, 0.5, 1e5, "s");
    c.range("line_sim.step_ramp_s", v.step_ramp_s, 0, 60, "s");
    c.range("line_sim.noise_mm", v.noise_mm, 0, 10, "mm");
    c.range("line_sim.slip_fraction", v.slip_fraction, 0, 0.2, "");
    return c.issues;
}

} // namespace cutcell
