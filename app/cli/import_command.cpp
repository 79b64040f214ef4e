// cutcell-cli import-<name> FILE --out JOB.json: one command per registered importer
// (MachineModule::importers(), core/machine/job_importer.h), e.g. import-dstv. Prints the
// importer's report (what the job does not do, line by line), writes the job atomically.
#include "cli_commands.h"

#include "core/job/job_io.h"
#include "core/machine/job_importer.h"

#include <cstdio>

namespace cutcell::cli {

int runImport(const ImportOptions& o) {
    const std::string command = "cutcell-cli import-" + o.importer;
    JobImporter importer;
    if (!findJobImporter(o.importer, &importer)) {
        std::fprintf(stderr, "%s: no importer \"%s\"\n", command.c_str(), o.importer.c_str());
        return kUsage;
    }
    std::string text;
    try {
        text = readTextFile(o.file);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", command.c_str(), e.what());
        return kFailure;
    }
    ImportResult result;
    try {
        result = importer.import(text);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s refused: %s\n", command.c_str(), o.file.c_str(), e.what());
        return kInvalidJob;
    }
    try {
        saveJobFile(result.job, o.out);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", command.c_str(), e.what());
        return kFailure;
    }
    for (const std::string& line : result.report)
        std::printf("%s: %s\n", o.file.c_str(), line.c_str());
    std::printf("wrote %s (%s, %zu report lines)\n", o.out.c_str(), result.job.name.c_str(),
                result.report.size());
    return kOk;
}

} // namespace cutcell::cli
