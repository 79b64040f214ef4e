#include "devices/canopen/can_interface.h"
#include "core/common/c_format.h"

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
            *error =
                messageC("CAN plugin \"%s\" is not installed; installed: %s",
                         plugin.toStdString().c_str(), plugins.join(", ").toStdString().c_str());
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
        const std::string offers =
            names.isEmpty() ? messageC("none") : names.join(", ").toStdString();
        *error = why.isEmpty()
                     ? messageC("CAN interface \"%s\" is not offered by plugin %s; it offers: %s",
                                interface.toStdString().c_str(), plugin.toStdString().c_str(),
                                offers.c_str())
                     : messageC("CAN interface \"%s\" is not offered by plugin %s; it offers: %s "
                                "(%s)",
                                interface.toStdString().c_str(), plugin.toStdString().c_str(),
                                offers.c_str(), why.toStdString().c_str());
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
