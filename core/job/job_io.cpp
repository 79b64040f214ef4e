#include "core/job/job_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace cutcell {
namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// Reads members of one JSON object, tracking the dotted path for messages.
class Reader {
  public:
    Reader(const json::Value& v, std::string path) : v_(v), path_(std::move(path)) {
        if (!v_.isObject())
            throw JobError(label() + " must be a JSON object, found " + v_.typeName());
    }

    std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }

    const json::Value* get(const std::string& k) const { return v_.find(k); }

    double number(const std::string& k, const char* unit) const {
        const json::Value* m = v_.find(k);
        if (!m) throw JobError("missing required key " + key(k) + " (a number in " + unit + ")");
        return asNumber(*m, k, unit);
    }
    double number(const std::string& k, const char* unit, double fallback) const {
        const json::Value* m = v_.find(k);
        return m ? asNumber(*m, k, unit) : fallback;
    }
    std::string string(const std::string& k, const std::string& fallback) const {
        const json::Value* m = v_.find(k);
        if (!m) return fallback;
        if (!m->isString()) throw JobError(key(k) + " must be a string, found " + m->typeName());
        return m->asString();
    }
    bool boolean(const std::string& k, bool fallback) const {
        const json::Value* m = v_.find(k);
        if (!m) return fallback;
        if (!m->isBool()) throw JobError(key(k) + " must be true or false, found " + m->typeName());
        return m->asBool();
    }
    Reader child(const std::string& k) const {
        const json::Value* m = v_.find(k);
        if (!m) throw JobError("missing required section " + key(k));
        return Reader(*m, key(k));
    }
    bool has(const std::string& k) const { return v_.find(k) != nullptr; }

    template <typename E>
    E choice(const std::string& k, std::initializer_list<std::pair<const char*, E>> options,
             E fallback) const {
        const json::Value* m = v_.find(k);
        if (!m) return fallback;
        std::string allowed;
        for (const auto& [name, value] : options) {
            if (m->isString() && m->asString() == name) return value;
            allowed += allowed.empty() ? "" : ", ";
            allowed += std::string("\"") + name + "\"";
        }
        const std::string found = m->isString() ? "\"" + m->asString() + "\"" : m->typeName();
        throw JobError(key(k) + " = " + found + " is not one of " + allowed);
    }

    const json::Value& value() const { return v_; }

  private:
    std::string label() const { return path_.empty() ? "the job" : path_; }
    double asNumber(const json::Value& m, const std::string& k, const char* unit) const {
        if (!m.isNumber())
            throw JobError(key(k) + " must be a number in " + unit + ", found " + m.typeName());
        return m.asNumber();
    }
    const json::Value& v_;
    std::string path_;
};

PipeSpec readPipe(const Reader& r, double defaultLength) {
    PipeSpec p;
    p.radius_mm = r.number("radius_mm", "mm");
    p.wall_mm = r.number("wall_mm", "mm");
    p.length_mm = r.number("length_mm", "mm", defaultLength);
    return p;
}

template <typename T, typename F>
void readTable(const Reader& parent, const std::string& k, std::array<T, kAxisCount>& out,
               F readRow) {
    const json::Value* m = parent.get(k);
    if (!m) return;
    if (!m->isArray())
        throw JobError(parent.key(k) + " must be an array of " + std::to_string(kAxisCount) +
                       " rows (axis 0 = chuck, 1..5 = arm), found " + m->typeName());
    const auto& arr = m->asArray();
    if (arr.size() != kAxisCount)
        throw JobError(parent.key(k) + " has " + std::to_string(arr.size()) + " rows; it needs " +
                       std::to_string(kAxisCount) + " (axis 0 = chuck, 1..5 = arm)");
    for (size_t i = 0; i < arr.size(); ++i)
        out[i] = readRow(Reader(arr[i], parent.key(k) + "[" + std::to_string(i) + "]"));
}

