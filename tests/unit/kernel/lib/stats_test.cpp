// Under test: kernel/lib/stats.h.
// lib::median_in_place and lib::summarise_in_place against std::nth_element and std::sort, on
// random arrays (few and many distinct values) and the shapes that break naive pivots.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "kernel/lib/stats.h"

namespace {

// Checks the contract on one array: the median at v[n / 2] and returned, nothing greater before
// it nor smaller after it, and the same values as before.
void expect_median(std::vector<uint32_t> v, const std::string& what) {
    SCOPED_TRACE(what + ", n = " + std::to_string(v.size()));
    std::vector<uint32_t> want = v;
    const size_t k = v.size() / 2;
    std::nth_element(want.begin(), want.begin() + std::ptrdiff_t(k), want.end());
    std::vector<uint32_t> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(want[k], sorted[k]);

    uint32_t got = lib::median_in_place(v.data(), uint32_t(v.size()));
    EXPECT_EQ(got, sorted[k]);
    EXPECT_EQ(v[k], sorted[k]);
    for (size_t i = 0; i < k; ++i) ASSERT_LE(v[i], v[k]) << "at " << i;
    for (size_t i = k + 1; i < v.size(); ++i) ASSERT_GE(v[i], v[k]) << "at " << i;
    std::sort(v.begin(), v.end());
    EXPECT_EQ(v, sorted) << "a permutation of the input";
}

TEST(Stats, MedianOfTheSmallestArrays) {
    expect_median({7}, "one");
    expect_median({3, 9}, "two, sorted");
    expect_median({9, 3}, "two, reversed");
    expect_median({5, 5}, "two, equal");
    expect_median({2, 1, 3}, "three");
    expect_median({0xFFFFFFFFu, 0, 0xFFFFFFFFu, 0}, "extremes");
}

TEST(Stats, MedianOfRandomArraysMatchesNthElement) {
    std::mt19937 rng(20261121);
    for (int round = 0; round < 3000; ++round) {
        const size_t n = 1 + rng() % (round < 2000 ? 40 : 2000);
        // few distinct values (many duplicates) in a third of the rounds
        const uint32_t range = round % 3 == 0 ? 1 + rng() % 4 : round % 3 == 1 ? 1000 : 0xFFFFFFFFu;
        std::vector<uint32_t> v(n);
        for (uint32_t& x : v) x = range == 0xFFFFFFFFu ? uint32_t(rng()) : uint32_t(rng() % range);
        expect_median(v, "random");
    }
}

TEST(Stats, MedianOfOrderedAndRepeatedShapes) {
    for (size_t n : {1u, 2u, 3u, 4u, 5u, 8u, 9u, 100u, 101u, 4096u, 100000u}) {
        std::vector<uint32_t> v(n);
        std::iota(v.begin(), v.end(), 10u);
        expect_median(v, "sorted");
        std::reverse(v.begin(), v.end());
        expect_median(v, "reversed");
        std::fill(v.begin(), v.end(), 42u);
        expect_median(v, "all equal");
        for (size_t i = 0; i < n; ++i) v[i] = uint32_t(std::min(i, n - 1 - i));
        expect_median(v, "organ pipe");
        for (size_t i = 0; i < n; ++i) v[i] = uint32_t(i % 2);
        expect_median(v, "alternating");
        for (size_t i = 0; i < n; ++i) v[i] = uint32_t(i % 7 == 0 ? 1000000 + i : i);
        expect_median(v, "sorted with spikes");
    }
}

TEST(Stats, SummaryHasSumMinMaxAndMedian) {
    std::vector<uint32_t> v = {40, 10, 0xFFFFFFFFu, 30, 20};
    lib::Summary s = lib::summarise_in_place(v.data(), uint32_t(v.size()));
    EXPECT_EQ(s.sum, 100ull + 0xFFFFFFFFull) << "summed in 64 bits";
    EXPECT_EQ(s.min, 10u);
    EXPECT_EQ(s.max, 0xFFFFFFFFu);
    EXPECT_EQ(s.median, 30u);
    std::vector<uint32_t> one = {5};
    s = lib::summarise_in_place(one.data(), 1);
    EXPECT_EQ(s.sum, 5u);
    EXPECT_EQ(s.min, 5u);
    EXPECT_EQ(s.max, 5u);
    EXPECT_EQ(s.median, 5u);
}

}  // namespace
