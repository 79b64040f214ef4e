#include "core/job/row_table.h"

namespace cutcell {

std::string rowKey(const std::string& array, size_t i) {
    return array + "[" + std::to_string(i) + "]";
}

const json::Array& requiredRows(SectionReader& parent, const std::string& leaf, size_t count,
                                const char* rowsAre) {
    const std::string n = std::to_string(count);
    const json::Value* m = parent.get(leaf);
    if (!m)
        throw JobError("missing required key " + parent.key(leaf) + " (" + n + " rows: " + rowsAre +
                       ")");
    if (!m->isArray())
        throw JobError(parent.key(leaf) + " must be an array of " + n + " rows (" + rowsAre +
                       "), found " + m->typeName());
    const auto& arr = m->asArray();
    if (arr.size() != count)
        throw JobError(parent.key(leaf) + " has " + std::to_string(arr.size()) +
                       " rows; it needs " + n + " (" + rowsAre + ")");
    return arr;
}

} // namespace cutcell
