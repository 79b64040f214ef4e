// The common part of a job file (schema 2: name, description, units note, sim, engine,
// devices) and the dispatch of the `machine` section to its module. Schema-1 files (machine
// keys at the top level) are migrated in memory first (upgradeJobDocument()).
#include "core/job/job_io.h"

#include "core/common/c_format.h"
#include "core/job/section_reader.h"
#include "core/machine/machine_registry.h"

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

// Keys of the common part; everything else of a schema-1 file belongs to its machine.
const char* const kCommonKeys[] = {"schema", "name",   "description", "units",
                                   "sim",    "engine", "devices"};

bool isCommonKey(const std::string& k) {
    for (const char* c : kCommonKeys)
        if (k == c) return true;
    return false;
}

void readSim(SectionReader r, Job& job) {
    job.sim.period_s = r.number("period_s", "s");
    job.sim.duration_s = r.number("duration_s", "s");
    r.finish();
}

void readEngine(SectionReader e, Job& job) {
    job.engine.estop_category = e.choice<StopCategory>(
        "estop_category", {{"cat0", StopCategory::Cat0}, {"cat1", StopCategory::Cat1}},
        job.engine.estop_category);
    job.engine.feed_hold_decel_s = e.number("feed_hold_decel_s", "s", job.engine.feed_hold_decel_s);
    job.engine.torch_on_during_feed_hold =
        e.boolean("torch_on_during_feed_hold", job.engine.torch_on_during_feed_hold);
    job.engine.following_error_limit_deg =
        e.number("following_error_limit_deg", "deg", job.engine.following_error_limit_deg);
    job.engine.home_speed_deg_s =
        e.number("home_speed_deg_s", "deg/s", job.engine.home_speed_deg_s);
    job.engine.following_error_limit_mm =
        e.number("following_error_limit_mm", "mm", job.engine.following_error_limit_mm);
    job.engine.home_speed_mm_s = e.number("home_speed_mm_s", "mm/s", job.engine.home_speed_mm_s);
    job.engine.runs_dir = e.string("runs_dir", job.engine.runs_dir);
    e.finish();
}

// "[1, 2, 3]" for a message.
// Cut after about 80 characters: "[1, 2, 3, ... (100000 entries)]".
std::string arrayText(const json::Value& v) {
    std::string out = "[";
    const auto& a = v.asArray();
    for (size_t i = 0; i < a.size(); ++i) {
        if (out.size() > 80) return out + ", ... (" + std::to_string(a.size()) + " entries)]";
        out += (i > 0 ? ", " : "") + (a[i].isNumber() ? num(a[i].asNumber()) : a[i].typeName());
    }
    return out + "]";
}

// Files written before the machines had their own axis counts held 6 entries per axis list.
constexpr int kLegacyPerAxisEntries = 6;

// One entry per axis of the machine; 6 entries (the fixed length of files written before the
// machines had their own axis counts) are read as the first axes, the rest keep defaults.
// Any other length is refused with the key, the value and the machine's axis count.
template <typename T, typename ReadOne>
void readPerAxis(SectionReader& d, const char* key, const char* what, const std::string& machine,
                 int axisCount, T& out, ReadOne readOne) {
    const json::Value* arr = d.get(key);
    if (!arr) return;
    const std::string k = d.key(key);
    if (!arr->isArray())
        throw JobError(k + " must be an array of " + std::to_string(axisCount) + " " + what +
                       ", one per axis of the " + machine);
    const size_t n = arr->asArray().size();
    if (n != static_cast<size_t>(axisCount) && n != static_cast<size_t>(kLegacyPerAxisEntries))
        throw JobError(k + " = " + arrayText(*arr) + " has " + std::to_string(n) +
                       " entries: the " + machine + " has " + std::to_string(axisCount) +
                       " axes (give " + std::to_string(axisCount) + " " + what + ", one per axis)");
    for (size_t i = 0; i < n; ++i) {
        const json::Value& v = arr->asArray()[i];
        const std::string ki = k + "[" + std::to_string(i) + "]";
        const auto value = readOne(v, ki);
        if (i < out.size() && i < static_cast<size_t>(axisCount)) out[i] = value;
    }
}

