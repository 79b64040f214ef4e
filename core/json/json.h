#pragma once
// The core's JSON value (a small ordered tree) read and written through nlohmann-json
// (json.cpp): strict parsing with line/column and the key path in every message, duplicate
// keys refused, a UTF-8 BOM accepted, a size cap; numbers written locale-independently and
// never NaN or Inf.
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace cutcell::json {

class Value;
using Array = std::vector<Value>;
// Object keys keep insertion order so written files read like the documented schema.
using Object = std::vector<std::pair<std::string, Value>>;

class Value {
  public:
    Value() : data_(nullptr) {}
    Value(std::nullptr_t) : data_(nullptr) {}
    Value(bool b) : data_(b) {}
    Value(double d) : data_(d) {}
    Value(int i) : data_(static_cast<double>(i)) {}
    Value(std::int64_t i) : data_(static_cast<double>(i)) {}
    Value(const char* s) : data_(std::string(s)) {}
    Value(std::string s) : data_(std::move(s)) {}
    Value(Array a) : data_(std::make_shared<Array>(std::move(a))) {}
    Value(Object o) : data_(std::make_shared<Object>(std::move(o))) {}

    bool isNull() const { return std::holds_alternative<std::nullptr_t>(data_); }
    bool isBool() const { return std::holds_alternative<bool>(data_); }
    bool isNumber() const { return std::holds_alternative<double>(data_); }
    bool isString() const { return std::holds_alternative<std::string>(data_); }
    bool isArray() const { return std::holds_alternative<std::shared_ptr<Array>>(data_); }
    bool isObject() const { return std::holds_alternative<std::shared_ptr<Object>>(data_); }

    bool asBool() const { return std::get<bool>(data_); }
    double asNumber() const { return std::get<double>(data_); }
    const std::string& asString() const { return std::get<std::string>(data_); }
    const Array& asArray() const { return *std::get<std::shared_ptr<Array>>(data_); }
    Array& asArray() { return *std::get<std::shared_ptr<Array>>(data_); }
    const Object& asObject() const { return *std::get<std::shared_ptr<Object>>(data_); }
    Object& asObject() { return *std::get<std::shared_ptr<Object>>(data_); }

    // Object lookup; nullptr when absent or when this is not an object.
    const Value* find(const std::string& key) const;
    // Insert or replace a member (this must be an object).
    void set(const std::string& key, Value v);

    std::string typeName() const;

  private:
    std::variant<std::nullptr_t, bool, double, std::string, std::shared_ptr<Array>,
                 std::shared_ptr<Object>>
        data_;
};

struct ParseError : std::runtime_error {
    ParseError(const std::string& msg, int line_, int column_)
        : std::runtime_error(msg), line(line_), column(column_) {}
    int line;
    int column;
};

// Documents larger than this are refused before parsing (a job is a few kB).
inline constexpr size_t kMaxDocumentBytes = 16u << 20; // 16 MiB

// Throws ParseError naming line and column (0, 0 for a duplicate key or a too deep nesting,
// which name the key path instead).
Value parse(const std::string& text);
// Pretty-printed with `indent` spaces (a negative indent: all on one line, for JSON Lines);
// numbers as the shortest text that reads back to
// the same double. Throws std::domain_error naming the key path for NaN or Inf.
std::string write(const Value& v, int indent = 2);

// A string for a message: in double quotes, cut to maxChars (UTF-8 safe) with "…" appended.
std::string quote(const std::string& s, size_t maxChars = 80);
// A finite number as JSON writes it (integers without a fraction). Throws for NaN / Inf.
std::string formatNumber(double d);

} // namespace cutcell::json
