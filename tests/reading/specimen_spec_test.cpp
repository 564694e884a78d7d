// The one builder of a specimen's spec from key/value pairs (manifest columns, config keys).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "reading/specimen_spec.h"

namespace icacam::reading {
namespace {

bool build(const std::map<std::string, std::string> &fields, bool needsScale, SpecimenSpec *spec, std::string *why)
{
    auto lookup = [&fields](std::string_view key) -> const char * {
        auto it = fields.find(std::string(key));
        return it == fields.end() ? nullptr : it->second.c_str();
    };
    return specimenFromFields(lookup, needsScale, spec, why);
}

TEST(SpecimenFields, EveryKeySetsItsValueAndAbsentOnesKeepTheDefaults)
{
    SpecimenSpec s;
    std::string why;
    ASSERT_TRUE(build({{"n", "0.21"},
                       {"mm_per_px", " 0.0153 "},
                       {"k_mpa", "640"},
                       {"h_final_mm", "7.4"},
                       {"n_tol", "0.02"},
                       {"tolerance_mu", "0.015"},
                       {"tolerance_rel", "0.04"},
                       {"mm_per_px_tol", "0.01"},
                       {"h_final_tol_mm", "0.1"},
                       {"tone_gamma", "2.2"}},
                      true, &s, &why))
        << why;
    EXPECT_EQ(s.n, 0.21);
    EXPECT_EQ(s.mmPerPx, 0.0153);
    EXPECT_EQ(s.kMpa, 640);
    EXPECT_EQ(s.hFinalMm, 7.4);
    EXPECT_EQ(s.toneGamma, 2.2);
    EXPECT_EQ(s.d0Mm, 10) << "absent: the default";
    EXPECT_EQ(s.tolerances.n, 0.02);
    EXPECT_EQ(s.tolerances.scaleRel, 0.01);
    EXPECT_EQ(s.tolerances.hFinalMm, 0.1);
    EXPECT_EQ(s.tolerance.absMu, 0.015);
    EXPECT_EQ(s.tolerance.relMu, 0.04);
}

TEST(SpecimenFields, EachProblemIsNamed)
{
    SpecimenSpec s;
    std::string why;
    EXPECT_FALSE(build({{"mm_per_px", "0.02"}}, true, &s, &why));
    EXPECT_EQ(why, "missing n");
    EXPECT_FALSE(build({{"n", "0.2"}}, true, &s, &why));
    EXPECT_EQ(why, "missing mm_per_px");
    EXPECT_TRUE(build({{"n", "0.2"}}, false, &s, &why)) << "a calibration sizes the search";
    EXPECT_FALSE(build({{"n", "0.2x"}, {"mm_per_px", "0.02"}}, true, &s, &why));
    EXPECT_EQ(why, "bad number in n: '0.2x'");
    EXPECT_FALSE(build({{"n", "0.2"}, {"mm_per_px", "0.02"}, {"n_tol", "-1"}}, true, &s, &why));
    EXPECT_EQ(why, "n_tol must not be negative");
    EXPECT_FALSE(build({{"n", "0.2"}, {"mm_per_px", "-0.02"}}, true, &s, &why));
    EXPECT_EQ(why, "mm_per_px must be positive");
    EXPECT_FALSE(build({{"n", "0.2"}, {"mm_per_px", "0.02"}, {"h0_mm", "0"}}, true, &s, &why));
    EXPECT_EQ(why, "h0_mm must be positive");
    EXPECT_FALSE(build({{"n", "nan"}, {"mm_per_px", "0.02"}}, true, &s, &why)) << "only finite numbers";
    for (const char *gamma : {"0.8", "3.5"}) {
        SpecimenSpec fresh;
        EXPECT_FALSE(build({{"n", "0.2"}, {"mm_per_px", "0.02"}, {"tone_gamma", gamma}}, true, &fresh, &why)) << gamma;
        EXPECT_EQ(why.rfind("tone_gamma must lie in 1-3", 0), 0u) << why;
    }
}

} // namespace
} // namespace icacam::reading