void readDevices(SectionReader d, Job& job, const MachineModule& module) {
    const int axisCount = static_cast<int>(module.axes(job).size());
    const int sensorCount = static_cast<int>(module.sensorNames().size());
    const std::string machine = "machine " + json::quote(module.id());
    job.devices.kind = d.choice<DeviceKind>(
        "kind", {{"simulated", DeviceKind::Simulated}, {"canopen", DeviceKind::CanOpen}},
        job.devices.kind);
    job.devices.can_plugin = d.string("can_plugin", job.devices.can_plugin);
    job.devices.can_interface = d.string("can_interface", job.devices.can_interface);
    // Range first, then the conversion (a double such as 1e10 does not fit an int).
    job.devices.bitrate_bps =
        d.integer("bitrate_bps", "bit/s", job.devices.bitrate_bps, 1, 1000000000);
    job.devices.heartbeat_timeout_ms =
        d.number("heartbeat_timeout_ms", "ms", job.devices.heartbeat_timeout_ms);
    job.devices.sync_counter_overflow =
        d.integer("sync_counter_overflow", "", job.devices.sync_counter_overflow, 0, 240);
    auto nodeId = [](const json::Value& v, const std::string& k) {
        if (!v.isNumber()) throw JobError(k + " must be a number (a node id 1..127)");
        const double id = v.asNumber();
        if (!(id >= 1 && id <= 127) || id != std::floor(id))
            throw JobError(k + " = " + num(id) +
                           " is not a CANopen node id: a whole number in [1, 127]");
        return static_cast<int>(id);
    };
    readPerAxis(d, "node_ids", "node ids (1..127)", machine, axisCount, job.devices.node_ids,
                nodeId);
    readPerAxis(d, "counts_per_unit", "numbers (counts/deg or counts/mm)", machine, axisCount,
                job.devices.counts_per_unit, [](const json::Value& v, const std::string& k) {
                    if (!v.isNumber())
                        throw JobError(k + " must be a number (counts/deg or counts/mm)");
                    // Every entry, also those past the axis count (a 6-entry file of a
                    // machine with fewer axes): the axis's own range is checked later.
                    if (!(v.asNumber() > 0))
                        throw JobError(k + " = " + num(v.asNumber()) +
                                       " counts per unit: a drive's resolution is > 0");
                    return v.asNumber();
                });
    if (const json::Value* ids = d.get("sensor_node_ids")) {
        const std::string k = d.key("sensor_node_ids");
        if (!ids->isArray() || ids->asArray().size() != static_cast<size_t>(sensorCount))
            throw JobError(k + (ids->isArray() ? " = " + arrayText(*ids) : std::string()) +
                           ": the " + machine + " reads " + std::to_string(sensorCount) +
                           " sensor" + (sensorCount == 1 ? "" : "s") +
                           " (give one node id 1..127 each)");
        for (size_t i = 0; i < ids->asArray().size(); ++i)
            job.devices.sensor_node_ids[i] =
                nodeId(ids->asArray()[i], k + "[" + std::to_string(i) + "]");
    }
    d.finish();
}

json::Value devicesJson(const DeviceSpec& d, const MachineModule& module, const Job& job) {
    const int axisCount = static_cast<int>(module.axes(job).size());
    const int sensorCount = static_cast<int>(module.sensorNames().size());
    json::Array ids, cpu, sensors;
    for (int i = 0; i < axisCount; ++i) {
        ids.emplace_back(d.node_ids[static_cast<size_t>(i)]);
        cpu.emplace_back(d.counts_per_unit[static_cast<size_t>(i)]);
    }
    json::Object out{{"kind", toString(d.kind)},
                     {"can_plugin", d.can_plugin},
                     {"can_interface", d.can_interface},
                     {"bitrate_bps", d.bitrate_bps},
                     {"node_ids", ids},
                     {"counts_per_unit", cpu}};
    for (int k = 0; k < sensorCount; ++k)
        sensors.emplace_back(sensorNodeId(d, axisCount, k));
    if (sensorCount > 0) out.emplace_back("sensor_node_ids", sensors);
    out.emplace_back("heartbeat_timeout_ms", d.heartbeat_timeout_ms);
    out.emplace_back("sync_counter_overflow", d.sync_counter_overflow);
    return out;
}

double schemaOf(const json::Value& doc) {
    const json::Value* s = doc.isObject() ? doc.find("schema") : nullptr;
    if (!s) throw JobError("missing required key schema (the job file's version: 1 or 2)");
    if (!s->isNumber()) throw JobError("schema must be a number (1 or 2), found " + s->typeName());
    const double v = s->asNumber();
    if (v != 1 && v != 2)
        throw JobError("schema = " + num(v) +
                       " is not supported; this CutCell reads schema 1 and 2");
    return v;
}

} // namespace

json::Value upgradeJobDocument(const json::Value& doc) {
    if (!doc.isObject()) throw JobError("the job must be a JSON object, found " + doc.typeName());
    if (schemaOf(doc) == 2) return doc;
    std::string kind;
    if (const json::Value* m = doc.find("machine")) {
        if (!m->isString())
            throw JobError("machine must be a string (the machine's id), found " + m->typeName());
        kind = m->asString();
    } else {
        kind = schema1DefaultMachine();
    }
    const MachineModule* module = findMachine(kind);
    if (!module)
        throw JobError("machine = " + json::quote(kind) + " is not one of " + machineIdList());
    json::Object out{{"schema", 2}};
    json::Object section{{"kind", kind}};
    for (const auto& [k, v] : doc.asObject()) {
        if (k == "schema" || k == "machine") continue;
        // A common key in the wrong case would otherwise be read as the machine's own
        // ("machine.DEVICES (machine has no such key)").
        for (const char* c : kCommonKeys)
            if (k != c && lowerAscii(k) == c)
                throw JobError("unknown key " + json::quote(k) + " (did you mean \"" +
                               std::string(c) + "\"?)");
        if (isCommonKey(k))
            out.emplace_back(k, v);
        else
            section.emplace_back(k, v);
    }
    module->migrateSchema1(section);
    // The machine section after the description, as schema-2 files are written.
    json::Object ordered;
    for (auto& kv : out) {
        ordered.push_back(kv);
        if (kv.first == "description") ordered.emplace_back("machine", section);
    }
    bool placed = false;
    for (const auto& kv : ordered)
        placed = placed || kv.first == "machine";
    if (!placed) ordered.emplace_back("machine", section);
    return ordered;
}

