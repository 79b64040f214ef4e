#include "devices/process/safe_shutdown.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fcntl.h>
#include <mutex>
#include <thread>
#include <typeinfo>
#include <unistd.h>
#include <vector>

namespace cutcell {

struct SafeShutdownEntry {
    SafeShutdown::Action action;
    std::mutex running; // held while the action runs; the owner's unregistration waits on it
    bool dead = false;  // under running
    std::atomic<bool> done{false};
};

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
constexpr int kGraceSeconds = 3;

std::mutex& registryMutex() {
    static std::mutex m;
    return m;
}
std::vector<std::shared_ptr<SafeShutdownEntry>>& registry() {
    static std::vector<std::shared_ptr<SafeShutdownEntry>> r;
    return r;
}
std::mutex& callbackMutex() {
    static std::mutex m;
    return m;
}
std::function<void(int)>& onRequest() {
    static std::function<void(int)> f;
    return f;
}

int g_pipe[2] = {-1, -1};
std::atomic<int> g_requested{0};
std::atomic<bool> g_signalActionsRunning{false};
std::atomic<int> g_signalsSeen{0};
std::terminate_handler g_previousTerminate = nullptr;

void onSignal(int sig) {
    // Async-signal-safe only: a counter, write(2), _exit(2).
    const int saved = errno;
    if (g_signalsSeen.fetch_add(1) >= 1 && g_requested.load() != 0) _exit(128 + sig); // 2nd
    const unsigned char b = static_cast<unsigned char>(sig);
    [[maybe_unused]] const ssize_t n = ::write(g_pipe[1], &b, 1);
    errno = saved;
}

void watch() {
    for (;;) {
        unsigned char b = 0;
        const ssize_t n = ::read(g_pipe[0], &b, 1);
        if (n < 0 && errno == EINTR) continue;
        if (n != 1) return;
        const int sig = b;
        if (g_requested.load() != 0) _exit(128 + sig); // asked twice: end now
        bool any;
        {
            std::lock_guard lock(registryMutex());
            any = !registry().empty();
        }
        if (!any) _exit(128 + sig); // nothing to bring to a safe state: the default action
        g_signalActionsRunning.store(true);
        SafeShutdown::bringToSafeState(SafeShutdown::signalName(sig));
        g_requested.store(sig);
        g_signalActionsRunning.store(false);
        {
            std::lock_guard lock(callbackMutex());
            if (onRequest()) onRequest()(sig);
        }
        // The program ends its own way; if it does not, end it here (drives already safe).
        std::thread([sig] {
            std::this_thread::sleep_for(std::chrono::seconds(kGraceSeconds));
            std::fprintf(stderr, "cutcell: %s: the program did not end within %d s; exiting\n",
                         SafeShutdown::signalName(sig), kGraceSeconds);
            _exit(128 + sig);
        }).detach();
    }
}

void onTerminate() {
    std::string why = "std::terminate";
    if (std::exception_ptr e = std::current_exception()) {
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& x) {
            why += ": uncaught exception: " + std::string(x.what());
        } catch (...) {
            why += ": uncaught exception of an unknown type";
        }
    }
    SafeShutdown::bringToSafeState(why);
    std::abort();
}

} // namespace

SafeShutdown::Registration& SafeShutdown::Registration::operator=(Registration&& other) noexcept {
    if (this != &other) {
        reset();
        entry_ = std::move(other.entry_);
    }
    return *this;
}

SafeShutdown::Registration::~Registration() {
    reset();
}

void SafeShutdown::Registration::reset() {
    if (!entry_) return;
    {
        std::lock_guard lock(registryMutex());
        auto& r = registry();
        for (auto it = r.begin(); it != r.end(); ++it)
            if (*it == entry_) {
                r.erase(it);
                break;
            }
    }
    std::lock_guard lock(entry_->running); // wait for a running action
    entry_->dead = true;
    entry_.reset();
}

void SafeShutdown::install() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (::pipe2(g_pipe, O_CLOEXEC) != 0) {
            std::perror("cutcell: safe shutdown pipe");
            return;
        }
        std::thread(watch).detach();
        struct sigaction sa {};
        sa.sa_handler = onSignal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        for (int sig : kSignals)
            sigaction(sig, &sa, nullptr);
        g_previousTerminate = std::set_terminate(onTerminate);
    });
}

SafeShutdown::Registration SafeShutdown::add(Action action) {
    auto e = std::make_shared<SafeShutdownEntry>();
    e->action = std::move(action);
    std::lock_guard lock(registryMutex());
    registry().push_back(e);
    return Registration(e);
}

void SafeShutdown::bringToSafeState(const std::string& why) {
    std::vector<std::shared_ptr<SafeShutdownEntry>> entries;
    {
        // try_lock: std::terminate may come from a thread that holds it.
        std::unique_lock lock(registryMutex(), std::try_to_lock);
        for (int i = 0; i < 100 && !lock.owns_lock(); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            lock.try_lock();
        }
        if (!lock.owns_lock()) return;
        entries = registry();
    }
    // Latest registered first: the engine (torch, drives) before the bus it runs on.
    for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
        SafeShutdownEntry& e = **it;
        std::unique_lock lock(e.running, std::try_to_lock);
        if (!lock.owns_lock()) continue; // running on another thread right now
        if (e.dead || e.done.exchange(true)) continue;
        try {
            e.action(why);
        } catch (...) {
            // Nothing more can be done here; the other actions still run.
        }
    }
}

int SafeShutdown::requestedSignal() {
    return g_requested.load(std::memory_order_acquire);
}

int SafeShutdown::requestedSignalAfterActions(int timeout_ms) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    while (g_signalActionsRunning.load() && g_requested.load() == 0 &&
           std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return requestedSignal();
}

void SafeShutdown::setOnRequest(std::function<void(int signal)> callback) {
    std::lock_guard lock(callbackMutex());
    onRequest() = std::move(callback);
}

const char* SafeShutdown::signalName(int signal) {
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    case SIGHUP:
        return "SIGHUP";
    case SIGQUIT:
        return "SIGQUIT";
    default:
        return "signal";
    }
}

} // namespace cutcell
