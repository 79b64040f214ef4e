// Reading, checking and writing the shop-floor link's configuration file (shopfloor_config.h).
#include "devices/shopfloor/shopfloor_config.h"

#include "core/job/job_io.h"
#include "core/job/section_reader.h"
#include "core/json/json.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <vector>

namespace cutcell::shopfloor {
namespace {

[[noreturn]] void fail(const std::string& msg) {
    throw ShopfloorConfigError("shop-floor configuration: " + msg);
}

// One JSON object read strictly: each key read is remembered, and finish() refuses the others
// with the closest known key as a hint (a misspelt "hots" must not leave the host unset).
class Reader {
  public:
    Reader(const json::Value& v, std::string path, std::vector<std::string> keys)
        : v_(v), path_(std::move(path)), keys_(std::move(keys)) {
        if (!v_.isObject())
            fail((path_.empty() ? std::string("the file") : path_) +
                 " must be a JSON object, found " + v_.typeName());
    }
    std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
    const json::Value* get(const std::string& k) const { return v_.find(k); }

    std::string text(const std::string& k, const std::string& fallback) const {
        const json::Value* m = get(k);
        if (!m) return fallback;
        if (!m->isString()) fail(key(k) + " must be a string, found " + m->typeName());
        return m->asString();
    }
    bool boolean(const std::string& k, bool fallback) const {
        const json::Value* m = get(k);
        if (!m) return fallback;
        if (!m->isBool()) fail(key(k) + " must be true or false, found " + m->typeName());
        return m->asBool();
    }
    double number(const std::string& k, const char* unit, double fallback, double lo,
                  double hi) const {
        const json::Value* m = get(k);
        if (!m) return fallback;
        const std::string u = *unit ? std::string(" ") + unit : std::string();
        if (!m->isNumber())
            fail(key(k) + " must be a number" + (*unit ? " in" + u : "") + ", found " +
                 m->typeName());
        const double v = m->asNumber();
        if (!(v >= lo && v <= hi))
            fail(key(k) + " = " + num(v) + u + " is outside [" + num(lo) + ", " + num(hi) + "]" +
                 u);
        return v;
    }
    int integer(const std::string& k, const char* unit, int fallback, int lo, int hi) const {
        const double v = number(k, unit, fallback, lo, hi); // range first: 1e300 is no int
        if (v != std::floor(v))
            fail(key(k) + " = " + num(v) + (*unit ? std::string(" ") + unit : "") +
                 " is not a whole number");
        return static_cast<int>(v);
    }
    void finish() const {
        for (const auto& [k, unused] : v_.asObject()) {
            (void)unused;
            if (std::find(keys_.begin(), keys_.end(), k) != keys_.end()) continue;
            std::string hint, list;
            std::size_t best = 0;
            for (const std::string& known : keys_) {
                list += (list.empty() ? "" : ", ") + known;
                const std::size_t d = editDistance(lowerAscii(k), lowerAscii(known));
                if (d <= std::max<std::size_t>(2, known.size() / 3) && (hint.empty() || d < best)) {
                    hint = known;
                    best = d;
                }
            }
            fail("unknown key " + json::quote(key(k)) +
                 (hint.empty() ? "" : " (did you mean " + key(hint) + "?)") + "; the keys are " +
                 list);
        }
    }

