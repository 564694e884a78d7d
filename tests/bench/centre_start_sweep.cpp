// centre_start_sweep --manifest M.csv [--model NAME] [--offsets 1,3] [--verbose]: how far a measurement
// depends on where the centre search starts. Every record is measured from the locator's
// coarse centre and from starts moved by each offset (pixels) in eight directions; per record
// the spread (largest minus smallest) of the centre, both radii, the silhouette and μ over
// the starts, then the largest spreads and on how many records μ moved.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "friction/friction_models.h"
#include "host_tools/manifest.h"
#include "host_tools/record_measurer.h"
#include "vision/end_face_analyzer.h"
#include "vision/specimen_locator.h"

namespace {

struct Spread {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v)
    {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    double width() const { return hi >= lo ? hi - lo : 0; }
};

std::vector<double> parseOffsets(const std::string &text)
{
    std::vector<double> out;
    std::stringstream s(text);
    std::string item;
    while (std::getline(s, item, ',')) out.push_back(std::stod(item));
    return out;
}

} // namespace

int main(int argc, char **argv)
{
    using namespace icacam;
    std::string manifestPath, modelName = "paper";
    std::vector<double> offsets{1, 3};
    bool verbose = false;
    for (int i = 1; i < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--verbose") {
            verbose = true;
            --i;
        } else if (i + 1 >= argc)
            break;
        else if (a == "--manifest")
            manifestPath = argv[i + 1];
        else if (a == "--model")
            modelName = argv[i + 1];
        else if (a == "--offsets")
            offsets = parseOffsets(argv[i + 1]);
    }
    const friction::FrictionModel *model = friction::frictionModel(modelName);
    if (manifestPath.empty() || !model) {
        std::fprintf(stderr, "usage: centre_start_sweep --manifest M.csv [--model NAME] [--offsets 1,3] [--verbose]\n");
        return 2;
    }
    host::Manifest manifest;
    std::string err;
    if (!host::readManifest(manifestPath, &manifest, &err)) {
        std::fprintf(stderr, "centre_start_sweep: %s\n", err.c_str());
        return 1;
    }
    host::RecordMeasurer measurer(*model, reading::SpecimenSpec{});
    vision::EndFaceAnalyzer analyzer;
    std::unique_ptr<uint8_t[]> locatorWork(new uint8_t[vision::SpecimenLocator::kWorkBytes]);
    std::printf("%-16s %6s %8s %8s %8s %8s %9s\n", "id", "starts", "centre", "R_i", "R_o", "R_max", "mu");
    Spread worstCentre, worstRi, worstRo, worstMax, worstMu;
    int records = 0, muMoved = 0, muMovedVisibly = 0, lost = 0;
    host::RecordReading rec;
    for (const host::ManifestRow &row : manifest.rows) {
        measurer.measure(row, manifest, &rec);
        if (!rec.measured) continue;
        const cv::Mat &luma = rec.image.luma;
        const vision::LumaView view{luma.data, luma.cols, luma.rows, int(luma.step[0]), 1};
        const vision::FaceSearch search{rec.spec.d0Mm, rec.spec.mmPerPx};
        analyzer.configure(luma.cols, luma.rows);
        vision::SpecimenLocator locator(locatorWork.get());
        const double r0 = 0.5 * search.d0Mm / search.mmPerPx;
        const vision::CentreEstimate coarse = locator.locate(view, 0.8 * r0, 1.8 * r0);
        if (!coarse.found) continue;
        Spread cx, cy, ri, ro, rmax, mu;
        int starts = 0, found = 0;
        auto measureAt = [&](double x, double y) {
            ++starts;
            const vision::EndFaceGeometry g = analyzer.measureFrom(view, search, x, y);
            if (verbose)
                std::printf("  start %.2f %.2f: %s centre %.3f %.3f R_i %.3f R_o %.3f R_max %.3f\n", x, y,
                            g.found() ? "found" : "error", g.centreX, g.centreY, g.inner.rEqPx, g.outer.rEqPx,
                            g.rMaxPx);
            if (!g.found()) return;
            ++found;
            cx.add(g.centreX);
            cy.add(g.centreY);
            ri.add(g.inner.rEqPx);
            ro.add(g.outer.rEqPx);
            rmax.add(g.rMaxPx);
            const reading::Reading r = measurer.instrument().interpret(g, rec.spec);
            if (r.hasValue()) mu.add(r.mu);
        };
        measureAt(coarse.x, coarse.y);
        for (double d : offsets)
            for (int k = 0; k < 8; ++k) {
                const double a = k * M_PI / 4;
                measureAt(coarse.x + d * std::cos(a), coarse.y + d * std::sin(a));
            }
        ++records;
        if (found < starts) ++lost;
        if (mu.width() > 0) ++muMoved;
        if (mu.width() >= 1e-4) ++muMovedVisibly;
        const double centre = std::hypot(cx.width(), cy.width());
        std::printf("%-16s %3d/%-3d %8.3f %8.3f %8.3f %8.3f %9.5f\n", row.get("id").c_str(), found, starts, centre,
                    ri.width(), ro.width(), rmax.width(), mu.width());
        worstCentre.add(centre);
        worstRi.add(ri.width());
        worstRo.add(ro.width());
        worstMax.add(rmax.width());
        worstMu.add(mu.width());
    }
    std::printf("%d records; largest spread: centre %.3f px, R_i %.3f px, R_o %.3f px, R_max %.3f px, mu %.5f; "
                "mu moved on %d (by 0.0001 or more on %d), a start lost the reading on %d\n",
                records, worstCentre.hi, worstRi.hi, worstRo.hi, worstMax.hi, worstMu.hi, muMoved, muMovedVisibly,
                lost);
    return 0;
}
