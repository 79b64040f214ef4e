#include "core/machines/section_steel/dstv/dstv_reader.h"

#include "core/common/c_format.h"
#include "core/json/json.h"

#include <cctype>
#include <cmath>
#include <optional>

namespace cutcell::dstv {

DstvError::DstvError(int l, const std::string& message)
    : std::runtime_error("line " + std::to_string(l) + ": " + message), line(l) {}

namespace {

// Largest coordinate or dimension accepted (mm): longer than any bar a beam line takes.
constexpr double kMaxMm = 100000;

std::string trim(const std::string& s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
        ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
        --b;
    return s.substr(a, b - a);
}

std::string num(double v) {
    return formatC("%g", v);
}

bool isBlockCode(const std::string& code) {
    static const char* const known[] = {"ST", "EN", "BO", "SI", "AK", "IK", "PU",
                                        "KO", "SC", "TO", "UE", "PR", "KA", "IN"};
    for (const char* k : known)
        if (code == k) return true;
    // Plane blocks: E, B, S, A, I, P, K followed by the plane number 0..9.
    return code.size() == 2 && std::string("EBSAIPK").find(code[0]) != std::string::npos &&
           code[1] >= '0' && code[1] <= '9';
}

// A number of a field, checked: "line N: <field> = "<text>" is not a number" or out of range.
double checkedNumber(const std::string& text, int line, const std::string& field, double lo,
                     double hi, const char* unit) {
    std::string t = text;
    if (!t.empty() && t[0] == '+') t.erase(0, 1);
    const std::optional<double> v = parseDouble(t);
    if (!v || !std::isfinite(*v))
        throw DstvError(line, field + " = " + json::quote(text) + " is not a number" +
                                  (text.find(',') != std::string::npos
                                       ? " (DSTV numbers take a decimal point)"
                                       : ""));
    if (*v < lo || *v > hi)
        throw DstvError(line, field + " = " + num(*v) + " " + unit + " is outside [" + num(lo) +
                                  ", " + num(hi) + "] " + unit);
    return *v;
}

// One number of a data line and the letters written right after it.
struct Value {
    std::string text;
    std::string flag;
};

// A data line split into its face letter (0 when absent) and values. A "**" ends the line.
struct DataLine {
    char face = 0;
    std::vector<Value> values;
};

// Field names by position, for messages.
const std::vector<std::string> kContourFields = {"x",
                                                 "y",
                                                 "radius",
                                                 "weld preparation angle 1",
                                                 "weld preparation blunting 1",
                                                 "weld preparation angle 2",
                                                 "weld preparation blunting 2"};
const std::vector<std::string> kHoleFields = {"x",          "y",           "diameter",  "depth",
                                              "slot width", "slot height", "slot angle"};

DataLine splitDataLine(const std::string& raw, int line, const std::vector<std::string>& fields) {
    std::string s = raw;
    if (const size_t c = s.find("**"); c != std::string::npos) s.erase(c);
    DataLine out;
    size_t i = 0;
    while (i < s.size()) {
        const unsigned char ch = static_cast<unsigned char>(s[i]);
        if (std::isspace(ch)) {
            ++i;
        } else if (std::isdigit(ch) || ch == '.' || ch == '-' || ch == '+') {
            size_t j = i;
            while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                                    s[j] == '-' || s[j] == '+' || s[j] == ','))
                ++j;
            out.values.push_back({s.substr(i, j - i), {}});
            i = j;
        } else if (std::isalpha(ch)) {
            size_t j = i;
            while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j])))
                ++j;
            const std::string letters = s.substr(i, j - i);
            if (out.values.empty() && out.face == 0) {
                if (letters.size() != 1 ||
                    std::string("vouh").find(letters[0]) == std::string::npos)
                    throw DstvError(line,
                                    "face " + json::quote(letters) +
                                        " is not v (front), o (top), u (bottom) or h (behind)");
                out.face = letters[0];
            } else if (!out.values.empty() &&
                       (letters.size() != 1 ||
                        !std::islower(static_cast<unsigned char>(letters[0])))) {
                // "3OO.00": a number with letters in it (a flag is one lower-case letter).
                size_t a = i, b = j;
                while (a > 0 && !std::isspace(static_cast<unsigned char>(s[a - 1])))
                    --a;
                while (b < s.size() && !std::isspace(static_cast<unsigned char>(s[b])))
                    ++b;
                const size_t k = out.values.size() - 1;
                const std::string field =
                    k < fields.size() ? fields[k] : "value " + std::to_string(k + 1);
                throw DstvError(line, field + " " + json::quote(s.substr(a, b - a)) +
                                          " is not a number (a flag after a number is one "
                                          "lower-case letter)");
            } else if (out.values.empty() || !out.values.back().flag.empty()) {
                throw DstvError(line, "unexpected letters " + json::quote(letters) +
                                          " (a flag follows a number)");
            } else {
                out.values.back().flag = letters;
            }
            i = j;
        } else {
            throw DstvError(line, std::string("unexpected character '") + s[i] + "' in column " +
                                      std::to_string(i + 1));
        }
    }
    return out;
}

