// SPDX-License-Identifier: MIT
#pragma once
// Internal: the 2D broad phase's cell crossings, at most one per body, in an indexed binary
// min-heap ordered by (time, body). A body's entry is replaced in place when its crossing is
// predicted again, so that the crossings never leave stale entries behind: in the main event
// queue they did, two of every three of them (each impact predicts its two disks' crossings
// afresh), and every stale entry cost a pop of the larger heap. See plane_grid.cpp.
#include <cstdint>
#include <utility>
#include <vector>

namespace collide::physics::detail {

class CrossingQueue {
 public:
  struct Entry {
    double time_s = 0.0;
    int body = 0;
    int direction = 0;  // the face crossed: +x, -x, +y, -y
  };

  // Empty, for bodies 0 .. bodies - 1.
  void reset(int bodies) {
    heap_.clear();
    position_.assign(static_cast<std::size_t>(bodies), kAbsent);
  }
  void clear() { reset(0); }
  bool empty() const { return heap_.empty(); }
  const Entry& top() const { return heap_.front(); }

  // The body's next crossing: inserted, or its entry moved to its new place.
  void set(int body, double time_s, int direction) {
    const Entry entry{time_s, body, direction};
    int at = position_[body];
    if (at == kAbsent) {
      at = static_cast<int>(heap_.size());
      heap_.push_back(entry);
      siftUp(at);
      return;
    }
    const bool earlier = before(entry, heap_[at]);
    heap_[at] = entry;
    if (earlier) {
      siftUp(at);
    } else {
      siftDown(at);
    }
  }

  // The body has no crossing ahead.
  void remove(int body) {
    const int at = position_[body];
    if (at == kAbsent) return;
    position_[body] = kAbsent;
    const int last = static_cast<int>(heap_.size()) - 1;
    if (at == last) {
      heap_.pop_back();
      return;
    }
    const bool earlier = before(heap_[last], heap_[at]);
    place(at, heap_[last]);
    heap_.pop_back();
    if (earlier) {
      siftUp(at);
    } else {
      siftDown(at);
    }
  }

 private:
  static constexpr int kAbsent = -1;

  // The event queue's order among crossings: time, then body (one crossing per body).
  static bool before(const Entry& x, const Entry& y) {
    return x.time_s < y.time_s || (x.time_s == y.time_s && x.body < y.body);
  }
  void place(int at, const Entry& entry) {
    heap_[at] = entry;
    position_[entry.body] = at;
  }
  void siftUp(int at) {
    const Entry moving = heap_[at];
    while (at > 0) {
      const int parent = (at - 1) / 2;
      if (!before(moving, heap_[parent])) break;
      place(at, heap_[parent]);
      at = parent;
    }
    place(at, moving);
  }
  void siftDown(int at) {
    const Entry moving = heap_[at];
    const int size = static_cast<int>(heap_.size());
    for (;;) {
      int child = 2 * at + 1;
      if (child >= size) break;
      if (child + 1 < size && before(heap_[child + 1], heap_[child])) ++child;
      if (!before(heap_[child], moving)) break;
      place(at, heap_[child]);
      at = child;
    }
    place(at, moving);
  }

  std::vector<Entry> heap_;
  std::vector<int> position_;  // per body: its index in heap_, or kAbsent
};

}  // namespace collide::physics::detail
