#include "host_tools/outline_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <stdexcept>

#include "friction/radii_consistency.h"
#include "host_tools/cli_options.h"
#include "host_tools/photo/barrel_profile.h"

namespace icacam::host {

namespace {

const char *kUsage = "usage: icacam fe outline-table [--profiles CSV] [--out HEADER]\n"
                     "  --profiles CSV  the FE's barrel profiles (default data/photobench/fe_profiles.csv)\n"
                     "  --out HEADER    the generated table (default friction/outline_table.h)\n"
                     "The outline a pinhole camera at working distance W sees of the upset specimen (the\n"
                     "farthest projection of the barrel's free surface), as a ratio to R_max, over n, mu,\n"
                     "the reduction and D0/W (docs/uncertainty.md).\n";

constexpr double kD0Mm = 10, kH0Mm = 15;
// D0/W from a telecentric view (0) to a camera 40 mm from the end face (0.25).
constexpr int kXCount = 11;
constexpr double kXStep = 0.025;

// The outline over R_max: the farthest projection, at the end face's scale, of the barrel's
// upper half (the lower half lies farther and is narrower at each radius it reaches). A
// point at radius r, z below the end face, projects at r·W/(W + z).
double outlineRatio(const photo::BarrelShape &shape, double rOuter, double rMax, double h, double x)
{
    double best = 0;
    for (size_t k = 0; k < shape.s.size(); ++k) {
        const double r = rOuter + shape.s[k] * (rMax - rOuter);
        const double z = h / 2 * (1 - shape.zeta[k]);
        best = std::max(best, r / (1 + x * z / kD0Mm));
    }
    return best / rMax;
}

// An end face X off the optical axis: the side z below it lies at X·W/(W + z) from the axis,
// nearer than the face's centre, so the outline's centre is drawn towards the axis. In
// direction φ (from the axis outwards at 0) the outline reaches max over z of
// r(z)·k(z) − X·(1 − k(z))·cos φ, k = W/(W + z) (the farthest of the circles each height
// projects to); its first harmonic is the shift. Per unit X, at X 3 mm (the shift is within
// about 2 % of that over 0.5–10 mm: the band the outline comes from moves little with X).
constexpr double kShiftAtMm = 3.0;
constexpr int kShiftAngles = 180;
double outlineShift(const photo::BarrelShape &shape, double rOuter, double rMax, double h, double x)
{
    if (!(x > 0)) return 0;
    double first = 0;
    for (int a = 0; a < kShiftAngles; ++a) {
        const double c = std::cos(2 * std::numbers::pi * (a + 0.5) / kShiftAngles);
        double best = -1e9;
        for (size_t k = 0; k < shape.s.size(); ++k) {
            const double r = rOuter + shape.s[k] * (rMax - rOuter);
            const double z = h / 2 * (1 - shape.zeta[k]);
            const double kz = 1 / (1 + x * z / kD0Mm);
            best = std::max(best, r * kz - kShiftAtMm * (1 - kz) * c);
        }
        first += best * c;
    }
    return -first * 2 / kShiftAngles / kShiftAtMm;
}

} // namespace

std::string outlineTableText(const std::string &profilesPath, const std::string &sourceDir, std::string *summary)
{
    const std::vector<photo::BarrelProfile> table = photo::readBarrelProfiles(sourceDir + profilesPath);
    const auto &ns = photo::profileGridN(), &mus = photo::profileGridMu(), &rs = photo::profileReductions();
    auto solved = [&](double n, double mu, double r) {
        return std::any_of(table.begin(), table.end(), [&](const photo::BarrelProfile &p) {
            return std::fabs(p.n - n) < 1e-6 && std::fabs(p.mu - mu) < 1e-6 && std::fabs(p.reduction - r) < 1e-6;
        });
    };
    std::string body, shiftBody;
    char b[160];
    // The ratio as the bench renders the side: the profile's shape scaled onto the FE base's
    // R_o and R_max; and as this coarse mesh alone gives it (its own radii). Their difference
    // at a close camera is the table's own error.
    double sumSq = 0, worst = 0;
    int compared = 0, copied = 0;
    for (double r : rs) {
        body += "    {\n";
        shiftBody += "    {\n";
        for (double n : ns) {
            body += "        {\n";
            shiftBody += "        {\n";
            for (double mu : mus) {
                // A snapshot the run did not reach takes the nearest reduction's shape.
                double rShape = r;
                if (!solved(n, mu, r)) {
                    ++copied;
                    for (double alt : rs)
                        if (solved(n, mu, alt) &&
                            (!solved(n, mu, rShape) || std::fabs(alt - r) < std::fabs(rShape - r)))
                            rShape = alt;
                }
                const photo::BarrelShape shape = photo::barrelShapeAt(table, n, mu, rShape);
                double ro, rm;
                const bool base = friction::feRadiusAt(friction::FeRadius::Outer, n, mu, r, &ro) &&
                                  friction::feRMaxAt(n, mu, r, &rm) && rm > ro;
                const auto own = std::find_if(table.begin(), table.end(), [&](const photo::BarrelProfile &p) {
                    return std::fabs(p.n - n) < 1e-6 && std::fabs(p.mu - mu) < 1e-6 &&
                           std::fabs(p.reduction - r) < 1e-6;
                });
                double ownRo = 0, ownRm = 0;
                if (own != table.end()) {
                    ownRo = own->rMm.back();
                    ownRm = *std::max_element(own->rMm.begin(), own->rMm.end());
                }
                const double useRo = base ? ro : ownRo, useRm = base ? rm : ownRm;
                if (!(useRm > useRo && useRo > 0)) throw std::runtime_error("outline table: no radii at a grid point");
                const double h = kH0Mm * (1 - r);
                body += "            {";
                shiftBody += "            {";
                for (int i = 0; i < kXCount; ++i) {
                    const double x = i * kXStep;
                    std::snprintf(b, sizeof b, "%s%.5f", i ? ", " : "", outlineRatio(shape, useRo, useRm, h, x));
                    body += b;
                    std::snprintf(b, sizeof b, "%s%.5f", i ? ", " : "", outlineShift(shape, useRo, useRm, h, x));
                    shiftBody += b;
                }
                body += "},\n";
                shiftBody += "},\n";
                if (base && own != table.end()) {
                    const double x = kD0Mm / 60; // a camera 60 mm away
                    const double d =
                        std::log(outlineRatio(shape, ro, rm, h, x) / outlineRatio(shape, ownRo, ownRm, h, x));
                    sumSq += d * d, worst = std::max(worst, std::fabs(d)), ++compared;
                }
            }
            body += "        },\n";
            shiftBody += "        },\n";
        }
        body += "    },\n";
        shiftBody += "    },\n";
    }
    const double rms = compared ? std::sqrt(sumSq / compared) : 0;
    std::string o;
    o += "#pragma once\n// GENERATED by `icacam fe outline-table --profiles " + profilesPath + "` — do not edit.\n";
    o += "// The outline a pinhole camera sees of the upset specimen over its R_max (friction/outline_ratio.h):\n"
         "// the farthest projection, at the end face's scale, of the barrel's free surface, max over z of\n"
         "// r(z)·W/(W + z) (z below the end face, W the working distance to it). The side's shape from the\n"
         "// FE's deformed lateral nodes (" +
         profilesPath +
         ", host_tools/photo/barrel_profile.h), scaled onto\n"
         "// the FE base's R_o and R_max (friction/fe_model_table.h) as the photographic bench renders it.\n";
    std::snprintf(b, sizeof b,
                  "// Shape scaled onto the base's radii against the coarse mesh's own radii, W 60 mm: RMS %.4f, "
                  "largest %.4f (ln);\n",
                  rms, worst);
    o += b;
    std::snprintf(b, sizeof b, "// %d grid points without their snapshot take the nearest reduction's shape.\n",
                  copied);
    o += b;
    o += "namespace icacam::friction::outline_table {\n";
    o += "inline constexpr const char *kProvenance = \"icacam fe outline-table --profiles " + profilesPath + "\";\n";
    o += "inline constexpr double kD0Mm = 10, kH0Mm = 15;\n";
    std::snprintf(b, sizeof b, "inline constexpr int kRCount = %zu, kNCount = %zu, kMuCount = %zu, kXCount = %d;\n",
                  rs.size(), ns.size(), mus.size(), kXCount);
    o += b;
    auto list = [&](const char *name, const char *count, const std::vector<double> &v) {
        o += std::string("inline constexpr double ") + name + "[" + count + "] = {";
        for (size_t i = 0; i < v.size(); ++i) {
            std::snprintf(b, sizeof b, "%s%g", i ? ", " : "", v[i]);
            o += b;
        }
        o += "};\n";
    };
    list("kR", "kRCount", rs);
    list("kN", "kNCount", ns);
    list("kMu", "kMuCount", mus);
    std::vector<double> xs;
    for (int i = 0; i < kXCount; ++i) xs.push_back(i * kXStep);
    o += "// D0/W: 0 a telecentric view, 0.25 a camera 40 mm from the end face.\n";
    list("kX", "kXCount", xs);
    std::snprintf(b, sizeof b,
                  "// The table's own relative error (the shape's radii: the comparison above).\n"
                  "inline constexpr double kRelSigma = %.4f;\n",
                  std::max(rms, 0.001));
    o += b;
    o += "// [reduction][n][μ][D0/W]: outline / R_max\n";
    o += "inline constexpr double kRatio[kRCount][kNCount][kMuCount][kXCount] = {\n" + body + "};\n";
    o += "// [reduction][n][μ][D0/W]: how far the outline's centre is drawn towards the optical axis,\n"
         "// per unit of the end face's own distance from it (first harmonic, at 3 mm off the axis)\n";
    o += "inline constexpr double kShift[kRCount][kNCount][kMuCount][kXCount] = {\n" + shiftBody + "};\n";
    o += "} // namespace icacam::friction::outline_table\n";
    std::snprintf(b, sizeof b, "outline/R_max over %zu x %zu x %zu x %d, the shape's error %.4f (RMS)", rs.size(),
                  ns.size(), mus.size(), kXCount, rms);
    *summary = b;
    return o;
}

int outlineTableCommand(const std::vector<std::string> &args)
{
    std::string profiles = "data/photobench/fe_profiles.csv", out = "friction/outline_table.h";
    cli::OptionReader r(args, kUsage);
    while (r.next()) {
        if (r.isHelp()) {
            std::cout << kUsage;
            return 0;
        }
        if (r.is("--profiles"))
            profiles = r.value();
        else if (r.is("--out"))
            out = r.value();
        else
            r.unknown();
    }
    std::string summary;
    const std::string text = outlineTableText(profiles, "", &summary);
    std::ofstream f(out, std::ios::binary);
    if (!(f << text)) throw std::runtime_error("cannot write " + out);
    std::cout << "outline table: " << summary << " -> " << out << "\n";
    return 0;
}

} // namespace icacam::host
