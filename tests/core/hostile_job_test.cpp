// Hostile jobs (issue 27): every machine's shipped job, mutated member by member - absurd
// numbers, wrong types, missing and unknown keys, empty and huge arrays, long strings - is read
// by the same parseJob() the GUI and the CLI use. Each case either reads as a valid job or is
// refused with a message that names a key of the job, is short, and says where. No crash, no
// hang, no exception of another type. A valid mutated job is also planned (bounded work).
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <set>
#include <string>
#include <variant>
#include <vector>

using namespace cutcell;

namespace {

// A step into a document: an object's key or an array's index.
using Step = std::variant<std::string, size_t>;
using Path = std::vector<Step>;

json::Value* at(json::Value& root, const Path& path) {
    json::Value* cur = &root;
    for (const Step& s : path) {
        if (const auto* k = std::get_if<std::string>(&s)) {
            json::Value* next = nullptr;
            for (auto& [key, v] : cur->asObject())
                if (key == *k) next = &v;
            if (!next) return nullptr;
            cur = next;
        } else {
            cur = &cur->asArray()[std::get<size_t>(s)];
        }
    }
    return cur;
}

std::string dotted(const Path& path) {
    std::string out;
    for (const Step& s : path) {
        if (const auto* k = std::get_if<std::string>(&s))
            out += (out.empty() ? "" : ".") + *k;
        else
            out += "[" + std::to_string(std::get<size_t>(s)) + "]";
    }
    return out.empty() ? "(root)" : out;
}

// Every member of the document (objects and arrays too), depth first; arrays give their
// first two entries only (the rest are alike: rows of a table, entries per axis).
void collect(const json::Value& v, Path& path, std::vector<Path>& out,
             std::set<std::string>& keys) {
    out.push_back(path);
    if (v.isObject()) {
        for (const auto& [k, child] : v.asObject()) {
            keys.insert(k);
            path.emplace_back(k);
            collect(child, path, out, keys);
            path.pop_back();
        }
    } else if (v.isArray()) {
        for (size_t i = 0; i < v.asArray().size() && i < 2; ++i) {
            path.emplace_back(i);
            collect(v.asArray()[i], path, out, keys);
            path.pop_back();
        }
    }
}

struct Mutation {
    std::string what;
    std::function<void(json::Value& member, json::Value* parent, const Step* last)> apply;
};

json::Value hugeArrayOf(const json::Value& e, size_t n) {
    json::Array a;
    for (size_t i = 0; i < n; ++i)
        a.push_back(e);
    return json::Value(std::move(a));
}

std::vector<Mutation> mutationsFor(const json::Value& v, bool isRoot) {
    std::vector<Mutation> m;
    auto set = [](json::Value x) {
        return [x](json::Value& member, json::Value*, const Step*) { member = x; };
    };
    if (v.isNumber()) {
        for (const double x : {-1e308, 1e308, 0.0, -1.0, 1e-320, 4294967296.0, 0.5, -0.0})
            m.push_back({"number " + std::to_string(x), set(json::Value(x))});
        m.push_back({"number as a string", set(json::Value(std::string("12")))});
    } else if (v.isString()) {
        m.push_back({"empty string", set(json::Value(std::string()))});
        m.push_back({"long string", set(json::Value(std::string(5000, 'x')))});
        m.push_back(
            {"unicode string", set(json::Value(std::string("\xC3\xA9\xC3\x9F\xE2\x82\xAC")))});
        m.push_back({"string as a number", set(json::Value(42.0))});
    } else if (v.isArray()) {
        m.push_back({"empty array", set(json::Value(json::Array{}))});
        if (!v.asArray().empty())
            // As many as a job file of 16 MiB can hold for the largest rows (a drive's table).
            m.push_back({"20000 entries", set(hugeArrayOf(v.asArray().front(), 20000))});
        m.push_back({"array as a string", set(json::Value(std::string("x")))});
    } else if (v.isObject()) {
        m.push_back({"unknown key", [](json::Value& member, json::Value*, const Step*) {
                         member.set("bogus_key", json::Value(1.0));
                     }});
        if (!isRoot) {
            m.push_back({"object as an array", set(json::Value(json::Array{}))});
            m.push_back({"object as a number", set(json::Value(1.0))});
        }
    } else {
        m.push_back({"bool as a number", set(json::Value(0.0))});
    }
    if (!isRoot) {
        m.push_back({"null", set(json::Value())});
        m.push_back({"removed", [](json::Value&, json::Value* parent, const Step* last) {
                         if (const auto* k = std::get_if<std::string>(last)) {
                             auto& o = parent->asObject();
                             std::erase_if(o, [&](const auto& kv) { return kv.first == *k; });
                         } else {
                             auto& a = parent->asArray();
                             a.erase(a.begin() + static_cast<long>(std::get<size_t>(*last)));
                         }
                     }});
    }
    return m;
}

bool namesAKey(const std::string& message, const std::set<std::string>& keys) {
    for (const std::string& k : keys)
        if (k.size() > 1 && message.find(k) != std::string::npos) return true;
    return message.find("bogus_key") != std::string::npos;
}

} // namespace

TEST(HostileJobs, EveryMachinesSectionIsRefusedByKeyOrReadAsValid) {
    if (machines().empty()) registerMachines();
    int cases = 0, valid = 0, refused = 0, planned = 0;
    double slowestMs = 0;
    std::string slowest;
    for (const MachineModule* module : machines()) {
        const std::string base = json::write(jobToJson(module->defaultJob()));
        const json::Value doc = json::parse(base);
        std::vector<Path> paths;
        std::set<std::string> keys;
        Path p;
        collect(doc, p, paths, keys);
        for (const Path& path : paths) {
            json::Value probe = json::parse(base);
            const std::vector<Mutation> mutations = mutationsFor(*at(probe, path), path.empty());
            for (const Mutation& mutation : mutations) {
                json::Value d = json::parse(base); // a deep copy: values share their members
                json::Value* member = at(d, path);
                json::Value* parent = nullptr;
                if (!path.empty()) parent = at(d, Path(path.begin(), path.end() - 1));
                mutation.apply(*member, parent, path.empty() ? nullptr : &path.back());
                const std::string text = json::write(d);
                const std::string label = module->id() + " " + dotted(path) + ": " + mutation.what;
                ++cases;
                const auto t0 = std::chrono::steady_clock::now();
                try {
                    const Job job = parseJob(text);
                    ++valid;
                    // Valid after all (a default, a value inside its range): it plans or says
                    // why, within the commands' work bounds.
                    const MachinePlan plan = machineFor(job).plan(job);
                    if (!plan.ok()) {
                        EXPECT_FALSE(plan.outcome.message.empty()) << label;
                    }
                    ++planned;
                } catch (const JobError& e) {
                    ++refused;
                    const std::string what = e.what();
                    EXPECT_TRUE(namesAKey(what, keys)) << label << ": " << what;
                    EXPECT_LT(what.size(), 600u) << label << ": " << what.substr(0, 300);
                    EXPECT_EQ(what.find("line 0"), std::string::npos) << label << ": " << what;
                } catch (const std::exception& e) {
                    ADD_FAILURE() << label << ": not a JobError: " << e.what();
                }
                const double ms =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count();
                if (ms > slowestMs) {
                    slowestMs = ms;
                    slowest = label;
                }
            }
        }
    }
    std::printf("%d hostile jobs over %zu machines: %d refused, %d valid (%d planned); slowest "
                "%.0f ms (%s)\n",
                cases, machines().size(), refused, valid, planned, slowestMs, slowest.c_str());
    EXPECT_GE(cases, 2000);
}