void checkFlag(const Value& v, int line, const std::string& field, const std::string& allowed) {
    if (v.flag.empty()) return;
    if (v.flag.size() != 1 || allowed.find(v.flag[0]) == std::string::npos) {
        std::string list;
        for (char c : allowed)
            list += (list.empty() ? "" : ", ") + std::string(1, c);
        throw DstvError(
            line, field + " " + json::quote(v.text + v.flag) + ": flag " + json::quote(v.flag) +
                      (allowed.empty() ? " not allowed here" : " is not one of " + list));
    }
}

struct Line {
    int number;
    std::string text;
};

class Reader {
  public:
    // Lines end in LF, CR LF or a lone CR (old Macintosh exports); a last line without its
    // end is a line.
    explicit Reader(const std::string& text) {
        int n = 0;
        size_t a = 0;
        while (a < text.size()) {
            size_t b = text.find_first_of("\r\n", a);
            if (b == std::string::npos) b = text.size();
            lines_.push_back({++n, text.substr(a, b - a)});
            a = b + (text.compare(b, 2, "\r\n") == 0 ? 2 : 1);
        }
    }

    Header parseHeader() {
        Header h;
        skipBlankAndComments();
        if (at_ >= lines_.size()) throw DstvError(1, "empty file: no ST block");
        if (code(lines_[at_]) != "ST")
            throw DstvError(lines_[at_].number, "the file must start with the ST block, found " +
                                                    json::quote(trim(lines_[at_].text)));
        readHeader(h);
        return h;
    }

    Part parse() {
        Part part;
        part.header = parseHeader();
        while (true) {
            skipBlankAndComments();
            if (at_ >= lines_.size())
                throw DstvError(static_cast<int>(lines_.size()) + 1,
                                "the file ends without the EN block (truncated?)");
            const Line& l = lines_[at_];
            if (isData(l))
                throw DstvError(l.number,
                                "data line outside a block: " + json::quote(trim(l.text)));
            const std::string c = code(l);
            if (!isBlockCode(c)) throw DstvError(l.number, "unknown block " + json::quote(c));
            if (c == "ST") throw DstvError(l.number, "second ST block (one piece per file)");
            ++at_;
            if (c == "EN") {
                part.end_line = l.number;
                break;
            }
            const std::vector<Line> data = blockData();
            if (c == "AK" || c == "IK")
                readContours(l.number, c == "AK", data, part.contours);
            else if (c == "BO")
                for (const Line& d : data)
                    part.holes.push_back(readHole(d));
            else if (c == "SI")
                for (const Line& d : data)
                    part.markings.push_back(readMarking(d));
            else
                part.others.push_back({l.number, c, static_cast<int>(data.size())});
        }
        for (size_t i = at_; i < lines_.size(); ++i) {
            const std::string t = trim(lines_[i].text);
            if (!t.empty() && t.rfind("**", 0) != 0)
                throw DstvError(lines_[i].number, "text after the EN block: " + json::quote(t));
        }
        return part;
    }

