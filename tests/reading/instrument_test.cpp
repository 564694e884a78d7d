// The instrument around the pipeline: a read is the pipeline's geometry interpreted once; a
// calibration holds only for frames of its size; the search is sized from the calibration
// where no scale is declared.
#include <gtest/gtest.h>

#include "friction/friction_models.h"
#include "reading/instrument.h"
#include "tests/vision/synthetic_end_face.h"

namespace icacam::reading {
namespace {

constexpr double kMmPerPx = 5.0 / 250; // the synthetic face's initial radius is 250 px

SpecimenSpec spec()
{
    SpecimenSpec s;
    s.n = 0.25, s.mmPerPx = kMmPerPx;
    return s;
}

TEST(Instrument, AReadIsThePipelinesGeometryInterpreted)
{
    const test::SyntheticEndFace face;
    const std::vector<uint8_t> px = face.draw();
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    Instrument instrument;
    ASSERT_EQ(instrument.configure(face.width, face.height, model), ErrorCode::None);
    const Reading r = instrument.read(face.view(px), spec());
    ASSERT_TRUE(r.hasValue()) << vision::errorMessage(r.error);
    EXPECT_NEAR(r.face.rInnerMm, face.rInner * kMmPerPx, 0.01);
    EXPECT_NEAR(r.face.rOuterMm, face.rOuter * kMmPerPx, 0.01);
    const Reading again = instrument.interpret(r.geometry, spec());
    EXPECT_EQ(again.mu, r.mu);
    EXPECT_EQ(again.muSigma, r.muSigma);
    EXPECT_EQ(again.flags, r.flags);
    // The same face as radii measured elsewhere reads the same μ at the declared scale.
    const Reading radii = instrument.interpret(FaceInMm{r.face.rInnerMm, r.face.rOuterMm, r.face.rMaxMm, 0}, spec());
    EXPECT_FALSE(radii.imaged);
    EXPECT_DOUBLE_EQ(radii.declared.mu, r.declared.mu);
    EXPECT_NEAR(radii.mu, r.mu, 2 * r.muSigma);
}

TEST(Instrument, ACalibrationHoldsOnlyForFramesOfItsSize)
{
    const test::SyntheticEndFace face;
    const std::vector<uint8_t> px = face.draw();
    Instrument instrument;
    ASSERT_EQ(instrument.configure(face.width, face.height, *friction::frictionModel(friction::kDefaultModel)),
              ErrorCode::None);
    vision::PlaneCalibration cal;
    cal.fx = cal.fy = 4000, cal.cx = 450, cal.cy = 440, cal.t[2] = 87.5;
    instrument.setCalibration(&cal, 1280, 960);
    EXPECT_EQ(instrument.frameSizeIssue(face.width, face.height),
              "frame is 900x880 but the calibration is for 1280x960 images");
    EXPECT_EQ(instrument.read(face.view(px), spec()).error, ErrorCode::CalibrationSize);
    instrument.setCalibration(&cal, face.width, face.height);
    EXPECT_EQ(instrument.frameSizeIssue(face.width, face.height), "");
    SpecimenSpec noScale = spec();
    noScale.mmPerPx = 0;
    const vision::FaceSearch search = instrument.searchFor(noScale, face.width, face.height);
    EXPECT_GT(search.mmPerPx, 0) << "the calibration's scale at the image centre sizes the search";
    instrument.setCalibration(nullptr, 0, 0);
    EXPECT_EQ(instrument.searchFor(noScale, face.width, face.height).mmPerPx, 0);
}

} // namespace
} // namespace icacam::reading
