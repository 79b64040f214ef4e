#include "devices/canopen/virtualcan_host.h"
#include "devices/canopen/thread_priority.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QCoreApplication>
#include <QHostAddress>
#include <QThread>
#include <QUrl>

#include <cstdlib>
#include <memory>

namespace cutcell::canopen {
namespace {

struct HostThread {
    QThread thread;
    QObject* context = nullptr; // lives on thread
};

void stopHostThread();

// Created once, never deleted (a QThread destroyed while running aborts the program). Stopped
// when the application object goes, or at exit before the plugin's server is destroyed.
HostThread* hostThread() {
    static HostThread* const host = [] {
        auto* h = new HostThread;
        h->thread.setObjectName(QStringLiteral("virtualcan-host"));
        h->context = new QObject;
        h->context->moveToThread(&h->thread);
        h->thread.start();
        // The server relays every frame of every cycle (thread_priority.h); best effort.
        QMetaObject::invokeMethod(
            h->context, [] { raiseCallingThreadToFifo(kBusHostThreadPriority); },
            Qt::QueuedConnection);
        qAddPostRoutine(stopHostThread);
        return h;
    }();
    return host;
}

void stopHostThread() {
    HostThread* h = hostThread();
    h->thread.quit();
    h->thread.wait();
}

} // namespace

void hostVirtualCanBus(const QString& plugin, const QString& interface) {
    if (plugin != QLatin1String("virtualcan")) return;
    const QString host = interface.contains(QLatin1Char('/')) ? QUrl(interface).host() : QString();
    if (!host.isEmpty() && !QHostAddress(host).isLoopback()) return; // someone else's bus
    HostThread* h = hostThread();
    if (!h->thread.isRunning()) return; // the application is ending
    const auto tryToHost = [plugin, interface] {
        // Connecting a device makes the plugin start its server here (synchronously, inside
        // connectDevice) unless this process already runs one or the port is taken. The device
        // itself is not needed: dropping it closes its socket, the server stays.
        std::unique_ptr<QCanBusDevice> device(
            QCanBus::instance()->createDevice(plugin, interface, nullptr));
        if (device) device->connectDevice();
    };
    if (QThread::currentThread() == &h->thread)
        tryToHost();
    else
        QMetaObject::invokeMethod(h->context, tryToHost, Qt::BlockingQueuedConnection);
    // The plugin's server (a global static, built by the first device at the latest) is
    // destroyed at exit: stop its thread first. Handlers registered later run earlier.
    static const bool registered = [] { return std::atexit(stopHostThread) == 0; }();
    (void)registered;
}

} // namespace cutcell::canopen
