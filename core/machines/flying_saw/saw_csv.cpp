#include "core/machines/flying_saw/saw_csv.h"

#include "core/common/c_format.h"
#include "core/common/types.h"

namespace cutcell {

std::string camTableCsv(const FlyingSawPlan& plan) {
    const SawCycle& c = plan.saw;
    std::string out = "index,theta_deg,feed_mm,feed_blade2_mm,tip_radius_mm\n";
    for (int i = 0; i < c.cam.count; ++i) {
        const double theta = c.cam.period * i / (c.cam.count - 1);
        const double f = c.cam.slave[static_cast<size_t>(i)];
        out += formatC("%d,%.9g,%.9f,%.9f,%.9f\n", i, rad2deg(theta), f, f, c.retract_radius - f);
    }
    return out;
}

std::vector<CycleRow> nominalCycle(const FlyingSawPlan& plan, double dt, double wait_s) {
    const double V = plan.line_speed_mm_s;
    const ForwardStroke& f = plan.forward;
    const double T1 = f.d1 / V, T2 = plan.T2, T3 = f.d3 / V;
    const double xE = f.d1 / 2 + V * T2;
    const ReverseProfile& rev = plan.nominal_reverse; // what the source plans from xE + d3 / 2
    std::vector<CycleRow> rows;
    const double ends[] = {wait_s, wait_s + T1, wait_s + T1 + T2, wait_s + T1 + T2 + T3};
    const double tEnd = ends[3] + rev.duration() + wait_s;
    for (double t = 0; t <= tEnd + 1e-12; t += dt) {
        CycleRow row;
        row.t = t;
        if (t < ends[0]) {
            row.period = "AB";
        } else if (t < ends[1]) {
            const double u = V * (t - ends[0]);
            row = {t, f.accel(u), V * f.accelSlope(u), V * V * f.accelCurvature(u), "BC"};
        } else if (t < ends[2]) {
            row = {t, f.d1 / 2 + V * (t - ends[1]), V, 0, "CE"};
        } else if (t < ends[3]) {
            const double u = V * (t - ends[2]);
            row = {t, xE + f.decel(u), V * f.decelSlope(u), V * V * f.decelCurvature(u), "EF"};
        } else {
            const double tr = t - ends[3];
            const char* p = tr < rev.ta            ? "FG"
                            : tr < rev.ta + rev.ts ? "GH"
                            : tr < rev.duration()  ? "HI"
                                                   : "AB";
            row = {t, rev.distance - rev.travel(tr), -rev.speed(tr), -rev.accel(tr), p};
        }
        rows.push_back(row);
    }
    return rows;
}

std::string cycleCsv(const FlyingSawPlan& plan) {
    std::string out = "t_s,s_mm,v_mm_s,a_mm_s2,period\n";
    for (const CycleRow& r : nominalCycle(plan, 0.002))
        out += formatC("%.4f,%.6f,%.6f,%.6f,%s\n", r.t, r.s, r.v, r.a, r.period);
    return out;
}

std::string piecesCsv(const SawSimResult& r) {
    std::string out = "piece,ordered_mm,length_mm,error_mm,cut_spread_mm\n";
    for (const PieceRecord& p : r.pieces)
        out += formatC("%d,%.4f,%.6f,%.6f,%.6f\n", p.piece, p.ordered_mm, p.length_mm, p.error_mm,
                       p.spread_mm);
    return out;
}

} // namespace cutcell
