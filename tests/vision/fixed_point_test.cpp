#include <gtest/gtest.h>

#include "vision/fixed_point.h"

using namespace icacam::vision;

TEST(FixedPoint, RoundTripWithinHalfAnUlp)
{
    for (double v : {0.0, 1.0, -1.0, 3.14159, -1234.5678, 32767.99})
        EXPECT_NEAR(Q16_16::fromDouble(v).toDouble(), v, 0.5 / 65536 + 1e-12);
}

TEST(FixedPoint, SaturatesInsteadOfWrapping)
{
    EXPECT_EQ(Q16_16::fromDouble(1e9).raw(), Q16_16::kMaxRaw);
    EXPECT_EQ(Q16_16::fromDouble(-1e9).raw(), Q16_16::kMinRaw);
    EXPECT_EQ((Q16_16::fromDouble(30000) + Q16_16::fromDouble(30000)).raw(), Q16_16::kMaxRaw);
    EXPECT_EQ((Q16_16::fromDouble(-30000) - Q16_16::fromDouble(30000)).raw(), Q16_16::kMinRaw);
    EXPECT_EQ(Q2_14::fromDouble(2.5).raw(), Q2_14::kMaxRaw);
    EXPECT_EQ(Q16_16::fromDouble(0.0 / 0.0 + 0).raw(), 0); // NaN → 0
}

TEST(FixedPoint, ProductRoundsToNearestAgainstDouble)
{
    // Q16.16 × Q2.14 (a radius times a direction): error ≤ half an ulp of Q16.16 plus the
    // quantisation of the operands.
    for (double r : {0.0, 1.5, 100.25, 731.7, -12.125})
        for (double c : {1.0, 0.70710678, -0.5, 0.0001, -0.99999}) {
            const auto q = Q16_16::fromDouble(r).mul(Q2_14::fromDouble(c));
            const double ref = Q16_16::fromDouble(r).toDouble() * Q2_14::fromDouble(c).toDouble();
            EXPECT_NEAR(q.toDouble(), ref, 0.5 / 65536 + 1e-12) << r << " * " << c;
        }
}

TEST(FixedPoint, FloorAndFractionOfNegatives)
{
    const auto q = Q16_16::fromDouble(-1.25);
    EXPECT_EQ(q.floor(), -2);
    EXPECT_EQ(q.frac(), 0xC000);
}
