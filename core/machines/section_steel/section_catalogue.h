#pragma once
// The profile catalogue (resources/sections/steel_sections.csv, compiled in): I/H sections
// (IPE, HEA, HEB), channels (UPN, UPE) and angles (L) with h, b, tw, tf, r after EN 10365 and
// EN 10056-1 (r1, r2, the flange slope of UPN and the tabulated area too), plus user-defined
// dimensions.
#include <optional>
#include <string>
#include <vector>

namespace cutcell::section_steel {

enum class SectionFamily { I, U, L };
const char* toString(SectionFamily f); // "I", "U", "L"

struct SectionDims {
    SectionFamily family = SectionFamily::I;
    std::string designation; // "IPE 300"; empty for user-defined dimensions
    double h_mm = 0;         // height (L: vertical leg)
    double b_mm = 0;         // flange width (L: horizontal leg)
    double tw_mm = 0;        // web thickness (L: leg thickness)
    double tf_mm = 0;        // flange thickness (L: leg thickness)
    double r_mm = 0;         // root radius r1
    double r2_mm = 0;        // toe radius (UPN flange toes, angle leg ends); 0 = square toe
    double slope_pct = 0;    // inner flange slope (UPN: 8 %); tf is then t at b/2
    double area_cm2 = 0;     // the standard's tabulated area (0: not known, user-defined)
};

const std::vector<SectionDims>& sectionCatalogue();
// Case- and blank-insensitive ("ipe300" finds "IPE 300").
std::optional<SectionDims> findSection(const std::string& designation);
// Parses the catalogue text (exposed for tests); throws std::runtime_error naming the line.
std::vector<SectionDims> parseSectionCatalogue(const std::string& csv);
// The compiled-in CSV text.
const std::string& sectionCatalogueText();

} // namespace cutcell::section_steel