std::string upgradeJobText(const std::string& text) {
    json::Value doc;
    try {
        doc = json::parse(text);
    } catch (const json::ParseError& e) {
        throw JobError(std::string("the job file is not valid JSON: ") + e.what());
    }
    const json::Value upgraded = upgradeJobDocument(doc);
    (void)jobFromJson(upgraded); // it must read back (keys and types), else refuse it now
    return json::write(upgraded);
}

Job jobFromJson(const json::Value& input) {
    const json::Value doc = upgradeJobDocument(input);
    SectionReader r(doc, "");
    Job job;
    job.schema = 2;
    r.get("schema");
    job.name = r.string("name", "");
    job.description = r.string("description", "");
    job.units_note = r.string("units", "");
    SectionReader m = r.child("machine");
    const std::string kind = m.string("kind", "");
    if (kind.empty())
        throw JobError("missing required key machine.kind (one of " + machineIdList() + ")");
    const MachineModule* module = findMachine(kind);
    if (!module)
        throw JobError("machine.kind = " + json::quote(kind) + " is not one of " + machineIdList());
    job.machine = kind;
    module->readSection(*doc.find("machine"), job);
    readSim(r.child("sim"), job);
    if (r.has("engine")) readEngine(r.child("engine"), job);
    if (r.has("devices")) readDevices(r.child("devices"), job, *module);
    r.accept({"engine", "devices"}); // optional: known keys for the typo hint when absent
    r.finish();
    return job;
}

json::Value jobToJson(const Job& job) {
    const MachineModule& module = machineFor(job);
    json::Object doc{{"schema", 2}, {"name", job.name}, {"description", job.description}};
    if (!job.units_note.empty()) doc.emplace_back("units", job.units_note);
    doc.emplace_back("machine", module.writeSection(job));
    doc.emplace_back(
        "sim", json::Object{{"period_s", job.sim.period_s}, {"duration_s", job.sim.duration_s}});
    doc.emplace_back(
        "engine", json::Object{{"estop_category", toString(job.engine.estop_category)},
                               {"feed_hold_decel_s", job.engine.feed_hold_decel_s},
                               {"torch_on_during_feed_hold", job.engine.torch_on_during_feed_hold},
                               {"following_error_limit_deg", job.engine.following_error_limit_deg},
                               {"home_speed_deg_s", job.engine.home_speed_deg_s},
                               {"following_error_limit_mm", job.engine.following_error_limit_mm},
                               {"home_speed_mm_s", job.engine.home_speed_mm_s},
                               {"runs_dir", job.engine.runs_dir}});
    doc.emplace_back("devices", devicesJson(job.devices, module, job));
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
    std::error_code dirEc;
    if (std::filesystem::is_directory(path, dirEc))
        throw JobFileError("cannot read " + path + ": it is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw JobFileError("cannot open " + path + ": " + std::strerror(errno));
    // Refuse a huge file before reading it into memory (a job is a few kB).
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > json::kMaxDocumentBytes)
        throw JobError(path + " is " + std::to_string(size) +
                       " bytes; a job file may have at most " +
                       std::to_string(json::kMaxDocumentBytes) + " bytes (16 MiB)");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw JobFileError("cannot read " + path + ": " + std::strerror(errno));
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

std::string writeTemporaryFile(std::string tmpl, const std::string& forPath,
                               const std::string& contents) {
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) throw JobError("cannot write " + forPath + ": " + std::strerror(errno));
    size_t done = 0;
    while (done < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n < 0) {
            const int err = errno;
            ::close(fd);
            ::unlink(tmpl.c_str());
            throw JobError("cannot write " + forPath + ": " + std::strerror(err));
        }
        done += static_cast<size_t>(n);
    }
    // The data must be on disk before a rename makes it visible under the real name.
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        throw JobError("cannot write " + forPath + ": " + std::strerror(err));
    }
    ::chmod(tmpl.c_str(), 0644);
    return tmpl;
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    // A device or a pipe (--report /dev/null, /dev/stdout, a FIFO) is written, never replaced:
    // a rename would put a plain file in the place of /dev/null.
    if (std::error_code ec; fs::exists(target, ec) && !fs::is_regular_file(target, ec) &&
                            !fs::is_directory(target, ec)) {
        std::ofstream out(path, std::ios::binary);
        out << contents;
        out.flush();
        if (!out) throw JobError("cannot write " + path + ": " + std::strerror(errno));
        return;
    }
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
    const std::string tmpl = writeTemporaryFile(
        (dir / ("." + target.filename().string() + ".XXXXXX")).string(), path, contents);
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
