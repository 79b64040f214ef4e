#pragma once
// A reader of DSTV NC files (NC1: "Standard description for steel structure pieces for the
// numerical controls", Deutscher Stahlbau-Verband, 7th edition 1998 and its later revisions),
// the file every structural-steel detailing package writes for CNC beam lines. Pure text in,
// a Part out; no machine knowledge here (dstv_import.h maps a Part to a section-steel job).
//
// The format as read here: one piece per file. A block starts with its two-letter code alone on
// its line; its data lines follow (the standard indents them by two blanks; lines without the
// blanks, as some writers make them, are read the same; line ends LF, CR LF or CR). "**" in columns
// 1-2 is a comment line (a "**" in a data line ends it). ST (header: 20 fixed lines + up to 4
// text lines) comes first, EN last; between them AK (outer contour), IK (inner contour), BO
// (holes), SI (marking) and the blocks this reader knows but does not interpret (PU, KO, SC,
// TO, UE, PR, KA, IN, the plane blocks E0..E9, B0..B9, S0..S9, A0..A9, I0..I9, P0..P9, K0..K9).
// In a data line a number is ended by a blank or by a letter; a letter right after a number is
// that number's flag (x reference o/u/s after x, hole kind g/l/m/s after y, notch t/w, slot l).
// The first letter of a data line is the face: v (front = web), o (top flange), u (bottom
// flange), h (behind); a contour's later points may omit it.
//
// Every number is read with std::from_chars (the process locale is never consulted) and checked
// against a range; every refusal is a DstvError whose message starts with "line N:" and names
// the field.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace cutcell::dstv {

struct DstvError : std::runtime_error {
    DstvError(int line, const std::string& message);
    int line; // 1-based; the line after the last one for "missing EN"
};

// The ST block. field_line[i] is the file line of header field i + 1 (1..24; 0 = absent).
struct Header {
    int line = 0; // the "ST" line
    std::string order, drawing, phase, piece, steel_grade;
    int quantity = 1;
    std::string profile;      // designation as written ("IPE300", "HE300A", "W21X44")
    std::string profile_code; // I, U, L, B, RU, RO, M, C, T, SO
    double length_mm = 0;
    double saw_length_mm = 0; // 0: not given
    double h_mm = 0, b_mm = 0, tf_mm = 0, tw_mm = 0, r_mm = 0;
    double weight_kg_per_m = 0, paint_m2_per_m = 0;
    double web_start_deg = 0, web_end_deg = 0, flange_start_deg = 0, flange_end_deg = 0;
    std::array<std::string, 4> text;
    std::array<int, 24> field_line{};
};

// Weld preparation of the contour edge that starts at a point: the flame-cutting angle to the
// square edge and the blunting (the land left square, "Abstumpfung").
struct WeldPrep {
    double angle_deg = 0;
    double blunting_mm = 0;
};

struct ContourPoint {
    int line = 0;
    double x_mm = 0, y_mm = 0;
    char x_ref = 0; // 'o', 'u', 's' or 0 (dimension reference; does not change the value)
    double radius_mm = 0;
    char notch = 0;             // 't' (tangential) or 'w' (hole-like) notch corner, or 0
    std::vector<WeldPrep> prep; // 0, 1 or 2 (both sides of the plate)
};

struct Contour {
    int line = 0;                     // the AK / IK line
    bool outer = true;                // AK (true) or IK
    char face = 'v';                  // v, o, u, h
    std::vector<ContourPoint> points; // closed: last == first
};

struct Hole {
    int line = 0;
    char face = 'v';
    double x_mm = 0, y_mm = 0;
    char x_ref = 0;
    char kind = 0; // 0 through hole, 'g' thread, 'l' left thread, 'm' mark, 's' countersink
    double diameter_mm = 0, depth_mm = 0;
    bool slot = false; // 'l' after the depth: width, height, angle follow
    double slot_width_mm = 0, slot_height_mm = 0, slot_angle_deg = 0;
    int extra_values = 0; // numbers after the depth that are no slot's (not interpreted)
};

struct Marking {
    int line = 0;
    char face = 'v';
    double x_mm = 0, y_mm = 0;
    double angle_deg = 0;
    int height_mm = 0;
    std::string text;
};

// A block the reader knows but does not interpret (PU, KO, SC, TO, UE, PR, KA, IN, planes).
struct OtherBlock {
    int line = 0;
    std::string code;
    int data_lines = 0;
};

struct Part {
    Header header;
    std::vector<Contour> contours; // AK and IK, in file order
    std::vector<Hole> holes;
    std::vector<Marking> markings;
    std::vector<OtherBlock> others;
    int end_line = 0; // the EN line
};

// Parses a whole file; throws DstvError.
Part parseDstv(const std::string& text);
// Only the ST block (what the piece is, before its contours are read); throws DstvError.
Header parseDstvHeader(const std::string& text);

// "web (v)", "top flange (o)", ...: the face letter for messages.
std::string faceName(char face);
// What a known block code is ("PU" -> "powder marking"); empty for an unknown code.
std::string blockTitle(const std::string& code);

} // namespace cutcell::dstv
