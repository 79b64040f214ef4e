// The lock-free rings between the engine and its neighbours, under real concurrency.
#include "core/engine/mpsc_queue.h"
#include "core/engine/spsc_ring.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace cutcell {
namespace {

TEST(SpscRing, BoundedAndFifo) {
    SpscRing<int> r(5); // rounded up to 8
    EXPECT_EQ(r.capacity(), 8u);
    for (int i = 0; i < 8; ++i)
        EXPECT_TRUE(r.push(i));
    EXPECT_FALSE(r.push(99)) << "full: the producer is told, nothing is overwritten";
    int v = -1;
    for (int i = 0; i < 8; ++i) {
        ASSERT_TRUE(r.pop(v));
        EXPECT_EQ(v, i);
    }
    EXPECT_FALSE(r.pop(v));
}

TEST(SpscRing, EveryValueArrivesOnceInOrderAcrossThreads) {
    SpscRing<long> r(64);
    constexpr long n = 20000;
    long dropped = 0;
    std::thread producer([&] {
        for (long i = 0; i < n; ++i)
            while (!r.push(i)) { // retry: this test wants every value
                ++dropped;
                std::this_thread::yield();
            }
    });
    long expected = 0, v = 0;
    while (expected < n) {
        if (r.pop(v)) {
            ASSERT_EQ(v, expected++);
        } else {
            std::this_thread::yield();
        }
    }
    producer.join();
    EXPECT_EQ(expected, n);
}

TEST(MpscQueue, ManyProducersOneConsumerLoseNothing) {
    struct Item {
        int producer;
        int seq;
    };
    MpscQueue<Item> q(128);
    constexpr int producers = 4, perProducer = 5000;
    std::vector<std::thread> threads;
    for (int p = 0; p < producers; ++p)
        threads.emplace_back([&q, p] {
            for (int i = 0; i < perProducer; ++i)
                while (!q.push({p, i}))
                    std::this_thread::yield();
        });
    std::vector<int> next(producers, 0);
    int received = 0;
    Item it{};
    while (received < producers * perProducer) {
        if (!q.pop(it)) {
            std::this_thread::yield();
            continue;
        }
        ASSERT_EQ(it.seq, next[static_cast<size_t>(it.producer)]) << "per-producer order";
        ++next[static_cast<size_t>(it.producer)];
        ++received;
    }
    for (auto& t : threads)
        t.join();
    EXPECT_FALSE(q.pop(it));
}

TEST(MpscQueue, FullQueueRefusesWithoutBlocking) {
    MpscQueue<int> q(4);
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(q.push(i));
    EXPECT_FALSE(q.push(4));
    int v = 0;
    EXPECT_TRUE(q.pop(v));
    EXPECT_EQ(v, 0);
    EXPECT_TRUE(q.push(4));
}

} // namespace
} // namespace cutcell
