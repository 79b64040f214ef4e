#include "devices/canopen/virtualcan_host.h"
#include "devices/canopen/thread_priority.h"
#include "devices/canopen/virtualcan_wire.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QCoreApplication>
#include <QHostAddress>
#include <QLoggingCategory>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QUrl>

#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

Q_LOGGING_CATEGORY(lcVirtualCanRelay, "cutcell.canopen.relay")

namespace cutcell::canopen {
namespace {

constexpr quint16 kVirtualCanDefaultPort = 35468; // Qt's virtualcan default

// The bus server, in place of the plugin's: the same protocol, but a line is relayed only when
// parseVirtualCanLine() accepts it; anything else is dropped and logged (the first ten of each
// client, then every thousandth), and a client that writes more than a line's worth without a
// line feed is dropped. Lives on the host thread.
class VirtualCanRelay : public QObject {
  public:
    bool listen(quint16 port) {
        if (!server_.listen(QHostAddress::LocalHost, port)) return false;
        QObject::connect(&server_, &QTcpServer::newConnection, this, [this] { accept(); });
        return true;
    }

  private:
    struct Client {
        QPointer<QTcpSocket> socket;
        bool channels[kVirtualCanChannels] = {false, false};
        std::uint64_t dropped = 0;
    };

    void accept() {
        while (QTcpSocket* s = server_.nextPendingConnection()) {
            s->setSocketOption(QAbstractSocket::LowDelayOption, 1); // no Nagle on the bus
            clients_.push_back(std::make_unique<Client>());
            clients_.back()->socket = s;
            QObject::connect(s, &QIODevice::readyRead, this, [this, s] { read(s); });
            QObject::connect(s, &QTcpSocket::disconnected, this, [this, s] { forget(s); });
        }
    }

    Client* find(QTcpSocket* s) {
        for (auto& c : clients_)
            if (c->socket == s) return c.get();
        return nullptr;
    }

    void forget(QTcpSocket* s) {
        std::erase_if(clients_, [s](const auto& c) { return c->socket == s || !c->socket; });
        s->deleteLater();
    }

    void drop(Client& c, const QByteArray& line, const std::string& why) {
        ++c.dropped;
        if (c.dropped <= 10 || c.dropped % 1000 == 0)
            qCWarning(lcVirtualCanRelay,
                      "virtualcan bus: dropped a malformed line from a client (%s): \"%s\"; "
                      "%llu dropped from it so far",
                      why.c_str(), line.trimmed().left(80).toPercentEncoding(" :#").constData(),
                      static_cast<unsigned long long>(c.dropped));
    }

    void read(QTcpSocket* s) {
        Client* c = find(s);
        if (!c) return;
        while (s->canReadLine()) {
            const QByteArray line = s->readLine(4096);
            const VirtualCanLine l =
                parseVirtualCanLine(std::string_view(line.constData(), size_t(line.size())));
            switch (l.kind) {
            case VirtualCanLineKind::Connect:
                c->channels[l.channel] = true;
                break;
            case VirtualCanLineKind::Disconnect:
                c->channels[l.channel] = false;
                s->disconnectFromHost();
                return;
            case VirtualCanLineKind::Malformed:
                drop(*c, line, l.why);
                break;
            case VirtualCanLineKind::Frame: {
                QByteArray out(l.body.data(), qsizetype(l.body.size()));
                out += '\n';
                for (auto& other : clients_)
                    if (other.get() != c && other->socket && other->channels[l.channel])
                        other->socket->write(out);
                break;
            }
            }
        }
        if (s->bytesAvailable() > static_cast<qint64>(kVirtualCanMaxLine) * 4) {
            drop(*c, s->peek(80), "no line feed within a line's length; client dropped");
            s->abort();
        }
    }

    QTcpServer server_;
    std::vector<std::unique_ptr<Client>> clients_;
};

// The plugin keeps one bus server per process and starts it from whichever thread connects a
// device; while it is not listening, each connect from another thread tries again (a "cannot
// create children for a parent in a different thread" warning each time). Started once here,
// on a free port nobody uses, it stays idle ("already running") and the relay keeps the bus's.
void parkThePluginsServer() {
    static bool parked = false;
    if (parked) return;
    parked = true;
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0)) return;
    const quint16 idle = probe.serverPort();
    probe.close();
    std::unique_ptr<QCanBusDevice> device(QCanBus::instance()->createDevice(
        QStringLiteral("virtualcan"), QStringLiteral("tcp://127.0.0.1:%1/can0").arg(idle)));
    if (device) device->connectDevice(); // starts the server; the device itself is not needed
}

struct HostThread {
    QThread thread;
    QObject* context = nullptr;                 // lives on thread
    std::map<quint16, VirtualCanRelay*> relays; // [thread] children of context, by port
};

void stopHostThread();

// Created once, never deleted (a QThread destroyed while running aborts the program). Stopped
// when the application object goes, or at exit.
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
    const quint16 port =
        static_cast<quint16>(QUrl(interface.contains(QLatin1Char('/')) ? interface : QString())
                                 .port(kVirtualCanDefaultPort));
    const auto tryToHost = [h, port] {
        parkThePluginsServer();
        // Taken by this process already, or by another (which then hosts the bus: the plugin
        // connects to it as a client). The plugin's own server finds the port taken and stays
        // idle, so every client of a bus this process hosts talks to the checking relay.
        if (h->relays.count(port)) return;
        auto* relay = new VirtualCanRelay;
        relay->setParent(h->context);
        if (relay->listen(port))
            h->relays[port] = relay;
        else
            delete relay;
    };
    if (QThread::currentThread() == &h->thread)
        tryToHost();
    else
        QMetaObject::invokeMethod(h->context, tryToHost, Qt::BlockingQueuedConnection);
    // Stop the host thread at exit before the statics it uses go. Handlers registered later run
    // earlier.
    static const bool registered = [] { return std::atexit(stopHostThread) == 0; }();
    (void)registered;
}

} // namespace cutcell::canopen
