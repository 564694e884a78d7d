// The slenderness carry (friction/aspect_corrected_model.h) and its generated table
// (friction/aspect_table.h) against the committed FE runs it names.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "friction/aspect_corrected_model.h"
#include "friction/aspect_table.h"
#include "friction/fe_model.h"
#include "friction/paper_model.h"
#include "host_tools/fe/fe_aspect.h"
#include "host_tools/fe/fe_rows.h"
#include "tests/support/table_inputs.h"

using namespace icacam;
namespace t = icacam::friction::aspect_table;

namespace {
std::vector<std::string> tableInputs()
{
    return test::repositoryPaths(t::kInputs);
}
int index(const double *axis, int count, double x)
{
    for (int i = 0; i < count; ++i)
        if (std::fabs(axis[i] - x) < 1e-9) return i;
    return -1;
}
} // namespace

TEST(AspectTable, MatchesCommittedData)
{
    const auto in = tableInputs();
    ASSERT_FALSE(in.empty());
    for (const auto &p : in) ASSERT_TRUE(std::filesystem::exists(p)) << p << " (named by " << t::kProvenance << ")";
    const auto ar = host::fe::aspectRatios(in);
    int simulated = 0;
    for (int a = 0; a < t::kACount; ++a)
        for (int n = 0; n < t::kNCount; ++n)
            for (int r = 0; r < t::kRCount; ++r)
                for (int m = 0; m < t::kMuCount; ++m) simulated += t::kSimulated[a][n][r][m];
    EXPECT_EQ(size_t(simulated), ar.ratio.size()) << "stale table: rerun icacam fe tables";
    for (const auto &[k, v] : ar.ratio) {
        const auto [a, n, r, mu] = k;
        const int ia = index(t::kAspect, t::kACount, a), in_ = index(t::kN, t::kNCount, n),
                  ir = index(t::kR, t::kRCount, r), im = index(t::kMu, t::kMuCount, mu);
        ASSERT_TRUE(ia >= 0 && in_ >= 0 && ir >= 0 && im >= 0) << "run not in the table: rerun icacam fe tables";
        EXPECT_TRUE(t::kSimulated[ia][in_][ir][im]);
        EXPECT_NEAR(t::kURatio[ia][in_][ir][im], v, 2e-5) << "stale table: rerun icacam fe tables";
        // The lookup returns the simulated ratio at a simulated point.
        EXPECT_NEAR(friction::AspectCorrectedModel::uRatio(a, n, r, mu), v, 2e-5);
    }
    int rMaxChecked = 0;
    for (const auto &[k, v] : ar.rMaxRatio) {
        const auto [a, n, r, mu] = k;
        const int ia = index(t::kAspect, t::kACount, a), in_ = index(t::kN, t::kNCount, n),
                  ir = index(t::kR, t::kRCount, r), im = index(t::kMu, t::kMuCount, mu);
        if (ia < 0 || in_ < 0 || ir < 0 || im < 0) continue; // a reduction outside the u table's axis
        EXPECT_NEAR(t::kRMaxRatio[ia][in_][ir][im], v, 2e-5) << "stale table: rerun icacam fe tables";
        EXPECT_NEAR(friction::AspectCorrectedModel::rMaxRatio(a, n, r, mu), v, 2e-5);
        ++rMaxChecked;
    }
    EXPECT_GE(size_t(rMaxChecked), ar.ratio.size());
}

TEST(AspectCorrectedModel, IsTheBaseModelAtThePapersSlenderness)
{
    friction::PaperModel paper;
    friction::AspectCorrectedModel model(paper);
    for (double u : {0.2, 0.6, 1.0}) {
        const friction::ModelInputs in{u, 0.25, 500, 10, 15};
        EXPECT_EQ(model.estimate(in).mu, paper.estimate(in).mu);
        const friction::ModelInputs big{2 * u, 0.25, 500, 20, 30};
        EXPECT_EQ(model.estimate(big).mu, paper.estimate(big).mu);
    }
}

