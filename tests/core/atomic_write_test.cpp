// writeFileAtomically: the file appears whole, and the hidden temporary files of writers that
// were killed before their rename (".<name>.XXXXXX") are cleared at the next write there.
#include "core/job/job_io.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace cutcell;

namespace {

void touch(const fs::path& p, std::chrono::seconds age) {
    std::ofstream(p) << "partial";
    fs::last_write_time(p, fs::file_time_type::clock::now() - age);
}

} // namespace

TEST(AtomicWrite, StaleTemporariesOfKilledWritersAreRemoved) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    using std::chrono::seconds;
    touch(dir / ".cut.ngc.Ab12Cd", seconds(120));   // a killed export of cut.ngc
    touch(dir / ".cut.ngc.Zz99yy", seconds(0));     // a writer still at work: kept
    touch(dir / "cut.svg", seconds(0));             // an earlier export beside it ...
    touch(dir / ".cut.svg.Qw12er", seconds(300));   // ... whose replacement was killed
    touch(dir / ".bashrc.backup", seconds(3600));   // not ours ("bashrc" is no file here)
    touch(dir / ".notes.txt.abcdef", seconds(600)); // no notes.txt beside it: not ours
    writeFileAtomically((dir / "cut.ngc").string(), "G21\n");

    EXPECT_FALSE(fs::exists(dir / ".cut.ngc.Ab12Cd"));
    EXPECT_FALSE(fs::exists(dir / ".cut.svg.Qw12er"));
    EXPECT_TRUE(fs::exists(dir / ".cut.ngc.Zz99yy"));
    EXPECT_TRUE(fs::exists(dir / ".bashrc.backup"));
    EXPECT_TRUE(fs::exists(dir / ".notes.txt.abcdef"));
    EXPECT_TRUE(fs::exists(dir / "cut.svg"));
    std::ifstream in(dir / "cut.ngc");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "G21\n");
    // The write left no temporary of its own.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++files;
    }
    EXPECT_EQ(files, 5); // cut.ngc, cut.svg and the three kept above
    fs::remove_all(dir);
}

// A target that is no plain file - a pipe here, /dev/null in `--report /dev/null` - is written
// into and stays what it was: renaming a temporary over it once put a plain file in the place
// of /dev/null.
TEST(AtomicWrite, APipeOrDeviceIsWrittenIntoNotReplaced) {
    const fs::path dir = fs::temp_directory_path() / ("cutcell_fifo_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path fifo = dir / "report.pipe";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo);
        std::stringstream text;
        text << in.rdbuf();
        received = text.str();
    });
    writeFileAtomically(fifo.string(), "{\"outcome\": \"completed\"}\n");
    if (!fs::is_fifo(fifo)) {
        reader.detach(); // it waits for a writer that never comes
        FAIL() << "the pipe was replaced by a file";
    }
    reader.join();
    EXPECT_EQ(received, "{\"outcome\": \"completed\"}\n");
    fs::remove_all(dir);
}
