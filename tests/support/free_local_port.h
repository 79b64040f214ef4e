#pragma once
// A TCP port on 127.0.0.1 that nothing is bound to now, chosen by the kernel, for a test's own
// virtualcan bus. Ports derived from the test's pid collided: ctest starts tests with nearby
// pids, and "pid + 5" of one test was "pid" of another (a bus hosted twice, a client refused).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace cutcell::test {

// 0 if the host has no loopback socket to give.
inline int freeLocalPort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return 0;
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    socklen_t len = sizeof a;
    int port = 0;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
        port = ntohs(a.sin_port);
    ::close(fd); // the kernel does not hand an ephemeral port out again soon
    return port;
}

} // namespace cutcell::test