  private:
    const json::Value& v_;
    std::string path_;
    std::vector<std::string> keys_;
};

void checkText(const std::string& key, const std::string& value, std::size_t max) {
    if (value.size() > max)
        fail(key + " = " + json::quote(value) + " is longer than " + std::to_string(max) +
             " bytes");
    if (std::any_of(value.begin(), value.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
        fail(key + " = " + json::quote(value) + " contains a control character");
}

} // namespace

std::string sparkplugIdProblem(const std::string& id) {
    if (id.empty()) return "is empty";
    if (id.size() > 128) return "is longer than 128 bytes";
    for (char c : id) {
        if (c == '+' || c == '#' || c == '/')
            return std::string("contains '") + c +
                   "' (Sparkplug ids must not contain '+', '#' or '/': they are MQTT topic "
                   "wildcards and the level separator)";
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            return "contains a control character";
    }
    return {};
}

std::string ShopfloorConfig::resolve(const std::string& file) const {
    if (file.empty() || file.front() == '/' || base_dir.empty()) return file;
    return (std::filesystem::path(base_dir) / file).string();
}

void checkShopfloorConfig(const ShopfloorConfig& c) {
    checkText("host", c.host, 253);
    if (c.host.find(' ') != std::string::npos)
        fail("host = " + json::quote(c.host) + " contains a space");
    if (c.port < 1 || c.port > 65535)
        fail("port = " + std::to_string(c.port) + " is outside [1, 65535]");
    for (const auto& [key, id] :
         {std::pair<const char*, const std::string&>{"group_id", c.group_id},
          {"edge_node_id", c.edge_node_id}}) {
        if (id.empty() && !c.enabled) continue;
        const std::string problem = sparkplugIdProblem(id);
        if (!problem.empty()) fail(std::string(key) + " = " + json::quote(id) + " " + problem);
    }
    checkText("username", c.username, 256);
    for (const auto& [key, file] :
         {std::pair<const char*, const std::string&>{"password_file", c.password_file},
          {"tls.ca_file", c.tls.ca_file},
          {"tls.cert_file", c.tls.cert_file},
          {"tls.key_file", c.tls.key_file}})
        checkText(key, file, 4096);
    if (c.tls.cert_file.empty() != c.tls.key_file.empty())
        fail("tls.cert_file and tls.key_file go together: give both (a client certificate) or "
             "neither");
    if (!c.password_file.empty() && c.username.empty())
        fail("password_file = " + json::quote(c.password_file) + " is given without a username");
    if (!(c.axis_rate_hz >= 0.1 && c.axis_rate_hz <= 10))
        fail("axis_rate_hz = " + num(c.axis_rate_hz) + " Hz is outside [0.1, 10] Hz");
    if (c.store_forward_capacity < 1 || c.store_forward_capacity > 100000)
        fail("store_forward_capacity = " + std::to_string(c.store_forward_capacity) +
             " messages is outside [1, 100000] messages");
    if (c.keepalive_s < 5 || c.keepalive_s > 3600)
        fail("keepalive_s = " + std::to_string(c.keepalive_s) + " s is outside [5, 3600] s");
    if (!c.enabled) return;
    // What an enabled link cannot do without.
    if (c.host.empty()) fail("host is missing (the broker's name or address)");
    if (c.tls.ca_file.empty())
        fail("tls.ca_file is missing: the link only talks TLS, and checks the broker's "
             "certificate against this CA");
}

ShopfloorConfig parseShopfloorConfig(const std::string& text) {
    json::Value doc;
    try {
        doc = json::parse(text);
    } catch (const json::ParseError& e) {
        fail(e.what());
    }
    const Reader r(doc, "",
                   {"format", "version", "enabled", "host", "port", "group_id", "edge_node_id",
                    "username", "password_file", "tls", "axis_rate_hz", "store_forward_capacity",
                    "keepalive_s"});
    const std::string format = r.text("format", "");
    if (format != kShopfloorConfigFormat)
        fail("format = " + json::quote(format) + " must be \"" + kShopfloorConfigFormat +
             "\" (is this a shop-floor configuration file?)");
    const json::Value* version = r.get("version");
    if (!version || !version->isNumber() || version->asNumber() != kShopfloorConfigVersion)
        fail("version = " +
             (version ? (version->isNumber() ? num(version->asNumber()) : version->typeName())
                      : std::string("(missing)")) +
             " is not one this CutCell reads (" + std::to_string(kShopfloorConfigVersion) + ")");
    r.finish();
    ShopfloorConfig c;
    c.enabled = r.boolean("enabled", false);
    c.host = r.text("host", "");
    c.port = r.integer("port", "", c.port, 1, 65535);
    c.group_id = r.text("group_id", "");
    c.edge_node_id = r.text("edge_node_id", "");
    c.username = r.text("username", "");
    c.password_file = r.text("password_file", "");
    if (const json::Value* tls = r.get("tls")) {
        const Reader t(*tls, "tls", {"ca_file", "cert_file", "key_file"});
        t.finish();
        c.tls.ca_file = t.text("ca_file", "");
        c.tls.cert_file = t.text("cert_file", "");
        c.tls.key_file = t.text("key_file", "");
    }
    c.axis_rate_hz = r.number("axis_rate_hz", "Hz", c.axis_rate_hz, 0.1, 10);
    c.store_forward_capacity =
        r.integer("store_forward_capacity", "messages", c.store_forward_capacity, 1, 100000);
    c.keepalive_s = r.integer("keepalive_s", "s", c.keepalive_s, 5, 3600);
    checkShopfloorConfig(c);
    return c;
}

ShopfloorConfig loadShopfloorConfig(const std::string& path) {
    std::string text;
    try {
        text = readTextFile(path);
    } catch (const JobError& e) {
        fail(e.what());
    }
    try {
        ShopfloorConfig c = parseShopfloorConfig(text);
        c.base_dir = std::filesystem::absolute(path).parent_path().string();
        return c;
    } catch (const ShopfloorConfigError& e) {
        throw ShopfloorConfigError(path + ": " + e.what());
    }
}

std::string writeShopfloorConfig(const ShopfloorConfig& c) {
    checkShopfloorConfig(c);
    json::Object tls{{"ca_file", c.tls.ca_file}};
    if (!c.tls.cert_file.empty()) {
        tls.emplace_back("cert_file", c.tls.cert_file);
        tls.emplace_back("key_file", c.tls.key_file);
    }
    json::Object o{{"format", kShopfloorConfigFormat},
                   {"version", kShopfloorConfigVersion},
                   {"enabled", c.enabled},
                   {"host", c.host},
                   {"port", c.port},
                   {"group_id", c.group_id},
                   {"edge_node_id", c.edge_node_id},
                   {"username", c.username},
                   {"password_file", c.password_file},
                   {"tls", std::move(tls)},
                   {"axis_rate_hz", c.axis_rate_hz},
                   {"store_forward_capacity", c.store_forward_capacity},
                   {"keepalive_s", c.keepalive_s}};
    return json::write(o, 2) + "\n";
}

void saveShopfloorConfig(const ShopfloorConfig& c, const std::string& path) {
    const std::string text = writeShopfloorConfig(c);
    try {
        writeFileAtomically(path, text);
    } catch (const JobError& e) {
        fail(e.what());
    }
}

std::string readPasswordFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) fail("password_file " + path + ": " + std::strerror(errno));
    // Like ssh with a private key: a secret others can read is no secret; say so rather than
    // send it.
    if (st.st_mode & S_IRWXO) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
        fail("password_file " + path + " may be read by other users (mode " + mode +
             "): chmod 600 it");
    }
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line))
        fail("password_file " + path + ": cannot read its first line");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) fail("password_file " + path + ": the first line (the password) is empty");
    return line;
}

} // namespace cutcell::shopfloor
