#include "core/machines/quick_return/experiments.h"
#include "core/common/c_format.h"

#include <cmath>
#include <numbers>

namespace cutcell::quick_return {

namespace {

struct Sim {
    Sim(const ExperimentSetup& s, const QuickReturnLawConfig& lc, double q0)
        : setup(s), plant(lc.dims, s.plant), law(lc) {
        plant.setState(q0, 0);
        in.period_s = s.sample_time;
        in.axis_count = 1;
        in.axes = &axes;
        in.sensors = &sensors;
        in.request = SourceRequest::Run;
        read(0);
        law.start(in);
    }
    void read(double t) {
        in.now_s = t;
        axes[0].position = plant.state().q;
        axes[0].velocity = plant.state().dq;
        axes[0].state = DriveState::Enabled;
        const double y = plant.sliderPosition(), r = setup.scale_resolution;
        sensors[0].position = 1000 * (r > 0 ? std::round(y / r) * r : y);
        sensors[0].valid = true;
    }
    // One cycle at t; returns the applied torque.
    double cycle(double t) {
        read(t);
        law.update(in, out);
        const double dist =
            setup.disturbance_amplitude * std::sin(2 * std::numbers::pi * setup.disturbance_hz * t);
        return plant.step(out.torque[0], dist, setup.sample_time);
    }
    const ExperimentSetup& setup;
    CrankPlant plant;
    QuickReturnLaw law;
    std::array<DriveFeedback, kMaxAxes> axes{};
    std::array<SensorReading, kMaxSensors> sensors{};
    SourceInput in;
    SourceOutput out;
};

} // namespace

TrackingResult runTracking(const ExperimentSetup& setup, ControllerKind controller) {
    QuickReturnLawConfig lc = setup.law;
    lc.experiment = Experiment::Tracking;
    lc.controller = controller;
    CrankPlantParams pp = setup.plant;
    (void)pp;
    ExperimentSetup s = setup;
    s.plant.contact = false;
    const QuickReturnLaw probe(lc);
    Sim sim(s, lc, probe.crankForSlider(lc.track_offset));
    TrackingResult r;
    r.controller = controller;
    const double T = s.sample_time, end = lc.track_duration;
    const int n = static_cast<int>(std::llround(end / T));
    double sum = 0;
    int count = 0;
    if (s.keep_errors) {
        r.error.reserve(static_cast<size_t>(n));
        r.error_rate.reserve(static_cast<size_t>(n));
        r.crank.reserve(static_cast<size_t>(n));
    }
    for (int i = 0; i < n; ++i) {
        const double t = i * T;
        const double tau = sim.cycle(t);
        const QrSample& q = sim.law.last();
        r.max_torque = std::max(r.max_torque, std::fabs(tau));
        // The error of the state this command acts on (the true slider position).
        const double e = q.y_d - sim.plant.sliderPosition();
        if (s.keep_errors) {
            r.error.push_back(e);
            r.error_rate.push_back(q.dy_d - sim.plant.sliderVelocity());
            r.crank.push_back(sim.plant.state().q);
        }
        if (t >= end - s.mse_window) {
            sum += (s.mse_scale * e) * (s.mse_scale * e);
            ++count;
            r.max_abs_error = std::max(r.max_abs_error, std::fabs(e));
        }
        if (i % s.trace_every == 0) r.trace.push_back({t, q.y, q.dy, q.y_d, q.dy_d, tau, false});
    }
    r.mse = count > 0 ? sum / count : 0;
    return r;
}

CuttingResult runCutting(const ExperimentSetup& setup, ControllerKind controller) {
    QuickReturnLawConfig lc = setup.law;
    lc.experiment = Experiment::Cutting;
    lc.controller = controller;
    ExperimentSetup s = setup;
    s.plant.contact = true;
    s.plant.cut_low = std::min(lc.profile.y_a, lc.profile.y_b);
    s.plant.cut_high = std::max(lc.profile.y_a, lc.profile.y_b);
    // At rest just past the bottom singular point: the run begins with an open-loop return
    // (a cut needs the crank turning forward through the top singular point).
    Sim sim(s, lc, lc.stroke.q_bottom + 0.01);
    CuttingResult r;
    r.controller = controller;
    const double T = s.sample_time;
    const double limit = lc.strokes * (lc.profile.duration() + 3.0) + 2.0;
    double sum = 0, firstCut = -1, lastCut = -1, returnSum = 0, returnFrom = -1;
    int cuts = 0, returns = 0;
    QrPhase prev = sim.law.phase();
    for (int i = 0; i * T < limit; ++i) {
        const double t = i * T;
        const double tau = sim.cycle(t);
        const QrSample& q = sim.law.last();
        r.max_torque = std::max(r.max_torque, std::fabs(tau));
        if (sim.out.status == SourceStatus::Fault) {
            r.problem = sim.out.fault;
            break;
        }
        const QrPhase ph = sim.law.phase();
        if (ph == QrPhase::Cut && prev != QrPhase::Cut) {
            if (firstCut < 0) firstCut = t;
            lastCut = t;
            ++cuts;
            if (returnFrom >= 0) {
                returnSum += t - returnFrom;
                ++returns;
            }
        }
        if (ph == QrPhase::ReturnPush && prev != QrPhase::ReturnPush) returnFrom = t;
        prev = ph;
        const double y = sim.plant.sliderPosition(), dy = sim.plant.sliderVelocity();
        if (ph == QrPhase::Cut && y >= s.plant.cut_low && y <= s.plant.cut_high) {
            const double ev = q.dy_d - dy;
            r.velocity_error_max = std::max(r.velocity_error_max, std::fabs(ev));
            sum += ev * ev;
            ++r.samples_in_work;
        }
        if (i % s.trace_every == 0)
            r.trace.push_back({t, y, dy, q.y_d, q.dy_d, tau, ph == QrPhase::Cut});
        if (sim.out.status == SourceStatus::Done) {
            r.completed = true;
            break;
        }
    }
    r.strokes = sim.law.strokesDone();
    if (!r.completed && r.problem.empty())
        r.problem = messageC("did not finish %d strokes in %d s", static_cast<int>(lc.strokes),
                             static_cast<int>(limit));
    r.velocity_error_rms = r.samples_in_work > 0 ? std::sqrt(sum / r.samples_in_work) : 0;
    r.cycle_time = cuts > 1 ? (lastCut - firstCut) / (cuts - 1) : 0;
    r.return_time = returns > 0 ? returnSum / returns : 0;
    return r;
}

} // namespace cutcell::quick_return
