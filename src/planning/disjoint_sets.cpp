#include "pmdplan/planning/disjoint_sets.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace pmdplan {

std::size_t DisjointSets::add() {
  parent_.push_back(parent_.size());
  setSize_.push_back(1);
  ++setCount_;
  return parent_.size() - 1;
}

std::size_t DisjointSets::find(std::size_t x) const {
  if (x >= parent_.size()) throw std::out_of_range("DisjointSets::find: no element " + std::to_string(x));
  while (parent_[x] != x) {
    parent_[x] = parent_[parent_[x]];
    x = parent_[x];
  }
  return x;
}

bool DisjointSets::unite(std::size_t a, std::size_t b) {
  std::size_t rootA = find(a);
  std::size_t rootB = find(b);
  if (rootA == rootB) return false;
  if (setSize_[rootA] < setSize_[rootB]) std::swap(rootA, rootB);
  parent_[rootB] = rootA;
  setSize_[rootA] += setSize_[rootB];
  --setCount_;
  return true;
}

void DisjointSets::clear() {
  parent_.clear();
  setSize_.clear();
  setCount_ = 0;
}

}  // namespace pmdplan
