#pragma once
// One table per machine section: each key of the section is written once - its dotted path
// below `machine`, its unit, its physical range and its label - and the table drives reading
// (the key's type, unknown keys refused with a hint), writing (in table order), the range
// checks (key, value, unit and limit in the message) and the form's field (label, unit,
// decimals, range). A key cannot be spelt two ways. Checks that depend on other values (a
// torque within the motor's limit) stay with the machine's validate().
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"
#include "core/json/json.h"

#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

enum class FieldCheck : std::uint8_t {
    None,     // checked by the machine's own validate() (its bounds depend on other values)
    Range,    // lo <= v <= hi
    Positive, // v > 0 and lo <= v <= hi
};

using FieldChoices = std::array<const char*, 6>;

template <class Spec> struct SectionField {
    const char* key;   // dotted below `machine`: "cut.velocity_m_s"
    const char* unit;  // "m/s"; "1" for a plain ratio
    const char* label; // the operator's name for it: "Cutting velocity"
    double lo = 0, hi = 0;
    FieldCheck check = FieldCheck::None;
    int decimals = 3; // shown in the form
    // Exactly one of these says where the value lives and what it is.
    double& (*number)(Spec&) = nullptr;
    int& (*integer)(Spec&) = nullptr; // a whole number in [lo, hi] (checked on reading)
    bool& (*boolean)(Spec&) = nullptr;
    // A choice of names (in the order of the values 0, 1, ...; unused entries null), read and
    // written as the name.
    FieldChoices choices{};
    int (*getChoice)(const Spec&) = nullptr;
    void (*setChoice)(Spec&, int) = nullptr;
    // A value of its own shape (an array of orders): read from the object holding it, written
    // as returned (null: not written). Its checks are the machine's validate()'s.
    void (*readCustom)(SectionReader& parent, const std::string& leaf, Spec&) = nullptr;
    json::Value (*writeCustom)(const Spec&) = nullptr;
    // The key exists only while this holds (a round tube has a diameter, a rectangular one a
    // width and a height): read, written and checked only then. Keys before it are read first.
    bool (*when)(const Spec&) = nullptr;

    // The last part of the key ("velocity_m_s") and the object it is in ("cut").
    std::string leaf() const;
    std::string parent() const;
};

// The nested objects of a section as they are opened while reading, each read by its own
// SectionReader, finished (unknown keys refused) once every field was read.
class SectionTree {
  public:
    explicit SectionTree(SectionReader& root) : root_(root) {}
    // The reader of the object at a dotted path ("" = the section), opened on first use; null
    // when the section has no such object (its fields keep their values).
    SectionReader* at(const std::string& path);
    void finish() const;

  private:
    SectionReader& root_;
    std::deque<std::pair<std::string, SectionReader>> open_; // stable references
};

// Index of `name` in `names`; -1 when absent.
int choiceIndex(const FieldChoices& names, const std::string& name);
// A JobError naming the key, the value found and the names allowed.
[[noreturn]] void throwBadChoice(const std::string& key, const json::Value& found,
                                 const FieldChoices& names);
// Sets the member at a dotted path of a JSON object, creating the objects on the way (in the
// order of first use).
void setAtPath(json::Object& root, const std::string& path, json::Value v);

template <class Spec> std::string SectionField<Spec>::leaf() const {
    const std::string k = key;
    const auto dot = k.rfind('.');
    return dot == std::string::npos ? k : k.substr(dot + 1);
}

template <class Spec> std::string SectionField<Spec>::parent() const {
    const std::string k = key;
    const auto dot = k.rfind('.');
    return dot == std::string::npos ? std::string() : k.substr(0, dot);
}

// Reads every field of the table present in the section into s; absent keys keep s's value.
// Opens the nested objects as needed; the caller finishes the section's own reader.
template <class Spec>
void readFields(SectionReader& section, std::span<const SectionField<Spec>> table, Spec& s) {
    SectionTree tree(section);
    for (const SectionField<Spec>& f : table) {
        if (f.when && !f.when(s)) continue;
        SectionReader* r = tree.at(f.parent());
        if (!r) continue;
        const std::string leaf = f.leaf();
        if (f.readCustom) {
            f.readCustom(*r, leaf, s);
        } else if (f.boolean) {
            f.boolean(s) = r->boolean(leaf, f.boolean(s));
        } else if (f.number) {
            f.number(s) = r->number(leaf, f.unit, f.number(s));
        } else if (f.integer) {
            f.integer(s) = r->integer(leaf, f.unit, f.integer(s), static_cast<int>(f.lo),
                                      static_cast<int>(f.hi));
        } else if (f.getChoice && f.setChoice) {
            const json::Value* v = r->get(leaf);
            if (!v) continue;
            const int i = v->isString() ? choiceIndex(f.choices, v->asString()) : -1;
            if (i < 0) throwBadChoice(r->key(leaf), *v, f.choices);
            f.setChoice(s, i);
        }
    }
    tree.finish();
}

// The table's fields of s as the section's JSON (nested objects in the order of first use).
// A machine section held whole by its table: `kind` (checked by the caller) and every field,
// unknown keys refused.
template <class Spec>
Spec readSectionFields(const json::Value& section, std::span<const SectionField<Spec>> table) {
    SectionReader m(section, "machine");
    m.get("kind");
    Spec s;
    readFields(m, table, s);
    m.finish();
    return s;
}

template <class Spec>
json::Object writeFields(std::span<const SectionField<Spec>> table, const Spec& s) {
    json::Object out;
    Spec& read = const_cast<Spec&>(s); // the accessors only read here
    for (const SectionField<Spec>& f : table) {
        if (f.when && !f.when(s)) continue;
        if (f.writeCustom) {
            if (json::Value v = f.writeCustom(s); !v.isNull()) setAtPath(out, f.key, std::move(v));
        } else if (f.boolean)
            setAtPath(out, f.key, f.boolean(read));
        else if (f.number)
            setAtPath(out, f.key, f.number(read));
        else if (f.integer)
            setAtPath(out, f.key, f.integer(read));
        else if (f.getChoice)
            setAtPath(out, f.key, f.choices[static_cast<size_t>(f.getChoice(s))]);
    }
    return out;
}

// The table's range checks of s (FieldCheck::Range / Positive; numbers and whole numbers) into c.
template <class Spec>
void checkFields(IssueChecker& c, std::span<const SectionField<Spec>> table, const Spec& s) {
    Spec& read = const_cast<Spec&>(s); // the accessors only read here
    for (const SectionField<Spec>& f : table) {
        if (f.when && !f.when(s)) continue;
        if (!f.number && !f.integer) continue;
        const double v = f.number ? f.number(read) : static_cast<double>(f.integer(read));
        if (f.check == FieldCheck::Range) c.range(f.key, v, f.lo, f.hi, f.unit);
        if (f.check == FieldCheck::Positive) c.positive(f.key, v, f.lo, f.hi, f.unit);
    }
}

// The field of a key; null when the table has none.
template <class Spec>
const SectionField<Spec>* findField(std::span<const SectionField<Spec>> table,
                                    const std::string& key) {
    for (const SectionField<Spec>& f : table)
        if (key == f.key) return &f;
    return nullptr;
}

} // namespace cutcell
