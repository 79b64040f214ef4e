// The virtualcan relay's line check (devices/canopen/virtualcan_wire.h). The lines Qt's own
// client writes are relayed in canopen_bus (a Qt device sends them through the relay); here the
// edges: what Qt's client would crash on, and what a frame may not be.
#include "devices/canopen/virtualcan_wire.h"

#include <gtest/gtest.h>

using namespace cutcell::canopen;

TEST(VirtualCanWire, FramesAndCommandsAsQtWritesThem) {
    const VirtualCanLine sync = parseVirtualCanLine("can0:128##\n");
    EXPECT_EQ(sync.kind, VirtualCanLineKind::Frame);
    EXPECT_EQ(sync.channel, 0);
    EXPECT_EQ(sync.body, "128##");
    const VirtualCanLine rpdo = parseVirtualCanLine("can1:515#L#0f00e8030000");
    EXPECT_EQ(rpdo.kind, VirtualCanLineKind::Frame);
    EXPECT_EQ(rpdo.channel, 1);
    EXPECT_EQ(parseVirtualCanLine("can0:536870911#XR#").kind, VirtualCanLineKind::Frame);
    EXPECT_EQ(parseVirtualCanLine("can0:291#FB#" + std::string(128, 'a')).kind,
              VirtualCanLineKind::Frame);
    EXPECT_EQ(parseVirtualCanLine("connect:can0").kind, VirtualCanLineKind::Connect);
    EXPECT_EQ(parseVirtualCanLine("disconnect:can1\r\n").kind, VirtualCanLineKind::Disconnect);
}

TEST(VirtualCanWire, MalformedLinesAreRefusedWithTheReason) {
    struct Case {
        const char* line;
        const char* why;
    };
    const Case cases[] = {
        {"can0:hello", "not <id>#<flags>#<data>"}, // relayed by Qt's server: crashes clients
        {"hello", "no ':'"},
        {"", "no ':'"},
        {"can2:1##", "unknown channel"},
        {"connect:can9", "unknown channel"},
        {"can0:1#", "not <id>#<flags>#<data>"},
        {"can0:1#L#00#00", "not <id>#<flags>#<data>"},
        {"can0:#L#00", "1 to 9 decimal digits"},
        {"can0:0x80##", "not decimal"},
        {"can0:-1##", "not decimal"},
        {"can0:9999999999##", "1 to 9 decimal digits"},
        {"can0:2048##", "standard id above 0x7FF"},
        {"can0:536870912#X#", "extended id above 0x1FFFFFFF"},
        {"can0:1#Q#", "unknown flag 'Q'"},
        {"can0:1#LL#", "a flag given twice"},
        {"can0:1##abc", "odd number"},
        {"can0:1##zz", "not hex"},
        {"can0:1##001122334455667788", "more than 8 data bytes"},
        {"can0:1##00:1", "not hex"},
    };
    for (const Case& c : cases) {
        const VirtualCanLine l = parseVirtualCanLine(c.line);
        EXPECT_EQ(l.kind, VirtualCanLineKind::Malformed) << c.line;
        EXPECT_NE(l.why.find(c.why), std::string::npos) << c.line << ": " << l.why;
    }
    EXPECT_EQ(parseVirtualCanLine(std::string("can0:1##0") + '\0' + "0").kind,
              VirtualCanLineKind::Malformed);
    EXPECT_EQ(parseVirtualCanLine("can0:1##" + std::string(300, '0')).kind,
              VirtualCanLineKind::Malformed);
    EXPECT_EQ(parseVirtualCanLine("can0:1#F#" + std::string(130, '0')).kind,
              VirtualCanLineKind::Malformed);
}
