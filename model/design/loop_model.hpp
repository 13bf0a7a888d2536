// The model as a design loop's prints have taught it: after each measured print the forcing model
// is fitted again with it (loop_refit.hpp), and what the refitted model still misses at every
// print is carried to the designs near it (print_discrepancy.hpp). Proposes the next print and
// says when to stop (design_loop.hpp). The same for every face and for the loop's simulated world.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "model/design/design_loop.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/loop_refit.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {

struct LoopSetup {
  const PredictionInputs* inputs = nullptr;  // the model the loop starts from, its catalog
  // The catalog's exemplars with their responses (forcing::load_forcing_inputs), refitted with
  // the prints.
  std::span<const forcing::ForcingExemplar> catalog_exemplars;
  const DesignResponseGrid* grid = nullptr;  // the range's FEM, interpolated per candidate
  const space::DescriptorMap* map = nullptr;
  space::Placement target;
  std::string surface;
  RangeSearchOptions range;  // its materials are the grid's
  // Not empty: the loop chooses among these designs only (each inside the range), as a lab that
  // prints only some, or whose prints exist already (the paper's recordings).
  std::vector<DesignPoint> candidates;
  NextPrintRule rule = kDefaultNextPrintRule;
  double threshold = 1.0;
  Eigen::MatrixXd measurement_noise;  // a measurement's descriptor noise, the map's order
  int max_rounds = 6;
  // false: only the refit learns from the prints (the world's comparison of what each part does).
  bool correct_by_prints = true;
  int samples = 2000;
};

struct LoopPrint {
  DesignPoint point;
  io::Pairing measured;
  MeasuredPlacement placement;
};

class LoopModel {
 public:
  // Throws std::invalid_argument for a setup without inputs, grid or map, a threshold that is not
  // positive, a round limit below 1, a noise of the wrong size, or a range the grid does not span.
  explicit LoopModel(LoopSetup setup);
  LoopModel(const LoopModel&) = delete;
  LoopModel& operator=(const LoopModel&) = delete;

  // Takes a measured print in: places it, refits, recomputes every print's residual. Throws what
  // print_exemplar and the refit throw, naming the print.
  void add_print(const DesignPoint& point, const io::Pairing& measured);

  Proposal propose() const;
  // The prediction of the model alone (the refit, without the prints' correction).
  PredictedTool predict_uncorrected(const DesignPoint& point) const;
  LoopStop stop(const Proposal* next) const;

  const std::vector<LoopPrint>& prints() const { return prints_; }
  std::vector<double> measured_distances() const;
  const forcing::ForcingModel& model() const { return *model_; }
  const LoopSetup& setup() const { return setup_; }
  LoopContext context() const;

 private:
  void rebuild();

  LoopSetup setup_;
  std::vector<LoopPrint> prints_;
  std::vector<forcing::ForcingExemplar> print_exemplars_;
  std::unique_ptr<forcing::ForcingModel> model_;
  PredictionSetup prediction_;  // the inputs' setup on model_
  std::unique_ptr<PrintDiscrepancy> discrepancy_;
  DiscrepancyPrior prior_;
};

}  // namespace nibrig::model::design
