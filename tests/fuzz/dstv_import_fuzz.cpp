// libFuzzer harness of the DSTV (NC1) import: any bytes into the section-steel cutter's
// importer (reader + mapping to a job). Its documented refusal is ImportError; anything else
// is a finding (another exception, a crash, UB, a float->int overflow, a slow input). Seeds:
// tests/data/dstv/. Run:
//   build-fuzz/tests/fuzz/dstv_import_fuzz -max_total_time=60 CORPUS tests/data/dstv
#include "core/machines/section_steel/dstv/dstv_import.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)cutcell::section_steel::importDstv(text);
    } catch (const cutcell::ImportError&) {
        // Refused naming the line: the documented outcome for bad input.
    }
    return 0;
}
