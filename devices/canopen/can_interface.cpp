#include "devices/canopen/can_interface.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QStringList>
#include <QTcpSocket>
#include <QUrl>

#include <arpa/inet.h>
#include <cstdlib>
#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

namespace cutcell::canopen {

bool checkCanInterface(const QString& plugin, const QString& interface, std::string* error) {
    const QStringList plugins = QCanBus::instance()->plugins();
    if (!plugins.contains(plugin)) {
        if (error)
            *error = "CAN plugin \"" + plugin.toStdString() +
                     "\" is not installed; installed: " + plugins.join(", ").toStdString();
        return false;
    }
    QString name = interface;
    if (plugin == QLatin1String("virtualcan") && interface.contains(QLatin1Char('/')))
        name = QUrl(interface).fileName();
    QString why;
    const QList<QCanBusDeviceInfo> offered = QCanBus::instance()->availableDevices(plugin, &why);
    QStringList names;
    for (const QCanBusDeviceInfo& d : offered)
        names << d.name();
    if (names.contains(name)) return true;
    if (error) {
        *error = "CAN interface \"" + interface.toStdString() + "\" is not offered by plugin " +
                 plugin.toStdString() + "; it offers: " +
                 (names.isEmpty() ? std::string("none") : names.join(", ").toStdString());
        if (!why.isEmpty()) *error += " (" + why.toStdString() + ")";
    }
    return false;
}

namespace {

// Every TCP socket of this process bound to 127.0.0.1:port (the bus server's side).
int setNoDelayOnLocalPort(int port) {
    int n = 0;
    DIR* dir = ::opendir("/proc/self/fd");
    if (!dir) return 0;
    while (const dirent* e = ::readdir(dir)) {
        char* end = nullptr;
        const long fd = std::strtol(e->d_name, &end, 10);
        if (end == e->d_name || *end != '\0') continue;
        sockaddr_in local{};
        socklen_t len = sizeof local;
        if (::getsockname(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&local), &len) != 0 ||
            local.sin_family != AF_INET || ntohs(local.sin_port) != port)
            continue;
        const int one = 1;
        if (::setsockopt(static_cast<int>(fd), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one) == 0)
            ++n;
    }
    ::closedir(dir);
    return n;
}

} // namespace

int setLowDelay(QCanBusDevice* device, const QString& plugin, const QString& interface) {
    if (!device) return 0;
    int n = 0;
    for (QTcpSocket* s : device->findChildren<QTcpSocket*>()) {
        s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        ++n;
    }
    if (plugin == QLatin1String("virtualcan")) {
        constexpr int kVirtualCanDefaultPort = 35468; // Qt's virtualcan server
        const int port = interface.contains(QLatin1Char('/'))
                             ? QUrl(interface).port(kVirtualCanDefaultPort)
                             : kVirtualCanDefaultPort;
        n += setNoDelayOnLocalPort(port);
    }
    return n;
}

void flushDevice(QCanBusDevice* device) {
    if (!device) return;
    for (QTcpSocket* s : device->findChildren<QTcpSocket*>())
        s->flush();
}

} // namespace cutcell::canopen
