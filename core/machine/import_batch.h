#pragma once
// A batch of files through one importer (`cutcell-cli import-dstv DIR --out DIR`, File -> Import
// with several files): one job per file, written atomically into a folder, and a report table -
// per file imported (the importer's facts: what the piece is, what is ignored) or refused (the
// line and the reason) - kept as <folder>/import-report.csv. Pure C++; the CLI and the GUI show
// the table their own way.
#include "core/machine/job_importer.h"

#include <string>
#include <vector>

namespace cutcell {

struct ImportBatchRow {
    std::string file; // the input's file name
    std::string job;  // the job file's name in the folder ("" when refused)
    bool imported = false;
    std::string reason; // why it was refused ("line 10: profile code B (a plate): ...")
    std::vector<std::pair<std::string, std::string>> facts;
    std::vector<std::string> report;
};

struct ImportBatch {
    std::vector<ImportBatchRow> rows;
    std::vector<std::string> columns; // the facts' columns, first seen first
    int refused = 0;
    std::string csv_path;
    // The value of a fact column in a row ("" when the row has none).
    static std::string fact(const ImportBatchRow& row, const std::string& column);
};

// The files of `dir` the importer's patterns match (case-insensitively), sorted by name.
// Throws JobError naming the folder when it cannot be read.
std::vector<std::string> filesMatching(const JobImporter& importer, const std::string& dir);

// Imports each file into <outDir>/<its name>.json (letters, digits, '-', '_', '.'; a number
// added where two would collide) and writes <outDir>/import-report.csv, both atomically. A file
// that cannot be read or is refused is a refused row; throws JobError only when the folder
// cannot be made or the table not written.
ImportBatch importBatch(const JobImporter& importer, const std::vector<std::string>& files,
                        const std::string& outDir);

} // namespace cutcell
