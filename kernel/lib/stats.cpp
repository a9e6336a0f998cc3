// Selection (Hoare's FIND as Wirth writes it) and the summaries built on it.
#include "kernel/lib/stats.h"

namespace lib {

namespace {

void swap(uint32_t& a, uint32_t& b) {
    uint32_t t = a;
    a = b, b = t;
}

}  // namespace

uint32_t median_in_place(uint32_t* v, uint32_t n) {
    // Signed indices: j steps below lo when a partition ends at the range's first element.
    const int32_t k = int32_t(n / 2);
    int32_t lo = 0, hi = int32_t(n) - 1;
    while (lo < hi) {
        // Ordering the range's ends and middle makes the middle the pivot and the ends sentinels
        // that stop both scans inside the range.
        int32_t mid = lo + (hi - lo) / 2;
        if (v[mid] < v[lo]) swap(v[mid], v[lo]);
        if (v[hi] < v[lo]) swap(v[hi], v[lo]);
        if (v[hi] < v[mid]) swap(v[hi], v[mid]);
        const uint32_t pivot = v[mid];
        int32_t i = lo, j = hi;
        // Equal elements stop both scans and are swapped: runs of duplicates split evenly.
        while (i <= j) {
            while (v[i] < pivot) ++i;
            while (pivot < v[j]) --j;
            if (i <= j) swap(v[i++], v[j--]);
        }
        // Now v[lo..j] <= pivot <= v[i..hi], and anything between j and i equals the pivot.
        if (j < k) lo = i;
        if (k < i) hi = j;
    }
    return v[k];
}

Summary summarise_in_place(uint32_t* v, uint32_t n) {
    Summary s;
    s.min = s.max = v[0];
    for (uint32_t i = 0; i < n; ++i) {
        s.sum += v[i];
        if (v[i] < s.min) s.min = v[i];
        if (v[i] > s.max) s.max = v[i];
    }
    s.median = median_in_place(v, n);
    return s;
}

}  // namespace lib
