// stable_order.h: the order in which an interaction emits its few
// candidate contacts (deepest first).
#pragma once

namespace karma::mcd {

// Sorts idx[0, n) so that key[idx[j]] increases, indices of equal keys
// keeping their order. For keys without NaN this is the order
// std::stable_sort gives (a stable sort's result is unique), made by
// insertion in place: no buffer is allocated, and n is small.
template <class Real>
void StableOrderByKey(int *idx, int n, const Real *key) {
  for (int i = 1; i < n; ++i) {
    const int moving = idx[i];
    int j = i;
    for (; j > 0 && key[moving] < key[idx[j - 1]]; --j) idx[j] = idx[j - 1];
    idx[j] = moving;
  }
}

}  // namespace karma::mcd
