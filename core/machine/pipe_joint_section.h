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

// The wall of the pipe being cut (the main pipe for its hole, the branch for its end): the
// thickness that picks the cut chart's row unless process.thickness_mm is given.
double cutPartWallMm(const Job& job);
// With a process section, cut.speed_mm_s becomes the chart's speed (or its override) for the
// part's wall, 0 when the chart refuses it (validation then says why). Reading the section calls
// it; so must whoever edits the pipes, the target or the process afterwards (the forms).
void syncProcessSpeed(Job& job);

// Longest cut accepted (s): a cut longer than an hour is refused with the figures.
inline constexpr double kMaxCutTime_s = 3600;
// Most samples of a plan at the control period (joints.csv rows, engine steps).
inline constexpr double kMaxPlanSamples = 4e6;

} // namespace cutcell
