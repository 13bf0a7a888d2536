// A lab's calibrated forcing models kept by name: saved into the store, found by name or as a file,
// never written over unless asked, and an unknown name refused with what is stored.
#include "model/forcing/forcing_store.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "model/forcing/forcing_file.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::forcing {
namespace {

// NIBRIG_FORCING_MODELS pointed at a scratch folder for one test, and unset after it.
class ForcingStore : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = nibrig::test::scratch_dir("forcing_store") / "forcing";
    ::setenv("NIBRIG_FORCING_MODELS", dir_.c_str(), 1);
  }
  void TearDown() override { ::unsetenv("NIBRIG_FORCING_MODELS"); }
  std::filesystem::path dir_;
};

ForcingModel stored_test_model(const std::string& note) {
  ForcingModel model = fit_forcing_model(test::make_synthetic_truth(5).exemplars);
  model.notes = {note};
  return model;
}

TEST_F(ForcingStore, ASavedModelIsFoundByNameAndNotWrittenOver) {
  EXPECT_EQ(forcing_store_folder(), dir_);
  const auto file = save_forcing_model("lab PLA", stored_test_model("first"));
  EXPECT_EQ(file, dir_ / "lab_PLA.json");  // the name made safe for a file name
  EXPECT_EQ(find_forcing_model("lab PLA"), file);
  EXPECT_EQ(read_forcing_model(find_forcing_model("lab PLA")).notes,
            std::vector<std::string>{"first"});
  // A file is a file, whatever the store holds.
  const auto other = nibrig::test::scratch_dir("forcing_store_file") / "mine.json";
  write_forcing_model(other, stored_test_model("file"));
  EXPECT_EQ(find_forcing_model(other.string()), other);

  try {
    save_forcing_model("lab PLA", stored_test_model("second"));
    ADD_FAILURE() << "a stored model was written over";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stored already"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_forcing_model(file).notes, std::vector<std::string>{"first"});
  save_forcing_model("lab PLA", stored_test_model("second"), true);
  EXPECT_EQ(read_forcing_model(file).notes, std::vector<std::string>{"second"});
}

TEST_F(ForcingStore, AnUnknownNameIsRefusedWithWhatIsStored) {
  save_forcing_model("resin", stored_test_model("r"));
  try {
    find_forcing_model("pla");
    ADD_FAILURE() << "an unknown name was found";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no forcing model file 'pla'"), std::string::npos) << what;
    EXPECT_NE(what.find(dir_.string()), std::string::npos) << what;
    EXPECT_NE(what.find("stored: resin"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace nibrig::model::forcing
