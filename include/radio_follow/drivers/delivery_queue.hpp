// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace radio_follow::drivers {

/// A bounded queue and the thread that empties it, between a driver's I/O thread and
/// whatever hands its measurements on (the ROS publisher). The I/O thread only moves an
/// item in and goes back to reading the device: it never waits for serialization or for a
/// lock inside the middleware, so the device's own buffer cannot overrun behind it. When
/// the consumer falls behind by `capacity` items the oldest one is dropped, and counted:
/// the one place where a driver loses a measurement is one it can report.
///
/// `push()` may be called from any thread; `deliver` runs on the queue's own thread, one
/// item at a time, in push order.
template <typename T>
class DeliveryQueue {
 public:
  using Deliver = std::function<void(T& item)>;

  /// Starts the delivery thread. `capacity` must be at least 1.
  DeliveryQueue(std::size_t capacity, Deliver deliver)
      : slots_(capacity < 1 ? 1 : capacity), deliver_(std::move(deliver)) {
    thread_ = std::thread([this] { run(); });
  }

  ~DeliveryQueue() { stop(); }
  DeliveryQueue(const DeliveryQueue&) = delete;
  DeliveryQueue& operator=(const DeliveryQueue&) = delete;

  /// Queues `item` without blocking. Returns false when the queue was full and its oldest
  /// item was dropped to make room (or when stopped: then `item` itself is dropped).
  bool push(T item) {
    bool dropped = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) {
        ++dropped_;
        return false;
      }
      if (size_ == slots_.size()) {
        head_ = (head_ + 1) % slots_.size();  // overwrite the oldest
        --size_;
        ++dropped_;
        dropped = true;
      }
      slots_[(head_ + size_) % slots_.size()] = std::move(item);
      ++size_;
      peak_ = size_ > peak_ ? size_ : peak_;
    }
    wake_.notify_one();
    return !dropped;
  }

  /// Delivers what is still queued, then ends the thread. Idempotent.
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    if (thread_.joinable()) {
      thread_.join();
    }
  }

  std::size_t capacity() const { return slots_.size(); }

  /// Items dropped so far because the queue was full (or stopped).
  std::uint64_t dropped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return dropped_;
  }

  /// The most items ever waiting at once: how close a burst came to `capacity`.
  std::size_t peak() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return peak_;
  }

 private:
  void run() {
    T item;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return size_ > 0 || stopping_; });
        if (size_ == 0) {
          return;  // stopping, and everything was delivered
        }
        item = std::move(slots_[head_]);
        head_ = (head_ + 1) % slots_.size();
        --size_;
      }
      deliver_(item);
    }
  }

  std::vector<T> slots_;  // ring buffer: size_ items from head_
  Deliver deliver_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::size_t peak_ = 0;
  std::uint64_t dropped_ = 0;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace radio_follow::drivers
