#pragma once
// The root of x in a union-find forest over body indices (parent[x] == x at a root), halving the
// path on the way. The contact stage's islands use it: sleeping (contact_sleep.cpp) and the effort
// per island (contact_effort.cpp).
#include <vector>

namespace tumble::physics {

inline int union_root(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

} // namespace tumble::physics
