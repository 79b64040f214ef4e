// libFuzzer harness of the job parser: any bytes into cutcell::parseJob. Its documented way to
// refuse a job is JobError; anything else is a finding: another exception (it escapes and
// aborts), a crash, undefined behaviour or a float->int overflow (sanitizers), an allocation
// over -malloc_limit_mb, an input slower than -timeout. Run it with tools/fuzz.sh.
#include "core/job/job_io.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)cutcell::parseJob(text);
    } catch (const cutcell::JobError&) {
        // Refused with a message: the documented outcome for bad input.
    }
    return 0;
}
