// Union-find over 0..n-1 with path halving: connected components of graphs.
#pragma once

#include <numeric>
#include <vector>

namespace pcskeleton {

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    bool unite(int a, int b) {
        a = find(a), b = find(b);
        if (a == b) return false;
        parent_[b] = a;
        return true;
    }

private:
    std::vector<int> parent_;
};

}  // namespace pcskeleton
