// Locating the stimuli of judged queries in a fitted space and predicting the answers: judged
// stimuli exactly, with P = Φ(−s·d) computed here by hand; a stimulus the space does not know and
// cannot place is refused naming the query file.
#include "model/space/space_inputs.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::space {
namespace {

SpaceFile three_tools() {
  SpaceFile s;
  s.stimuli = {"pencil/office", "charcoal/office", "pen/office"};
  s.coordinates.resize(2, 3);
  s.coordinates << 0.0, 1.0, 3.0,  //
      0.0, 0.5, -1.0;
  s.model.scale = 2.0 / 3.0;
  return s;
}

TEST(SpaceInputs, JudgedStimuliAreLocatedExactlyAndTheirAnswerHasNoSpread) {
  const SpaceFile s = three_tools();
  StimulusLocator locator(s, "space.json", "");
  io::TripletSet queries;
  queries.stimuli = {"pen/office", "pencil/office", "charcoal/office"};
  queries.triplets = {{0, 1, 2, 0, 0, ""}, {0, 2, 1, 0, 0, ""}};  // reference pen, then swapped
  const auto p = predict_queries(s, queries, locator, "queries.csv");
  ASSERT_EQ(p.size(), 2u);
  // d = |pencil − pen| − |charcoal − pen|, P(pencil closer) = Φ(−s·d) = erfc(s·d/√2)/2.
  const double d = std::hypot(3.0, 1.0) - std::hypot(2.0, 1.5);
  EXPECT_NEAR(p[0].p, 0.5 * std::erfc(s.model.scale * d / std::sqrt(2.0)), 1e-12);
  EXPECT_NEAR(p[0].p + p[1].p, 1.0, 1e-12);  // the same question asked the other way round
  EXPECT_EQ(p[0].sd, 0.0);
  EXPECT_FALSE(locator.placed("pen/office"));
}

TEST(SpaceInputs, AStimulusTheSpaceCannotPlaceIsRefusedNamingTheQueryFile) {
  const SpaceFile s = three_tools();
  StimulusLocator locator(s, "space.json", "");
  try {
    locator.locate("crayon/office", "queries.csv");
    FAIL() << "an unknown stimulus was located";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("queries.csv: stimulus 'crayon/office' is not in space.json"));
  }
  // Without a descriptor map no catalog can place anything.
  EXPECT_THROW(StimulusLocator(s, "space.json", "catalog.json"), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
