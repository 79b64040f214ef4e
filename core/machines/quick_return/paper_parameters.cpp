#include "core/machines/quick_return/paper_parameters.h"

#include "core/common/c_format.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcell::quick_return {

QuickReturnSpec paperParameters(QuickReturnSpec s) {
    s.plant.slider_mass = kPaperSliderMass;
    s.gains.model_mass = kPaperSliderMass;
    s.gains.ffc_wn2 = kPaperFfcWn2;
    s.gains.ffc_xi = kPaperFfcXi;
    s.gains.osmc_k1 = kPaperOsmcK1;
    s.gains.osmc_k2 = kPaperOsmcK2;
    s.mse_scale = kPaperMseScale;
    s.mse_window = kPaperMseWindow;
    s.experiment = Experiment::Tracking;
    s.controller = ControllerKind::Osmc;
    return s;
}

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

double rmsOf(std::span<const double> x) {
    double sum = 0;
    for (const double v : x)
        sum += v * v;
    return x.empty() ? 0 : std::sqrt(sum / static_cast<double>(x.size()));
}

} // namespace

LimitCycle detectLimitCycle(std::span<const double> all, double dt, const LimitCycleOptions& o) {
    LimitCycle r;
    const size_t want = static_cast<size_t>(std::llround(o.window_s / dt));
    if (!(dt > 0) || want < 16 || all.size() < want) {
        r.verdict = messageC("too short: %zu samples for a %.3g s window", all.size(), o.window_s);
        return r;
    }
    const std::span<const double> x = all.subspan(all.size() - want);
    const double window = static_cast<double>(want) * dt, nyquist = 0.5 / dt;
    // The forced tones with their harmonics (below Nyquist, each once).
    std::vector<double> forced;
    for (const double f : o.forced_hz)
        for (int k = 1; f > 0 && k <= o.forced_harmonics; ++k)
            if (const double h = k * f;
                h < 0.95 * nyquist && std::none_of(forced.begin(), forced.end(), [&](double g) {
                    return std::fabs(g - h) < 1e-9 * h;
                }))
                forced.push_back(h);
    // Residual of mean, drift and the forced tones (least squares).
    const Eigen::Index n = static_cast<Eigen::Index>(want);
    const Eigen::Index cols = 2 + 2 * static_cast<Eigen::Index>(forced.size());
    Eigen::MatrixXd a(n, cols);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) * dt;
        a(i, 0) = 1;
        a(i, 1) = t / window - 0.5;
        for (size_t k = 0; k < forced.size(); ++k) {
            const Eigen::Index c = 2 + 2 * static_cast<Eigen::Index>(k);
            a(i, c) = std::cos(kTwoPi * forced[k] * t);
            a(i, c + 1) = std::sin(kTwoPi * forced[k] * t);
        }
        b(i) = x[static_cast<size_t>(i)];
    }
    const Eigen::VectorXd res = b - a * a.colPivHouseholderQr().solve(b);
    const std::span<const double> rs(res.data(), want);
    const double rms = rmsOf(rs);
    r.amplitude = std::sqrt(2.0) * rms;
    r.amplitude_early = std::sqrt(2.0) * rmsOf(rs.first(want / 2));
    r.amplitude_late = std::sqrt(2.0) * rmsOf(rs.subspan(want / 2));
    if (!(rms > 0) || !std::isfinite(rms)) {
        r.verdict = "no oscillation beside the forced tones";
        return r;
    }
    // Biased autocorrelation, normalised by the zero lag, up to window / min_cycles.
    const size_t maxLag = std::min(
        want - 2, static_cast<size_t>(static_cast<double>(want) / std::max(o.min_cycles, 1.0)));
    std::vector<double> acf(maxLag + 2, 0.0);
    const double r0 = rms * rms * static_cast<double>(want);
    for (size_t k = 0; k < acf.size() && k < want; ++k) {
        double sum = 0;
        for (size_t i = k; i < want; ++i)
            sum += res(static_cast<Eigen::Index>(i)) * res(static_cast<Eigen::Index>(i - k));
        acf[k] = sum / r0;
    }
    // A period at a removed forced frequency (within a quarter of the window's resolution) is
    // what the least squares left of the forced response.
    const auto isForced = [&](double f) {
        return std::any_of(forced.begin(), forced.end(),
                           [&](double g) { return std::fabs(f - g) < 0.25 / window; });
    };
    size_t from = 1;
    while (from <= maxLag && acf[from] > 0)
        ++from;
    // The local peaks (parabola through each and its neighbours: lag and height between the
    // lags), not at a forced frequency. The period is the first whose height is within
    // kPeakShare of the highest: a periodic signal peaks as high at every multiple of its
    // period, and a whole number of samples may come closer to a multiple than to the period.
    struct Peak {
        double lag = 0, height = 0;
    };
    std::vector<Peak> peaks;
    for (size_t k = std::max<size_t>(from, 2); k <= maxLag; ++k) {
        const double y0 = acf[k - 1], y1 = acf[k], y2 = acf[k + 1];
        if (!(y1 >= y0 && y1 >= y2)) continue;
        const double den = y0 - 2 * y1 + y2;
        const double shift = den < 0 ? std::clamp(0.5 * (y0 - y2) / den, -0.5, 0.5) : 0.0;
        const Peak p{static_cast<double>(k) + shift, y1 - 0.25 * (y0 - y2) * shift};
        if (!isForced(1 / (p.lag * dt))) peaks.push_back(p);
    }
    if (peaks.empty()) {
        r.verdict = messageC("no period between %.4g s and %.4g s", 2 * dt,
                             static_cast<double>(maxLag) * dt);
        return r;
    }
    constexpr double kPeakShare = 0.9;
    double highest = peaks.front().height;
    for (const Peak& p : peaks)
        highest = std::max(highest, p.height);
    const auto first = std::find_if(peaks.begin(), peaks.end(), [&](const Peak& p) {
        return p.height >= kPeakShare * highest;
    });
    // With every peak below zero the highest is the period's best guess.
    const Peak period =
        first != peaks.end()
            ? *first
            : *std::max_element(peaks.begin(), peaks.end(), [](const Peak& p1, const Peak& p2) {
                  return p1.height < p2.height;
              });
    r.frequency_hz = 1 / (period.lag * dt);
    r.periodicity = period.height;
    const double floor = o.min_amplitude + o.min_amplitude_per_hz * r.frequency_hz;
    if (r.periodicity < o.min_periodicity)
        r.verdict = messageC("not periodic: the autocorrelation's best peak, at %.4g Hz, is %.2f "
                             "(less than %.2f)",
                             r.frequency_hz, r.periodicity, o.min_periodicity);
    else if (!(r.amplitude_late > floor))
        r.verdict = messageC("%.4g Hz oscillation below the floor (amplitude %.3g <= %.3g)",
                             r.frequency_hz, r.amplitude_late, floor);
    else if (r.ratio() < o.sustain_ratio)
        r.verdict = messageC("decaying: the %.4g Hz oscillation falls to %.2f of its amplitude "
                             "over the window (less than %.2f)",
                             r.frequency_hz, r.ratio(), o.sustain_ratio);
    else {
        r.detected = true;
        r.verdict = messageC("limit cycle: %.4g Hz sustained (periodicity %.2f, late/early "
                             "amplitude %.2f)",
                             r.frequency_hz, r.periodicity, r.ratio());
    }
    return r;
}

