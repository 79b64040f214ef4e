#include "devices/canopen/can_interface.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QStringList>
#include <QTcpSocket>
#include <QUrl>

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

int setLowDelay(QCanBusDevice* device) {
    if (!device) return 0;
    int n = 0;
    for (QTcpSocket* s : device->findChildren<QTcpSocket*>()) {
        s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        ++n;
    }
    return n;
}

void flushDevice(QCanBusDevice* device) {
    if (!device) return;
    for (QTcpSocket* s : device->findChildren<QTcpSocket*>())
        s->flush();
}

} // namespace cutcell::canopen
