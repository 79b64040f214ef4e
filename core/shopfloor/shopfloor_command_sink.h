#pragma once
// What the shop floor may ask of the cell, and nothing more. The shop-floor link turns the
// commands it accepts from the network (Sparkplug NCMDs) into these calls; the app implements
// them. There is deliberately no start, reset or emergency-stop release here: work queued from
// the network waits for the operator to start it, and a machine is never set moving or
// re-armed from outside the cell. A feed hold only ever stops motion, so it is always allowed.
#include <string>

namespace cutcell::shopfloor {

class ShopfloorCommandSink {
  public:
    virtual ~ShopfloorCommandSink() = default;

    // Queue a job given as the text of a job file. The app validates it exactly as a file the
    // operator opened by hand and returns the refusal's message (naming key, value, unit and
    // limit), or an empty string when the job was queued. `source` says who sent it (shown in
    // the queue panel beside the job).
    virtual std::string queueJob(const std::string& jobText, const std::string& source) = 0;
    // Request a feed hold of the running job (no effect when nothing runs).
    virtual void feedHold() = 0;
    // Remove the jobs waiting in the queue (never the one running).
    virtual void clearQueue() = 0;
};

// The calls come on the link's network thread, one at a time: an implementation hands them to
// its own thread (the GUI's event loop) and must not block for long (a job's validation is
// fine, waiting for the operator is not).

} // namespace cutcell::shopfloor
