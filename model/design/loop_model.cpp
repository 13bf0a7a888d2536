#include "model/design/loop_model.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace nibrig::model::design {

LoopModel::LoopModel(LoopSetup setup) : setup_(std::move(setup)) {
  if (setup_.inputs == nullptr || setup_.grid == nullptr || setup_.map == nullptr)
    throw std::invalid_argument("a design loop needs its prediction inputs, design grid and space");
  if (!(setup_.threshold > 0) || !std::isfinite(setup_.threshold))
    throw std::invalid_argument(fmt::format(
        "a design loop's threshold must be a positive distance, not {}", setup_.threshold));
  if (setup_.max_rounds < 1) throw std::invalid_argument("a design loop needs at least one round");
  const auto& names = setup_.map->descriptor_names;
  const auto n = static_cast<Eigen::Index>(names.size());
  if (setup_.measurement_noise.rows() != n || setup_.measurement_noise.cols() != n)
    throw std::invalid_argument(
        "the measurement's descriptor noise must be one row and column per descriptor of the "
        "space's map");
  const auto& axes = setup_.grid->axes;
  if (axes.material_a != setup_.range.first_material ||
      axes.material_b != setup_.range.second_material)
    throw std::invalid_argument("the design grid mixes " + axes.material_a + " and " +
                                axes.material_b + ", the loop's range " +
                                setup_.range.first_material + " and " +
                                setup_.range.second_material);
  prior_.names = names;
  const auto& errors = setup_.inputs->descriptor_errors;
  prior_.model_error = errors ? errors->block(names) : Eigen::MatrixXd::Zero(n, n);
  prior_.measurement_noise = setup_.measurement_noise;
  prior_.second_material = setup_.range.second_material;
  rebuild();
}

LoopContext LoopModel::context() const {
  LoopContext c;
  c.map = setup_.map;
  c.target = setup_.target;
  c.threshold = setup_.threshold;
  c.measurement_noise = setup_.measurement_noise;
  c.samples = setup_.samples;
  return c;
}

PredictedTool LoopModel::predict_uncorrected(const DesignPoint& point) const {
  return predict_from_response(
      prediction_, point, setup_.surface,
      interpolate_response(*setup_.grid, point.fraction_of(setup_.grid->axes.material_b),
                           point.tip_diameter_m));
}

void LoopModel::rebuild() {
  model_ = std::make_unique<forcing::ForcingModel>(
      print_exemplars_.empty()
          ? setup_.inputs->model
          : refit_with_prints(setup_.catalog_exemplars, print_exemplars_, setup_.inputs->model));
  prediction_ = setup_.inputs->setup;
  prediction_.model = model_.get();
  std::vector<PrintResidual> residuals;
  if (setup_.correct_by_prints)
    for (const auto& print : prints_)
      residuals.push_back(
          {print.point, print.placement.descriptors -
                            predicted_descriptors(*setup_.map, predict_uncorrected(print.point))});
  discrepancy_ = std::make_unique<PrintDiscrepancy>(prior_, std::move(residuals));
}

void LoopModel::add_print(const DesignPoint& point, const io::Pairing& measured) {
  if (!measured.vibration)
    throw std::invalid_argument("the print " + to_string(point) +
                                " was measured without a vibration spectrum");
  const std::string name = fmt::format("loop print {} ({})", prints_.size() + 1, to_string(point));
  LoopPrint print{point, measured, place_measured(context(), measured)};
  const SimulatedResponse response = interpolate_response(
      *setup_.grid, point.fraction_of(setup_.grid->axes.material_b), point.tip_diameter_m);
  print_exemplars_.push_back(print_exemplar(name, point, setup_.surface,
                                            measured.vibration->spectrum,
                                            response.response_magnitude, setup_.inputs->model));
  prints_.push_back(std::move(print));
  rebuild();
}

Proposal LoopModel::propose() const {
  const Predict predict = [this](const DesignPoint& p) { return predict_uncorrected(p); };
  std::vector<DesignPoint> printed;
  for (const auto& p : prints_) printed.push_back(p.point);
  return propose_next_print(context(), *discrepancy_, predict, setup_.range, setup_.rule,
                            setup_.candidates, printed);
}

std::vector<double> LoopModel::measured_distances() const {
  std::vector<double> out;
  for (const auto& p : prints_) out.push_back(p.placement.distance);
  return out;
}

LoopStop LoopModel::stop(const Proposal* next) const {
  return loop_stop(measured_distances(), setup_.threshold, setup_.max_rounds, next);
}

}  // namespace nibrig::model::design
