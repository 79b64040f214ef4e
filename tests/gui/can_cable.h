#pragma once
// A cable between the CAN master and a private virtualcan bus, for GUI tests: a TCP relay the
// master connects to instead of the bus. cut() drops every connection through it (the master
// sees its bus go away, as when a cable is pulled or the bus host ends) and refuses new ones
// until plugIn(). GUI-thread object (its sockets live on the test's thread).
#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>

#include <vector>

class CanCable : public QObject {
  public:
    explicit CanCable(quint16 busPort) : busPort_(busPort) {
        server_.listen(QHostAddress::LocalHost, 0);
        connect(&server_, &QTcpServer::newConnection, this, [this] { accept(); });
    }
    quint16 port() const { return server_.serverPort(); }
    int accepted() const { return accepted_; } // connections made through it so far
    int open() const {                         // connections open now
        int n = 0;
        for (const Link& l : links_)
            n += l.down && l.down->state() == QAbstractSocket::ConnectedState ? 1 : 0;
        return n;
    }
    void cut() {
        plugged_ = false;
        for (Link& l : links_) {
            if (l.down) l.down->abort();
            if (l.up) l.up->abort();
        }
    }
    void plugIn() { plugged_ = true; }

  private:
    struct Link {
        QTcpSocket* down = nullptr; // the master's side
        QTcpSocket* up = nullptr;   // the bus's side
    };
    void accept() {
        while (QTcpSocket* down = server_.nextPendingConnection()) {
            if (!plugged_) {
                down->abort();
                down->deleteLater();
                continue;
            }
            ++accepted_;
            auto* up = new QTcpSocket(this);
            down->setParent(this);
            for (QTcpSocket* s : {down, up})
                s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            links_.push_back({down, up});
            const auto pump = [down, up] {
                if (up->state() == QAbstractSocket::ConnectedState && down->bytesAvailable())
                    up->write(down->readAll());
            };
            connect(down, &QTcpSocket::readyRead, this, pump);
            connect(up, &QTcpSocket::connected, this, pump);
            connect(up, &QTcpSocket::readyRead, this, [down, up] { down->write(up->readAll()); });
            connect(down, &QTcpSocket::disconnected, up, &QTcpSocket::disconnectFromHost);
            connect(up, &QTcpSocket::disconnected, down, &QTcpSocket::disconnectFromHost);
            up->connectToHost(QHostAddress::LocalHost, busPort_);
        }
    }

    quint16 busPort_;
    QTcpServer server_;
    std::vector<Link> links_;
    int accepted_ = 0;
    bool plugged_ = true;
};
