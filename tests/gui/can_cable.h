#pragma once
// A cable between the CAN master and a private virtualcan bus, for GUI tests: a TCP relay the
// master connects to instead of the bus. cut() drops every connection through it (the master
// sees its bus go away, as when a cable is pulled or the bus host ends) and refuses new ones
// until plugIn().
//
// The relay runs on a thread of its own, on SCHED_FIFO where allowed, like the bus's server
// (devices/canopen/virtualcan_host.cpp): every frame of every cycle passes through it, and on
// the test's (GUI) thread each waited for the window's painting - a delay the operator
// station's own bus, which never passes through its GUI thread, does not have.
//
// Threading contract: construct, use and destroy on one thread (the test's); every call blocks
// that thread only for the relay thread to do the call's own small step.
#include "devices/canopen/thread_priority.h"

#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>

#include <vector>

class CanCable {
  public:
    explicit CanCable(quint16 busPort) {
        thread_.setObjectName(QStringLiteral("can-cable"));
        thread_.start();
        relay_ = new Relay(busPort);
        relay_->moveToThread(&thread_);
        onRelay([this] {
            cutcell::canopen::raiseCallingThreadToFifo(cutcell::canopen::kBusHostThreadPriority);
            relay_->listen();
        });
    }
    ~CanCable() {
        onRelay([this] { delete relay_; });
        thread_.quit();
        thread_.wait();
    }
    CanCable(const CanCable&) = delete;
    CanCable& operator=(const CanCable&) = delete;

    quint16 port() const { return relay_->port; } // set before the constructor returned
    int accepted() const {                        // connections made through it so far
        int n = 0;
        onRelay([&] { n = relay_->accepted; });
        return n;
    }
    int open() const { // connections open now
        int n = 0;
        onRelay([&] { n = relay_->open(); });
        return n;
    }
    void cut() {
        onRelay([this] { relay_->cut(); });
    }
    void plugIn() {
        onRelay([this] { relay_->plugged = true; });
    }

  private:
    // Lives on thread_: its sockets are created, used and destroyed there.
    class Relay : public QObject {
      public:
        explicit Relay(quint16 busPort) : busPort_(busPort) {}
        void listen() {
            server_ = new QTcpServer(this);
            server_->listen(QHostAddress::LocalHost, 0);
            port = server_->serverPort();
            QObject::connect(server_, &QTcpServer::newConnection, this, [this] { accept(); });
        }
        int open() const {
            int n = 0;
            for (const Link& l : links_)
                n += l.down && l.down->state() == QAbstractSocket::ConnectedState ? 1 : 0;
            return n;
        }
        void cut() {
            plugged = false;
            for (Link& l : links_) {
                if (l.down) l.down->abort();
                if (l.up) l.up->abort();
            }
        }
        quint16 port = 0;
        int accepted = 0;
        bool plugged = true;

      private:
        struct Link {
            QTcpSocket* down = nullptr; // the master's side
            QTcpSocket* up = nullptr;   // the bus's side
        };
        void accept() {
            while (QTcpSocket* down = server_->nextPendingConnection()) {
                if (!plugged) {
                    down->abort();
                    down->deleteLater();
                    continue;
                }
                ++accepted;
                auto* up = new QTcpSocket(this);
                down->setParent(this);
                down->setSocketOption(QAbstractSocket::LowDelayOption, 1);
                links_.push_back({down, up});
                const auto pump = [down, up] {
                    if (up->state() == QAbstractSocket::ConnectedState && down->bytesAvailable())
                        up->write(down->readAll());
                };
                QObject::connect(down, &QTcpSocket::readyRead, this, pump);
                // No Nagle towards the bus either. Set once connected: a socket without its
                // engine yet drops the option. Set before connectToHost (as it was), the
                // master's frames waited for the bus's delayed ACK: every frame on the bus
                // stopped for 40 ms every 100 ms (the crank's feedback 31 cycles late).
                QObject::connect(up, &QTcpSocket::connected, this, [up, pump] {
                    up->setSocketOption(QAbstractSocket::LowDelayOption, 1);
                    pump();
                });
                QObject::connect(up, &QTcpSocket::readyRead, this,
                                 [down, up] { down->write(up->readAll()); });
                QObject::connect(down, &QTcpSocket::disconnected, up,
                                 &QTcpSocket::disconnectFromHost);
                QObject::connect(up, &QTcpSocket::disconnected, down,
                                 &QTcpSocket::disconnectFromHost);
                up->connectToHost(QHostAddress::LocalHost, busPort_);
            }
        }
        quint16 busPort_;
        QTcpServer* server_ = nullptr;
        std::vector<Link> links_;
    };

    template <class F> void onRelay(F&& f) const {
        QMetaObject::invokeMethod(relay_, std::forward<F>(f), Qt::BlockingQueuedConnection);
    }

    QThread thread_;
    Relay* relay_ = nullptr;
};
