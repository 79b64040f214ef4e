#include "core/machine/job_importer.h"

#include "core/machine/machine_registry.h"

namespace cutcell {

std::vector<JobImporter> jobImporters() {
    std::vector<JobImporter> out;
    for (const MachineModule* m : machines())
        for (JobImporter& i : m->importers())
            out.push_back(std::move(i));
    return out;
}

bool findJobImporter(const std::string& name, JobImporter* out) {
    for (JobImporter& i : jobImporters())
        if (i.name == name) {
            if (out) *out = std::move(i);
            return true;
        }
    return false;
}

} // namespace cutcell
