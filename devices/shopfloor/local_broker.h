#pragma once
// A Mosquitto broker (Debian `mosquitto`) on a loopback port, with TLS and a password file made
// for it in a fresh folder: a CA, the broker's certificate for 127.0.0.1 and localhost signed by
// it, a second CA that signed nothing of the broker's (an untrusted one), and a password file
// (mosquitto_passwd) with the users asked for, each also in <name>.pw (chmod 600) for a
// ShopfloorConfig's password_file. For the shop-floor tests and `cutcell-cli bench-shopfloor`:
// CutCell never runs a broker for a shop (a shop runs its own, see README.md).
//
// The broker keeps persistent sessions (saved every second and on a clean stop), queues QoS 0
// messages for them, and publishes its $SYS figures every `sys_interval_s`.
#include "devices/shopfloor/shopfloor_config.h"

#include <string>
#include <sys/types.h>
#include <vector>

namespace cutcell::shopfloor {

struct BrokerUser {
    std::string name, password;
};

class LocalBroker {
  public:
    LocalBroker() = default;
    ~LocalBroker(); // the broker killed; the folder removed unless keepFolder()
    LocalBroker(const LocalBroker&) = delete;
    LocalBroker& operator=(const LocalBroker&) = delete;

    // Makes the folder, the certificates, the password file and the configuration, then starts
    // the broker and waits until its port accepts. "" when it runs, else why not (a program
    // missing: which one and the package; a step failed: the folder's setup.log).
    std::string start(const std::vector<BrokerUser>& users, int sys_interval_s = 10);
    // start() and restart() tie the broker's life to the calling thread (PR_SET_PDEATHSIG: a
    // crashed program leaves no broker behind): that thread must outlive the broker.
    // The same broker again (same port, folder and saved sessions). false if it did not come up.
    bool restart();
    // SIGTERM (a clean stop: sessions saved, wills published) or SIGKILL (gone at once).
    void stop(bool clean = true);
    bool running() const { return pid_ > 0; }

    int port() const { return port_; }
    const std::string& folder() const { return dir_; }
    pid_t pid() const { return pid_; }
    // CPU time the broker process used (user + system), s; 0 when it is not running.
    double cpuSeconds() const;
    void keepFolder() { keep_ = true; }

    // A cell's configuration for this broker: TLS with the broker's CA, user `user` and its
    // password file.
    ShopfloorConfig cellConfig(const std::string& group, const std::string& edge,
                               const std::string& user) const;

  private:
    bool run(const std::string& command) const;
    bool launch();

    std::string mosquitto_, dir_;
    int port_ = 0;
    pid_t pid_ = -1;
    bool keep_ = false;
};

// The path of an executable (PATH, then /usr/sbin and /usr/local/sbin, where Debian puts
// mosquitto), or "" when there is none. `env`: a variable that overrides the search.
std::string findProgram(const std::string& name, const char* env = nullptr);

} // namespace cutcell::shopfloor
