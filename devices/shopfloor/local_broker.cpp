#include "devices/shopfloor/local_broker.h"

#include "devices/net/loopback_port.h"

#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <netinet/in.h>
#include <pthread.h>
#include <pwd.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace cutcell::shopfloor {
namespace {

bool portAccepts(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
    ::close(fd);
    return ok;
}

// vfork, except under a sanitizer: its runtime's interceptors (signal, open) would run in the
// child on the parent's memory; a sanitised build measures no jitter anyway.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CUTCELL_CHILD_BY_FORK 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define CUTCELL_CHILD_BY_FORK 1
#endif
#endif

} // namespace

std::string findProgram(const std::string& name, const char* env) {
    if (const char* e = env ? std::getenv(env) : nullptr; e && *e)
        return ::access(e, X_OK) == 0 ? e : "";
    std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    path += ":/usr/sbin:/usr/local/sbin";
    for (std::size_t at = 0; at <= path.size();) {
        const std::size_t end = std::min(path.find(':', at), path.size());
        const std::string candidate = path.substr(at, end - at) + "/" + name;
        if (end > at && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        at = end + 1;
    }
    return "";
}

LocalBroker::~LocalBroker() {
    stop(false);
    if (!dir_.empty() && !keep_) {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
}

bool LocalBroker::run(const std::string& command) const {
    return std::system(("cd '" + dir_ + "' && (" + command + ") >>setup.log 2>&1").c_str()) == 0;
}

std::string LocalBroker::start(const std::vector<BrokerUser>& users, int sys_interval_s) {
    mosquitto_ = findProgram("mosquitto", "CUTCELL_MOSQUITTO");
    const std::string openssl = findProgram("openssl"), pwtool = findProgram("mosquitto_passwd");
    if (mosquitto_.empty() || pwtool.empty())
        return "needs mosquitto and mosquitto_passwd (apt-get install mosquitto)";
    if (openssl.empty()) return "needs openssl (apt-get install openssl)";
    char tmpl[] = "/tmp/cutcell-broker-XXXXXX";
    if (!::mkdtemp(tmpl)) return "cannot make a folder in /tmp";
    dir_ = tmpl;
    port_ = net::freeLoopbackPort();
    if (port_ == 0) return "no loopback port to listen on";
    const std::string ec = " -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes";
    bool made =
        run(openssl + " req -x509" + ec +
            " -keyout ca.key -out ca.crt -days 2 -subj '/CN=Test CA'") &&
        run(openssl + " req" + ec + " -keyout server.key -out server.csr -subj '/CN=localhost'") &&
        run("printf 'subjectAltName=IP:127.0.0.1,DNS:localhost\\n' > san.cnf") &&
        run(openssl + " x509 -req -in server.csr -CA ca.crt -CAkey ca.key -CAcreateserial"
                      " -out server.crt -days 2 -extfile san.cnf") &&
        run(openssl + " req -x509" + ec +
            " -keyout other.key -out other.crt -days 2 -subj '/CN=Other CA'") &&
        run("touch passwd");
    for (const BrokerUser& u : users)
        made = made && run(pwtool + " -b passwd '" + u.name + "' '" + u.password + "'") &&
               run("printf '%s\\n' '" + u.password + "' > '" + u.name + ".pw' && chmod 600 '" +
                   u.name + ".pw'");
    if (!made) return "the broker's set-up failed (see " + dir_ + "/setup.log)";
    const passwd* me = ::getpwuid(::geteuid());
    std::ofstream(dir_ + "/mosquitto.conf")
        << "listener " << port_ << " 127.0.0.1\n"
        << "cafile " << dir_ << "/ca.crt\ncertfile " << dir_ << "/server.crt\nkeyfile " << dir_
        << "/server.key\nallow_anonymous false\npassword_file " << dir_ << "/passwd\n"
        << "persistence true\npersistence_location " << dir_ << "/\nautosave_interval 1\n"
        << "queue_qos0_messages true\nmax_queued_messages 100000\n"
        << "sys_interval " << sys_interval_s << "\n"
        << "log_dest file " << dir_ << "/mosquitto.log\n"
        << "user " << (me ? me->pw_name : "root") << "\n";
    if (!launch()) return "the broker did not start (see " + dir_ + "/mosquitto.log)";
    return {};
}

bool LocalBroker::launch() {
    // vfork, not fork: a fork copies the page tables and leaves every page of this process
    // copy-on-write, so a real-time engine thread beside it takes a page fault on each page it
    // writes next (measured: 100 ms of jitter when the bench restarted its broker mid-run).
    // The child only makes system calls on prepared data before exec.
    const std::string out = dir_ + "/mosquitto.out", conf = dir_ + "/mosquitto.conf";
    const char* argv[] = {mosquitto_.c_str(), "-c", conf.c_str(), nullptr};
    // No signal handler of this program may run in the child (it shares our memory until exec):
    // every signal blocked across vfork, the child resets the handlers before it unblocks them.
    sigset_t all, before;
    ::sigfillset(&all);
    ::pthread_sigmask(SIG_SETMASK, &all, &before);
    const pid_t parent = ::getpid();
#ifdef CUTCELL_CHILD_BY_FORK
    pid_ = ::fork();
#else
    pid_ = ::vfork(); // here, not in a helper: a vfork child must not return from a function
#endif
    if (pid_ == 0) {
        for (int sig = 1; sig < NSIG; ++sig)
            ::signal(sig, SIG_DFL); // the child's own table (vfork shares memory, not handlers)
        ::sigprocmask(SIG_SETMASK, &before, nullptr);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);      // never outlive the thread that started it
        if (::getppid() != parent) ::_exit(127); // that thread died before the line above
        const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
        if (fd >= 0) {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
        }
        ::close_range(3, ~0U, 0); // our sockets and files are not the broker's
        ::execv(argv[0], const_cast<char* const*>(argv));
        ::_exit(127);
    }
    ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
    if (pid_ < 0) return false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!portAccepts(port_)) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) { // it ended (and is reaped): no kill
            pid_ = -1;
            return false;
        }
        if (std::chrono::steady_clock::now() > until) {
            stop(false);
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

bool LocalBroker::restart() {
    int status = 0;
    if (pid_ > 0 && ::waitpid(pid_, &status, WNOHANG) == pid_) pid_ = -1; // it died on its own
    if (running()) return true;
    return launch();
}

void LocalBroker::stop(bool clean) {
    if (pid_ <= 0) return;
    // Mosquitto 2.0.11 sets its run flag after it installs its SIGTERM handler and opens its
    // port: a SIGTERM in between is lost (measured: a broker stopped right after start() ran on
    // and the stop waited for ever). So the SIGTERM is sent again until the broker ends, and a
    // broker that has not ended after 10 s is killed.
    const auto began = std::chrono::steady_clock::now();
    auto last_signal = began;
    ::kill(pid_, clean ? SIGTERM : SIGKILL);
    int status = 0;
    for (;;) {
        const pid_t ended = ::waitpid(pid_, &status, WNOHANG);
        if (ended == pid_ || (ended < 0 && errno != EINTR)) break; // gone (or reaped elsewhere)
        const auto now = std::chrono::steady_clock::now();
        if (now - began > std::chrono::seconds(10)) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, &status, 0);
            break;
        }
        if (now - last_signal > std::chrono::milliseconds(500)) {
            ::kill(pid_, clean ? SIGTERM : SIGKILL);
            last_signal = now;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    pid_ = -1;
}

double LocalBroker::cpuSeconds() const {
    if (pid_ <= 0) return 0;
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    const std::string all((std::istreambuf_iterator<char>(in)), {});
    const std::size_t paren = all.rfind(')');
    if (paren == std::string::npos) return 0;
    std::istringstream rest(all.substr(paren + 2));
    std::string field;
    double ticks = 0;
    for (int i = 3; i <= 15 && rest >> field; ++i)
        if (i == 14 || i == 15) ticks += std::stod(field); // utime, stime
    return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

ShopfloorConfig LocalBroker::cellConfig(const std::string& group, const std::string& edge,
                                        const std::string& user) const {
    ShopfloorConfig c;
    c.enabled = true;
    c.host = "127.0.0.1";
    c.port = port_;
    c.group_id = group;
    c.edge_node_id = edge;
    c.username = user;
    c.password_file = user + ".pw";
    c.tls.ca_file = "ca.crt";
    c.base_dir = dir_;
    return c;
}

} // namespace cutcell::shopfloor
