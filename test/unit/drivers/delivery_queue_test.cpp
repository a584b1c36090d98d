// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/delivery_queue.hpp"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <vector>

namespace radio_follow::drivers {
namespace {

// A consumer that can be held, to let the queue fill as behind a stalled publisher.
struct GatedSink {
  std::mutex mutex;
  std::condition_variable changed;
  bool open = true;
  std::size_t entered = 0;  // deliver() calls begun
  std::vector<int> delivered;

  void deliver(int& item) {
    std::unique_lock<std::mutex> lock(mutex);
    ++entered;
    changed.notify_all();
    changed.wait(lock, [this] { return open; });
    delivered.push_back(item);
    changed.notify_all();
  }
  void setOpen(bool value) {
    std::lock_guard<std::mutex> lock(mutex);
    open = value;
    changed.notify_all();
  }
  // Waits until the consumer holds its `n`-th item.
  void waitEntered(std::size_t n) {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return entered >= n; });
  }
};

TEST(DeliveryQueue, DeliversEverythingInOrderWhenItFits) {
  GatedSink sink;
  DeliveryQueue<int> queue(1000, [&](int& i) { sink.deliver(i); });
  for (int i = 0; i < 1000; ++i) {
    EXPECT_TRUE(queue.push(i));
  }
  queue.stop();
  ASSERT_EQ(sink.delivered.size(), 1000u);
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(sink.delivered[static_cast<std::size_t>(i)], i);
  }
  EXPECT_EQ(queue.dropped(), 0u);
}

// A producer faster than the consumer: whatever the interleaving, every item is either
// delivered (in order, the last one always) or counted as dropped.
TEST(DeliveryQueue, EveryItemIsDeliveredOrCounted) {
  GatedSink sink;
  DeliveryQueue<int> queue(8, [&](int& i) { sink.deliver(i); });
  std::uint64_t refused = 0;
  for (int i = 0; i < 100000; ++i) {
    refused += queue.push(i) ? 0 : 1;
  }
  queue.stop();
  EXPECT_EQ(sink.delivered.size() + queue.dropped(), 100000u);
  EXPECT_EQ(queue.dropped(), refused);
  EXPECT_EQ(sink.delivered.back(), 99999);
  for (std::size_t i = 1; i < sink.delivered.size(); ++i) {
    ASSERT_LT(sink.delivered[i - 1], sink.delivered[i]);
  }
  EXPECT_LE(queue.peak(), 8u);
}

// Behind a stalled consumer the queue keeps the newest `capacity` items, drops the oldest
// and counts each drop; push() says when it had to.
TEST(DeliveryQueue, DropsTheOldestWhenFullAndCountsIt) {
  GatedSink sink;
  DeliveryQueue<int> queue(4, [&](int& i) { sink.deliver(i); });
  sink.setOpen(false);
  ASSERT_TRUE(queue.push(0));
  sink.waitEntered(1);  // 0 is held by the consumer; the queue is empty
  std::vector<bool> accepted;
  for (int i = 1; i <= 8; ++i) {
    accepted.push_back(queue.push(i));
  }
  EXPECT_EQ(accepted, (std::vector<bool>{true, true, true, true, false, false, false, false}));
  EXPECT_EQ(queue.dropped(), 4u);
  EXPECT_EQ(queue.peak(), 4u);
  sink.setOpen(true);
  queue.stop();
  EXPECT_EQ(sink.delivered, (std::vector<int>{0, 5, 6, 7, 8}));  // the newest, in order
  EXPECT_EQ(sink.delivered.size() + queue.dropped(), 9u);        // every item accounted for
}

TEST(DeliveryQueue, StopDeliversWhatIsQueuedAndCountsLaterPushes) {
  GatedSink sink;
  DeliveryQueue<int> queue(16, [&](int& i) { sink.deliver(i); });
  sink.setOpen(false);
  for (int i = 0; i < 10; ++i) {
    queue.push(i);
  }
  sink.setOpen(true);
  queue.stop();
  EXPECT_EQ(sink.delivered.size(), 10u);
  EXPECT_FALSE(queue.push(10));
  EXPECT_EQ(queue.dropped(), 1u);
  queue.stop();  // idempotent
  EXPECT_EQ(sink.delivered.size(), 10u);
}

}  // namespace
}  // namespace radio_follow::drivers
