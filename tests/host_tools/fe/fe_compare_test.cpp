// `icacam fe compare` (host_tools/fe/fe_compare.h): rows matched by physics across meshes,
// Δu judged against the bar, and the two radii's own shifts reported beside Δu.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "host_tools/fe/fe_compare.h"

using namespace icacam::host::fe;
namespace fs = std::filesystem;

namespace {
const char *kHead = "case,status,k_mpa,n,mu,e_mpa,nu,d0_mm,h0_mm,reduction,elem_mm,corner_mm,element,r_i_mm,"
                    "r_o_mm,r_o_interp_mm,r_max_mm,u_mm,u_interp_mm,force_kn,u_track_mm\n";
std::string row(double corner, double mu, double reduction, double ri, double u)
{
    std::ostringstream s;
    s << "c,ok,500,0.05," << mu << ",210000,0.3,10,15," << reduction << ",0.5," << corner << ",CAX8R," << ri << ","
      << ri + u << "," << ri + u << ",7.2," << u << "," << u << ",78," << u << "\n";
    return s.str();
}
std::string slurp(const fs::path &p)
{
    std::ifstream f(p);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}
} // namespace

TEST(FeCompare, JudgesDeltaUAndReportsWhichRadiusMoved)
{
    const fs::path dir = fs::temp_directory_path() / "icacam_fe_compare_test";
    fs::create_directories(dir);
    // The reference's u(μ) at 50 % is a straight line (u = 0.15 + 3.8 (μ − 0.05)), so the μ read
    // at another u is known by hand.
    std::ofstream(dir / "ref.csv") << kHead << row(0.1, 0.05, 0.5, 6.54, 0.150) << row(0.1, 0.3, 0.5, 5.10, 1.100)
                                   << row(0.1, 0.2, 0.5, 5.6, 0.72) << row(0.1, 0.3, 0.45, 5.0, 0.05);
    // Low μ: the end face slid 20 µm further, the edge stayed: u −13 %. High μ: +0.5 %.
    std::ofstream(dir / "other.csv") << kHead << row(0.05, 0.05, 0.5, 6.56, 0.130) << row(0.05, 0.3, 0.5, 5.10, 1.1055)
                                     << row(0.05, 0.3, 0.45, 5.0, 0.09) << row(0.05, 0.25, 0.5, 5.5, 0.8)
                                     << row(0.05, 0.2, 0.5, 5.6, 0.76);
    ASSERT_EQ(compareCommand({(dir / "ref.csv").string(), (dir / "other.csv").string()}, (dir / "out.md").string(), 0.1,
                             0.01, true),
              0);
    const std::string md = slurp(dir / "out.md");
    // Beyond the reference's u range the μ is extrapolated along the line and bracketed:
    // 0.05 − 0.02/3.8 = 0.04474 (−10.5 %); 0.3 + 0.0055/3.8 (+0.5 %).
    EXPECT_NE(md.find("| 0.1300 | -13.3 | +20.0 | +0.0 | (-10.5) | **no** |"), std::string::npos) << md;
    EXPECT_NE(md.find("| 1.1055 | +0.5 | +0.0 | +5.5 | (+0.5) | yes |"), std::string::npos) << md;
    // Inside: 0.2 + 0.04/3.8 = 0.21053, +5.3 % in μ for +5.6 % in u.
    EXPECT_NE(md.find("| 0.7600 | +5.6 | +0.0 | +40.0 | +5.3 | **no** |"), std::string::npos) << md;
    EXPECT_NE(md.find("(u ≤ bar's floor)"), std::string::npos) << md; // 0.05 mm: not judged
    EXPECT_NE(md.find("1 of 3 comparisons with u > 0.1 mm within 1 %; largest |Δu| 13.3 %"), std::string::npos) << md;
    EXPECT_NE(
        md.find("In μ (the judged comparisons inside the reference's u range): 0 of 1 within 1 %; largest |Δμ| 5.3 %"),
        std::string::npos)
        << md;
    EXPECT_EQ(md.find("| 0.25 |"), std::string::npos) << "a row without a reference is not compared";
    fs::remove_all(dir);
}
