#include "core/machines/section_steel/section_catalogue.h"

#include "core/json/json.h"

#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace cutcell::section_steel {
namespace {

std::string key(const std::string& s) {
    std::string k;
    for (char c : s)
        if (!std::isspace(static_cast<unsigned char>(c)))
            k += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return k;
}

double field(const std::string& s, int line, bool zeroAllowed = false) {
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v); // locale-independent
    if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !(v > 0 || (zeroAllowed && v == 0)))
        throw std::runtime_error("steel_sections.csv line " + std::to_string(line) + ": " +
                                 json::quote(s) + " is not a " +
                                 (zeroAllowed ? "non-negative" : "positive") + " number");
    return v;
}

} // namespace

const char* toString(SectionFamily f) {
    switch (f) {
    case SectionFamily::I:
        return "I";
    case SectionFamily::U:
        return "U";
    case SectionFamily::L:
        return "L";
    }
    return "?";
}

std::vector<SectionDims> parseSectionCatalogue(const std::string& csv) {
    std::vector<SectionDims> out;
    std::istringstream in(csv);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f;
        std::stringstream ls(line);
        std::string cell;
        while (std::getline(ls, cell, ','))
            f.push_back(cell);
        if (f.size() != 10)
            throw std::runtime_error("steel_sections.csv line " + std::to_string(n) + ": " +
                                     std::to_string(f.size()) + " fields, 10 expected");
        SectionDims d;
        if (f[0] == "I")
            d.family = SectionFamily::I;
        else if (f[0] == "U")
            d.family = SectionFamily::U;
        else if (f[0] == "L")
            d.family = SectionFamily::L;
        else
            throw std::runtime_error("steel_sections.csv line " + std::to_string(n) + ": family " +
                                     json::quote(f[0]) + " is not I, U or L");
        d.designation = f[1];
        d.h_mm = field(f[2], n);
        d.b_mm = field(f[3], n);
        d.tw_mm = field(f[4], n);
        d.tf_mm = field(f[5], n);
        d.r_mm = field(f[6], n);
        d.r2_mm = field(f[7], n, true);
        d.slope_pct = field(f[8], n, true);
        d.area_cm2 = field(f[9], n);
        out.push_back(d);
    }
    return out;
}

const std::vector<SectionDims>& sectionCatalogue() {
    static const std::vector<SectionDims> c = parseSectionCatalogue(sectionCatalogueText());
    return c;
}

std::optional<SectionDims> findSection(const std::string& designation) {
    const std::string k = key(designation);
    for (const auto& d : sectionCatalogue())
        if (key(d.designation) == k) return d;
    return std::nullopt;
}

} // namespace cutcell::section_steel
