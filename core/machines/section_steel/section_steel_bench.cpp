#include "core/machines/section_steel/section_steel_bench.h"
#include "core/machines/section_steel/section_steel_module.h"

#include "core/machines/section_steel/section_steel_planner.h"

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

namespace cutcell::section_steel {

void benchSectionSteel(bool quick, json::Object& out) {
    using Clock = std::chrono::steady_clock;
    const GrooveArm arm;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-kPi, kPi);
    std::vector<Pose> poses;
    for (int i = 0; i < 1000; ++i)
        poses.push_back(arm.forward({u(rng), u(rng), u(rng), u(rng), u(rng)}));
    volatile size_t sink = 0;
    const int repeats = quick ? 2 : 20;
    auto t0 = Clock::now();
    for (int r = 0; r < repeats; ++r)
        for (const Pose& p : poses)
            sink = sink + arm.inverse(p).size();
    double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    out.emplace_back("section_ik_ns_per_solve", ns / (static_cast<double>(poses.size()) * repeats));

    // Torch IK (tip + direction, every solution): the same 1000 poses.
    const int torchRepeats = quick ? 1 : 5;
    size_t torchSolutions = 0;
    t0 = Clock::now();
    for (int r = 0; r < torchRepeats; ++r)
        for (const Pose& p : poses)
            torchSolutions += arm.inverseTorch(p.translation(), p.linear().col(0)).size();
    ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    const double torchSolves = static_cast<double>(poses.size()) * torchRepeats;
    sink = sink + torchSolutions;
    out.emplace_back("section_torch_ik_ns_per_solve", ns / torchSolves);
    out.emplace_back("section_torch_ik_solutions_per_pose",
                     static_cast<double>(torchSolutions) / torchSolves);

    const SectionSteelSpec spec = defaultSectionSteelSpec();
    double best = 1e300;
    for (int r = 0; r < (quick ? 1 : 5); ++r) {
        t0 = Clock::now();
        const SteelPlan plan = planEndCut(spec);
        sink = sink + plan.knots.size();
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    out.emplace_back("section_end_cut_plan_ms", best);

    // A full grooved mitred end: IPE 300 mitred 30/15 deg, V flanges, Y web (square pass by the
    // path arm, six bevel passes by the groove arm).
    SectionSteelSpec grooved = spec;
    grooved.cut = {30, 15, {GrooveType::V, 30, 0}, {GrooveType::Y, 30, 2}};
    best = 1e300;
    for (int r = 0; r < (quick ? 1 : 5); ++r) {
        t0 = Clock::now();
        const SteelPlan plan = planEndCut(grooved);
        sink = sink + plan.knots.size() + (plan.ok ? 0 : 1);
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    out.emplace_back("section_grooved_mitred_end_cut_plan_ms", best);
}

} // namespace cutcell::section_steel

namespace cutcell {

void SectionSteelModule::addBenchFigures(bool quick, json::Object& out) const {
    section_steel::benchSectionSteel(quick, out);
}

} // namespace cutcell
