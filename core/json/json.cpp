// Parsing and writing through nlohmann-json (Debian nlohmann-json3-dev). The parser runs as a
// SAX handler that builds the small Value tree the core uses, checks duplicate keys with one
// hash set per open object (linear in the document), tracks the key path for every message
// and limits the nesting depth. Numbers are read and written without the C locale's help, so a
// German or French locale (decimal comma) changes nothing.
#include "core/json/json.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <tuple>
#include <unordered_set>

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

std::string quote(const std::string& s, size_t maxChars) {
    std::string body = s;
    if (body.size() > maxChars) {
        size_t cut = maxChars;
        // Do not split a UTF-8 sequence.
        while (cut > 0 && (static_cast<unsigned char>(body[cut]) & 0xC0) == 0x80)
            --cut;
        body = body.substr(0, cut) + "\xE2\x80\xA6"; // "…"
    }
    return "\"" + body + "\"";
}

std::string formatNumber(double d) {
    if (!std::isfinite(d)) throw std::domain_error("a number is not finite (NaN or Inf)");
    if (d == std::floor(d) && std::fabs(d) < 1e15)
        return nlohmann::json(static_cast<std::int64_t>(d)).dump();
    return nlohmann::json(d).dump(); // shortest text that reads back to the same double
}

namespace {

using nl = nlohmann::json;

constexpr int kMaxDepth = 64;

// Builds Values from nlohmann's SAX events.
class Builder : public nlohmann::json_sax<nl> {
  public:
    std::string error; // set when a check of ours stops the parse
    Value root;

    bool null() override { return add(Value()); }
    bool boolean(bool b) override { return add(Value(b)); }
    bool number_integer(number_integer_t v) override { return add(Value(static_cast<double>(v))); }
    bool number_unsigned(number_unsigned_t v) override {
        return add(Value(static_cast<double>(v)));
    }
    bool number_float(number_float_t v, const string_t& text) override {
        if (!std::isfinite(v))
            return fail(where() + "the number " + quote(text, 40) +
                        " is out of the range of a double");
        return add(Value(v));
    }
    bool string(string_t& s) override { return add(Value(std::move(s))); }
    bool binary(binary_t&) override { return fail("binary values are not JSON"); }

    bool start_object(std::size_t) override {
        if (!open(Value(Object{}))) return false;
        keys_.emplace_back();
        return true;
    }
    bool key(string_t& k) override {
        Frame& f = stack_.back();
        if (!keys_.back().insert(k).second)
            return fail("duplicate key " + quote(joinPath(k), 80) +
                        " (each key may appear once in an object)");
        f.key = k;
        return true;
    }
    bool end_object() override {
        keys_.pop_back();
        return close();
    }
    bool start_array(std::size_t) override { return open(Value(Array{})); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& ex) override {
        // "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..."
        nlohmannMessage = ex.what();
        nlohmannPosition = position; // bytes read: where it failed (also for a number overflow)
        return false;
    }
    std::string nlohmannMessage;
    std::size_t nlohmannPosition = 0;

    // "main_pipe.radius_mm" of the value being read, or "" at the top.
    std::string currentPath() const { return joinPath(""); }

  private:
    struct Frame {
        Value value;
        std::string key;  // objects: the key of the member being read
        size_t index = 0; // arrays: the index of the element being read
    };
    std::vector<Frame> stack_;
    std::vector<std::unordered_set<std::string>> keys_;

