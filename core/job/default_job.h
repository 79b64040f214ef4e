#pragma once
// The default job (resources/jobs/default_job.json), compiled in so every tool has it.
#include "core/job/job.h"

#include <string>

namespace cutcell {

const std::string& defaultJobText();
Job defaultJob();

} // namespace cutcell
