// GoogleTest helpers shared by the test programs: bit-exact comparison of whole runs.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "run/run.h"

namespace tactile::test_support {

inline bool bitEqual(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Every column bit for bit (so -0.0 and 0.0 differ), metadata, truth and x_ columns.
inline void expectSameRun(const RunData& a, const RunData& b) {
  EXPECT_EQ(a.metadata, b.metadata);
  EXPECT_TRUE(bitEqual(a.x, b.x));
  EXPECT_TRUE(bitEqual(a.y, b.y));
  EXPECT_TRUE(bitEqual(a.theta, b.theta));
  EXPECT_TRUE(bitEqual(a.v, b.v));
  EXPECT_TRUE(bitEqual(a.omega, b.omega));
  EXPECT_TRUE(bitEqual(a.sensors, b.sensors));
  EXPECT_EQ(a.blocked, b.blocked);
  EXPECT_EQ(a.truth, b.truth);
  EXPECT_EQ(a.extraColumns, b.extraColumns);
  EXPECT_EQ(a.extraValues, b.extraValues);
}

}  // namespace tactile::test_support
