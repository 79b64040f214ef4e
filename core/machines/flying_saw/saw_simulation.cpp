#include "core/machines/flying_saw/saw_simulation.h"

#include "core/common/c_format.h"
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"
#include "core/json/json.h"
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/pipe_line_sim.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace cutcell {

double sawSimExpectedSeconds(const FlyingSawSpec& spec, const FlyingSawPlan& plan) {
    double mm = 0;
    for (const PieceOrder& o : spec.queue)
        mm += (o.length_mm + spec.blade_kerf_mm) * o.count;
    return mm / plan.line_speed_mm_s + 4 * plan.cycle_time_s + 10;
}

std::string sawSimWorkProblem(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                              const SawSimOptions& opt) {
    const double expected = sawSimExpectedSeconds(spec, plan);
    if (expected <= opt.max_time_s) return "";
    const double perPiece = (expected - 4 * plan.cycle_time_s - 10) / spec.pieceCount();
    return messageC("the queue of %d pieces needs about %.0f s of line time (%.3g cycles at "
                    "%.3g ms), over the simulation's bound of %.0f s: split it (about %d pieces "
                    "of this queue's mean length fit)",
                    spec.pieceCount(), expected, expected / opt.period_s, opt.period_s * 1e3,
                    opt.max_time_s,
                    static_cast<int>((opt.max_time_s - 4 * plan.cycle_time_s - 10) / perPiece));
}

SawSimResult simulateFlyingSaw(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                               const SawSimOptions& opt) {
    SawSimResult res;
    const double T = opt.period_s;
    const double expected = sawSimExpectedSeconds(spec, plan);
    PipeLineConfig lc;
    lc.speed_mm_s = plan.line_speed_mm_s;
    lc.resolution_mm = spec.encoderResolutionMm();
    lc.sim = spec.line_sim;
    lc.duration_s = 2 * expected;
    PipeLineSim line(lc);
    FlyingSawSource src(sawSourceConfig(spec, plan));
    PidFilter pid(sawAxisGains(), T);
    JointPlant plant(sawAxisPlant(), T);
    plant.setState(spec.wait_position_mm, 0);

    std::array<DriveFeedback, kMaxAxes> fb{};
    std::array<SensorReading, kMaxSensors> sensors{};
    SourceInput in;
    in.period_s = T;
    in.axis_count = 4;
    in.axes = &fb;
    in.sensors = &sensors;
    in.request = SourceRequest::Run;
    in.tool_ok = true;
    in.setpoint = JointVector::Zero();
    in.setpoint[0] = spec.wait_position_mm;
    sensors[0] = line.read(0);
    src.start(in);
    res.first_sync_master_mm = src.firstSync();

    const int pieces = spec.pieceCount();
    CutLengthMeter meter(pieces + 8);
    std::vector<double> ordered(static_cast<size_t>(pieces) + 2, 0.0);
    std::deque<std::pair<int, double>> gaugeQueue; // pieces measured, not yet reported
    std::uint32_t gaugeRng = spec.line_sim.seed * 7919u + 3u;
    size_t cutsSeen = 0;
    double prevSp = spec.wait_position_mm, prevV = 0;
    SawPhase prevPhase = src.phase();
    SourceOutput out;
    const double xSync = src.carriageSyncPosition();
    const bool noSlip = spec.line_sim.slip_fraction == 0;

    long k = 0;
    for (; static_cast<double>(k) * T < opt.max_time_s; ++k) {
        const double t = static_cast<double>(k) * T;
        sensors[0] = line.read(t);
        fb[0].position = plant.position();
        fb[0].velocity = plant.velocity();
        fb[0].state = DriveState::Enabled;
        in.now_s = t;
        out = SourceOutput{};
        src.update(in, out);
        in.setpoint = out.position;
        if (opt.each_cycle) opt.each_cycle(t, src);
        if (out.status == SourceStatus::Fault) {
            res.problem = out.fault;
            break;
        }
        const SawPhase ph = src.phase();
        // The cut on the pipe and the servo's error against what it was told to reach now.
        meter.feed(src.bladeInWall(), src.cutIndex(), plant.position() - line.position(), t);
        if (ph == SawPhase::InSync) {
            res.max_following_error_mm =
                std::max(res.max_following_error_mm, std::fabs(prevSp - plant.position()));
            if (noSlip)
                res.max_sync_error_mm = std::max(
                    res.max_sync_error_mm,
                    std::fabs(out.position[0] - (xSync + line.position() - src.syncPosition())));
        }
        if (prevPhase == SawPhase::Returning && ph != SawPhase::Returning)
            res.max_return_miss_mm = std::max(res.max_return_miss_mm,
                                              std::fabs(out.position[0] - spec.wait_position_mm));
        if (opt.record_cycle && src.cutsDone() == 1) {
            const double v = (out.position[0] - prevSp) / T;
            res.cycle.push_back({t, out.position[0], v, (v - prevV) / T, static_cast<int>(ph)});
        }
        prevV = (out.position[0] - prevSp) / T;
        prevPhase = ph;
        // Carriage servo: sample, PID, plant (the simulated drive's order).
        prevSp = out.position[0];
        plant.step(pid.step(out.position[0] - plant.position()));

        // A cut closed: the piece it ends goes to the gauge; reported gauge_delay pieces later.
        while (cutsSeen < meter.cuts().size()) {
            const CutRecord& c = meter.cuts()[cutsSeen];
            if (c.index >= 1 && c.index < static_cast<int>(ordered.size()))
                ordered[static_cast<size_t>(c.index)] = src.orderedLength(c.index);
            if (spec.gauge_enabled && cutsSeen >= 1) {
                const CutRecord& before = meter.cuts()[cutsSeen - 1];
                gaugeRng = gaugeRng * 1664525u + 1013904223u;
                const double u = static_cast<double>(gaugeRng >> 8) / (1u << 24);
                const double noise = spec.gauge_noise_mm * (2 * u - 1);
                gaugeQueue.emplace_back(c.index, before.position_mm - c.position_mm -
                                                     spec.blade_kerf_mm + noise);
                while (static_cast<int>(gaugeQueue.size()) > spec.gauge_delay_pieces) {
                    src.reportGauge(gaugeQueue.front().first, gaugeQueue.front().second);
                    gaugeQueue.pop_front();
                }
            }
            ++cutsSeen;
        }
        if (out.status == SourceStatus::Done) {
            res.completed = true;
            break;
        }
    }
    meter.feed(false, -1, 0, static_cast<double>(k) * T);
    res.simulated_s = static_cast<double>(k) * T;
    res.cuts = meter.cuts();
    res.pieces = meter.pieces(spec.blade_kerf_mm, [&](int p) {
        return p < static_cast<int>(ordered.size()) ? ordered[static_cast<size_t>(p)] : 0.0;
    });
    // A piece whose closing cut never came (the run stopped first) was not made: no record.
    std::erase_if(res.pieces, [](const PieceRecord& p) { return p.ordered_mm <= 0; });
    if (!res.completed && res.problem.empty())
        res.problem = messageC("stopped at the simulation's bound of %.0f s of line time with %d "
                               "of %d pieces made",
                               opt.max_time_s, static_cast<int>(res.pieces.size()), pieces);
    res.stats = lengthStats(res.pieces, spec.tolerance_mm);
    res.final_scale = src.scale();
    return res;
}

std::string sawReportJson(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                          const SawSimResult& r) {
    json::Array pieces;
    for (const PieceRecord& p : r.pieces)
        pieces.emplace_back(json::Object{{"piece", p.piece},
                                         {"ordered_mm", p.ordered_mm},
                                         {"length_mm", p.length_mm},
                                         {"error_mm", p.error_mm},
                                         {"cut_spread_mm", p.spread_mm}});
    json::Object periods{{"T1_s", plan.T1}, {"T2_s", plan.T2},          {"T3_s", plan.T3},
                         {"T4_s", plan.T4}, {"T5_s", plan.T5},          {"T6_s", plan.T6},
                         {"k", plan.k},     {"d1_mm", plan.forward.d1}, {"d3_mm", plan.forward.d3}};
    json::Object doc{{"machine", "flying saw"},
                     {"completed", r.completed},
                     {"problem", r.problem},
                     {"simulated_s", r.simulated_s},
                     {"line_speed_mm_s", plan.line_speed_mm_s},
                     {"periods", periods},
                     {"stroke_needed_mm", plan.stroke_needed_mm},
                     {"shortest_length_mm", plan.shortest_length_mm},
                     {"cam_max_between_points_mm", plan.cam_max_between_points_mm},
                     {"feed_accel_peak_mm_s2", plan.feed_accel_peak_mm_s2},
                     {"tolerance_mm", spec.tolerance_mm},
                     {"pieces_measured", r.stats.count},
                     {"cut_length_error_mm_mean", r.stats.mean},
                     {"cut_length_error_mm_std", r.stats.std},
                     {"cut_length_error_mm_max_abs", r.stats.max_abs},
                     {"cpk", r.stats.cpk},
                     {"carriage_following_error_mm_max", r.max_following_error_mm},
                     {"carriage_return_miss_mm_max", r.max_return_miss_mm},
                     {"encoder_scale_final", r.final_scale},
                     {"pieces", pieces}};
    return json::write(json::Value(doc));
}

std::string sawReportText(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                          const SawSimResult& r) {
    return formatC("%d pieces, %.1f s simulated%s%s\n"
                   "length error: mean %.4f mm, std %.4f mm, max |e| %.4f mm, Cpk %.2f "
                   "(+-%.3g mm)\n"
                   "periods: T1 %.3f s, T2 %.3f s, T3 %.3f s, T4 = T6 %.3f s, T5 %.3f s, k %.3f; "
                   "stroke %.1f of %.1f mm; shortest piece %.1f mm\n",
                   r.stats.count, r.simulated_s,
                   r.completed ? "" : ", NOT completed: ", r.problem.c_str(), r.stats.mean,
                   r.stats.std, r.stats.max_abs, r.stats.cpk, spec.tolerance_mm, plan.T1, plan.T2,
                   plan.T3, plan.T4, plan.T5, plan.k, plan.stroke_needed_mm, spec.stroke_mm,
                   plan.shortest_length_mm);
}

} // namespace cutcell