  private:
    // What a line is. The standard puts a block code in columns 1-2 and data two blanks in, but
    // writers in the wild drop the blanks (of header lines, of contour points): a line is a
    // block line when it holds nothing but two capitals (or a capital and a digit), a comment
    // when it starts with "**", else data.
    static bool isComment(const Line& l) { return trim(l.text).rfind("**", 0) == 0; }
    static bool isBlank(const Line& l) { return trim(l.text).empty(); }
    // The block code a line holds alone ("" when it holds anything else); never throws.
    static std::string plainBlockCode(const Line& l) {
        std::string t = l.text;
        if (const size_t c = t.find("**"); c != std::string::npos) t.erase(c);
        t = trim(t);
        const bool code = t.size() == 2 && std::isupper(static_cast<unsigned char>(t[0])) &&
                          (std::isupper(static_cast<unsigned char>(t[1])) ||
                           std::isdigit(static_cast<unsigned char>(t[1])));
        return code ? t : std::string();
    }
    // The same, refusing a known code in columns 1-2 with data on its line ("AK  v 0 0 0").
    static std::string blockCodeOf(const Line& l) {
        std::string t = plainBlockCode(l);
        if (t.empty()) {
            const std::string c = l.text.substr(0, 2);
            if (l.text.size() > 2 && isBlockCode(c) &&
                std::isspace(static_cast<unsigned char>(l.text[2])) && !isComment(l))
                throw DstvError(l.number, "text after the block code " + c + ": " +
                                              json::quote(trim(l.text.substr(2))) +
                                              " (a block's data go on the lines below it)");
        }
        return t;
    }
    static bool isData(const Line& l) {
        return !isBlank(l) && !isComment(l) && blockCodeOf(l).empty();
    }
    // The block code of a line that is no data.
    static std::string code(const Line& l) {
        const std::string c = blockCodeOf(l);
        return c.empty() ? trim(l.text) : c;
    }

    void skipBlankAndComments() {
        while (at_ < lines_.size() && (isBlank(lines_[at_]) || isComment(lines_[at_])))
            ++at_;
    }

    // The data lines of the block just opened (comments and blank lines skipped).
    std::vector<Line> blockData() {
        std::vector<Line> out;
        while (at_ < lines_.size()) {
            const Line& l = lines_[at_];
            if (isComment(l) || isBlank(l)) {
                ++at_;
                continue;
            }
            if (!isData(l)) break;
            out.push_back(l);
            ++at_;
        }
        return out;
    }

