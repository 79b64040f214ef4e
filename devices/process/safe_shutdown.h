#pragma once
// Whatever ends the program - SIGINT, SIGTERM, SIGHUP, SIGQUIT, an uncaught exception,
// std::terminate, or the normal way out - first brings the machine to a safe state (torch off,
// drives disabled with the frames on the bus), then logs it. Plain C++ and POSIX, no Qt.
//
// How: the signal handler only writes the signal number to a pipe (async-signal-safe); a
// watcher thread reads it and runs the registered safe-state actions, logs, then sets
// requestedSignal() so the program's own loops end in order (and calls the on-request
// callback, e.g. to quit a Qt event loop). If the program has not ended 3 s later, or a second
// signal comes, the watcher ends the process (_exit(128 + signal)). std::terminate runs the
// same actions on the terminating thread, then aborts.
//
// Each action runs at most once; unregistering (the Registration's destructor) waits for a
// running action, so an action never outlives the objects it uses.
#include <functional>
#include <memory>
#include <string>

namespace cutcell {

class SafeShutdown {
  public:
    // Receives why the program ends ("SIGINT", "std::terminate: uncaught exception: ...").
    using Action = std::function<void(const std::string& why)>;

    class Registration {
      public:
        Registration() = default;
        explicit Registration(std::shared_ptr<struct SafeShutdownEntry> e) : entry_(std::move(e)) {}
        Registration(Registration&&) noexcept = default;
        Registration& operator=(Registration&& other) noexcept;
        ~Registration();
        void reset();

      private:
        std::shared_ptr<struct SafeShutdownEntry> entry_;
    };

    // Installs the signal handlers, the watcher thread and the terminate handler (once).
    static void install();
    // Registers an action that brings devices to a safe state and logs it.
    [[nodiscard]] static Registration add(Action action);
    // Runs every registered action that has not run yet, with `why`. Any thread.
    static void bringToSafeState(const std::string& why);
    // The signal that asked the program to end after its actions ran; 0 when none.
    static int requestedSignal();
    // requestedSignal(), but first waits (at most timeout_ms) while a signal's actions are
    // still running: a loop that ended because the machine stopped (the action's E-STOP) learns
    // that a signal stopped it, not that the run failed.
    static int requestedSignalAfterActions(int timeout_ms);
    // Called by the watcher after the actions ran (any thread: post to your event loop).
    static void setOnRequest(std::function<void(int signal)> callback);
    // "SIGINT", "SIGTERM", ... (async-signal-safe: static strings).
    static const char* signalName(int signal);
};

} // namespace cutcell
