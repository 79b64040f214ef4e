#pragma once
// Collects JobIssues; every message names the key, the value with its unit and the limit.
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
    void append(const std::vector<JobIssue>& more) {
        issues.insert(issues.end(), more.begin(), more.end());
    }

    void finite(const std::string& key, double v, const char* unit) {
        if (!std::isfinite(v))
            add(key, key + " = " + num(v) + " " + unit + " is not a finite number");
    }
    // lo <= v <= hi (NaN fails).
    void range(const std::string& key, double v, double lo, double hi, const char* unit) {
        if (!(v >= lo && v <= hi))
            add(key, key + " = " + num(v) + " " + unit + " is outside [" + num(lo) + ", " +
                         num(hi) + "] " + unit);
    }
    // A physical quantity that must be > 0: in (tiny, hi]. The lower bound keeps values such as
    // 5e-324 (which pass "> 0") from dividing into infinities later.
    void positive(const std::string& key, double v, double lo, double hi, const char* unit) {
        if (!(v > 0)) {
            add(key, key + " = " + num(v) + " " + unit + " must be > 0 " + unit);
            return;
        }
        range(key, v, lo, hi, unit);
    }
};

} // namespace cutcell
