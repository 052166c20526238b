#pragma once
// Fixed-capacity ring buffer: keeps the newest `capacity` values, oldest first by index. Memory stays
// bounded however many values are pushed (the live simulation view keeps the last N samples per signal).
#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

namespace mx::widgets {

template <class T>
class RingBuffer {
 public:
  explicit RingBuffer(std::size_t capacity) : data_(capacity) {
    if (capacity == 0) throw std::invalid_argument("RingBuffer: capacity must be >= 1");
  }

  std::size_t capacity() const { return data_.size(); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Values pushed since construction or clear(), including the ones overwritten.
  std::size_t totalPushed() const { return total_; }

  void clear() {
    head_ = 0;
    size_ = 0;
    total_ = 0;
  }

  void push(const T& value) {
    data_[head_] = value;
    head_ = (head_ + 1) % data_.size();
    size_ = std::min(size_ + 1, data_.size());
    ++total_;
  }

  void push(std::span<const T> values) {
    // Only the last `capacity` values can survive.
    const std::size_t skip = values.size() > data_.size() ? values.size() - data_.size() : 0;
    total_ += skip;
    for (std::size_t i = skip; i < values.size(); ++i) push(values[i]);
  }

  // i = 0 is the oldest value kept, size() - 1 the newest.
  const T& operator[](std::size_t i) const { return data_[(head_ + data_.size() - size_ + i) % data_.size()]; }
  const T& front() const { return (*this)[0]; }
  const T& back() const { return (*this)[size_ - 1]; }

  // The kept values, oldest first.
  std::vector<T> toVector() const {
    std::vector<T> out;
    out.reserve(size_);
    for (std::size_t i = 0; i < size_; ++i) out.push_back((*this)[i]);
    return out;
  }

 private:
  std::vector<T> data_;
  std::size_t head_ = 0;  // slot of the next push
  std::size_t size_ = 0;
  std::size_t total_ = 0;
};

}  // namespace mx::widgets
