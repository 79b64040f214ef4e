#pragma once
// One table per row of a machine section's arrays (the robot's robot.dh[], controller[],
// plant[]): each key of a row is written once - its name in the row, its unit, its physical
// range, its label and the decimals the form shows - and the table drives reading (unknown
// keys refused with a hint), writing (in table order), the range checks (the key with its row,
// the value, the unit and the limit in the message) and the form's column. Checks that depend on
// other values (min below max) stay with the machine's validate().
#include "core/job/field_table.h"
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"
#include "core/json/json.h"

#include <optional>
#include <span>
#include <string>

namespace cutcell {

template <class Row> struct RowField {
    const char* key;   // the member of the row: "a_mm"
    const char* unit;  // "mm"
    const char* label; // the form's column: "a"
    double lo = 0, hi = 0;
    FieldCheck check = FieldCheck::None;
    int decimals = 3; // shown in the form
    double& (*number)(Row&) = nullptr;
    // The value of an absent key; none: the key is required.
    std::optional<double> absent{};
};

// The dotted key of row i of an array: "robot.dh[2]".
std::string rowKey(const std::string& array, size_t i);

// The array at parent's leaf with exactly `count` rows ("rowsAre" says what they are: "axis 0 =
// chuck, 1..5 = arm"); a JobError when it is missing, not an array or of another length.
const json::Array& requiredRows(SectionReader& parent, const std::string& leaf, size_t count,
                                const char* rowsAre);

// The table's keys of one row (a row may hold the keys of several tables; the caller finishes
// the row's reader).
template <class Row>
void readRowFields(SectionReader& row, std::span<const RowField<Row>> table, Row& out) {
    for (const RowField<Row>& f : table)
        f.number(out) = f.absent ? row.number(f.key, f.unit, *f.absent) : row.number(f.key, f.unit);
}

// Every element of `rows` (the array at the dotted key `key`, as many elements as out has) into
// out, unknown keys refused.
template <class Row>
void readRows(const json::Array& rows, const std::string& key, std::span<const RowField<Row>> table,
              std::span<Row> out) {
    for (size_t i = 0; i < out.size() && i < rows.size(); ++i) {
        SectionReader row(rows[i], rowKey(key, i));
        readRowFields(row, table, out[i]);
        row.finish();
    }
}

// The table's keys of a row appended to out, in table order.
template <class Row>
void writeRowFields(std::span<const RowField<Row>> table, const Row& r, json::Object& out) {
    Row& read = const_cast<Row&>(r); // the accessors only read here
    for (const RowField<Row>& f : table)
        out.emplace_back(f.key, f.number(read));
}

template <class Row>
json::Array writeRows(std::span<const RowField<Row>> table, std::span<const Row> rows) {
    json::Array out;
    for (const Row& r : rows) {
        json::Object o;
        writeRowFields(table, r, o);
        out.emplace_back(std::move(o));
    }
    return out;
}

// The table's range checks of one row, keys below `rowPath` ("robot.dh[2]").
template <class Row>
void checkRow(IssueChecker& c, std::span<const RowField<Row>> table, const std::string& rowPath,
              const Row& r) {
    Row& read = const_cast<Row&>(r); // the accessors only read here
    for (const RowField<Row>& f : table) {
        const std::string k = rowPath + "." + f.key;
        if (f.check == FieldCheck::Range) c.range(k, f.number(read), f.lo, f.hi, f.unit);
        if (f.check == FieldCheck::Positive) c.positive(k, f.number(read), f.lo, f.hi, f.unit);
    }
}

// The range checks of every row of the array at the dotted key `key`.
template <class Row>
void checkRows(IssueChecker& c, std::span<const RowField<Row>> table, const std::string& key,
               std::span<const Row> rows) {
    for (size_t i = 0; i < rows.size(); ++i)
        checkRow(c, table, rowKey(key, i), rows[i]);
}

} // namespace cutcell
