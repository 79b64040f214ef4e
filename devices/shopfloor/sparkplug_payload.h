#pragma once
// A small C++ view of a Sparkplug B payload (sparkplug_b.proto) so the edge node and the tests
// never touch the generated protobuf classes: a metric is a name and/or an alias, a Sparkplug
// datatype and one value. encode() checks what the specification requires of a value before
// the bytes leave (the datatype matches the value's kind, integers fit their type, no NaN or
// Inf); decode() reads any payload back, also one written by another implementation.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace cutcell::sparkplug {

// The Sparkplug datatype codes (Metric.datatype), as the specification numbers them.
enum class DataType : std::uint32_t {
    Unknown = 0,
    Int8 = 1,
    Int16 = 2,
    Int32 = 3,
    Int64 = 4,
    UInt8 = 5,
    UInt16 = 6,
    UInt32 = 7,
    UInt64 = 8,
    Float = 9,
    Double = 10,
    Boolean = 11,
    String = 12,
    DateTime = 13,
    Text = 14,
    UUID = 15,
    DataSet = 16,
    Bytes = 17,
    File = 18,
    Template = 19,
};

// "Double", "UInt64", ... ("Unknown(77)" for a code this list lacks).
std::string toString(DataType t);

// No value (is_null), a boolean, a signed or unsigned integer, a float, a double, or text/bytes.
// Which one a datatype takes: Boolean -> bool; Int8..Int64 -> int64; UInt8..UInt64 and
// DateTime -> uint64; Float -> float; Double -> double; String, Text, UUID, Bytes -> string.
using Value =
    std::variant<std::monostate, bool, std::int64_t, std::uint64_t, float, double, std::string>;

struct Metric {
    std::string name; // empty: by alias only (DATA after a BIRTH)
    std::optional<std::uint64_t> alias;
    std::uint64_t timestamp_ms = 0; // 0: none (the payload's timestamp applies)
    DataType type = DataType::Unknown;
    Value value;             // monostate: is_null
    bool historical = false; // is_historical: sent late from the store-and-forward queue
    bool transient = false;
    // String-valued properties ("engUnit" -> "mm"); enough for units and descriptions.
    std::vector<std::pair<std::string, std::string>> properties;

    bool isNull() const { return std::holds_alternative<std::monostate>(value); }
    // "'Axes/1/Position' (alias 101)", for messages.
    std::string label() const;
};

struct Payload {
    std::uint64_t timestamp_ms = 0;
    std::optional<std::uint64_t> seq; // absent in NDEATH
    std::vector<Metric> metrics;
    std::string uuid;

    // The first metric with this name / alias, or nullptr.
    const Metric* find(const std::string& name) const;
    const Metric* findAlias(std::uint64_t alias) const;
};

struct PayloadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws PayloadError naming the metric for a value that does not fit its datatype, a NaN or an
// Inf, a datatype this API does not write (DataSet, Template, File), or a metric with neither
// a name nor an alias.
std::string encode(const Payload& p);
// nullopt (and *error set) for bytes that are not a Sparkplug B payload; datasets, templates
// and extensions are skipped (their metrics keep type and name, value null).
std::optional<Payload> decode(const std::string& bytes, std::string* error = nullptr);

// A metric of the given type and value, for building payloads briefly.
Metric metric(std::string name, std::optional<std::uint64_t> alias, DataType t, Value v);

} // namespace cutcell::sparkplug
