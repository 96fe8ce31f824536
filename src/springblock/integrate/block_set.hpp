#pragma once
// A set of blocks of the chain: membership by block, tested in O(1), and the members in the
// order they joined, so a pass over the set costs its size, not N.
#include <cstdint>
#include <vector>

namespace sb::event_detail {

class BlockSet {
 public:
  explicit BlockSet(int N) : in_(N, 0) {}
  void add(int i) {
    if (!in_[i]) in_[i] = 1, list_.push_back(i);
  }
  bool has(int i) const { return in_[i] != 0; }
  const std::uint8_t* flags() const { return in_.data(); }  // 1 per member block
  const std::vector<int>& list() const { return list_; }
  void clear() {
    for (int i : list_) in_[i] = 0;
    list_.clear();
  }

 private:
  std::vector<std::uint8_t> in_;
  std::vector<int> list_;
};

}  // namespace sb::event_detail
