#pragma once
// Eigen sizes the blocks of a large matrix product from the cache sizes it reads off the CPU, and
// the block sizes set the order of the sums over the frames, so a covariance's last bits (and a
// 12th model decimal near a rounding boundary) would depend on the machine. Products made while a
// PinnedProductBlocking lives use fixed sizes (the ones the shipped default model was made with);
// the sizes found are restored afterwards. Not thread-safe: Eigen keeps the sizes in one global.
#include <Eigen/Core>
#include <cstddef>

namespace pmdplan {
namespace detail {

class PinnedProductBlocking {
 public:
  PinnedProductBlocking() : l1_(Eigen::l1CacheSize()), l2_(Eigen::l2CacheSize()), l3_(Eigen::l3CacheSize()) {
    Eigen::setCpuCacheSizes(48 * 1024, 512 * 1024, 8 * 1024 * 1024);
  }
  ~PinnedProductBlocking() { Eigen::setCpuCacheSizes(l1_, l2_, l3_); }
  PinnedProductBlocking(const PinnedProductBlocking&) = delete;
  PinnedProductBlocking& operator=(const PinnedProductBlocking&) = delete;

 private:
  std::ptrdiff_t l1_, l2_, l3_;
};

}  // namespace detail

/// x^T x, summed over the rows (frames) in the same order on every machine.
inline Eigen::MatrixXd gramOverFrames(const Eigen::MatrixXd& x) {
  const detail::PinnedProductBlocking pinned;
  return x.transpose() * x;
}

}  // namespace pmdplan
