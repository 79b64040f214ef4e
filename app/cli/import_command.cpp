// cutcell-cli import-<name> FILE --out JOB.json: one command per registered importer
// (MachineModule::importers(), core/machine/job_importer.h), e.g. import-dstv. Prints the
// importer's report (what the job does not do, line by line), writes the job atomically.
// import-<name> DIR --out DIR: a batch, every file of DIR the importer's patterns match (by
// name, case-insensitively, sorted): one job per file, and a report table of every file -
// imported (what the piece is, what is ignored) or refused (the line and the reason) - on
// standard output and as DIR/import-report.csv.
#include "cli_commands.h"

#include "core/job/job_io.h"
#include "core/machine/import_batch.h"
#include "core/machine/job_importer.h"

#include <cstdio>
#include <filesystem>

namespace cutcell::cli {
namespace {

int runBatch(const JobImporter& importer, const ImportOptions& o, const std::string& command) {
    ImportBatch b;
    try {
        const std::vector<std::string> files = filesMatching(importer, o.file);
        if (files.empty()) {
            std::string patterns;
            for (const std::string& p : importer.patterns)
                patterns += (patterns.empty() ? "" : " ") + p;
            std::fprintf(stderr, "%s: no file in %s matches %s\n", command.c_str(), o.file.c_str(),
                         patterns.c_str());
            return kFailure;
        }
        b = importBatch(importer, files, o.out);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", command.c_str(), e.what());
        return kFailure;
    }
    for (const ImportBatchRow& r : b.rows) {
        std::printf("%-32s %-8s", r.file.c_str(), r.imported ? "imported" : "refused");
        if (!r.imported) {
            std::printf(" %s\n", r.reason.c_str());
            continue;
        }
        for (const auto& [k, v] : r.facts)
            std::printf("  %s %s", k.c_str(), v.empty() ? "-" : v.c_str());
        std::printf("  -> %s\n", r.job.c_str());
    }
    std::printf("%zu file(s): %zu imported, %d refused; the jobs and %s in %s\n", b.rows.size(),
                b.rows.size() - static_cast<size_t>(b.refused), b.refused, "import-report.csv",
                o.out.c_str());
    return b.refused > 0 ? kInvalidJob : kOk;
}

} // namespace

int runImport(const ImportOptions& o) {
    const std::string command = "cutcell-cli import-" + o.importer;
    JobImporter importer;
    if (!findJobImporter(o.importer, &importer)) {
        std::fprintf(stderr, "%s: no importer \"%s\"\n", command.c_str(), o.importer.c_str());
        return kUsage;
    }
    if (std::error_code ec; std::filesystem::is_directory(o.file, ec))
        return runBatch(importer, o, command);
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
