#include "core/job/job_diff.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <map>

namespace cutcell {
namespace {

void leaves(const json::Value& v, const std::string& path,
            std::vector<std::pair<std::string, std::string>>& out) {
    if (v.isObject()) {
        for (const auto& [k, child] : v.asObject())
            leaves(child, path.empty() ? k : path + "." + k, out);
    } else if (v.isArray()) {
        const auto& a = v.asArray();
        for (size_t i = 0; i < a.size(); ++i)
            leaves(a[i], path + "[" + std::to_string(i) + "]", out);
    } else {
        std::string text = json::write(v, -1);
        if (!text.empty() && text.back() == '\n') text.pop_back();
        out.emplace_back(path, std::move(text));
    }
}

} // namespace

std::vector<ChangedKey> changedKeys(const Job& from, const Job& to) {
    std::vector<std::pair<std::string, std::string>> a, b;
    leaves(jobToJson(from), "", a);
    leaves(jobToJson(to), "", b);
    const std::map<std::string, std::string> before(a.begin(), a.end());
    std::map<std::string, std::string> after(b.begin(), b.end());
    std::vector<ChangedKey> out;
    for (const auto& [key, value] : b) {
        const auto it = before.find(key);
        if (it == before.end())
            out.push_back({key, "", value});
        else if (it->second != value)
            out.push_back({key, it->second, value});
    }
    for (const auto& [key, value] : a)
        if (!after.count(key)) out.push_back({key, value, ""});
    return out;
}

} // namespace cutcell
