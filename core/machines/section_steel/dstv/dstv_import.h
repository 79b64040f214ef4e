#pragma once
// A DSTV (NC1) piece as a section-steel cutter job (the module's importer "dstv").
//
// What is taken: the profile (the catalogue entry when the designation names one and the
// header's h, b, tf, tw agree with it within 0.5 mm, else the header's dimensions as a
// user-defined I, U or L section, checked as such); the end at x = length (the cell cuts the
// bar end facing +x; DSTV x runs along the bar): its web saw cut angle as
// end_cut.mitre_horizontal_deg and its flange saw cut angle as end_cut.mitre_vertical_deg; the
// AK weld preparation of that end's edge per face as the groove of the web (faces v, h; an
// angle's vertical leg) or the flanges (faces o, u; an angle's horizontal leg): one couple =
// V (no blunting) or Y (root face = blunting), two equal couples = K.
// What is reported, one line each ("line 23: ..."): the start end (x = 0), copes and notches,
// weld preparations elsewhere or that the groove cannot take, holes, slots, inner contours,
// markings, the blocks not interpreted, a quantity above one, dimensions that differ from the
// catalogue. A piece that is not an I, U or L section, or an angle beyond the cutter's mitre
// range, is refused (ImportError naming the line and the field), as is any broken file.
#include "core/machine/job_importer.h"

#include <string>

namespace cutcell::section_steel {

// Throws ImportError ("line N: ...").
ImportResult importDstv(const std::string& text);

// The importer entry of SectionSteelModule::importers().
JobImporter dstvImporter();

} // namespace cutcell::section_steel
