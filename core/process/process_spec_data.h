#pragma once
// The job's process section as data (core/process/process_spec.h reads, writes, resolves and
// checks it): the cut chart's entry a torch machine cuts with and the operator's overrides.
#include "core/process/cut_chart.h"

#include <cstdint>
#include <optional>
#include <string>

namespace cutcell {

// A lead-in or lead-out of a closed cut (process.lead_in, process.lead_out): none, a straight
// line or a quarter arc, length_mm along the lead on the developed surface, on the scrap side.
// overlap_mm (lead-out only): how far the torch runs on past the cut's start before it leaves.
enum class LeadKind : std::uint8_t { None, Line, Arc };
struct LeadSpec {
    LeadKind kind = LeadKind::None;
    double length_mm = 0;
    double overlap_mm = 0;
    bool used() const { return kind != LeadKind::None; }
    bool operator==(const LeadSpec&) const = default;
};
// "none", "line", "arc".
const char* toString(LeadKind k);

// Torch height control (process.torch_height): whether the THC corrects the height, and the
// simulated cell's actual pipe (core/process/pipe_surface.h: PipeDefects without the radius,
// which is the cut pipe's) and arc noise. On a real cell the pipe is what it is and the voltage
// comes from the torch: the simulated_pipe keys then describe nothing and are refused there.
//
//   "torch_height": { "thc": true, "arc_noise_v": 0.5,
//                     "simulated_pipe": { "ovality_mm": 2, "major_axis_deg": 20,
//                                         "runout_mm": 0.5, "runout_deg": 20,
//                                         "taper_mm_per_m": 0 } }
struct TorchHeightSpec {
    bool used = false; // the object is in the job
    bool thc = true;   // false: the height is measured and reported, not corrected
    double arc_noise_v = 0;
    double ovality_mm = 0, major_axis_deg = 0, runout_mm = 0, runout_deg = 0, taper_mm_per_m = 0;
    bool operator==(const TorchHeightSpec&) const = default;
};

struct ProcessSpec {
    bool used = false; // the section is in the job
    CutProcess process = CutProcess::Plasma;
    std::string material;
    std::string consumable;
    std::optional<double> thickness_mm; // absent: the wall of the part being cut
    CutRow override;                    // the figures set over the chart's (thickness never)
    LeadSpec lead_in;                   // absent: none (the cut starts where it pierces)
    LeadSpec lead_out;                  // absent: none
    TorchHeightSpec torch_height;       // absent: no torch height control
    bool operator==(const ProcessSpec&) const = default;
};

} // namespace cutcell
