// Turns a modal analysis into the ModalModel the integrator runs: frequencies, Rayleigh damping
// ratios, and each mode's coupling to the tip force (input) and to the sensor's acceleration
// (output), read from the mode shapes at those two points.
#pragma once

#include <Eigen/Core>

#include "model/mechanics/modal_analysis.hpp"
#include "model/mechanics/point_probe.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::mechanics {

struct ModalProbe {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();             // where the surface force acts, m
  Eigen::Vector3d tip_direction = Eigen::Vector3d::UnitZ();  // unit direction of that force
  Eigen::Vector3d sensor = Eigen::Vector3d::Zero();          // where acceleration is read, m
  Eigen::Vector3d sensor_axis = Eigen::Vector3d::UnitZ();    // unit sensing axis
};

// Rayleigh damping D = αM + λK: mass_damping α in 1/s, stiffness_damping λ in s (the paper fits
// λ = 1.25e-3 s and uses α = 0). Throws std::invalid_argument when α or λ is negative or not
// finite, when a direction is not a unit vector (to 1e-6: a non-unit direction would silently scale
// b_i or c_i), when the shapes do not match the mesh, or when tip or sensor is outside the body
// (see PointLocator::locate).
modal::ModalModel build_modal_model(const PointLocator& locator, const ModalResult& modes,
                                    double mass_damping, double stiffness_damping,
                                    const ModalProbe& probe);

}  // namespace nibrig::model::mechanics
