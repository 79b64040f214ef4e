#include "core/job/field_table.h"

#include <algorithm>

namespace cutcell {

SectionReader* SectionTree::at(const std::string& path) {
    if (path.empty()) return &root_;
    for (auto& [p, r] : open_)
        if (p == path) return &r;
    const auto dot = path.rfind('.');
    SectionReader* parent = at(dot == std::string::npos ? std::string() : path.substr(0, dot));
    const std::string leaf = dot == std::string::npos ? path : path.substr(dot + 1);
    if (!parent || !parent->has(leaf)) return nullptr;
    open_.emplace_back(path, parent->child(leaf));
    return &open_.back().second;
}

void SectionTree::finish() const {
    // The innermost objects first: a misspelt key deep down is named as deep down.
    for (auto it = open_.rbegin(); it != open_.rend(); ++it)
        it->second.finish();
}

int choiceIndex(const FieldChoices& names, const std::string& name) {
    for (size_t i = 0; i < names.size() && names[i]; ++i)
        if (name == names[i]) return static_cast<int>(i);
    return -1;
}

void throwBadChoice(const std::string& key, const json::Value& found, const FieldChoices& names) {
    std::string allowed;
    for (const char* n : names) {
        if (!n) break;
        allowed += allowed.empty() ? "" : ", ";
        allowed += std::string("\"") + n + "\"";
    }
    const std::string what = found.isString() ? json::quote(found.asString()) : found.typeName();
    throw JobError(key + " = " + what + " is not one of " + allowed);
}

void setAtPath(json::Object& root, const std::string& path, json::Value v) {
    const auto dot = path.find('.');
    const std::string head = dot == std::string::npos ? path : path.substr(0, dot);
    auto it =
        std::find_if(root.begin(), root.end(), [&](const auto& m) { return m.first == head; });
    if (dot == std::string::npos) {
        if (it != root.end())
            it->second = std::move(v);
        else
            root.emplace_back(head, std::move(v));
        return;
    }
    if (it == root.end()) {
        root.emplace_back(head, json::Object{});
        it = root.end() - 1;
    }
    setAtPath(it->second.asObject(), path.substr(dot + 1), std::move(v));
}

} // namespace cutcell
