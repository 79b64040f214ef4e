#pragma once
// How a request to core went, in one shape for the whole core layer: Ok, or why not - the job
// key it is about ("" when none) and one sentence for the operator that names the value, the
// unit and the limit. It answers a machine module's queries (CAN support, a cut variant, the
// offline report, the kinematics), a plan (MachinePlan::outcome: Ok, Refused when the machine
// cannot make the cut, Cancelled), each problem of a job's validation (JobIssue is an Outcome,
// always Refused, with the range of a value outside it) and core's helpers that say why they
// could not (quick-return buildSetup, the kinematics' argument checks). Exceptions stay for a
// file or a configuration that cannot be read at all (JobError, JobFileError) and for
// programming errors.
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
