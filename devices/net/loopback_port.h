#pragma once
// A TCP port on 127.0.0.1 that nothing is bound to now, for a server a test or a bench starts
// (a virtualcan bus, a local Mosquitto broker).
//
// Chosen below the kernel's ephemeral range (/proc/sys/net/ipv4/ip_local_port_range): the kernel
// hands ports of that range to every connect() and bind(port 0) of every program on the machine,
// so a port found free there may be taken by another program between the check and the listen,
// or while its server restarts (a broker stopped and started again by a test); below the range
// only a program that asks for that very port can take it.
#include <arpa/inet.h>
#include <cstdint>
#include <fstream>
#include <netinet/in.h>
#include <random>
#include <sys/socket.h>
#include <unistd.h>

namespace cutcell::net {

// Binds 127.0.0.1:port (0: the kernel's choice) and lets it go; the port bound, or 0.
inline int tryLoopbackPort(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return 0;
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    socklen_t len = sizeof a;
    int bound = 0;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
        bound = ntohs(a.sin_port);
    ::close(fd);
    return bound;
}

// 0 if the host has no loopback port to give.
inline int freeLoopbackPort() {
    int ephemeral_low = 32768; // Linux's default
    std::ifstream("/proc/sys/net/ipv4/ip_local_port_range") >> ephemeral_low;
    constexpr int kLowest = 20000; // above the well-known and most registered services' ports
    if (ephemeral_low - kLowest >= 1000) {
        std::random_device seed;
        std::uniform_int_distribution<int> pick(kLowest, ephemeral_low - 1);
        for (int tries = 0; tries < 100; ++tries)
            if (const int port = tryLoopbackPort(pick(seed))) return port;
    }
    return tryLoopbackPort(0); // a machine whose ephemeral range starts low
}

} // namespace cutcell::net