LimitCycleOptions experiment1CycleOptions(const ExperimentSetup& s) {
    LimitCycleOptions o;
    o.window_s = std::min(4.0, 0.5 * s.law.track_duration);
    o.forced_hz.push_back(std::fabs(s.law.track_omega) / kTwoPi);
    if (s.disturbance_amplitude != 0 && s.disturbance_hz > 0)
        o.forced_hz.push_back(s.disturbance_hz);
    return o;
}

namespace {

Experiment1Run runOne(const ExperimentSetup& s, ControllerKind k, const LimitCycleOptions& o,
                      const QuickReturnLaw& probe) {
    const TrackingResult t = runTracking(s, k);
    Experiment1Run r;
    r.controller = k;
    r.k2 = s.law.gains.osmc_k2;
    r.mse = t.mse;
    r.max_abs_error = t.max_abs_error;
    r.max_torque = t.max_torque;
    // Floors: half a count of the scale the law reads, in e and in slope e + e' at the frequency.
    const double half = 0.5 * s.scale_resolution;
    LimitCycleOptions oe = o;
    oe.min_amplitude = half;
    r.error_cycle = detectLimitCycle(t.error, s.sample_time, oe);
    const OsmcSurface surf = osmcSurface(s.law.gains);
    std::vector<double> sliding(t.error.size());
    for (size_t i = 0; i < sliding.size(); ++i)
        sliding[i] = surf.slope() * t.error[i] + t.error_rate[i];
    LimitCycleOptions os = o;
    os.min_amplitude = surf.slope() * half;
    os.min_amplitude_per_hz = kTwoPi * half;
    r.sliding_cycle = detectLimitCycle(sliding, s.sample_time, os);
    const size_t n = t.crank.size();
    const size_t from =
        n - std::min(n, static_cast<size_t>(std::llround(o.window_s / s.sample_time)));
    for (size_t i = from + 1; i < n; ++i)
        if (probe.onCutBranch(t.crank[i]) != probe.onCutBranch(t.crank[i - 1])) ++r.singular_passes;
    if (n > from) r.crank_turns = (t.crank[n - 1] - t.crank[from]) / kTwoPi;
    return r;
}

} // namespace

