// The writer of the consumable ledger's kill test (consumable_ledger_test.cpp): opens the record
// given as its argument and records cuts of one set, 1 pierce, 0.5 s of arc and 10 mm each,
// until it is killed (or has recorded the optional count), printing the set's cut count after
// each commit. The line is written after the commit returned and flushed at once, so the
// last line the test reads is a count the record had committed.
#include "core/record/audit.h"
#include "devices/record/consumable_ledger_store.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace {

// Recording cuts writes no audit event; a replacement would, and this writer makes none.
struct NoAudit final : cutcell::AuditSink {
    void append(const cutcell::AuditEvent&) override {}
};

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: consumable_writer RECORD [CUTS]\n");
        return 64;
    }
    const long long limit = argc > 2 ? std::atoll(argv[2]) : -1;
    try {
        NoAudit audit;
        cutcell::ConsumableLedgerStore ledger(argv[1], audit, "kill-test");
        const cutcell::ConsumableSetId set{cutcell::CutProcess::Plasma, "kill test set"};
        for (long long i = 0; limit < 0 || i < limit; ++i) {
            const cutcell::ConsumableCounters c = ledger.recordCut(set, 1, 0.5, 10.0);
            std::printf("%lld\n", static_cast<long long>(c.cuts));
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumable_writer: %s\n", e.what());
        return 1;
    }
    return 0;
}
