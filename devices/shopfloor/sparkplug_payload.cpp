// Sparkplug B payloads to and from bytes through the classes protoc generates from
// sparkplug_b.proto (sparkplug_payload.h).
#include "devices/shopfloor/sparkplug_payload.h"

#include "sparkplug_b.pb.h"

#include <cmath>
#include <limits>

namespace cutcell::sparkplug {
namespace pb = org::eclipse::tahu::protobuf;

namespace {

[[noreturn]] void fail(const Metric& m, const std::string& why) {
    throw PayloadError("Sparkplug metric " + m.label() + ": " + why);
}

bool isSigned(DataType t) {
    return t == DataType::Int8 || t == DataType::Int16 || t == DataType::Int32 ||
           t == DataType::Int64;
}
bool isUnsigned(DataType t) {
    return t == DataType::UInt8 || t == DataType::UInt16 || t == DataType::UInt32 ||
           t == DataType::UInt64 || t == DataType::DateTime;
}
bool isText(DataType t) {
    return t == DataType::String || t == DataType::Text || t == DataType::UUID ||
           t == DataType::Bytes;
}

// The range a Sparkplug integer type holds: the lowest value (0 for the unsigned ones) and the
// highest.
struct IntRange {
    std::int64_t lo;
    std::uint64_t hi;
};

IntRange intRange(DataType t) {
    switch (t) {
    case DataType::Int8:
        return {-128, 127};
    case DataType::Int16:
        return {-32768, 32767};
    case DataType::Int32:
        return {INT32_MIN, INT32_MAX};
    case DataType::Int64:
        return {INT64_MIN, INT64_MAX};
    case DataType::UInt8:
        return {0, 255};
    case DataType::UInt16:
        return {0, 65535};
    case DataType::UInt32:
        return {0, UINT32_MAX};
    default:
        return {0, UINT64_MAX}; // UInt64, DateTime
    }
}

[[noreturn]] void outOfRange(const Metric& m, const std::string& value) {
    const IntRange r = intRange(m.type);
    fail(m, value + " is outside the range of " + toString(m.type) + " [" + std::to_string(r.lo) +
                ", " + std::to_string(r.hi) + "]");
}

// 8- to 32-bit types travel in the uint32 field, 64-bit types and DateTime in the uint64 field
// (the specification's mapping). `bits` is the value as 64-bit two's complement; cutting it to
// 32 bits keeps the two's complement of a negative Int8..Int32.
void storeInteger(const Metric& m, std::uint64_t bits, pb::Payload_Metric& out) {
    if (m.type == DataType::Int64 || m.type == DataType::UInt64 || m.type == DataType::DateTime)
        out.set_long_value(bits);
    else
        out.set_int_value(static_cast<std::uint32_t>(bits));
}

void setInteger(const Metric& m, std::uint64_t v, pb::Payload_Metric& out) {
    if (v > intRange(m.type).hi) outOfRange(m, std::to_string(v));
    storeInteger(m, v, out);
}

void setInteger(const Metric& m, std::int64_t v, pb::Payload_Metric& out) {
    if (v >= 0) return setInteger(m, static_cast<std::uint64_t>(v), out);
    if (v < intRange(m.type).lo) outOfRange(m, std::to_string(v));
    storeInteger(m, static_cast<std::uint64_t>(v), out);
}

void setValue(const Metric& m, pb::Payload_Metric& out) {
    const Value& v = m.value;
    if (m.isNull()) {
        out.set_is_null(true);
        return;
    }
    if (m.type == DataType::Boolean) {
        if (!std::holds_alternative<bool>(v)) fail(m, "a Boolean takes true or false");
        out.set_boolean_value(std::get<bool>(v));
    } else if (isSigned(m.type) || isUnsigned(m.type)) {
        if (const auto* i = std::get_if<std::int64_t>(&v))
            setInteger(m, *i, out);
        else if (const auto* u = std::get_if<std::uint64_t>(&v))
            setInteger(m, *u, out);
        else
            fail(m, toString(m.type) + " takes a whole number");
    } else if (m.type == DataType::Float || m.type == DataType::Double) {
        double d = 0;
        if (const auto* f = std::get_if<float>(&v))
            d = *f;
        else if (const auto* x = std::get_if<double>(&v))
            d = *x;
        else
            fail(m, toString(m.type) + " takes a number");
        // A host (and the historian behind it) cannot store NaN or Inf meaningfully: refuse
        // here, where the metric's name is known, rather than publish a value nobody can use.
        if (!std::isfinite(d))
            fail(m, "the value is " + std::string(std::isnan(d) ? "NaN" : "Inf") +
                        " (only finite numbers are published)");
        if (m.type == DataType::Float) {
            if (std::fabs(d) > std::numeric_limits<float>::max())
                fail(m, "the value does not fit a Float");
            out.set_float_value(static_cast<float>(d));
        } else {
            out.set_double_value(d);
        }
    } else if (isText(m.type)) {
        if (!std::holds_alternative<std::string>(v)) fail(m, toString(m.type) + " takes text");
        if (m.type == DataType::Bytes)
            out.set_bytes_value(std::get<std::string>(v));
        else
            out.set_string_value(std::get<std::string>(v));
    } else {
        fail(m, "the datatype " + toString(m.type) + " is not written by CutCell");
    }
}

Value readValue(const pb::Payload_Metric& in, DataType t) {
    if (in.is_null()) return std::monostate{};
    switch (in.value_case()) {
    case pb::Payload_Metric::kIntValue: {
        const std::uint32_t raw = in.int_value();
        // Undo the two's complement of the narrow signed types.
        if (t == DataType::Int8) return std::int64_t{static_cast<std::int8_t>(raw & 0xff)};
        if (t == DataType::Int16) return std::int64_t{static_cast<std::int16_t>(raw & 0xffff)};
        if (t == DataType::Int32) return std::int64_t{static_cast<std::int32_t>(raw)};
        return std::uint64_t{raw};
    }
    case pb::Payload_Metric::kLongValue:
        if (t == DataType::Int64) return static_cast<std::int64_t>(in.long_value());
        return std::uint64_t{in.long_value()};
    case pb::Payload_Metric::kFloatValue:
        return in.float_value();
    case pb::Payload_Metric::kDoubleValue:
        return in.double_value();
    case pb::Payload_Metric::kBooleanValue:
        return in.boolean_value();
    case pb::Payload_Metric::kStringValue:
        return in.string_value();
    case pb::Payload_Metric::kBytesValue:
        return in.bytes_value();
    default:
        return std::monostate{}; // dataset, template, extension or nothing
    }
}

} // namespace

std::string toString(DataType t) {
    static const char* const kNames[] = {"Unknown", "Int8",    "Int16",  "Int32",    "Int64",
                                         "UInt8",   "UInt16",  "UInt32", "UInt64",   "Float",
                                         "Double",  "Boolean", "String", "DateTime", "Text",
                                         "UUID",    "DataSet", "Bytes",  "File",     "Template"};
    const auto i = static_cast<std::uint32_t>(t);
    if (i < std::size(kNames)) return kNames[i];
    return "Unknown(" + std::to_string(i) + ")";
}

std::string Metric::label() const {
    std::string s = name.empty() ? std::string("(no name)") : "'" + name + "'";
    if (alias) s += " (alias " + std::to_string(*alias) + ")";
    return s;
}

const Metric* Payload::find(const std::string& n) const {
    for (const Metric& m : metrics)
        if (m.name == n) return &m;
    return nullptr;
}

const Metric* Payload::findAlias(std::uint64_t a) const {
    for (const Metric& m : metrics)
        if (m.alias && *m.alias == a) return &m;
    return nullptr;
}

Metric metric(std::string name, std::optional<std::uint64_t> alias, DataType t, Value v) {
    Metric m;
    m.name = std::move(name);
    m.alias = alias;
    m.type = t;
    m.value = std::move(v);
    return m;
}

std::string encode(const Payload& p) {
    pb::Payload out;
    if (p.timestamp_ms) out.set_timestamp(p.timestamp_ms);
    if (p.seq) out.set_seq(*p.seq);
    if (!p.uuid.empty()) out.set_uuid(p.uuid);
    for (const Metric& m : p.metrics) {
        if (m.name.empty() && !m.alias) fail(m, "a metric needs a name or an alias");
        pb::Payload_Metric& o = *out.add_metrics();
        if (!m.name.empty()) o.set_name(m.name);
        if (m.alias) o.set_alias(*m.alias);
        if (m.timestamp_ms) o.set_timestamp(m.timestamp_ms);
        o.set_datatype(static_cast<std::uint32_t>(m.type));
        if (m.historical) o.set_is_historical(true);
        if (m.transient) o.set_is_transient(true);
        setValue(m, o);
        if (!m.properties.empty()) {
            pb::Payload_PropertySet& ps = *o.mutable_properties();
            for (const auto& [key, text] : m.properties) {
                ps.add_keys(key);
                pb::Payload_PropertyValue& pv = *ps.add_values();
                pv.set_type(static_cast<std::uint32_t>(DataType::String));
                pv.set_string_value(text);
            }
        }
    }
    std::string bytes;
    if (!out.SerializeToString(&bytes)) throw PayloadError("Sparkplug payload: encoding failed");
    return bytes;
}

std::optional<Payload> decode(const std::string& bytes, std::string* error) {
    pb::Payload in;
    if (!in.ParseFromString(bytes)) {
        if (error)
            *error = "not a Sparkplug B payload (" + std::to_string(bytes.size()) +
                     " bytes that do not parse as one)";
        return std::nullopt;
    }
    Payload p;
    p.timestamp_ms = in.timestamp();
    if (in.has_seq()) p.seq = in.seq();
    p.uuid = in.uuid();
    for (const pb::Payload_Metric& m : in.metrics()) {
        Metric out;
        out.name = m.name();
        if (m.has_alias()) out.alias = m.alias();
        out.timestamp_ms = m.timestamp();
        out.type = static_cast<DataType>(m.datatype());
        out.historical = m.is_historical();
        out.transient = m.is_transient();
        out.value = readValue(m, out.type);
        if (m.has_properties()) {
            const auto& ps = m.properties();
            for (int i = 0; i < ps.keys_size() && i < ps.values_size(); ++i)
                if (ps.values(i).value_case() == pb::Payload_PropertyValue::kStringValue)
                    out.properties.emplace_back(ps.keys(i), ps.values(i).string_value());
        }
        p.metrics.push_back(std::move(out));
    }
    return p;
}

} // namespace cutcell::sparkplug