    void readHeader(Header& h) {
        h.line = lines_[at_].number;
        ++at_;
        static const char* const names[24] = {"order identification",
                                              "drawing identification",
                                              "phase identification",
                                              "piece identification",
                                              "steel quality",
                                              "quantity of pieces",
                                              "profile",
                                              "profile code",
                                              "length",
                                              "profile height",
                                              "flange width",
                                              "flange thickness",
                                              "web thickness",
                                              "radius",
                                              "weight by meter",
                                              "painting surface by meter",
                                              "web start cut",
                                              "web end cut",
                                              "flange start cut",
                                              "flange end cut",
                                              "text info 1",
                                              "text info 2",
                                              "text info 3",
                                              "text info 4"};
        // Fields by position, with or without their leading blanks; a line holding only a
        // known block code ends the header (the texts are optional, the 20 fields are not).
        std::array<std::string, 24> value;
        int n = 0;
        while (n < 24 && at_ < lines_.size()) {
            const Line& l = lines_[at_];
            if (isComment(l)) {
                ++at_;
                continue;
            }
            // A mark may read like a block code ("B1"): only where a number or a text line is
            // due does a block code end the header, and only one written from column 1 (an
            // indented "  NA" or "  EN 10025" is a text).
            const bool numberDue = n == 5 || (n >= 8 && n < 20);
            const bool indented =
                !l.text.empty() && std::isspace(static_cast<unsigned char>(l.text[0]));
            const std::string c = indented ? std::string() : plainBlockCode(l);
            if ((numberDue || n >= 20) && isBlockCode(c)) break; // the next block
            // Where the texts are due, two capitals followed by indented data are a block (an
            // unknown one, refused by name below), not a text such as "NA".
            if (n >= 20 && !c.empty() && at_ + 1 < lines_.size() && isData(lines_[at_ + 1]) &&
                std::isspace(static_cast<unsigned char>(lines_[at_ + 1].text[0])))
                break;
            value[static_cast<size_t>(n)] = trim(l.text);
            h.field_line[static_cast<size_t>(n)] = l.number;
            ++n;
            ++at_;
        }
        if (n < 20) {
            const int where =
                at_ < lines_.size() ? lines_[at_].number : static_cast<int>(lines_.size()) + 1;
            throw DstvError(where, "ST header truncated: field " + std::to_string(n + 1) + " (" +
                                       names[n] + ") missing; the header has 20 lines " +
                                       "(order .. flange end cut) and up to 4 text lines");
        }
        // Blank lines read as the texts may be the gap before the next block: give them back.
        while (n > 20 && value[static_cast<size_t>(n - 1)].empty()) {
            --n;
            h.field_line[static_cast<size_t>(n)] = 0;
        }
        const auto line = [&](int i) { return h.field_line[static_cast<size_t>(i)]; };
        const auto field = [&](int i) {
            return std::string(names[i]) + " (header field " + std::to_string(i + 1) + ")";
        };
        const auto number = [&](int i, double lo, double hi, const char* unit) {
            if (value[static_cast<size_t>(i)].empty())
                throw DstvError(line(i), field(i) + " is empty");
            return checkedNumber(value[static_cast<size_t>(i)], line(i), field(i), lo, hi, unit);
        };
        h.order = value[0];
        h.drawing = value[1];
        h.phase = value[2];
        h.piece = value[3];
        h.steel_grade = value[4];
        const double q = number(5, 1, 1e6, "pieces");
        if (q != std::floor(q))
            throw DstvError(line(5), field(5) + " = " + value[5] + " is not a whole number");
        h.quantity = static_cast<int>(q);
        h.profile = value[6];
        if (h.profile.empty()) throw DstvError(line(6), field(6) + " is empty");
        h.profile_code = value[7];
        static const char* const codes[] = {"I", "U", "L", "B", "RU", "RO", "M", "C", "T", "SO"};
        bool known = false;
        for (const char* c : codes)
            known = known || h.profile_code == c;
        if (!known)
            throw DstvError(line(7), field(7) + " " + json::quote(h.profile_code) +
                                         " is not one of I, U, L, B, RU, RO, M, C, T, SO");
        // "length[ saw length]" or "length,saw length" (Tekla writes "233.70,233.70"): the saw
        // length (the rough length before the end cuts) may follow. "5000,00" is no such pair
        // (00 is no saw length of a 5 m piece): a decimal comma, refused as one.
        std::string len = value[8];
        std::string saw;
        if (const size_t sep = len.find_first_of(" \t,"); sep != std::string::npos) {
            const std::string first = len.substr(0, sep), second = trim(len.substr(sep + 1));
            // A pair as Tekla writes it has a decimal point in each half ("1000,500" is a
            // decimal comma, refused as one, not a length of 1000 and a saw length of 500).
            const std::optional<double> a = parseDouble(first), b = parseDouble(second);
            const bool points =
                first.find('.') != std::string::npos && second.find('.') != std::string::npos;
            const bool pair = a && b && points && *a > 0;
            if (len[sep] != ',' || pair) {
                saw = second;
                len = first;
            }
        }
        h.length_mm = checkedNumber(len, line(8), field(8), 1, kMaxMm, "mm");
        if (!saw.empty()) {
            h.saw_length_mm = checkedNumber(saw, line(8), "saw length (header field 9)",
                                            h.length_mm * 0.5, h.length_mm * 1.5, "mm");
        }
        h.h_mm = number(9, 0, 5000, "mm");
        h.b_mm = number(10, 0, 5000, "mm");
        h.tf_mm = number(11, 0, 500, "mm");
        h.tw_mm = number(12, 0, 500, "mm");
        h.r_mm = number(13, 0, 500, "mm");
        h.weight_kg_per_m = number(14, 0, 1e5, "kg/m");
        h.paint_m2_per_m = number(15, 0, 100, "m2/m");
        // Saw cut angles: a square cut is 0; +-90 would be a cut along the bar.
        h.web_start_deg = number(16, -89.9, 89.9, "deg");
        h.web_end_deg = number(17, -89.9, 89.9, "deg");
        h.flange_start_deg = number(18, -89.9, 89.9, "deg");
        h.flange_end_deg = number(19, -89.9, 89.9, "deg");
        for (int i = 20; i < n; ++i)
            h.text[static_cast<size_t>(i - 20)] = value[static_cast<size_t>(i)];
    }

