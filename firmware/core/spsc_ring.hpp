// SpscRing: fixed-capacity single-producer/single-consumer ring, the one way data crosses from an ISR to the main
// loop (and back, for UART TX). Capacities and overflow rules: docs/hal.md §1.2 "Rings".
//
// Concurrency model: one core, the producer is an interrupt handler (or the main loop for TX), the consumer the
// other side. Each index is one byte, written by one side only, so loads and stores are atomic on the AVR without
// a critical section; a compiler barrier orders the element copy before the index that publishes it. The native
// port uses a ring from one thread only.
#pragma once

#include <stdint.h>

namespace driftlab {
namespace fw {

namespace detail {
/// Keeps the compiler from moving memory accesses across this point (the AVR has no reordering hardware).
inline void compiler_barrier() { __asm__ __volatile__("" ::: "memory"); }
}  // namespace detail

/// \tparam T         element type, trivially copyable
/// \tparam Capacity  the maximum number of elements held; a power of two from 2 to 128 so that free-running
///                   uint8_t indices wrap consistently and `head - tail` is the fill level
template <typename T, uint8_t Capacity>
class SpscRing {
  static_assert(Capacity >= 2 && Capacity <= 128 && (Capacity & (Capacity - 1)) == 0,
                "SpscRing capacity must be a power of two from 2 to 128");

 public:
  static constexpr uint8_t kCapacity = Capacity;

  /// Producer side: appends `value`; returns false (ring unchanged) when full.
  bool push(const T& value) {
    const uint8_t head = head_;
    if (static_cast<uint8_t>(head - tail_) == Capacity) {
      return false;
    }
    slots_[head & kMask] = value;
    detail::compiler_barrier();
    head_ = static_cast<uint8_t>(head + 1U);
    return true;
  }

  /// Consumer side: removes the oldest element into `*out`; returns false (out untouched) when empty.
  bool pop(T* out) {
    const uint8_t tail = tail_;
    if (head_ == tail) {
      return false;
    }
    detail::compiler_barrier();  // read the slot only after seeing the index that published it
    *out = slots_[tail & kMask];
    detail::compiler_barrier();
    tail_ = static_cast<uint8_t>(tail + 1U);
    return true;
  }

  /// Elements held; exact from the consumer's side, a lower bound of free space from the producer's.
  uint8_t size() const { return static_cast<uint8_t>(head_ - tail_); }
  bool empty() const { return head_ == tail_; }
  uint8_t free_space() const { return static_cast<uint8_t>(Capacity - size()); }

  /// Consumer side: drops everything currently held.
  void clear() { tail_ = head_; }

 private:
  static constexpr uint8_t kMask = static_cast<uint8_t>(Capacity - 1U);

  T slots_[Capacity];
  volatile uint8_t head_ = 0;  // written by the producer only
  volatile uint8_t tail_ = 0;  // written by the consumer only
};

}  // namespace fw
}  // namespace driftlab
