#pragma once
// Collects JobIssues; every message names the key, the value with its unit and the limit.
#include "core/common/c_format.h"
#include "core/job/job_io.h"
#include "core/job/section_reader.h"

#include <cmath>
#include <string>
#include <vector>

namespace cutcell {

class IssueChecker {
  public:
    std::vector<JobIssue> issues;

    void add(const std::string& key, const std::string& msg) { issues.push_back({key, msg}); }
    // Whether a message for `key` was given (a check relative to other values is then left out:
    // one message per key).
    bool has(const std::string& key) const {
        for (const JobIssue& i : issues)
            if (i.key == key) return true;
        return false;
    }
    void append(const std::vector<JobIssue>& more) {
        issues.insert(issues.end(), more.begin(), more.end());
    }

    void finite(const std::string& key, double v, const char* unit) {
        if (!std::isfinite(v))
            add(key, messageC("%s = %.6g %s is not a finite number", key.c_str(), v, unit));
    }
    // lo <= v <= hi (NaN fails).
    void range(const std::string& key, double v, double lo, double hi, const char* unit) {
        if (!(v >= lo && v <= hi))
            issues.push_back({key,
                              messageC("%s = %.6g %s is outside [%.6g, %.6g] %s", key.c_str(), v,
                                       unit, lo, hi, unit),
                              v, lo, hi, unit});
    }
    // A physical quantity that must be > 0: in [lo, hi] with a tiny lo > 0, which keeps values
    // such as 5e-324 (which pass "> 0") from dividing into infinities later. Zero or less is
    // told with the same range the field has ("must be > 0" read as if 0.01 were allowed
    // where the form allowed 0.1).
    void positive(const std::string& key, double v, double lo, double hi, const char* unit) {
        range(key, v, lo, hi, unit);
    }
};

} // namespace cutcell
