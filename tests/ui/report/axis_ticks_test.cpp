// Tick placement and labels: steps of 1, 2 or 5 × 10^k, labels that do not collide, decades on
// log axes, and numbers written as a reader expects them.
#include "ui/report/axis_ticks.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::ui::report::detail {
namespace {

using ::testing::ElementsAre;

// Every label 40 units long along an axis 1000 units long, 10 units apart at least.
const LabelExtent forty = [](const std::string&) { return 40.0; };

std::vector<double> positions(const AxisTicks& t) {
  std::vector<double> p;
  for (const auto& tick : t.major) p.push_back(tick.position);
  return p;
}

std::vector<std::string> labels(const AxisTicks& t) {
  std::vector<std::string> l;
  for (const auto& tick : t.major) l.push_back(tick.label);
  return l;
}

TEST(AxisTicks, LinearTicksTakeTheDensestNiceStepWhoseLabelsFit) {
  // Labels 80 long and 10 apart need 90 units between ticks. Over 0-1000 on 1000 units a step of
  // 100 gives exactly 100.
  const LabelExtent eighty = [](const std::string&) { return 80.0; };
  const auto t = linear_ticks(0.0, 1000.0, 1000.0, eighty, 10.0);
  ASSERT_EQ(t.major.size(), 11u);
  EXPECT_DOUBLE_EQ(t.major[1].position, 100.0);
  EXPECT_EQ(t.major[1].label, "100");
  // Half the length: 100 would be 50 apart, so 200.
  EXPECT_THAT(positions(linear_ticks(0.0, 1000.0, 500.0, eighty, 10.0)),
              ElementsAre(0.0, 200.0, 400.0, 600.0, 800.0, 1000.0));
  // 150 units: 500 would be 75 apart, so only the ends.
  EXPECT_THAT(positions(linear_ticks(0.0, 1000.0, 150.0, eighty, 10.0)), ElementsAre(0.0, 1000.0));
  // However long the axis, no more than 15 labels: 100, not 50 (21 labels).
  EXPECT_EQ(linear_ticks(0.0, 1000.0, 1e5, forty, 10.0).major.size(), 11u);
}

TEST(AxisTicks, LinearTicksStayInsideTheRangeAndMinorTicksSplitTheSteps) {
  const auto t = linear_ticks(-0.37, 0.81, 600.0, forty, 10.0);
  ASSERT_GE(t.major.size(), 2u);
  for (const auto& tick : t.major) {
    EXPECT_GE(tick.position, -0.37);
    EXPECT_LE(tick.position, 0.81);
  }
  const double step = t.major[1].position - t.major[0].position;
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << step;
  EXPECT_FALSE(t.minor.empty());
  for (double m : t.minor) {
    for (const auto& tick : t.major) EXPECT_GT(std::abs(m - tick.position), 1e-12);
  }
}

TEST(AxisTicks, NumbersAreWrittenWithTheDecimalsTheStepNeeds) {
  EXPECT_EQ(format_tick(-0.25, 0.05, 1.0), "\u22120.25");    // a true minus sign
  EXPECT_EQ(format_tick(0.1 + 0.2 - 0.3, 0.1, 1.0), "0.0");  // rounding noise is zero, not -0.0
  EXPECT_EQ(format_tick(250.0, 50.0, 1000.0), "250");
  // The exponent follows the axis's largest magnitude, so all labels of an axis share it.
  EXPECT_EQ(format_tick(2e5, 1e5, 1e6), "0.2\u00d710#u6#d");
  EXPECT_EQ(format_tick(3e5, 1e5, 5e5), "3\u00d710#u5#d");
  EXPECT_EQ(format_tick(5e-4, 1e-4, 9e-4), "5\u00d710#u\u22124#d");
}

TEST(AxisTicks, LogTicksLabelDecadesWithMinorTicksBetween) {
  const auto t = log_ticks(-3.2, 1.1, 600.0, forty, 10.0);
  EXPECT_THAT(positions(t), ElementsAre(-3.0, -2.0, -1.0, 0.0, 1.0));
  EXPECT_EQ(t.major[0].label, "10#u\u22123#d");
  EXPECT_EQ(t.major[3].label, "10#u0#d");
  // 2..9 times each decade, including those of the partial decades at both ends.
  const auto has_minor = [&](double p) {
    for (double m : t.minor) {
      if (std::abs(m - p) < 1e-12) return true;
    }
    return false;
  };
  EXPECT_TRUE(has_minor(std::log10(2e-2)));
  EXPECT_TRUE(has_minor(std::log10(9e-4)));  // below 10^-3, above 10^-3.2
  EXPECT_FALSE(has_minor(1.0));              // 10 itself is major, not minor
}

TEST(AxisTicks, LogTicksThinDecadesWhenTheAxisIsShort) {
  // 12 decades on 150 units: at most 3 labels of 40 + 10 fit.
  const auto t = log_ticks(-6.0, 6.0, 150.0, forty, 10.0);
  ASSERT_GE(t.major.size(), 2u);
  ASSERT_LE(t.major.size(), 3u);
  for (std::size_t i = 1; i < t.major.size(); ++i) {
    EXPECT_GE((t.major[i].position - t.major[i - 1].position) / 12.0 * 150.0, 50.0);
  }
}

TEST(AxisTicks, LogTicksOverLessThanADecadeLabelTheValuesThemselves) {
  const auto t = log_ticks(std::log10(0.5), std::log10(1.5), 600.0, forty, 10.0);
  ASSERT_GE(t.major.size(), 3u);
  EXPECT_THAT(labels(t), ::testing::Contains("1.0"));
  for (const auto& tick : t.major) {
    EXPECT_GE(tick.position, std::log10(0.5) - 1e-12);
    EXPECT_LE(tick.position, std::log10(1.5) + 1e-12);
  }
}

TEST(AxisTicks, TextWidthCountsEscapesAsWhatTheyDraw) {
  // "#gm" draws one letter μ; "#u2#d" a superscript 2 smaller than a normal digit; "##" one '#'.
  EXPECT_NEAR(text_width_caps("#gm"), text_width_caps("\u03bc"), 1e-12);
  EXPECT_LT(text_width_caps("m/s#u2#d"), text_width_caps("m/s2"));
  EXPECT_GT(text_width_caps("m/s#u2#d"), text_width_caps("m/s"));
  EXPECT_NEAR(text_width_caps("a##b"), text_width_caps("a#b"), 1e-12);
  // Wide letters count wider than narrow ones.
  EXPECT_GT(text_width_caps("WWW"), text_width_caps("iii"));
}

}  // namespace
}  // namespace nibrig::ui::report::detail