std::vector<OtherBranch> readOtherBranches(const Reader& r) {
    std::vector<OtherBranch> out;
    const json::Value* m = r.get("other_branches");
    if (!m) return out;
    if (!m->isArray())
        throw JobError("other_branches must be an array of branch pipes, found " + m->typeName());
    for (size_t i = 0; i < m->asArray().size(); ++i) {
        const Reader b(m->asArray()[i], "other_branches[" + std::to_string(i) + "]");
        OtherBranch o;
        o.radius_mm = b.number("radius_mm", "mm");
        o.angle_deg = b.number("angle_deg", "deg");
        o.eccentricity_mm = b.number("eccentricity_mm", "mm", 0);
        o.position_mm = b.number("position_mm", "mm", 0);
        o.phase_deg = b.number("phase_deg", "deg", 0);
        out.push_back(o);
    }
    return out;
}

ProfileCutterSpec readProfileCutter(const Reader& r) {
    ProfileCutterSpec p;
    if (!r.has("profile_cutter")) return p;
    const Reader c = r.child("profile_cutter");
    auto integer = [&c](const std::string& k, const char* unit, int fallback) {
        const double v = c.number(k, unit, fallback);
        if (v != std::floor(v) || std::fabs(v) > 1e9)
            throw JobError(c.key(k) + " = " + num(v) + " " + unit + " must be a whole number");
        return static_cast<int>(v);
    };
    p.steps_per_rev_a = integer("steps_per_rev_a", "steps/rev", p.steps_per_rev_a);
    p.pulses_per_step_a = integer("pulses_per_step_a", "pulses/step", p.pulses_per_step_a);
    p.mm_per_pulse_x = c.number("mm_per_pulse_x", "mm/pulse", p.mm_per_pulse_x);
    p.max_pulse_rate_hz = c.number("max_pulse_rate_hz", "Hz", p.max_pulse_rate_hz);
    p.pierce_s = c.number("pierce_s", "s", p.pierce_s);
    p.x_travel_mm = c.number("x_travel_mm", "mm", p.x_travel_mm);
    p.branch_position_auto = !c.has("branch_position_mm");
    p.branch_position_mm = c.number("branch_position_mm", "mm", 0);
    return p;
}

bool isDefault(const ProfileCutterSpec& p) {
    const ProfileCutterSpec d;
    return p.steps_per_rev_a == d.steps_per_rev_a && p.pulses_per_step_a == d.pulses_per_step_a &&
           p.mm_per_pulse_x == d.mm_per_pulse_x && p.max_pulse_rate_hz == d.max_pulse_rate_hz &&
           p.pierce_s == d.pierce_s && p.x_travel_mm == d.x_travel_mm &&
           p.branch_position_auto == d.branch_position_auto;
}

json::Value pipeJson(const PipeSpec& p) {
    return json::Object{
        {"radius_mm", p.radius_mm}, {"wall_mm", p.wall_mm}, {"length_mm", p.length_mm}};
}

} // namespace