    // An AK / IK block: points until the contour closes; a closed contour followed by more
    // points starts the next contour of the block.
    void readContours(int blockLine, bool outer, const std::vector<Line>& data,
                      std::vector<Contour>& out) {
        const char* what = outer ? "AK" : "IK";
        if (data.empty()) throw DstvError(blockLine, std::string(what) + " block without points");
        Contour c;
        c.line = blockLine;
        c.outer = outer;
        char face = 0;
        int closed = 0; // contours of this block so far
        const auto close = [&](int line) {
            const ContourPoint& a = c.points.front();
            const ContourPoint& b = c.points.back();
            // A circle is two arcs: start, opposite point (with radii), start again.
            bool arcs = false;
            for (const ContourPoint& p : c.points)
                arcs = arcs || p.radius_mm != 0;
            const size_t least = arcs ? 3 : 4;
            if (c.points.size() < least)
                throw DstvError(line, std::string(what) + " contour on face " +
                                          std::string(1, c.face) + " has " +
                                          std::to_string(c.points.size()) +
                                          " points: a closed contour needs at least " +
                                          std::to_string(least) + (arcs ? "" : " (3 with arcs)"));
            if (a.x_mm != b.x_mm || a.y_mm != b.y_mm)
                throw DstvError(line,
                                std::string(what) + " contour on face " + std::string(1, c.face) +
                                    " is not closed: it starts (line " + std::to_string(a.line) +
                                    ") at (" + num(a.x_mm) + ", " + num(a.y_mm) +
                                    ") and ends at (" + num(b.x_mm) + ", " + num(b.y_mm) + ") mm");
            out.push_back(c);
            c.points.clear();
            ++closed;
        };
        for (const Line& l : data) {
            const DataLine d = splitDataLine(l.text, l.number, kContourFields);
            if (d.face != 0) {
                if (!c.points.empty() && d.face != face)
                    throw DstvError(l.number, "face " + std::string(1, d.face) +
                                                  " inside a contour on face " +
                                                  std::string(1, face) + " (not closed?)");
                face = d.face;
            }
            if (face == 0)
                throw DstvError(l.number, std::string(what) + " point without a face (v, o, u, h)");
            c.face = face;
            const size_t nv = d.values.size();
            if (nv != 3 && nv != 5 && nv != 7)
                throw DstvError(l.number, std::string(what) + " point has " + std::to_string(nv) +
                                              " numbers: x, y, radius [, weld preparation angle, "
                                              "blunting [, angle, blunting]] expected");
            ContourPoint p;
            p.line = l.number;
            checkFlag(d.values[0], l.number, "x", "ous");
            p.x_ref = d.values[0].flag.empty() ? 0 : d.values[0].flag[0];
            p.x_mm = checkedNumber(d.values[0].text, l.number, "x", -kMaxMm, kMaxMm, "mm");
            checkFlag(d.values[1], l.number, "y", "tw");
            p.y_mm = checkedNumber(d.values[1].text, l.number, "y", -kMaxMm, kMaxMm, "mm");
            checkFlag(d.values[2], l.number, "radius", "tw");
            p.radius_mm =
                checkedNumber(d.values[2].text, l.number, "radius", -kMaxMm, kMaxMm, "mm");
            for (size_t k : {size_t{1}, size_t{2}})
                if (!d.values[k].flag.empty()) p.notch = d.values[k].flag[0];
            for (size_t k = 3; k + 1 < nv; k += 2) {
                const int side = static_cast<int>((k - 1) / 2);
                const std::string sfx = " " + std::to_string(side);
                checkFlag(d.values[k], l.number, "weld preparation angle" + sfx, "");
                checkFlag(d.values[k + 1], l.number, "weld preparation blunting" + sfx, "");
                WeldPrep w;
                w.angle_deg = checkedNumber(d.values[k].text, l.number,
                                            "weld preparation angle" + sfx, -89.9, 89.9, "deg");
                w.blunting_mm = checkedNumber(d.values[k + 1].text, l.number,
                                              "weld preparation blunting" + sfx, 0, 500, "mm");
                p.prep.push_back(w);
            }
            // A couple of zeros is "no preparation".
            while (!p.prep.empty() && p.prep.back().angle_deg == 0 &&
                   p.prep.back().blunting_mm == 0)
                p.prep.pop_back();
            if (c.points.empty()) c.line = closed == 0 ? blockLine : l.number;
            c.points.push_back(p);
            bool arcs = false;
            for (const ContourPoint& q : c.points)
                arcs = arcs || q.radius_mm != 0;
            if (c.points.size() >= (arcs ? 3u : 4u) && c.points.front().x_mm == p.x_mm &&
                c.points.front().y_mm == p.y_mm)
                close(l.number);
        }
        if (!c.points.empty()) close(data.back().number);
    }