TEST(AspectCorrectedModel, CarriesTheSimulatedRunsBackToTheirMu)
{
    // A run at H0/D0 ≠ 1.5 at 50 %: its u, read through the carry and the FE model at 50 %,
    // gives the run's μ back (the ratio comes from the same runs, so this checks the lookup,
    // the fixed point and the composition, not the FE).
    friction::FeModel fe;
    friction::AspectCorrectedModel model(fe);
    const auto ar = host::fe::aspectRatios(tableInputs());
    int checked = 0;
    for (const auto &[k, ratio] : ar.ratio) {
        const auto [a, n, r, mu] = k;
        if (std::fabs(r - 0.5) > 1e-9) continue;
        const double u15 = fe.uAt(n, mu);
        if (!(u15 > 0.1)) continue;
        friction::ModelInputs in{u15 * ratio, n, 500, 10, 10 * a};
        const auto e = model.estimate(in);
        EXPECT_NEAR(e.mu, mu, 0.02 * mu) << "H0/D0 " << a << " n " << n << " mu " << mu;
        EXPECT_FALSE(e.range & friction::kModelAspectOutside);
        // Where the slenderness moves u by more than 10 %, the same u read without the carry
        // gives a clearly different μ (so this test can fail).
        friction::ModelInputs plain = in;
        plain.h0Mm = 15;
        if (std::fabs(ratio - 1) > 0.1) {
            EXPECT_GT(std::fabs(fe.estimate(plain).mu - mu), 0.02 * mu) << "H0/D0 " << a;
        }
        ++checked;
    }
    EXPECT_GE(checked, 1);
}

TEST(AspectCorrectedModel, FlagsSlendernessOutsideTheRuns)
{
    friction::PaperModel paper;
    friction::AspectCorrectedModel model(paper);
    const double lo = friction::AspectCorrectedModel::aspectMin(), hi = friction::AspectCorrectedModel::aspectMax();
    EXPECT_FALSE(model.estimate({0.4, 0.25, 500, 10, 10 * lo}).range & friction::kModelAspectOutside);
    EXPECT_FALSE(model.estimate({0.4, 0.25, 500, 10, 10 * hi}).range & friction::kModelAspectOutside);
    EXPECT_TRUE(model.estimate({0.4, 0.25, 500, 10, 10 * lo - 1}).range & friction::kModelAspectOutside);
    EXPECT_TRUE(model.estimate({0.4, 0.25, 500, 10, 10 * hi + 1}).range & friction::kModelAspectOutside);
    // A squat specimen's narrower ring means more friction than the paper's model says.
    EXPECT_GT(model.estimate({0.3, 0.25, 500, 10, 10}).mu, paper.estimate({0.3, 0.25, 500, 10, 15}).mu);
}

TEST(AspectTable, PairsRunsOfTheSameRegularisationOnly)
{
    // A slender run is divided by the paper-slenderness run with the same contact penalty and
    // stick slope, never by one that differs in the regularisation too.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "icacam_fe_aspect_pairing_test";
    fs::create_directories(dir);
    const char *head = "case,status,k_mpa,n,mu,e_mpa,nu,d0_mm,h0_mm,reduction,elem_mm,corner_mm,element,contact_slope,"
                       "stick_slope,r_i_mm,r_o_mm,r_o_interp_mm,r_max_mm,u_mm,u_interp_mm,force_kn,u_track_mm\n";
    auto row = [](double h0, double stick, double u) {
        std::ostringstream s;
        s << "c,ok,500,0.25,0.2,210000,0.3,10," << h0 << ",0.5,0.5,0.1,CAX8R,100000," << stick << ",5.5," << 5.5 + u
          << "," << 5.5 + u << ",7.3," << u << "," << u << ",80," << u << "\n";
        return s.str();
    };
    std::ofstream(dir / "base.csv") << head << row(15, 100000, 0.82) << row(15, 10000, 0.80);
    std::ofstream(dir / "slender.csv") << head << row(20, 100000, 0.90);
    const auto ar = host::fe::aspectRatios({(dir / "base.csv").string(), (dir / "slender.csv").string()});
    ASSERT_EQ(ar.ratio.size(), 1u);
    EXPECT_NEAR(ar.ratio.begin()->second, 0.90 / 0.82, 1e-9);
    fs::remove_all(dir);
}