Job jobFromJson(const json::Value& doc) {
    Reader r(doc, "");
    Job job;
    const double schema = r.number("schema", "(version number)");
    if (schema != 1)
        throw JobError("schema = " + num(schema) +
                       " is not supported; this CutCell reads schema 1");
    job.machine = r.string("machine", job.machine);
    job.name = r.string("name", "");
    job.description = r.string("description", "");
    job.main_pipe = readPipe(r.child("main_pipe"), 1000);
    job.branch_pipe = readPipe(r.child("branch_pipe"), 300);
    job.angle_deg = r.number("angle_deg", "deg");
    job.eccentricity_mm = r.number("eccentricity_mm", "mm", 0);
    job.method = r.choice<CutMethod>(
        "method",
        {{"static_pipe", CutMethod::StaticPipe}, {"rotating_pipe", CutMethod::RotatingPipe}},
        CutMethod::RotatingPipe);

    const Reader cut = r.child("cut");
    job.cut.target = cut.choice<CutTarget>(
        "target", {{"branch", CutTarget::Branch}, {"main", CutTarget::Main}}, CutTarget::Main);
    job.cut.bevel_deg = cut.number("bevel_deg", "deg", 0);
    job.cut.speed_mm_s = cut.number("speed_mm_s", "mm/s");
    job.cut.ramp_s = cut.number("ramp_s", "s", job.cut.ramp_s);
    job.cut.max_direction_deviation_deg =
        cut.number("max_direction_deviation_deg", "deg", job.cut.max_direction_deviation_deg);
    job.cut.knot_spacing_mm = cut.number("knot_spacing_mm", "mm", job.cut.knot_spacing_mm);
    job.cut.static_chuck_deg = cut.number("static_chuck_deg", "deg", job.cut.static_chuck_deg);
    job.cut.start_phi_auto = !cut.has("start_phi_deg");
    job.cut.start_phi_deg = cut.number("start_phi_deg", "deg", 0);

    job.dh = seedDhTable();
    if (r.has("robot")) {
        const Reader robot = r.child("robot");
        readTable(robot, "dh", job.dh, [](const Reader& row) {
            DhRow d;
            d.alpha_deg = row.number("alpha_deg", "deg");
            d.a_mm = row.number("a_mm", "mm");
            d.d_mm = row.number("d_mm", "mm");
            d.theta_offset_deg = row.number("theta_offset_deg", "deg", 0);
            d.min_deg = row.number("min_deg", "deg");
            d.max_deg = row.number("max_deg", "deg");
            return d;
        });
    }
    readTable(r, "controller", job.controller, [](const Reader& row) {
        PidGains g;
        g.kp = row.number("kp_nm_per_rad", "N m/rad");
        g.ki = row.number("ki_nm_per_rad_s", "N m/(rad s)");
        g.kd = row.number("kd_nm_s_per_rad", "N m s/rad");
        g.tau_f = row.number("tau_f_s", "s");
        return g;
    });
    if (!r.has("controller")) throw JobError("missing required key controller (6 PID rows)");
    readTable(r, "plant", job.plant, [](const Reader& row) {
        JointPlantParams p;
        p.inertia_kg_m2 = row.number("inertia_kg_m2", "kg m^2");
        p.viscous_nm_s_per_rad = row.number("viscous_nm_s_per_rad", "N m s/rad");
        p.torque_limit_nm = row.number("torque_limit_nm", "N m");
        return p;
    });
    if (!r.has("plant")) throw JobError("missing required key plant (6 joint model rows)");

    const Reader sim = r.child("sim");
    job.sim.period_s = sim.number("period_s", "s");
    job.sim.duration_s = sim.number("duration_s", "s");

    if (r.has("engine")) {
        const Reader e = r.child("engine");
        job.engine.estop_category = e.choice<StopCategory>(
            "estop_category", {{"cat0", StopCategory::Cat0}, {"cat1", StopCategory::Cat1}},
            job.engine.estop_category);
        job.engine.feed_hold_decel_s =
            e.number("feed_hold_decel_s", "s", job.engine.feed_hold_decel_s);
        job.engine.torch_on_during_feed_hold =
            e.boolean("torch_on_during_feed_hold", job.engine.torch_on_during_feed_hold);
        job.engine.following_error_limit_deg =
            e.number("following_error_limit_deg", "deg", job.engine.following_error_limit_deg);
        job.engine.home_speed_deg_s =
            e.number("home_speed_deg_s", "deg/s", job.engine.home_speed_deg_s);
        job.engine.runs_dir = e.string("runs_dir", job.engine.runs_dir);
    }
    if (r.has("devices")) {
        const Reader d = r.child("devices");
        job.devices.kind = d.choice<DeviceKind>(
            "kind", {{"simulated", DeviceKind::Simulated}, {"canopen", DeviceKind::CanOpen}},
            job.devices.kind);
        job.devices.can_plugin = d.string("can_plugin", job.devices.can_plugin);
        job.devices.can_interface = d.string("can_interface", job.devices.can_interface);
        job.devices.bitrate_bps =
            static_cast<int>(d.number("bitrate_bps", "bit/s", job.devices.bitrate_bps));
        job.devices.heartbeat_timeout_ms =
            d.number("heartbeat_timeout_ms", "ms", job.devices.heartbeat_timeout_ms);
        if (const json::Value* ids = d.get("node_ids")) {
            if (!ids->isArray() || ids->asArray().size() != kAxisCount)
                throw JobError(d.key("node_ids") + " must be an array of 6 node ids (1..127)");
            for (int i = 0; i < kAxisCount; ++i) {
                const auto& v = ids->asArray()[static_cast<size_t>(i)];
                if (!v.isNumber()) throw JobError(d.key("node_ids") + " must hold numbers");
                job.devices.node_ids[static_cast<size_t>(i)] = static_cast<int>(v.asNumber());
            }
        }
        if (const json::Value* cpu = d.get("counts_per_unit")) {
            if (!cpu->isArray() || cpu->asArray().size() != kAxisCount)
                throw JobError(d.key("counts_per_unit") +
                               " must be an array of 6 numbers (counts/deg)");
            for (int i = 0; i < kAxisCount; ++i) {
                const auto& v = cpu->asArray()[static_cast<size_t>(i)];
                if (!v.isNumber()) throw JobError(d.key("counts_per_unit") + " must hold numbers");
                job.devices.counts_per_unit[static_cast<size_t>(i)] = v.asNumber();
            }
        }
    }
    job.other_branches = readOtherBranches(r);
    job.profile_cutter = readProfileCutter(r);
    return job;
}

