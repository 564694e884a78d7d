#pragma once
// A friction model read backwards: the ICA width u that gives a μ at n. The rendered and
// synthetic record sets draw a specimen's μ and place its ring where the model puts it.
#include "friction/friction_model.h"

namespace icacam::host {

// u (mm) at which the model gives mu at n, for a specimen of diameter d0Mm at the model's own
// reduction: bisection on [0, 1.25] mm scaled with D0, where the models rise with u over the
// μ the synthetic sets draw; 100 halvings reach the double's last bit where u > 0.01 mm.
double uForMu(const friction::FrictionModel &model, double mu, double n, double d0Mm = 10);

} // namespace icacam::host
