#pragma once
/// A fixed number of the latest samples of one quantity, oldest first, for
/// the live plots.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace impulse::viewer {

class History {
 public:
  explicit History(std::size_t capacity) : capacity_(capacity) { values_.reserve(capacity); }

  void add(float value) {
    if (values_.size() == capacity_) values_.erase(values_.begin());
    values_.push_back(value);
  }
  const std::vector<float>& values() const { return values_; }
  float latest() const { return values_.empty() ? 0.0f : values_.back(); }
  float max() const {
    return values_.empty() ? 0.0f : *std::max_element(values_.begin(), values_.end());
  }

 private:
  std::size_t capacity_;
  std::vector<float> values_;
};

}  // namespace impulse::viewer