json::Value jobToJson(const Job& job) {
    json::Object cut{{"target", toString(job.cut.target)},
                     {"bevel_deg", job.cut.bevel_deg},
                     {"speed_mm_s", job.cut.speed_mm_s},
                     {"ramp_s", job.cut.ramp_s},
                     {"max_direction_deviation_deg", job.cut.max_direction_deviation_deg},
                     {"knot_spacing_mm", job.cut.knot_spacing_mm},
                     {"static_chuck_deg", job.cut.static_chuck_deg}};
    if (!job.cut.start_phi_auto) cut.emplace_back("start_phi_deg", job.cut.start_phi_deg);
    json::Array dh, ctrl, plant, ids, cpu;
    for (const auto& d : job.dh)
        dh.emplace_back(json::Object{{"alpha_deg", d.alpha_deg},
                                     {"a_mm", d.a_mm},
                                     {"d_mm", d.d_mm},
                                     {"theta_offset_deg", d.theta_offset_deg},
                                     {"min_deg", d.min_deg},
                                     {"max_deg", d.max_deg}});
    for (const auto& g : job.controller)
        ctrl.emplace_back(json::Object{{"kp_nm_per_rad", g.kp},
                                       {"ki_nm_per_rad_s", g.ki},
                                       {"kd_nm_s_per_rad", g.kd},
                                       {"tau_f_s", g.tau_f}});
    for (const auto& p : job.plant)
        plant.emplace_back(json::Object{{"inertia_kg_m2", p.inertia_kg_m2},
                                        {"viscous_nm_s_per_rad", p.viscous_nm_s_per_rad},
                                        {"torque_limit_nm", p.torque_limit_nm}});
    for (int id : job.devices.node_ids)
        ids.emplace_back(id);
    for (double c : job.devices.counts_per_unit)
        cpu.emplace_back(c);
    json::Object doc{
        {"schema", job.schema},
        {"machine", job.machine},
        {"name", job.name},
        {"description", job.description},
        {"main_pipe", pipeJson(job.main_pipe)},
        {"branch_pipe", pipeJson(job.branch_pipe)},
        {"angle_deg", job.angle_deg},
        {"eccentricity_mm", job.eccentricity_mm},
        {"method", toString(job.method)},
        {"cut", cut},
        {"robot", json::Object{{"dh", dh}}},
        {"controller", ctrl},
        {"plant", plant},
        {"sim", json::Object{{"period_s", job.sim.period_s}, {"duration_s", job.sim.duration_s}}},
        {"engine", json::Object{{"estop_category", toString(job.engine.estop_category)},
                                {"feed_hold_decel_s", job.engine.feed_hold_decel_s},
                                {"torch_on_during_feed_hold", job.engine.torch_on_during_feed_hold},
                                {"following_error_limit_deg", job.engine.following_error_limit_deg},
                                {"home_speed_deg_s", job.engine.home_speed_deg_s},
                                {"runs_dir", job.engine.runs_dir}}},
        {"devices", json::Object{{"kind", toString(job.devices.kind)},
                                 {"can_plugin", job.devices.can_plugin},
                                 {"can_interface", job.devices.can_interface},
                                 {"bitrate_bps", job.devices.bitrate_bps},
                                 {"node_ids", ids},
                                 {"counts_per_unit", cpu},
                                 {"heartbeat_timeout_ms", job.devices.heartbeat_timeout_ms}}},
    };
    // Profile-cutter keys are written when used, so robot job files keep their shape.
    if (!job.other_branches.empty()) {
        json::Array others;
        for (const auto& o : job.other_branches)
            others.emplace_back(json::Object{{"radius_mm", o.radius_mm},
                                             {"angle_deg", o.angle_deg},
                                             {"eccentricity_mm", o.eccentricity_mm},
                                             {"position_mm", o.position_mm},
                                             {"phase_deg", o.phase_deg}});
        doc.emplace_back("other_branches", others);
    }
    const ProfileCutterSpec& pc = job.profile_cutter;
    if (job.machine == "profile_cutter_2axis" || !isDefault(pc)) {
        json::Object o{{"steps_per_rev_a", pc.steps_per_rev_a},
                       {"pulses_per_step_a", pc.pulses_per_step_a},
                       {"mm_per_pulse_x", pc.mm_per_pulse_x},
                       {"max_pulse_rate_hz", pc.max_pulse_rate_hz},
                       {"pierce_s", pc.pierce_s},
                       {"x_travel_mm", pc.x_travel_mm}};
        if (!pc.branch_position_auto) o.emplace_back("branch_position_mm", pc.branch_position_mm);
        doc.emplace_back("profile_cutter", o);
    }
    return doc;
}

