#include "model/measure/threshold_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::measure {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto path = nibrig::test::scratch_dir("threshold_" + name) / "curve.csv";
  std::ofstream(path) << text;
  return path;
}

TEST(ThresholdCurve, LoadsTheShippedPenHoldCurve) {
  const ThresholdCurve c =
      ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  EXPECT_NE(c.source().find("Israr"), std::string::npos);
  EXPECT_NE(c.source().find("APPROXIMATION"), std::string::npos);  // says plainly what it is
  ASSERT_EQ(c.frequencies_hz().size(), 8u);
  // The table is a displacement curve converted with a = (2πf)² d: re-derive two rows independently
  // from the dB values stated in the file's comments (rounded there to 4 significant digits).
  const double two_pi = 2.0 * 3.14159265358979;
  EXPECT_NEAR(c.threshold_m_s2(10.0), std::pow(two_pi * 10, 2) * std::pow(10, 28.0 / 20) * 1e-6,
              1e-4);
  EXPECT_NEAR(c.threshold_m_s2(250.0), std::pow(two_pi * 250, 2) * std::pow(10, -21.0 / 20) * 1e-6,
              1e-4);
  // U-shaped in displacement: the displacement threshold a/(2πf)² is lowest at 250 Hz.
  double best_f = 0, best_d = 1e9;
  for (double f : c.frequencies_hz()) {
    const double d = c.threshold_m_s2(f) / std::pow(two_pi * f, 2);
    if (d < best_d) best_d = d, best_f = f;
  }
  EXPECT_EQ(best_f, 250.0);
}

TEST(ThresholdCurve, InterpolatesInLogLogAndClampsOutside) {
  const ThresholdCurve c({10.0, 40.0, 160.0}, {1.0, 4.0, 0.25}, "test");
  EXPECT_DOUBLE_EQ(c.threshold_m_s2(40.0), 4.0);
  // Geometric midpoint of 10 and 40 Hz (20 Hz) gets the geometric mean of 1 and 4: 2.
  EXPECT_NEAR(c.threshold_m_s2(20.0), 2.0, 1e-12);
  // Straight line in log-log: at 80 Hz, half-way (in log f) from 4 to 0.25 → sqrt(4 · 0.25) = 1.
  EXPECT_NEAR(c.threshold_m_s2(80.0), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.threshold_m_s2(1.0), 1.0);  // clamped below
  EXPECT_DOUBLE_EQ(c.threshold_m_s2(0.0), 1.0);
  EXPECT_DOUBLE_EQ(c.threshold_m_s2(5000.0), 0.25);  // clamped above
  EXPECT_THROW(c.threshold_m_s2(NAN), std::invalid_argument);
  EXPECT_THROW(c.threshold_m_s2(-1.0), std::invalid_argument);
  EXPECT_THROW(ThresholdCurve({10.0}, {1.0}, "x"), std::invalid_argument);
  EXPECT_THROW(ThresholdCurve({10.0, 10.0}, {1.0, 2.0}, "x"), std::invalid_argument);
  EXPECT_THROW(ThresholdCurve({10.0, 20.0}, {1.0, 0.0}, "x"), std::invalid_argument);
}

TEST(ThresholdCurve, RejectsMalformedFilesNamingTheLine) {
  auto expect_error = [](const std::string& name, const std::string& text,
                         const std::string& place) {
    const auto path = write(name, text);
    try {
      ThresholdCurve::load(path);
      ADD_FAILURE() << name << ": no error";
    } catch (const io::FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(place), std::string::npos) << e.what();
      EXPECT_EQ(e.file(), path);
    }
  };
  const std::string head = "# source: test\nfrequency_hz,threshold_m_s2\n";
  expect_error("header", "# source: t\nfreq,thr\n10,1\n20,2\n", "line 2");
  expect_error("number", head + "10,1\n20,abc\n", "line 4, field 'threshold_m_s2'");
  expect_error("order", head + "10,1\n30,2\n20,3\n", "line 5");
  expect_error("negative", head + "10,1\n20,-2\n", "line 4");
  expect_error("fields", head + "10,1,5\n", "line 3");
  expect_error("rows", head + "10,1\n", "at least 2 rows");
  expect_error("source", "frequency_hz,threshold_m_s2\n10,1\n20,2\n", "source");
  expect_error("missing", "", "header");
  EXPECT_THROW(ThresholdCurve::load("/nonexistent/curve.csv"), io::FormatError);
}

TEST(ThresholdCurve, WeightsSpectraBySensationRatio) {
  const ThresholdCurve c({10.0, 1000.0}, {0.5, 0.5}, "flat");
  io::VelocitySpectrum s{{50.0, 100.0}, {0.1, 0.2}, {{1.0, 0.5}, {2.0, 0.25}}};
  const auto r = weight_by_threshold(s, c);
  EXPECT_EQ(r, (std::vector<std::vector<double>>{{2.0, 1.0}, {4.0, 0.5}}));
  s.amplitude_m_s2[1].pop_back();
  EXPECT_THROW(weight_by_threshold(s, c), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::measure
