// Bus load from the frame format: properties, not figures copied from the output.
#include "devices/canopen/bus_load.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cutcell::canopen;

TEST(BusLoad, WorstCaseFrameBitsFromFrameFormat) {
    // Unstuffed: 1 SOF + 11 id + RTR + IDE + r0 + 4 DLC + 8n + 15 CRC + 1 + 2 ACK + 7 EOF + 3 IFS.
    for (int n = 0; n <= 8; ++n) {
        const int unstuffed = 1 + 11 + 1 + 1 + 1 + 4 + 8 * n + 15 + 1 + 2 + 7 + 3;
        const int stuffable = 34 + 8 * n; // SOF .. CRC
        const int maxStuff =
            (stuffable - 1) / 4; // a stuff bit after every 4 bits after the first 5
        EXPECT_EQ(worstCaseFrameBits(n), unstuffed + maxStuff) << n;
    }
    // The published figure for 8 bytes (STACK.md: "up to ~135 with worst-case stuffing").
    EXPECT_EQ(worstCaseFrameBits(8), 135);
}

TEST(BusLoad, LoadScalesWithPeriodAndAdviceHolds) {
    BusLoadInput in;
    in.period_s = 0.001;
    const BusLoad at1ms = computeBusLoad(in);
    EXPECT_EQ(at1ms.frames_per_cycle, 13);
    EXPECT_FALSE(at1ms.ok);
    EXPECT_GT(at1ms.load, 1.0); // six CSP axes do not fit 1 ms on 1 Mbit/s
    EXPECT_NE(at1ms.message.find("13 frames"), std::string::npos) << at1ms.message;
    EXPECT_NE(at1ms.message.find("the limit is 80 %"), std::string::npos) << at1ms.message;
    EXPECT_NE(at1ms.message.find("use a period >="), std::string::npos) << at1ms.message;
    // At the minimum period the load is exactly the limit; a little less fails.
    in.period_s = at1ms.min_period_s;
    EXPECT_NEAR(computeBusLoad(in).load, 0.8, 1e-9);
    in.period_s = at1ms.min_period_s * 1.001;
    EXPECT_TRUE(computeBusLoad(in).ok);
    in.period_s = at1ms.min_period_s * 0.999;
    EXPECT_FALSE(computeBusLoad(in).ok);
    // Doubling the bit rate halves the cyclic load.
    BusLoadInput a, b;
    a.heartbeat_period_s = b.heartbeat_period_s = 0;
    a.period_s = b.period_s = 0.004;
    b.bitrate_bps = 2 * a.bitrate_bps;
    EXPECT_NEAR(computeBusLoad(a).load, 2 * computeBusLoad(b).load, 1e-12);
    // The advised period (rounded up to 0.1 ms) passes.
    in.period_s = std::ceil(at1ms.min_period_s * 1e4) / 1e4;
    EXPECT_TRUE(computeBusLoad(in).ok);
}
