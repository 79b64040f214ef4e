#include "core/job/section_reader.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

size_t editDistance(const std::string& a, const std::string& b) {
    // Keys are short; anything longer than a key cannot be a misspelling of one.
    if (a.size() > 200 || b.size() > 200) return std::max(a.size(), b.size());
    std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min(
                {prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0u : 1u)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string lowerAscii(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return s;
}

std::string num(double v) {
    return formatC("%.6g", v);
}

SectionReader::SectionReader(const json::Value& v, std::string path)
    : v_(v), path_(std::move(path)) {
    if (!v_.isObject())
        throw JobError((path_.empty() ? std::string("the job") : path_) +
                       " must be a JSON object, found " + v_.typeName());
}

std::string SectionReader::key(const std::string& k) const {
    return path_.empty() ? k : path_ + "." + k;
}

bool SectionReader::has(const std::string& k) const {
    return v_.find(k) != nullptr;
}

const json::Value* SectionReader::get(const std::string& k) {
    read_.insert(k);
    return v_.find(k);
}

double SectionReader::asNumber(const json::Value& m, const std::string& k, const char* unit) const {
    if (!m.isNumber())
        throw JobError(key(k) + " must be a number in " + unit + ", found " + m.typeName());
    return m.asNumber();
}

std::string SectionReader::misspelling(const std::string& k) const {
    // A member nobody read whose name is close to k: most likely k, misspelt.
    std::string best;
    size_t bestDistance = 0;
    for (const auto& [member, unused] : v_.asObject()) {
        (void)unused;
        if (read_.count(member)) continue;
        const size_t d = editDistance(lowerAscii(member), lowerAscii(k));
        if (d <= std::max<size_t>(3, k.size() / 3) && (best.empty() || d < bestDistance)) {
            best = member;
            bestDistance = d;
        }
    }
    return best.empty() ? std::string() : "; found " + json::quote(key(best)) + " (misspelt?)";
}

double SectionReader::number(const std::string& k, const char* unit) {
    const json::Value* m = get(k);
    if (!m)
        throw JobError("missing required key " + key(k) + " (a number in " + unit + ")" +
                       misspelling(k));
    return asNumber(*m, k, unit);
}

double SectionReader::number(const std::string& k, const char* unit, double fallback) {
    const json::Value* m = get(k);
    return m ? asNumber(*m, k, unit) : fallback;
}

int SectionReader::integer(const std::string& k, const char* unit, int fallback, int lo, int hi) {
    const double v = number(k, unit, fallback);
    // Compare as doubles first: converting 1e308 or NaN to int is undefined behaviour.
    if (!(v >= lo && v <= hi))
        throw JobError(key(k) + " = " + num(v) + " " + unit + " is outside [" + std::to_string(lo) +
                       ", " + std::to_string(hi) + "] " + unit);
    if (v != std::floor(v))
        throw JobError(key(k) + " = " + num(v) + " " + unit + " must be a whole number");
    return static_cast<int>(v);
}

std::string SectionReader::string(const std::string& k, const std::string& fallback) {
    const json::Value* m = get(k);
    if (!m) return fallback;
    if (!m->isString()) throw JobError(key(k) + " must be a string, found " + m->typeName());
    return m->asString();
}

bool SectionReader::boolean(const std::string& k, bool fallback) {
    const json::Value* m = get(k);
    if (!m) return fallback;
    if (!m->isBool()) throw JobError(key(k) + " must be true or false, found " + m->typeName());
    return m->asBool();
}

SectionReader SectionReader::child(const std::string& k) {
    const json::Value* m = get(k);
    if (!m) throw JobError("missing required section " + key(k) + misspelling(k));
    return SectionReader(*m, key(k));
}

void SectionReader::accept(std::initializer_list<const char*> keys) {
    for (const char* k : keys)
        read_.insert(k);
}

void SectionReader::finish() const {
    // One pass over the members with a hash lookup each: linear in the object's size.
    for (const auto& [k, unused] : v_.asObject()) {
        (void)unused;
        if (read_.count(k)) continue;
        std::string best;
        size_t bestDistance = 0;
        for (const std::string& known : read_) {
            // Case does not count: "DEVICES" is a misspelt "devices".
            const size_t d = editDistance(lowerAscii(k), lowerAscii(known));
            if (best.empty() || d < bestDistance || (d == bestDistance && known < best)) {
                best = known;
                bestDistance = d;
            }
        }
        std::string msg = "unknown key " + json::quote(key(k));
        if (!best.empty() && bestDistance <= std::max<size_t>(3, best.size() / 3))
            msg += " (did you mean " + json::quote(key(best)) + "?)";
        else if (!best.empty())
            msg += " (" + (path_.empty() ? std::string("the job") : path_) + " has no such key)";
        throw JobError(msg);
    }
}

} // namespace cutcell
