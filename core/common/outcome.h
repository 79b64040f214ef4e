#pragma once
// How a request to core went, in one shape for every machine module's query (CAN support, a
// cut variant, the offline report, the kinematics): Ok, or why not - the job key it is about
// ("" when none) and one sentence for the operator that names the value, the unit and the
// limit. A job's validation lists every problem (JobIssue: key and message) and a plan says its
// own status (MachinePlan); exceptions stay for a file or a configuration that cannot be read
// at all.
#include <cstdint>
#include <string>
#include <utility>

namespace cutcell {

enum class OutcomeStatus : std::uint8_t {
    Ok,
    Refused,    // not done: the machine has no such thing, or the job cannot give it
    Incomplete, // done, but not all of it (a simulated run that stopped early): the message says
                // why
    Cancelled,  // stopped on the caller's request (a plan cancelled through PlanOptions::cancel)
};

struct Outcome {
    OutcomeStatus status = OutcomeStatus::Ok;
    std::string key;     // the job key the message is about ("" for none)
    std::string message; // empty when Ok

    bool ok() const { return status == OutcomeStatus::Ok; }
    bool refused() const { return status == OutcomeStatus::Refused; }
    bool cancelled() const { return status == OutcomeStatus::Cancelled; }
    static Outcome done() { return {}; }
    static Outcome refuse(std::string message, std::string key = {}) {
        return {OutcomeStatus::Refused, std::move(key), std::move(message)};
    }
    static Outcome incomplete(std::string message, std::string key = {}) {
        return {OutcomeStatus::Incomplete, std::move(key), std::move(message)};
    }
    static Outcome cancel() { return {OutcomeStatus::Cancelled, {}, {}}; }
};

} // namespace cutcell
