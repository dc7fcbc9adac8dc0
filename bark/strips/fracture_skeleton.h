// The fracture skeleton (Lefebvre & Neyret 2002, sec. 3.2.4): fracture elements linked across
// strips (FractureElement::up / down) form a graph whose connected components are the
// fractures; fractures that meet are merged. Union–find over the fracture ids keeps the
// components.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace phellem::bark {

class FractureSkeleton {
 public:
  int32_t make() {
    parent_.push_back(int32_t(parent_.size()));
    return parent_.back();
  }
  // Makes every id below `ids` that does not exist yet, each a fracture of its own (ids
  // allocated by a half of a step's sweep come in a fixed pattern; unused ones stay alone).
  void extend(size_t ids) {
    while (parent_.size() < ids) parent_.push_back(int32_t(parent_.size()));
  }
  int32_t find(int32_t id) const {
    while (parent_[size_t(id)] != id) id = parent_[size_t(id)];
    return id;
  }
  // Merges the two fractures; the older (smaller) id stays the root so that ids are stable.
  // Returns true when they were different fractures.
  bool merge(int32_t a, int32_t b) {
    a = find_compress(a);
    b = find_compress(b);
    if (a == b) return false;
    if (b < a) std::swap(a, b);
    parent_[size_t(b)] = a;
    ++merges_;
    return true;
  }
  // Points every id straight at its root (same roots; later find() calls are one step). A
  // parent's id is smaller than its child's (merge keeps the older id), so one pass in id
  // order meets every parent already pointing at its root.
  void compress() {
    for (size_t i = 0; i < parent_.size(); ++i) parent_[i] = parent_[size_t(parent_[i])];
  }
  // The root of `id` right after compress() (and before any merge): its parent, read without
  // a loop.
  int32_t compressed_root(int32_t id) const { return parent_[size_t(id)]; }
  size_t ids() const { return parent_.size(); }
  long long merges() const { return merges_; }

 private:
  int32_t find_compress(int32_t id) {
    int32_t root = find(id);
    while (parent_[size_t(id)] != root) {
      const int32_t next = parent_[size_t(id)];
      parent_[size_t(id)] = root;
      id = next;
    }
    return root;
  }
  std::vector<int32_t> parent_;
  long long merges_ = 0;
};

}  // namespace phellem::bark
