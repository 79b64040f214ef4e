#pragma once
// A TCP port on 127.0.0.1 that nothing is bound to now, for a test's own virtualcan bus (below
// the kernel's ephemeral range: see devices/net/loopback_port.h). Ports derived from the test's
// pid collided: ctest starts tests with nearby pids, and "pid + 5" of one test was "pid" of
// another (a bus hosted twice, a client refused).
#include "devices/net/loopback_port.h"

namespace cutcell::test {

// 0 if the host has no loopback port to give.
inline int freeLocalPort() {
    return net::freeLoopbackPort();
}

} // namespace cutcell::test
