#include "model/mechanics/modal_model_builder.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace nibrig::model::mechanics {
namespace {

void check_unit(const Eigen::Vector3d& v, const char* what) {
  if (!v.allFinite() || std::abs(v.norm() - 1.0) > 1e-6) {
    std::ostringstream s;
    s << "modal model: " << what << " (" << v.x() << ", " << v.y() << ", " << v.z()
      << ") is not a unit vector";
    throw std::invalid_argument(s.str());
  }
}

void check_coefficient(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    std::ostringstream s;
    s << "modal model: " << what << " must be finite and non-negative, got " << value;
    throw std::invalid_argument(s.str());
  }
}

}  // namespace

modal::ModalModel build_modal_model(const PointLocator& locator, const ModalResult& modes,
                                    double mass_damping, double stiffness_damping,
                                    const ModalProbe& probe) {
  check_coefficient(mass_damping, "mass damping coefficient alpha (1/s)");
  check_coefficient(stiffness_damping, "stiffness damping coefficient lambda (s)");
  check_unit(probe.tip_direction, "tip direction");
  check_unit(probe.sensor_axis, "sensor axis");
  const TetMesh& mesh = locator.mesh();
  if (modes.shapes.rows() != 3 * mesh.nodes.cols() || modes.shapes.cols() != modes.omega.size()) {
    std::ostringstream s;
    s << "modal model: " << modes.shapes.cols() << " mode shapes of " << modes.shapes.rows()
      << " DOFs for " << modes.omega.size() << " frequencies on a mesh of " << 3 * mesh.nodes.cols()
      << " DOFs";
    throw std::invalid_argument(s.str());
  }

  const PointLocation tip = locator.locate(probe.tip);
  const PointLocation sensor = locator.locate(probe.sensor);
  const Eigen::VectorXd b = evaluate_along(mesh, tip, modes.shapes, probe.tip_direction);
  const Eigen::VectorXd c = evaluate_along(mesh, sensor, modes.shapes, probe.sensor_axis);

  modal::ModalModel model;
  for (Eigen::Index i = 0; i < modes.omega.size(); ++i) {
    model.omega.push_back(modes.omega(i));
    model.zeta.push_back(
        modal::rayleigh_damping_ratio(modes.omega(i), mass_damping, stiffness_damping));
    model.input.push_back(b(i));
    model.output.push_back(c(i));
  }
  return model;
}

}  // namespace nibrig::model::mechanics
