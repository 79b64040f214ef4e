#pragma once
// The part of a machine section shared by the machines that cut a pipe joint (the pipe robot,
// the profile cutter): main_pipe, branch_pipe, angle_deg, eccentricity_mm and cut. The
// intersection maths itself is core/geometry.
#include "core/job/issue_checker.h"
#include "core/job/job.h"
#include "core/job/section_reader.h"

#include <string>
#include <vector>

namespace cutcell {

// Which cut.* keys a machine reads (the profile cutter has no torch tilt or static chuck).
struct CutKeys {
    bool bevel = true;
    bool direction_deviation = true;
    bool static_chuck = true;
    bool start_phi = true;
};

void readPipeJoint(SectionReader& section, Job& job, const CutKeys& keys);
void writePipeJoint(const Job& job, json::Object& section, const CutKeys& keys);
// Pipes, angle, fit of the branch, cut ranges; the cut length bounds (an hour at most, the
// number of samples at the control period) and the pipe lengths that must contain the cut.
void checkPipeJoint(IssueChecker& c, const Job& job, const CutKeys& keys);

// Longest cut accepted (s): a cut longer than an hour is refused with the figures.
inline constexpr double kMaxCutTime_s = 3600;
// Most samples of a plan at the control period (joints.csv rows, engine steps).
inline constexpr double kMaxPlanSamples = 4e6;

} // namespace cutcell
