#pragma once
// Union-find over 0..n-1: the roadmap's connected components (Algorithm 3's SAMECOMPONENT and
// UPDATE). Union by size and path halving keep every operation close to constant time.
#include <cstddef>
#include <vector>

namespace pmdplan {

class DisjointSets {
 public:
  /// Adds a new singleton set and returns its element.
  std::size_t add();
  /// The representative of x's set. Mutates (path halving) but not observably.
  std::size_t find(std::size_t x) const;
  /// Merges the sets of a and b; returns false if they were already one set.
  bool unite(std::size_t a, std::size_t b);
  bool same(std::size_t a, std::size_t b) const { return find(a) == find(b); }
  std::size_t size() const { return parent_.size(); }
  std::size_t setCount() const { return setCount_; }
  void clear();

 private:
  mutable std::vector<std::size_t> parent_;
  std::vector<std::size_t> setSize_;
  std::size_t setCount_ = 0;
};

}  // namespace pmdplan
