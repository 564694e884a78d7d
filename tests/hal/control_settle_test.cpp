// When a frame shows a control change (hal/libcamera/control_settle.h): frames reporting the
// old values are not taken for the new, and the sensor's rounding does not hold a frame back.
#include <gtest/gtest.h>

#include "hal/libcamera/control_settle.h"

using namespace icacam;

namespace {

hal::ControlChange exposureChange(int before, int asked)
{
    hal::ControlChange c;
    c.before.exposureUs = before;
    c.before.analogueGain = 1.0;
    c.asked.exposureUs = asked;
    return c;
}

hal::CameraControls reported(int exposureUs, double gain)
{
    hal::CameraControls r;
    r.exposureUs = exposureUs;
    r.analogueGain = gain;
    return r;
}

} // namespace

TEST(ControlSettle, FramesWithTheOldExposureDoNotShowTheChange)
{
    const hal::ControlChange c = exposureChange(10000, 20000);
    EXPECT_FALSE(showsChange(c, reported(10000, 1.0)));
    EXPECT_FALSE(showsChange(c, reported(10012, 1.0))); // the old value, rounded to a line
    EXPECT_TRUE(showsChange(c, reported(19987, 1.0)));  // the new, rounded to a line
    EXPECT_TRUE(showsChange(c, reported(20000, 1.0)));
}

TEST(ControlSettle, ADecreaseIsSeenAsWellAsAnIncrease)
{
    const hal::ControlChange c = exposureChange(20000, 4000);
    EXPECT_FALSE(showsChange(c, reported(20000, 1.0)));
    EXPECT_TRUE(showsChange(c, reported(4011, 1.0)));
}

TEST(ControlSettle, EveryChangedControlMustShow)
{
    hal::ControlChange c = exposureChange(10000, 20000);
    c.asked.analogueGain = 4.0;
    EXPECT_FALSE(showsChange(c, reported(20000, 1.0))); // gain still the old (it lags a frame less or more)
    EXPECT_FALSE(showsChange(c, reported(10000, 4.0)));
    EXPECT_TRUE(showsChange(c, reported(20000, 3.97))); // the gain register's step
}

TEST(ControlSettle, WhatAFrameDoesNotReportDoesNotHoldItBack)
{
    hal::ControlChange c = exposureChange(10000, 20000);
    c.asked.lensPosition = 2.0;
    c.before.lensPosition = 0.5;
    EXPECT_TRUE(showsChange(c, reported(20000, 1.0))); // no LensPosition in the metadata
    hal::CameraControls r = reported(20000, 1.0);
    r.lensPosition = 0.5;
    EXPECT_FALSE(showsChange(c, r)); // the lens has not moved yet
    // Nothing known before (a control never set): any frame will do.
    hal::ControlChange fresh;
    fresh.asked.exposureUs = 20000;
    EXPECT_TRUE(showsChange(fresh, reported(10000, 1.0)));
}
