#pragma once
// Reading, validating and writing job files. Every rejection names the key, the value,
// the unit and the limit, e.g.
//   "branch_pipe.radius_mm = 70 mm does not fit: |eccentricity_mm| + branch radius = 75 mm
//    must be <= main_pipe.radius_mm = 60 mm".
#include "core/common/outcome.h"
#include "core/job/job.h"
#include "core/json/json.h"

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

struct JobError : std::runtime_error {
    explicit JobError(const std::string& msg) : std::runtime_error(msg) {}
};
// The job file cannot be read at all (missing, a folder, no permission): an I/O error, not
// an invalid job (the CLI's exit 1, not 2).
struct JobFileError : JobError {
    using JobError::JobError;
};

// One problem with a job value: an Outcome, always Refused, with the dotted key and a full
// sentence for the user.
struct JobIssue : Outcome {
    JobIssue() : Outcome{OutcomeStatus::Refused, {}, {}} {}
    JobIssue(std::string k, std::string m) : Outcome(refuse(std::move(m), std::move(k))) {}
    JobIssue(std::string k, std::string m, double v, double low, double high, std::string u)
        : Outcome(refuse(std::move(m), std::move(k))), value(v), lo(low), hi(high),
          unit(std::move(u)) {}

    // A value outside its range (IssueChecker::range, positive): the value, the limits and the
    // unit, so that a form can say it in its own words with its field's label. The limits are
    // NaN for an issue of another kind (the message is all there is).
    double value = std::numeric_limits<double>::quiet_NaN();
    double lo = std::numeric_limits<double>::quiet_NaN();
    double hi = std::numeric_limits<double>::quiet_NaN();
    std::string unit;
};

// Parses the JSON document (schema 1 or 2) into a Job; the machine section is read by the
// module of machine.kind (core/machine/machine_registry.h). Missing optional keys take
// documented defaults. Throws JobError for unknown keys (with a hint), unknown enums, wrong
// types or missing required keys, naming the dotted key.
Job jobFromJson(const json::Value& doc);
// Always schema 2: the common part and the machine's section.
json::Value jobToJson(const Job& job);

// Schema 1 -> 2 (a schema-2 document is returned as it is): the machine's keys move into the
// `machine` section { "kind": ..., ... }, keys its machine never read in schema 1 are dropped.
json::Value upgradeJobDocument(const json::Value& doc);
// The text of a job file (schema 1 or 2) as a schema-2 file; throws JobError when it cannot be
// read (for `cutcell-cli upgrade`).
std::string upgradeJobText(const std::string& text);

// All range and consistency problems of a job (empty when the job is valid): the common part
// and the machine's own validation. The GUI and the CLI both call this one.
std::vector<JobIssue> validateJob(const Job& job);

// Parse + validate; throws JobError with the first problem (and a count of the others).
Job parseJob(const std::string& text);
Job loadJobFile(const std::string& path);
// Written atomically: a temporary file in the same folder, flushed, then renamed over.
void saveJobFile(const Job& job, const std::string& path);
void writeFileAtomically(const std::string& path, const std::string& contents);
// A new file from the mkstemp template `tmpl` (its XXXXXX replaced) holding `contents`, on disk
// and mode 0644 when it returns its name. Throws JobError naming `forPath`, leaving nothing.
std::string writeTemporaryFile(std::string tmpl, const std::string& forPath,
                               const std::string& contents);
std::string readTextFile(const std::string& path);

} // namespace cutcell
