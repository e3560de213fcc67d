// Counter-based random numbers.
#include "sim/random.h"

#include <gtest/gtest.h>

namespace raintrace::sim {
namespace {

TEST(Random, UniformHasMeanHalfAndVarianceOneTwelfth) {
  const int n = 200000;
  double s = 0.0, s2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double u = uniform(1, Stream::drop, k, 0);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  // σ of the mean = sqrt(1/12/n) = 6.5e-4: 5σ bounds.
  EXPECT_NEAR(s / n, 0.5, 3.2e-3);
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12.0, 2e-3);
}

TEST(Random, KeysAreIndependentOfOrderAndStream) {
  EXPECT_EQ(hash_key(1, Stream::drop, 5, 2), hash_key(1, Stream::drop, 5, 2));
  EXPECT_NE(hash_key(1, Stream::drop, 5, 2), hash_key(1, Stream::drop, 2, 5));
  EXPECT_NE(hash_key(1, Stream::drop, 5, 2), hash_key(1, Stream::fill, 5, 2));
  EXPECT_NE(hash_key(1, Stream::drop, 5, 2), hash_key(2, Stream::drop, 5, 2));
}

TEST(Random, ExponentialHasMeanOne) {
  const int n = 200000;
  double s = 0.0;
  for (int k = 0; k < n; ++k) s += exponential(3, Stream::lightning, k);
  EXPECT_NEAR(s / n, 1.0, 0.012);  // σ of the mean = 1/√n = 2.2e-3
}

}  // namespace
}  // namespace raintrace::sim
