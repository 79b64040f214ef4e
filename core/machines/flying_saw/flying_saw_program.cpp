#include "core/machines/flying_saw/flying_saw_program.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcell {

FlyingSawConfig sawSourceConfig(const FlyingSawSpec& spec, const FlyingSawPlan& plan) {
    FlyingSawConfig c;
    c.master_sensor = 0;
    c.filter_alpha = spec.filter_alpha;
    c.forward = plan.forward;
    c.saw = plan.saw;
    c.limits = spec.carriage;
    c.wait_position_mm = spec.wait_position_mm;
    c.kerf_mm = spec.blade_kerf_mm;
    c.queue.size = 0;
    for (const PieceOrder& o : spec.queue) {
        if (c.queue.size >= PieceQueue::kCapacity) break;
        c.queue.entries[static_cast<size_t>(c.queue.size++)] = {o.length_mm, o.count};
    }
    c.gauge_gain = spec.gauge_gain;
    c.first_sync = spec.first_sync_master_mm;
    return c;
}

std::shared_ptr<MotionProgram> buildFlyingSawProgram(const Job& job, const FlyingSawSpec& spec,
                                                     const FlyingSawPlan& plan,
                                                     const std::string& jobText) {
    auto p = std::make_shared<MotionProgram>();
    p->method = "flying_saw";
    p->source_kind = MotionSourceKind::MasterAxis;
    p->source = std::make_shared<FlyingSawSource>(sawSourceConfig(spec, plan));
    p->axis_count = 4;
    p->axis_names = {"carriage", "turntable", "feed 1", "feed 2"};
    p->axis_linear = {true, false, true, true};
    // The turntable turns on, half a turn a cut: Home and the approach at Start take the short
    // way instead of unwinding every turn of the runs before (120 s and more at the home speed
    // after a long run).
    p->axis_continuous[1] = true;
    p->axis_modes = {AxisCommandMode::Position, AxisCommandMode::Position,
                     AxisCommandMode::Position, AxisCommandMode::Position};
    JointVector start = JointVector::Zero();
    start[0] = spec.wait_position_mm;
    p->start_position = start;
    p->reference = start;
    p->min_position = JointVector::Constant(-1e9);
    p->max_position = JointVector::Constant(1e9);
    p->min_position[0] = std::min(0.0, spec.wait_position_mm);
    p->max_position[0] = spec.stroke_mm;
    p->min_position[2] = p->min_position[3] = 0;
    p->max_position[2] = p->max_position[3] = plan.saw.retract_radius;
    // Half a turn of the turntable a piece, on from wherever the last run left it (Home takes
    // it back within half a turn of its reference).
    p->endless_reach[1] = std::numbers::pi * (static_cast<double>(spec.pieceCount()) + 2);
    p->sensors_used = 1u;
    p->uses_tool = true;
    // The run's length: every piece at the nominal line speed, plus the first sync-in.
    const double pieces = spec.pieceCount();
    double metres = 0;
    for (const PieceOrder& o : spec.queue)
        metres += o.length_mm * o.count;
    p->cut_time_s = (metres + plan.forward.d1 * 2) / plan.line_speed_mm_s + plan.cycle_time_s;
    p->length_mm = metres;
    p->point_count = static_cast<size_t>(pieces);
    // The operator counts pieces (each with its length), not millimetres of a path.
    p->terms = flyingSawTerms();
    for (const PieceOrder& o : spec.queue)
        for (int k = 0; k < o.count; ++k)
            p->terms.piece_lengths_mm.push_back(o.length_mm);
    p->name = job.name;
    p->source_text = jobText;
    return p;
}

RunTerms flyingSawTerms() {
    RunTerms t;
    t.tool = "saw";
    t.process_ok = "blade at speed";
    t.process_lost = "blade speed lost";
    t.counts = WorkCount::Pieces;
    t.path_length = false;
    return t;
}

PidGains sawAxisGains() {
    PidGains g;
    g.kp = 10.8;
    g.ki = 216;
    g.kd = 0.175;
    g.tau_f = 0.002;
    return g;
}

JointPlantParams sawAxisPlant() {
    JointPlantParams p;
    p.inertia_kg_m2 = 0.001;
    p.viscous_nm_s_per_rad = 0.005;
    p.torque_limit_nm = 50;
    return p;
}

} // namespace cutcell
