#include "model/mechanics/ring_down_calibration.hpp"

#include <fmt/format.h>
#include <stdexcept>

#include "model/mechanics/mode_report.hpp"

namespace nibrig::model::mechanics {

RingDownCalibration calibrate_ring_down(const DesignModel& bar, const io::AccelerationTrace& trace,
                                        const RingDownCalibrationOptions& options) {
  if (options.name.empty())
    throw std::invalid_argument("ring-down calibration: the material needs a name");
  const Material& reference = body_material(bar);
  RingDownOptions fit_options;
  fit_options.reference_modulus = reference.youngs_modulus;
  fit_options.preload = options.preload;
  fit_options.mass_damping = bar.damping.mass;
  fit_options.fit_gain = !options.calibrated;

  RingDownCalibration out;
  out.fit = fit_ring_down(bar.modal, fit_options, trace);
  out.uncertainty = ring_down_uncertainty(bar.modal, fit_options, trace, out.fit);
  const RingDownFit& f = out.fit;
  const RingDownUncertainty& u = out.uncertainty;

  Material& m = out.material;
  m.name = options.name;
  m.youngs_modulus = f.youngs_modulus;
  m.poisson_ratio = reference.poisson_ratio;
  m.density = reference.density;
  m.damping = RayleighDamping{fit_options.mass_damping, f.rayleigh_stiffness};
  m.basis = "fitted";
  const std::string what = options.provenance.value("recording", std::string("a recording"));
  m.source = fmt::format(
      "E = {:.4g} ± {:.2g} GPa and Rayleigh stiffness {:.4g} ± {:.2g} s (one standard deviation) "
      "fitted to the ring-down {} of a printed bar{}{} (nibrig material calibrate). Density and "
      "Poisson ratio are {}'s ({}): a ring-down determines E/density, so keep this density with "
      "this E.",
      f.youngs_modulus / 1e9, u.youngs_modulus_sd / 1e9, f.rayleigh_stiffness,
      u.rayleigh_stiffness_sd, what,
      options.provenance.contains("printer")
          ? " on " + options.provenance["printer"].get<std::string>()
          : std::string(),
      options.provenance.contains("date") ? ", " + options.provenance["date"].get<std::string>()
                                          : std::string(),
      reference.name, describe_basis(reference));
  validate(m);

  nlohmann::json& c = out.calibration;
  c = options.provenance;
  c["method"] = "ring-down (Piovarci et al. 2018, Sec. 5.1)";
  c["reference_material"] = reference.name;
  c["reference_modulus"] = reference.youngs_modulus;
  c["youngs_modulus"] = f.youngs_modulus;
  c["youngs_modulus_sd"] = u.youngs_modulus_sd;
  c["rayleigh_stiffness"] = f.rayleigh_stiffness;
  c["rayleigh_stiffness_sd"] = u.rayleigh_stiffness_sd;
  c["rayleigh_mass"] = fit_options.mass_damping;
  c["modulus_damping_correlation"] = u.modulus_damping_correlation;
  c["first_mode_hz"] = f.first_mode_hz;
  c["first_mode_damping_ratio"] = f.first_mode_damping_ratio;
  c["release_time_s"] = f.release_time;
  c["gain"] = f.gain;
  c["relative_residual"] = f.relative_residual;
  c["residual_correlation"] = u.residual_correlation;
  c["variance_inflation"] = u.variance_inflation;
  c["sample_rate_hz"] = trace.sample_rate_hz;
  c["samples"] = trace.acceleration_m_s2.size();
  c["preload_mm"] = options.preload * 1e3;
  return out;
}

}  // namespace nibrig::model::mechanics
