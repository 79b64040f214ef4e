#pragma once
// Figures of the quick-return cutter as SVG (no GUI needed): the mechanism at a few crank
// angles with the workpiece, the cutting experiment's velocity profile, phase diagram (y
// against y') and velocity error over the workpiece, for the job's controller.
#include "core/machines/quick_return/experiments.h"

#include <string>

namespace cutcell::quick_return {

std::string cuttingFiguresSvg(const ExperimentSetup& setup, const CuttingResult& result);

} // namespace cutcell::quick_return
