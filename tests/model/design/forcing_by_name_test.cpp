// A forcing model a lab calibrated and stored by name is what `--forcing NAME` predicts with,
// wherever prediction inputs are loaded; a name that is neither a file nor stored is refused.
#include <gtest/gtest.h>

#include <cstdlib>

#include "model/design/prediction_inputs.hpp"
#include "model/forcing/forcing_store.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

TEST(ForcingByName, PredictionInputsLoadAStoredModelByName) {
  const auto dir = nibrig::test::scratch_dir("forcing_by_name") / "forcing";
  ::setenv("NIBRIG_FORCING_MODELS", dir.c_str(), 1);
  forcing::ForcingModel model =
      forcing::fit_forcing_model(forcing::test::make_synthetic_truth(9).exemplars);
  model.notes = {"the lab's own"};
  forcing::save_forcing_model("lab-resin", model);
  const auto inputs = load_prediction_inputs({}, "lab-resin");
  EXPECT_EQ(inputs->model.notes, model.notes);
  EXPECT_EQ(inputs->model.material_log_gain, model.material_log_gain);
  EXPECT_THROW(load_prediction_inputs({}, "lab-pla"), std::invalid_argument);
  ::unsetenv("NIBRIG_FORCING_MODELS");
}

}  // namespace
}  // namespace nibrig::model::design
