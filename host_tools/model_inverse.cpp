#include "host_tools/model_inverse.h"

namespace icacam::host {

double uForMu(const friction::FrictionModel &model, double mu, double n, double d0Mm)
{
    friction::ModelInputs in;
    in.n = n;
    in.d0Mm = d0Mm;
    double lo = 0, hi = 1.25 * d0Mm / 10.0;
    for (int i = 0; i < 100; ++i) {
        in.uMm = 0.5 * (lo + hi);
        if (model.estimate(in).mu < mu)
            lo = in.uMm;
        else
            hi = in.uMm;
    }
    return 0.5 * (lo + hi);
}

} // namespace icacam::host