    static Hole readHole(const Line& l) {
        const DataLine d = splitDataLine(l.text, l.number, kHoleFields);
        if (d.face == 0) throw DstvError(l.number, "BO hole without a face (v, o, u, h)");
        const size_t nv = d.values.size();
        Hole h;
        h.line = l.number;
        h.face = d.face;
        if (nv < 3)
            throw DstvError(l.number, "BO hole has " + std::to_string(nv) +
                                          " numbers: x, y, diameter [, depth [l width, height, "
                                          "angle]] expected");
        checkFlag(d.values[0], l.number, "x", "ous");
        h.x_ref = d.values[0].flag.empty() ? 0 : d.values[0].flag[0];
        h.x_mm = checkedNumber(d.values[0].text, l.number, "x", -kMaxMm, kMaxMm, "mm");
        checkFlag(d.values[1], l.number, "y", "glms");
        h.kind = d.values[1].flag.empty() ? 0 : d.values[1].flag[0];
        h.y_mm = checkedNumber(d.values[1].text, l.number, "y", -kMaxMm, kMaxMm, "mm");
        checkFlag(d.values[2], l.number, "diameter", "");
        h.diameter_mm = checkedNumber(d.values[2].text, l.number, "diameter", 0, 1000, "mm");
        if (nv >= 4) {
            checkFlag(d.values[3], l.number, "depth", "l");
            h.depth_mm = checkedNumber(d.values[3].text, l.number, "depth", -1000, 1000, "mm");
            h.slot = d.values[3].flag == "l";
        }
        if (h.slot) {
            if (nv != 7)
                throw DstvError(l.number, "BO slot (l after the depth) needs width, height and "
                                          "angle: " +
                                              std::to_string(nv) + " numbers found, 7 expected");
            for (size_t k = 4; k < 7; ++k)
                checkFlag(d.values[k], l.number, "slot value", "");
            h.slot_width_mm =
                checkedNumber(d.values[4].text, l.number, "slot width", 0, kMaxMm, "mm");
            h.slot_height_mm =
                checkedNumber(d.values[5].text, l.number, "slot height", 0, kMaxMm, "mm");
            h.slot_angle_deg =
                checkedNumber(d.values[6].text, l.number, "slot angle", -360, 360, "deg");
        } else if (nv > 4) {
            // Some writers add numbers of their own after the depth (a tolerance, a tool
            // number): kept out, and said in the import report.
            h.extra_values = static_cast<int>(nv - 4);
        }
        if (h.kind != 'm' && !(h.diameter_mm > 0))
            throw DstvError(l.number, "diameter = " + num(h.diameter_mm) +
                                          " mm: a hole needs a positive diameter");
        return h;
    }

