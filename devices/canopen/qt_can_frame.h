#pragma once
// Conversion between the protocol layer's CanFrame and Qt's QCanBusFrame (the transport edge).
#include "devices/canopen/can_frame.h"

#include <QCanBusFrame>

namespace cutcell::canopen {

inline QCanBusFrame toQt(const CanFrame& f) {
    return QCanBusFrame(f.id, QByteArray(reinterpret_cast<const char*>(f.data.data()), f.len));
}

// False for frames the protocol layer does not handle (remote, extended, FD, error frames).
inline bool fromQt(const QCanBusFrame& q, CanFrame& out) {
    if (q.frameType() != QCanBusFrame::DataFrame || q.hasExtendedFrameFormat() ||
        q.hasFlexibleDataRateFormat())
        return false;
    const QByteArray p = q.payload();
    if (p.size() > 8) return false;
    out.id = q.frameId();
    out.len = static_cast<std::uint8_t>(p.size());
    out.data.fill(0);
    for (qsizetype i = 0; i < p.size(); ++i)
        out.data[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(p[i]);
    return true;
}

} // namespace cutcell::canopen
