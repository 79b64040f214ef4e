#pragma once
// Reading, validating and writing job files. Every rejection names the key, the value,
// the unit and the limit, e.g.
//   "branch_pipe.radius_mm = 70 mm does not fit: |eccentricity_mm| + branch radius = 75 mm
//    must be <= main_pipe.radius_mm = 60 mm".
#include "core/job/job.h"
#include "core/json/json.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace cutcell {

struct JobError : std::runtime_error {
    explicit JobError(const std::string& msg) : std::runtime_error(msg) {}
};

// One problem with a job value: the dotted key and a full sentence for the user.
struct JobIssue {
    std::string key;
    std::string message;
};

// Parses the JSON document into a Job (missing optional keys take documented defaults).
// Throws JobError for syntax errors, unknown enums, wrong types or missing required keys.
Job jobFromJson(const json::Value& doc);
json::Value jobToJson(const Job& job);

// All range and consistency problems of a job (empty when the job is valid).
std::vector<JobIssue> validateJob(const Job& job);

// Parse + validate; throws JobError with the first problem (and a count of the others).
Job parseJob(const std::string& text);
Job loadJobFile(const std::string& path);
// Written atomically: a temporary file in the same folder, flushed, then renamed over.
void saveJobFile(const Job& job, const std::string& path);
void writeFileAtomically(const std::string& path, const std::string& contents);
std::string readTextFile(const std::string& path);

} // namespace cutcell
