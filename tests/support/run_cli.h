#pragma once
// Runs `cutcell-cli ARGS` (CUTCELL_CLI, set by the test's CMake target) through the shell and
// returns its exit code and output (stdout, with stderr unless withStderr is false).
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace cutcell::test {

struct CliResult {
    int code;
    std::string output;
};

inline CliResult runCli(const std::string& args, bool withStderr = true) {
    const std::string cmd =
        std::string(CUTCELL_CLI) + " " + args + (withStderr ? " 2>&1" : " 2>/dev/null");
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    while (p && fgets(buf, sizeof buf, p))
        out += buf;
    const int status = p ? pclose(p) : -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

} // namespace cutcell::test
