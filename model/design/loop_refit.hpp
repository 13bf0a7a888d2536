// A design loop's measured print taken into the forcing model: it is an exemplar of its mix and tip
// (forcing_fit.hpp: ln m the fractions' sum, ln t interpolated), fitted beside the catalog's
// printed tools, each print weighing as the one measurement it is, as each catalog exemplar does.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::design {

// The print of `point` measured on `surface` as an exemplar: `measured` put on the model's grid
// (io::spectrum_at_frequencies) and `response` the design's |H| there. Throws
// std::invalid_argument when the measured speeds are not the model's or its frequencies do not
// cover the model's, naming `name`.
forcing::ForcingExemplar print_exemplar(const std::string& name, const DesignPoint& point,
                                        const std::string& surface,
                                        const io::VelocitySpectrum& measured,
                                        std::vector<double> response,
                                        const forcing::ForcingModel& model);

// Eq. 10 fitted again to the catalog's exemplars and the prints, with `base`'s knots and
// references. What the catalog alone cannot give back is kept from `base`: the held-out
// descriptor errors (the prior of what a prediction misses), calibrated curves and surfaces the
// exemplars do not hold, and their standard errors. Throws what fit_forcing_model throws.
forcing::ForcingModel refit_with_prints(std::span<const forcing::ForcingExemplar> catalog,
                                        std::span<const forcing::ForcingExemplar> prints,
                                        const forcing::ForcingModel& base);

}  // namespace nibrig::model::design