    // face, x[ref], y, angle, text height, then the text (up to 40 characters).
    static Marking readMarking(const Line& l) {
        std::string s = l.text;
        // The text is free: split the numbers off the front by hand.
        size_t i = 0;
        const auto skipBlanks = [&] {
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
                ++i;
        };
        const auto token = [&](bool letters) {
            skipBlanks();
            const size_t a = i;
            while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) &&
                   (letters ? std::isalpha(static_cast<unsigned char>(s[i])) != 0
                            : std::isalpha(static_cast<unsigned char>(s[i])) == 0))
                ++i;
            return s.substr(a, i - a);
        };
        Marking m;
        m.line = l.number;
        const std::string face = token(true);
        if (face.size() != 1 || std::string("vouh").find(face[0]) == std::string::npos)
            throw DstvError(l.number, "SI face " + json::quote(face) + " is not v, o, u or h");
        m.face = face[0];
        m.x_mm = checkedNumber(token(false), l.number, "SI x", -kMaxMm, kMaxMm, "mm");
        if (i < s.size() && std::string("ous").find(s[i]) != std::string::npos) ++i; // x reference
        m.y_mm = checkedNumber(token(false), l.number, "SI y", -kMaxMm, kMaxMm, "mm");
        m.angle_deg = checkedNumber(token(false), l.number, "SI angle", -360, 360, "deg");
        const double height =
            checkedNumber(token(false), l.number, "SI text height", 1, 1000, "mm");
        if (height != std::floor(height))
            throw DstvError(l.number, "SI text height = " + num(height) + " mm is not whole");
        m.height_mm = static_cast<int>(height);
        if (i < s.size() && (s[i] == 'r' || s[i] == 'z')) ++i; // text modifier
        m.text = trim(i < s.size() ? s.substr(i) : "");
        if (m.text.empty()) throw DstvError(l.number, "SI marking without text");
        return m;
    }

    std::vector<Line> lines_;
    size_t at_ = 0;
};

} // namespace

Part parseDstv(const std::string& text) {
    return Reader(text).parse();
}

Header parseDstvHeader(const std::string& text) {
    return Reader(text).parseHeader();
}

std::string faceName(char face) {
    switch (face) {
    case 'v':
        return "face v (front)";
    case 'o':
        return "face o (top)";
    case 'u':
        return "face u (bottom)";
    case 'h':
        return "face h (behind)";
    }
    return std::string("face ") + face;
}

std::string blockTitle(const std::string& c) {
    static const std::pair<const char*, const char*> titles[] = {
        {"ST", "header"},         {"EN", "end"},           {"BO", "holes"},
        {"SI", "marking"},        {"AK", "outer contour"}, {"IK", "inner contour"},
        {"PU", "powder marking"}, {"KO", "punch marking"}, {"SC", "cut"},
        {"TO", "tolerance"},      {"UE", "camber"},        {"PR", "profile description"},
        {"KA", "bending"},        {"IN", "information"}};
    for (const auto& [k, t] : titles)
        if (c == k) return t;
    if (isBlockCode(c)) {
        switch (c[0]) {
        case 'E':
            return "plane definition";
        case 'B':
            return "holes in a plane";
        case 'S':
            return "marking in a plane";
        case 'A':
            return "outer contour in a plane";
        case 'I':
            return "inner contour in a plane";
        case 'P':
            return "powder marking in a plane";
        case 'K':
            return "punch marking in a plane";
        }
    }
    return {};
}

} // namespace cutcell::dstv
