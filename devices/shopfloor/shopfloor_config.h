#pragma once
// The shop-floor link's configuration: a JSON file of its own (not part of a job: a job moves
// between cells, the broker and the cell's identity do not), read strictly like the cut-chart
// file: unknown keys refused with a hint, every message names the key, the value, the unit and
// the limit. The link is off unless a file says "enabled": true. A password never sits in this
// file: password_file names a file whose first line is the password (readable by its owner).
//
// {
//   "format": "cutcell-shopfloor", "version": 1, "enabled": true,
//   "host": "broker.shop.lan", "port": 8883,
//   "group_id": "cutting", "edge_node_id": "cell-07",
//   "username": "cell-07", "password_file": "broker.password",
//   "tls": {"ca_file": "shop-ca.crt", "cert_file": "", "key_file": ""},
//   "axis_rate_hz": 10, "store_forward_capacity": 10000, "keepalive_s": 30
// }
// Relative file names are relative to the folder of the configuration file.
#include <stdexcept>
#include <string>

namespace cutcell::shopfloor {

inline constexpr const char* kShopfloorConfigFormat = "cutcell-shopfloor";
inline constexpr int kShopfloorConfigVersion = 1;

struct TlsFiles {
    std::string ca_file;   // the CA that signed the broker's certificate (required when enabled)
    std::string cert_file; // client certificate (optional; with key_file)
    std::string key_file;  // its private key, unencrypted (a passphrase prompt would hang)
};

struct ShopfloorConfig {
    bool enabled = false;
    std::string host;
    int port = 8883;
    std::string group_id;
    std::string edge_node_id;
    std::string username;      // empty: no user name (a client certificate may identify us)
    std::string password_file; // empty: no password
    TlsFiles tls;
    double axis_rate_hz = 10;           // [0.1, 10] Hz
    int store_forward_capacity = 10000; // [1, 100000] messages
    int keepalive_s = 30;               // [5, 3600] s

    // The folder relative file names are read from (set by loadShopfloorConfig, not written).
    std::string base_dir;
    // `file` as a path to open: absolute, or relative to base_dir.
    std::string resolve(const std::string& file) const;
};

struct ShopfloorConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws ShopfloorConfigError with the first problem.
ShopfloorConfig parseShopfloorConfig(const std::string& text);
ShopfloorConfig loadShopfloorConfig(const std::string& path);
// The same checks as the reader (a written file always reads back).
void checkShopfloorConfig(const ShopfloorConfig& c);
std::string writeShopfloorConfig(const ShopfloorConfig& c);
// Written atomically (a temporary beside it, then a rename).
void saveShopfloorConfig(const ShopfloorConfig& c, const std::string& path);

// The first line of the password file. Refused: a file others may read (chmod 600), an empty
// password.
std::string readPasswordFile(const std::string& path);

// Why `id` cannot be a Sparkplug group or edge node id ("" when it can): the specification
// forbids '+', '#' and '/' (MQTT wildcards and the level separator); CutCell also refuses an
// empty id, control characters and more than 128 bytes.
std::string sparkplugIdProblem(const std::string& id);

} // namespace cutcell::shopfloor