Experiment1Study studyExperiment1(const ExperimentSetup& base, const K2Sweep& sweep,
                                  double max_samples) {
    ExperimentSetup s = base;
    s.keep_errors = true;
    s.trace_every = 1 << 30; // no plot traces
    const LimitCycleOptions o = experiment1CycleOptions(s);
    const QuickReturnLaw probe(s.law);
    Experiment1Study st;
    st.k1 = s.law.gains.osmc_k1;
    for (ControllerKind k : kAllControllers)
        st.runs.push_back(runOne(s, k, o, probe));
    st.rival_mse = std::min(st.runs[static_cast<size_t>(ControllerKind::Ffc)].mse,
                            st.runs[static_cast<size_t>(ControllerKind::Lqt)].mse);
    const int points = std::max(sweep.points, 2);
    const double runSamples = s.law.track_duration / s.sample_time;
    const double samples = (points + sweep.refine_steps) * runSamples;
    if (samples > max_samples) {
        st.sweep_skipped = messageC("the k2 sweep would compute about %.3g samples (%d runs of "
                                    "%.3g), over the bound of %.3g",
                                    samples, points + sweep.refine_steps, runSamples, max_samples);
        return st;
    }
    const auto osmcAt = [&](double k2) {
        ExperimentSetup sk = s;
        sk.law.gains.osmc_k2 = k2;
        return runOne(sk, ControllerKind::Osmc, o, probe);
    };
    const double ratio = std::log(sweep.to / sweep.from) / (points - 1);
    int first = -1;
    for (int i = 0; i < points; ++i) {
        const double k2 = i == points - 1 ? sweep.to : sweep.from * std::exp(ratio * i);
        st.sweep.push_back(osmcAt(k2));
        if (first < 0 && st.sweep.back().mse < st.rival_mse) first = i;
    }
    if (first < 0) return st;
    st.osmc_wins = true;
    st.smallest_k2 = st.threshold_lo = st.threshold_hi = st.sweep[static_cast<size_t>(first)].k2;
    if (first == 0) return st;
    st.threshold_lo = st.sweep[static_cast<size_t>(first - 1)].k2;
    for (int i = 0; i < sweep.refine_steps; ++i) {
        const double mid = std::sqrt(st.threshold_lo * st.threshold_hi);
        (osmcAt(mid).mse < st.rival_mse ? st.threshold_hi : st.threshold_lo) = mid;
    }
    return st;
}

} // namespace cutcell::quick_return
