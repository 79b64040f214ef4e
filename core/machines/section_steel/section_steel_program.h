#pragma once
// The motion program of the section-steel cell: 8 rotary, position-commanded axes (0..2 path
// arm, 3..7 groove arm), the joint spline of the plan, the park position as reference, and a
// tip model (the torch of the arm that cuts: the path arm's while the groove arm is parked).
#include "core/engine/motion_program.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <memory>
#include <string>

namespace cutcell::section_steel {

std::shared_ptr<const MotionProgram> buildSectionSteelProgram(const Job& job,
                                                              const SectionSteelSpec& spec,
                                                              const SteelPlan& plan,
                                                              const std::string& jobText);

// CSV of the planned points: pass, point, face, s, tip, torch direction, tilt, joints. The tip
// is the torch centre; with kerf compensation (plan.kerf_mm > 0) three more columns give the
// theoretical edge's point (edge_x_mm, edge_y_mm, edge_z_mm).
std::string steelPathCsv(const SectionSteelSpec& spec, const SteelPlan& plan);

class SteelTipModel : public TipModel {
  public:
    SteelTipModel(const SectionSteelSpec& spec, const JointVector& park)
        : cell_(spec), park_(park) {}
    // The cell of a plan with kerf compensation (SteelPlan::kerf_mm): the tip is the torch centre.
    SteelTipModel(const SectionSteelSpec& spec, const JointVector& park, double kerf_mm)
        : cell_(spec, kerf_mm), park_(park) {}
    Vec3 tip(const JointVector& q) const override;

  private:
    SteelCell cell_;
    JointVector park_;
};

} // namespace cutcell::section_steel
