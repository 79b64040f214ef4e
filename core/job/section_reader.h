#pragma once
// Reads the members of one JSON object of a job, with the dotted key path in every message,
// and refuses the keys it was not asked for (finish()): a misspelt key is an error naming it,
// with the nearest valid key as a hint, never silently ignored.
#include "core/job/job_io.h"
#include "core/json/json.h"

#include <initializer_list>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace cutcell {

// Edit distance (insertions, deletions, substitutions) for the "did you mean" hint.
size_t editDistance(const std::string& a, const std::string& b);
// a with A-Z lowered (key names are ASCII).
std::string lowerAscii(std::string s);
// The number as messages write it ("%.6g", locale-independent).
std::string num(double v);

class SectionReader {
  public:
    // path: the dotted key of this object ("" for the document, "machine.cut", ...).
    SectionReader(const json::Value& v, std::string path);

    std::string key(const std::string& k) const;
    const std::string& path() const { return path_; }
    bool has(const std::string& k) const;
    // The member, marked as read; nullptr when absent.
    const json::Value* get(const std::string& k);

    double number(const std::string& k, const char* unit);                  // required
    double number(const std::string& k, const char* unit, double fallback); // optional
    // A whole number in [lo, hi] (range checked before the conversion: no UB on 1e308).
    int integer(const std::string& k, const char* unit, int fallback, int lo, int hi);
    std::string string(const std::string& k, const std::string& fallback);
    bool boolean(const std::string& k, bool fallback);
    SectionReader child(const std::string& k); // required object
    template <typename E>
    E choice(const std::string& k, std::initializer_list<std::pair<const char*, E>> options,
             E fallback);

    // Marks keys as known without reading them (read elsewhere or tolerated).
    void accept(std::initializer_list<const char*> keys);
    // Throws JobError for the first member that was never read or accepted, with a hint.
    void finish() const;

  private:
    double asNumber(const json::Value& m, const std::string& k, const char* unit) const;
    // "; found \"sim.period_S\" (misspelt?)" for a missing key k with an unread look-alike.
    std::string misspelling(const std::string& k) const;
    const json::Value& v_;
    std::string path_;
    std::unordered_set<std::string> read_;
};

template <typename E>
E SectionReader::choice(const std::string& k,
                        std::initializer_list<std::pair<const char*, E>> options, E fallback) {
    const json::Value* m = get(k);
    if (!m) return fallback;
    std::string allowed;
    for (const auto& [name, value] : options) {
        if (m->isString() && m->asString() == name) return value;
        allowed += allowed.empty() ? "" : ", ";
        allowed += std::string("\"") + name + "\"";
    }
    const std::string found = m->isString() ? json::quote(m->asString()) : m->typeName();
    throw JobError(key(k) + " = " + found + " is not one of " + allowed);
}

} // namespace cutcell
