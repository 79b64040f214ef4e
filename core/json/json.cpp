#include "core/json/json.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace cutcell::json {

const Value* Value::find(const std::string& key) const {
    if (!isObject()) return nullptr;
    for (const auto& [k, v] : asObject())
        if (k == key) return &v;
    return nullptr;
}

void Value::set(const std::string& key, Value v) {
    auto& obj = asObject();
    for (auto& [k, existing] : obj)
        if (k == key) {
            existing = std::move(v);
            return;
        }
    obj.emplace_back(key, std::move(v));
}

std::string Value::typeName() const {
    if (isNull()) return "null";
    if (isBool()) return "boolean";
    if (isNumber()) return "number";
    if (isString()) return "string";
    if (isArray()) return "array";
    return "object";
}

namespace {

class Parser {
  public:
    explicit Parser(const std::string& text) : s_(text) {}

    Value parseDocument() {
        skipSpace();
        Value v = parseValue(0);
        skipSpace();
        if (pos_ != s_.size()) fail("unexpected text after the JSON value");
        return v;
    }

  private:
    static constexpr int kMaxDepth = 64;
    const std::string& s_;
    size_t pos_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        int line = 1, col = 1;
        for (size_t i = 0; i < pos_ && i < s_.size(); ++i) {
            if (s_[i] == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        throw ParseError("JSON syntax error at line " + std::to_string(line) + ", column " +
                             std::to_string(col) + ": " + what,
                         line, col);
    }

    void skipSpace() {
        while (pos_ < s_.size() &&
               (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r'))
            ++pos_;
    }

    char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }

    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++pos_;
    }

    Value parseValue(int depth) {
        if (depth > kMaxDepth) fail("nesting deeper than 64 levels");
        switch (peek()) {
        case '{':
            return parseObject(depth);
        case '[':
            return parseArray(depth);
        case '"':
            return Value(parseString());
        case 't':
            literal("true");
            return Value(true);
        case 'f':
            literal("false");
            return Value(false);
        case 'n':
            literal("null");
            return Value(nullptr);
        case '\0':
            fail("unexpected end of input");
        default:
            return Value(parseNumber());
        }
    }

    void literal(const char* word) {
        for (const char* p = word; *p; ++p) {
            if (peek() != *p) fail(std::string("invalid literal, expected '") + word + "'");
            ++pos_;
        }
    }

    Value parseObject(int depth) {
        expect('{');
        Object obj;
        skipSpace();
        if (peek() == '}') {
            ++pos_;
            return Value(std::move(obj));
        }
        for (;;) {
            skipSpace();
            if (peek() != '"') fail("expected a quoted member name");
            std::string key = parseString();
            for (const auto& [k, v] : obj)
                if (k == key) fail("duplicate member \"" + key + "\"");
            skipSpace();
            expect(':');
            skipSpace();
            obj.emplace_back(std::move(key), parseValue(depth + 1));
            skipSpace();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            expect('}');
            return Value(std::move(obj));
        }
    }

    Value parseArray(int depth) {
        expect('[');
        Array arr;
        skipSpace();
        if (peek() == ']') {
            ++pos_;
            return Value(std::move(arr));
        }
        for (;;) {
            skipSpace();
            arr.push_back(parseValue(depth + 1));
            skipSpace();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            expect(']');
            return Value(std::move(arr));
        }
    }

    static void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    unsigned parseHex4() {
        unsigned v = 0;
        for (int i = 0; i < 4; ++i) {
            char c = peek();
            ++pos_;
            v <<= 4;
            if (c >= '0' && c <= '9')
                v |= static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f')
                v |= static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                v |= static_cast<unsigned>(c - 'A' + 10);
            else
                fail("invalid \\u escape");
        }
        return v;
    }

    std::string parseString() {
        expect('"');
        std::string out;
        for (;;) {
            if (pos_ >= s_.size()) fail("unterminated string");
            char c = s_[pos_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            char e = peek();
            ++pos_;
            switch (e) {
            case '"':
                out += '"';
                break;
            case '\\':
                out += '\\';
                break;
            case '/':
                out += '/';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                unsigned cp = parseHex4();
                if (cp >= 0xD800 && cp < 0xDC00 && peek() == '\\') {
                    ++pos_;
                    expect('u');
                    unsigned lo = parseHex4();
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                }
                appendUtf8(out, cp);
                break;
            }
            default:
                --pos_;
                fail("invalid escape in string");
            }
        }
    }

    double parseNumber() {
        size_t start = pos_;
        if (peek() == '-') ++pos_;
        if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("invalid value");
        while (std::isdigit(static_cast<unsigned char>(peek())))
            ++pos_;
        if (peek() == '.') {
            ++pos_;
            if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("invalid number");
            while (std::isdigit(static_cast<unsigned char>(peek())))
                ++pos_;
        }
        if (peek() == 'e' || peek() == 'E') {
            ++pos_;
            if (peek() == '+' || peek() == '-') ++pos_;
            if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("invalid exponent");
            while (std::isdigit(static_cast<unsigned char>(peek())))
                ++pos_;
        }
        const std::string token = s_.substr(start, pos_ - start);
        double v = std::strtod(token.c_str(), nullptr);
        if (!std::isfinite(v)) fail("number out of range");
        return v;
    }
};

void writeString(std::ostringstream& os, const std::string& s) {
    os << '"';
    for (char c : s) {
        switch (c) {
        case '"':
            os << "\\\"";
            break;
        case '\\':
            os << "\\\\";
            break;
        case '\n':
            os << "\\n";
            break;
        case '\r':
            os << "\\r";
            break;
        case '\t':
            os << "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
                os << buf;
            } else {
                os << c;
            }
        }
    }
    os << '"';
}

void writeNumber(std::ostringstream& os, double d) {
    if (d == std::floor(d) && std::fabs(d) < 1e15) {
        os << static_cast<long long>(d);
        return;
    }
    // Shortest of 15 or 17 significant digits that reads back to the same double.
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", d);
    if (std::strtod(buf, nullptr) != d) std::snprintf(buf, sizeof buf, "%.17g", d);
    os << buf;
}

void writeValue(std::ostringstream& os, const Value& v, int indent, int level) {
    const std::string pad(static_cast<size_t>(indent * (level + 1)), ' ');
    const std::string padEnd(static_cast<size_t>(indent * level), ' ');
    if (v.isNull())
        os << "null";
    else if (v.isBool())
        os << (v.asBool() ? "true" : "false");
    else if (v.isNumber())
        writeNumber(os, v.asNumber());
    else if (v.isString())
        writeString(os, v.asString());
    else if (v.isArray()) {
        const auto& a = v.asArray();
        if (a.empty()) {
            os << "[]";
            return;
        }
        // Arrays of scalars stay on one line: tables of numbers read better that way.
        bool flat = true;
        for (const auto& e : a)
            flat = flat && !e.isArray() && !e.isObject();
        os << '[';
        for (size_t i = 0; i < a.size(); ++i) {
            if (i) os << (flat ? ", " : ",");
            if (!flat) os << '\n' << pad;
            writeValue(os, a[i], indent, level + 1);
        }
        if (!flat) os << '\n' << padEnd;
        os << ']';
    } else {
        const auto& o = v.asObject();
        if (o.empty()) {
            os << "{}";
            return;
        }
        os << '{';
        for (size_t i = 0; i < o.size(); ++i) {
            if (i) os << ',';
            os << '\n' << pad;
            writeString(os, o[i].first);
            os << ": ";
            writeValue(os, o[i].second, indent, level + 1);
        }
        os << '\n' << padEnd << '}';
    }
}

} // namespace

Value parse(const std::string& text) {
    return Parser(text).parseDocument();
}

std::string write(const Value& v, int indent) {
    std::ostringstream os;
    writeValue(os, v, indent, 0);
    os << '\n';
    return os.str();
}

} // namespace cutcell::json