Job parseJob(const std::string& text) {
    json::Value doc;
    try {
        doc = json::parse(text);
    } catch (const json::ParseError& e) {
        throw JobError(std::string("the job file is not valid JSON: ") + e.what());
    }
    Job job = jobFromJson(doc);
    const auto issues = validateJob(job);
    if (!issues.empty()) {
        std::string msg = issues.front().message;
        if (issues.size() > 1)
            msg += " (and " + std::to_string(issues.size() - 1) + " more problem" +
                   (issues.size() > 2 ? "s" : "") + ")";
        throw JobError(msg);
    }
    return job;
}

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw JobError("cannot open " + path + ": " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Job loadJobFile(const std::string& path) {
    const std::string text = readTextFile(path);
    try {
        return parseJob(text);
    } catch (const JobError& e) {
        throw JobError(path + ": " + e.what());
    }
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // A writer killed between mkstemp and rename leaves ".<name>.XXXXXX" behind. Remove such
    // files older than a minute (no writer takes that long), and only where <name> is this
    // target or a file beside it, so an unrelated hidden file (".bashrc.backup") is never hit.
    {
        std::error_code ec;
        const auto stale = fs::file_time_type::clock::now() - std::chrono::minutes(1);
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string n = it->path().filename().string();
            if (n.size() < 9 || n[0] != '.' || n[n.size() - 7] != '.') continue;
            if (!std::all_of(n.end() - 6, n.end(), [](char c) { return std::isalnum(c & 0xff); }))
                continue;
            const std::string of = n.substr(1, n.size() - 8);
            std::error_code e2;
            if (of != target.filename().string() && !fs::is_regular_file(dir / of, e2)) continue;
            if (it->is_regular_file(e2) && !it->is_symlink(e2) &&
                fs::last_write_time(it->path(), e2) < stale && !e2)
                fs::remove(it->path(), e2);
        }
    }
    std::string tmpl = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) throw JobError("cannot write " + path + ": " + std::strerror(errno));
    size_t done = 0;
    while (done < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n < 0) {
            const int err = errno;
            ::close(fd);
            ::unlink(tmpl.c_str());
            throw JobError("cannot write " + path + ": " + std::strerror(err));
        }
        done += static_cast<size_t>(n);
    }
    // The data must be on disk before the rename makes it visible under the real name.
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        throw JobError("cannot write " + path + ": " + std::strerror(err));
    }
    ::chmod(tmpl.c_str(), 0644);
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        throw JobError("cannot replace " + path + ": " + std::strerror(err));
    }
}

void saveJobFile(const Job& job, const std::string& path) {
    writeFileAtomically(path, json::write(jobToJson(job)));
}

} // namespace cutcell