    std::string joinPath(const std::string& last) const {
        std::string p;
        for (const Frame& f : stack_) {
            if (f.value.isObject()) {
                const std::string& k = (&f == &stack_.back() && !last.empty()) ? last : f.key;
                if (k.empty()) continue;
                p += (p.empty() ? "" : ".") + k;
            } else {
                p += "[" + std::to_string(f.index) + "]";
            }
        }
        return p;
    }
    std::string where() const {
        const std::string p = currentPath();
        return p.empty() ? "" : "at " + quote(p, 80) + ": ";
    }
    bool fail(const std::string& msg) {
        error = msg;
        return false;
    }
    bool add(Value v) {
        if (stack_.empty()) {
            root = std::move(v);
            return true;
        }
        Frame& f = stack_.back();
        if (f.value.isObject()) {
            f.value.asObject().emplace_back(f.key, std::move(v));
        } else {
            f.value.asArray().push_back(std::move(v));
            ++f.index;
        }
        return true;
    }
    bool open(Value v) {
        if (static_cast<int>(stack_.size()) >= kMaxDepth)
            return fail(where() + "nesting deeper than " + std::to_string(kMaxDepth) + " levels");
        stack_.push_back({std::move(v), {}, 0});
        return true;
    }
    bool close() {
        Value v = std::move(stack_.back().value);
        stack_.pop_back();
        return add(std::move(v));
    }
};

void writeString(std::string& os, const std::string& s) {
    // nlohmann escapes control characters and checks UTF-8 (invalid bytes become U+FFFD).
    os += nl(s).dump(-1, ' ', false, nl::error_handler_t::replace);
}

void writeValue(std::string& os, const Value& v, int indent, int level, const std::string& path) {
    const bool oneLine = indent < 0; // JSON Lines: no line break anywhere
    const std::string pad(oneLine ? 0 : static_cast<size_t>(indent * (level + 1)), ' ');
    const std::string padEnd(oneLine ? 0 : static_cast<size_t>(indent * level), ' ');
    const std::string newline = oneLine ? "" : "\n";
    if (v.isNull())
        os += "null";
    else if (v.isBool())
        os += v.asBool() ? "true" : "false";
    else if (v.isNumber()) {
        if (!std::isfinite(v.asNumber()))
            throw std::domain_error("refusing to write " +
                                    std::string(std::isnan(v.asNumber()) ? "NaN" : "Inf") + " at " +
                                    (path.empty() ? "the top" : path) +
                                    ": JSON output holds finite numbers only");
        os += formatNumber(v.asNumber());
    } else if (v.isString())
        writeString(os, v.asString());
    else if (v.isArray()) {
        const auto& a = v.asArray();
        if (a.empty()) {
            os += "[]";
            return;
        }
        // Arrays of scalars stay on one line: tables of numbers read better that way.
        bool flat = true;
        for (const auto& e : a)
            flat = flat && !e.isArray() && !e.isObject();
        flat = flat || oneLine;
        os += '[';
        for (size_t i = 0; i < a.size(); ++i) {
            if (i) os += flat ? ", " : ",";
            if (!flat) os += "\n" + pad;
            writeValue(os, a[i], indent, level + 1, path + "[" + std::to_string(i) + "]");
        }
        if (!flat) os += "\n" + padEnd;
        os += ']';
    } else {
        const auto& o = v.asObject();
        if (o.empty()) {
            os += "{}";
            return;
        }
        os += '{';
        for (size_t i = 0; i < o.size(); ++i) {
            if (i) os += oneLine ? ", " : ",";
            os += newline + pad;
            writeString(os, o[i].first);
            os += ": ";
            writeValue(os, o[i].second, indent, level + 1,
                       path.empty() ? o[i].first : path + "." + o[i].first);
        }
        os += newline + padEnd + '}';
    }
}

// 1-based line and column of a byte offset.
std::pair<int, int> lineAndColumn(std::string_view text, size_t offset) {
    int line = 1, col = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return {line, col};
}

} // namespace

Value parse(const std::string& input) {
    if (input.size() > kMaxDocumentBytes)
        throw ParseError("the JSON document is " + std::to_string(input.size()) +
                             " bytes; the limit is " + std::to_string(kMaxDocumentBytes) +
                             " bytes (16 MiB)",
                         1, 1);
    // A UTF-8 byte order mark (some Windows editors write one) is not part of the document.
    const std::string_view bom = "\xEF\xBB\xBF";
    std::string_view text(input);
    if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
    if (text.substr(0, bom.size()) == bom) // nlohmann skipped a second one too
        throw ParseError("JSON syntax error at line 1, column 1: a second UTF-8 byte order mark", 1,
                         1);

    // A NUL byte is no part of a JSON text (nlohmann stopped reading there and accepted
    // whatever came before it).
    if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
        const auto [line, col] = lineAndColumn(text, nul);
        throw ParseError("JSON syntax error at line " + std::to_string(line) + ", column " +
                             std::to_string(col) + ": a NUL byte (not a text file?)",
                         line, col);
    }
    Builder b;
    bool ok = false;
    try {
        ok = nl::sax_parse(text.begin(), text.end(), &b, nlohmann::detail::input_format_t::json,
                           true, false);
    } catch (const nl::exception& e) {
        b.nlohmannMessage = e.what();
    }
    if (ok) return std::move(b.root);
    if (!b.error.empty()) throw ParseError(b.error, 0, 0);
    // nlohmann's message carries line and column; repeat them in our form and add the key.
    int line = 0, col = 0;
    std::string msg = b.nlohmannMessage;
    if (const size_t at = msg.find("parse error at line ");
        at != std::string::npos &&
        std::sscanf(msg.c_str() + at, "parse error at line %d, column %d", &line, &col) == 2) {
        const size_t colon = msg.find(": ", at);
        msg = colon == std::string::npos ? msg : msg.substr(colon + 2);
    } else if (const size_t close = msg.find("] "); close != std::string::npos) {
        msg = msg.substr(close + 2); // "[json.exception.out_of_range.406] number overflow ..."
    }
    // A message without a place (a number overflow): where the parser stopped reading.
    if (line == 0 && b.nlohmannPosition > 0)
        std::tie(line, col) = lineAndColumn(text, b.nlohmannPosition - 1);
    // The text it quotes is not repeated whole (a 400-digit number).
    const size_t q1 = msg.find('\''), q2 = msg.rfind('\'');
    if (q1 != std::string::npos && q2 > q1 + 41)
        msg = msg.substr(0, q1 + 38) + "...' (" + std::to_string(q2 - q1 - 1) + " characters)" +
              msg.substr(q2 + 1);
    if (msg.size() > 200) msg = msg.substr(0, 200) + "\xE2\x80\xA6";
    const std::string inKey = b.currentPath();
    throw ParseError(
        std::string("JSON syntax error") +
            (line > 0 ? " at line " + std::to_string(line) + ", column " + std::to_string(col)
                      : std::string()) +
            (inKey.empty() ? "" : " (in " + quote(inKey, 80) + ")") + ": " + msg,
        line, col);
}

std::string write(const Value& v, int indent) {
    std::string os;
    writeValue(os, v, indent, 0, "");
    os += '\n';
    return os;
}

} // namespace cutcell::json
