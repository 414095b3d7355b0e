// A heap array aligned to 64 bytes, for the dense kernels of the supernodal factorisation and
// solves (linalg/supernodal_cholesky.h, linalg/supernodal_factor.h).
//
// Why. Eigen's vectorised loops over a block of unknown alignment (triangular solves, matrix-vector
// products) handle the first elements up to a packet boundary one by one and the rest in AVX
// packets; with FMA (x86-64-v3) a packet computes a*b + c fused while the one-by-one code rounds
// the product first (-ffp-contract=off). Which elements take which path depends on the address
// modulo 32, and malloc only guarantees 16 bytes: the same factor stored at another address gave
// other last bits (measured: a 3D run differed between one and two threads, its first
// factorisation's supernode 346 in the 15th digit, with the heap laid out differently by the team).
// Storing the factor at a fixed alignment makes its arithmetic a function of the data alone.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace vs {

template <typename T>
class AlignedBuffer {
 public:
  static constexpr std::size_t kAlignment = 64;

  static_assert(std::is_trivially_copyable_v<T>, "elements are never constructed");

  AlignedBuffer() = default;
  explicit AlignedBuffer(std::size_t n) { resize(n); }
  AlignedBuffer(AlignedBuffer&& o) noexcept
      : data_(std::move(o.data_)), size_(std::exchange(o.size_, 0)) {}
  AlignedBuffer& operator=(AlignedBuffer&& o) noexcept {
    data_ = std::move(o.data_);
    size_ = std::exchange(o.size_, 0);
    return *this;
  }
  AlignedBuffer(const AlignedBuffer&) = delete;
  AlignedBuffer& operator=(const AlignedBuffer&) = delete;

  // Reallocates when n differs from the size; the contents are then unspecified.
  void resize(std::size_t n) {
    if (n == size_) return;
    data_.reset();
    size_ = 0;
    if (n == 0) return;
    const std::size_t bytes = (n * sizeof(T) + kAlignment - 1) / kAlignment * kAlignment;
    void* p = std::aligned_alloc(kAlignment, bytes);
    if (p == nullptr) throw std::bad_alloc();
    data_.reset(static_cast<T*>(p));
    size_ = n;
  }
  void assign(std::size_t n, const T& value) {
    resize(n);
    std::fill(data(), data() + n, value);
  }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T[], Free> data_;
  std::size_t size_ = 0;
};

}  // namespace vs
