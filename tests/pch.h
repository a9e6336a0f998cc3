// The headers most test files parse, precompiled once for all of them (the Makefile's TEST_PCH):
// GoogleTest, nlohmann-json (through the harness) and the standard library's heaviest.
// (No include guard: it is never included twice, and GCC refuses one in a header compiled alone.)

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
