#pragma once
// File formats a machine can turn into a job (File -> Import..., `cutcell-cli import-<name>`).
// A module lists its importers (MachineModule::importers()); the CLI and the GUI build their
// commands and menu entries from every registered importer, so no other layer names a machine
// or a format.
#include "core/job/job.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

// An input file the importer refuses: the message names the line and the field.
struct ImportError : std::runtime_error {
    explicit ImportError(const std::string& message) : std::runtime_error(message) {}
};

struct ImportResult {
    Job job; // valid (validateJob() finds nothing)
    // One line per thing of the file the job does not do or takes with a change
    // ("line 23: BO hole 22 mm on face v (front): not cut by this machine").
    std::vector<std::string> report;
    // What the piece is, for a batch's report table: (column, value) in column order, e.g.
    // ("piece", "B12"), ("section", "IPE 300"), ("length_mm", "4978"), ("ignored", "3 holes").
    std::vector<std::pair<std::string, std::string>> facts;
};

struct JobImporter {
    std::string name;                  // "dstv": `cutcell-cli import-dstv`
    std::string title;                 // "DSTV" ("Import DSTV...")
    std::string description;           // one line for help texts
    std::vector<std::string> patterns; // "*.nc", "*.nc1" (matched case-insensitively)
    // The file's text -> the job and its report; throws ImportError.
    std::function<ImportResult(const std::string& text)> import;
};

// Every registered machine's importers, in registration order.
std::vector<JobImporter> jobImporters();
// nullptr-like: false when no importer has this name.
bool findJobImporter(const std::string& name, JobImporter* out);

} // namespace cutcell
