#pragma once
// Prints a measured value beside the bound a test asserts (MuJoCo's habit of writing the measured
// number next to each threshold), so the ctest log always shows how much margin is left:
//   TUMBLE_MEASURED(worst_drift, 1e-6)  ->  "[measured] worst_drift = 2.2e-07 (bound 1e-06)"
#include <gtest/gtest.h>

#include <cstdio>

#define TUMBLE_MEASURED(value, bound)                                                              \
    do {                                                                                           \
        std::printf("[measured] %s = %.6g (bound %.6g)\n", #value, static_cast<double>(value),     \
                    static_cast<double>(bound));                                                   \
        ::testing::Test::RecordProperty(#value, std::to_string(static_cast<double>(value)));       \
    } while (0)
