#include "model/measure/friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

#include "tests/model/measure/gz_csv.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::measure {
namespace {

constexpr double kLoad = 2.2;

struct SyntheticFriction {
  std::vector<double> force;
  std::size_t begin, end;  // contact, samples
};

// Baseline 0 N with white sensor noise; a 0.2 s ramp up to μ(v)·N from `begin`, a ramp down at
// `end`; in contact μ(v) = mu0 + slope·v with the sweep's linear speed, plus AR(1) force noise (φ =
// 0.98, 50 ms correlation, like the real records' slow wander).
SyntheticFriction make_friction(std::size_t n, std::size_t begin, std::size_t end, double mu0,
                                double slope, unsigned seed) {
  SyntheticFriction s{std::vector<double>(n), begin, end};
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const SweepAssumption sweep;
  double ar = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = sweep.start_speed_m_s + (sweep.end_speed_m_s - sweep.start_speed_m_s) *
                                                 static_cast<double>(i) /
                                                 static_cast<double>(n - 1);
    double on = 0.0;
    if (i >= begin && i < end) on = std::min({1.0, (i - begin) / 200.0, (end - i) / 200.0});
    ar = 0.98 * ar + 0.004 * unit(rng);
    s.force[i] = on * ((mu0 + slope * v) * kLoad + ar) + 0.001 * unit(rng);
  }
  return s;
}

// Truth of the analysed mean: μ(v) averaged over the analysed samples (linear in v: at its mean
// speed).
double true_mean_mu(const FrictionFit& fit, std::size_t n, double mu0, double slope) {
  const SweepAssumption sweep;
  const double mid = 0.5 * static_cast<double>(fit.analysis_begin + fit.analysis_end - 1);
  return mu0 + slope * (sweep.start_speed_m_s + (sweep.end_speed_m_s - sweep.start_speed_m_s) *
                                                    mid / static_cast<double>(n - 1));
}

TEST(Friction, FindsTheContactAndRecoversMu) {
  const auto s = make_friction(40000, 12345, 38000, 0.25, 0.2, 1);
  const FrictionFit fit = fit_coulomb_friction(s.force, 1000.0, kLoad, SweepAssumption{});
  // The detected edges are where the ramp leaves the baseline by 10 % of the step: 20 samples into
  // the 200-sample ramp (±10 for noise and the 50 ms smoothing).
  EXPECT_NEAR(static_cast<double>(fit.contact.begin), 12345.0 + 20.0, 30.0);
  EXPECT_NEAR(static_cast<double>(fit.contact.end), 38000.0 - 20.0, 30.0);
  EXPECT_NEAR(fit.contact.baseline_N, 0.0, 1e-3);  // sensor noise 1 mN, median of thousands
  EXPECT_EQ(fit.analysis_begin, fit.contact.begin + 1000);
  EXPECT_EQ(fit.samples, fit.analysis_end - fit.analysis_begin);
  const double truth = true_mean_mu(fit, 40000, 0.25, 0.2);
  // One record: within 4 SE of the truth (its coverage is tested below over 200 records).
  const double se = (fit.mu_ci_high - fit.mu_ci_low) / (2.0 * 1.96);
  EXPECT_NEAR(fit.mu, truth, 4.0 * se);
  // AR(1) noise of SD 0.004/sqrt(1-0.98²) = 0.020 N, τ = 99 samples: SE of μ =
  // 0.020/2.2·sqrt(99/23600) = 5.9e-4; the interval half-width is 1.96 SE = 1.2e-3 (±30 % for the
  // SE's own estimate).
  EXPECT_NEAR((fit.mu_ci_high - fit.mu_ci_low) / 2.0, 1.16e-3, 0.35e-3);
  EXPECT_NEAR(fit.speed_slope_per_m_s, 0.2, 0.05);  // slope from 24 s of data: SE ≈ 0.01
  ASSERT_EQ(fit.speeds_m_s.size(), 8u);
  for (std::size_t b = 0; b < 8; ++b) {
    EXPECT_LT(fit.mu_by_speed_ci_low[b], fit.mu_by_speed[b]);
    EXPECT_GT(fit.mu_by_speed_ci_high[b], fit.mu_by_speed[b]);
    if (b > 0) {
      EXPECT_GT(fit.speeds_m_s[b], fit.speeds_m_s[b - 1]);
    }
  }
}

TEST(Friction, IntervalsCoverTheTruthAtTheirNominalRate) {
  // 200 records: with 95 % coverage the count of hits is Binomial(200, 0.95), mean 190, SD 3.1;
  // [180, 198] is beyond ±3 SD (a naive σ/√n interval covers ~35 % here and would fail by far).
  int hits = 0, bin_hits = 0, bin_total = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    const auto s = make_friction(30000, 4000, 29000, 0.30, 0.15, 1000 + seed);
    const FrictionFit fit = fit_coulomb_friction(s.force, 1000.0, kLoad, SweepAssumption{});
    const double truth = true_mean_mu(fit, 30000, 0.30, 0.15);
    hits += fit.mu_ci_low <= truth && truth <= fit.mu_ci_high;
    for (std::size_t b = 0; b < fit.speeds_m_s.size(); ++b) {
      const double tb =
          0.30 + 0.15 * fit.speeds_m_s[b];  // linear μ(v): true at the bin's mean speed
      bin_hits += fit.mu_by_speed_ci_low[b] <= tb && tb <= fit.mu_by_speed_ci_high[b];
      ++bin_total;
    }
  }
  std::cout << "coverage: overall " << hits << "/200, per speed bin " << bin_hits << "/"
            << bin_total << '\n';
  EXPECT_GE(hits, 180);
  EXPECT_LE(hits, 198);
  // 1600 bin intervals: mean 1520, SD 8.7; ±4 SD.
  EXPECT_NEAR(bin_hits, 0.95 * bin_total, 35.0);
}

TEST(Friction, RefusesRecordsWithoutContact) {
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0.0, 0.001);
  std::vector<double> flat(20000);
  for (double& v : flat) v = 0.5 + noise(rng);
  EXPECT_THROW(detect_contact(flat, 1000.0), std::runtime_error);
  std::vector<double> blip(20000, 0.0);
  for (std::size_t i = 5000; i < 5500; ++i) blip[i] = 0.5;  // 0.5 s: too short for a contact
  EXPECT_THROW(detect_contact(blip, 1000.0), std::runtime_error);
  EXPECT_THROW(detect_contact(std::vector<double>(1000, 0.0), 1000.0), std::invalid_argument);
  const auto s = make_friction(20000, 3000, 18000, 0.2, 0.0, 3);
  EXPECT_THROW(fit_coulomb_friction(s.force, 1000.0, 0.0, SweepAssumption{}),
               std::invalid_argument);
}

TEST(Friction, HandlesASensorThatReadsFrictionAsNegative) {
  auto s = make_friction(30000, 5000, 28000, 0.2, 0.0, 4);
  for (double& v : s.force) v = -v;
  const FrictionFit fit = fit_coulomb_friction(s.force, 1000.0, kLoad, SweepAssumption{});
  EXPECT_NEAR(fit.mu, 0.2, 0.005);  // 4 SE of this record's noise
  EXPECT_LT(fit.contact.plateau_N, fit.contact.baseline_N);
}

TEST(Friction, UpstreamMuIsTheMeanOfRows5000To20000) {
  std::vector<double> f(25000, 0.0);
  for (std::size_t i = 4999; i <= 19999; ++i) f[i] = 1.1;
  f[4998] = f[20000] = 100.0;                    // just outside the window: must not count
  EXPECT_NEAR(upstream_mu(f, 2.2), 0.5, 1e-12);  // 15001 summed values: rounding only
  EXPECT_THROW(upstream_mu(std::vector<double>(19999, 0.0), 2.2), std::invalid_argument);
}

struct FrictionFile {
  std::string name;
  std::vector<double> force_N;
};

// Z counts → newtons: 403.2 counts per newton divided by the arm's lever (the 4th '_' field).
FrictionFile load_friction(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t u = name.find('_'); u != std::string::npos; u = name.find('_', start)) {
    fields.push_back(name.substr(start, u - start));
    start = u + 1;
  }
  const double lever = std::stod(fields.at(3));
  auto column = nibrig::test::read_gz_csv_column(path, 3);
  // Only stab_stone ends in a truncated line (its last row lacks Z); nothing else is skipped.
  EXPECT_LE(column.short_rows, 1u) << name;
  for (double& v : column.values) v = v / 403.2 / lever;
  return {name, column.values};
}

TEST(FrictionOnPaperData, EveryRecordGivesAPlausibleCoefficientAndContact) {
  const auto root = nibrig::test::shared_data() / "piovarci2018" / "friction";
  const auto out = nibrig::test::scratch_dir("friction_paper") / "mu.csv";
  std::ofstream table(out);
  table << "file,contact_begin_s,contact_end_s,mu,ci_low,ci_high,effective_samples,slope_per_m_s,"
           "upstream_mu\n";
  std::size_t files = 0;
  double lo = 1e9, hi = -1e9;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    ++files;
    const FrictionFile f = load_friction(entry.path());
    const std::string folder = entry.path().parent_path().filename().string();
    const FrictionFit fit = fit_coulomb_friction(f.force_N, 1000.0, kLoad, SweepAssumption{});
    const double begin_s = static_cast<double>(fit.contact.begin) / 1000.0;
    const double seconds = static_cast<double>(f.force_N.size()) / 1000.0;
    // Physically plausible for dry sliding of these tips; the paper reports 0.13-0.33 (its method,
    // see the report for why the long real-tool records come out lower).
    EXPECT_GT(fit.mu, 0.05) << f.name;
    EXPECT_LT(fit.mu, 0.45) << f.name;
    EXPECT_LT(fit.mu_ci_low, fit.mu);
    EXPECT_GT(fit.mu_ci_high, fit.mu);
    EXPECT_LT(fit.mu_ci_high - fit.mu_ci_low, 0.05) << f.name;
    if (folder == "real_tools" && seconds > 50.0) {
      // The long real-tool records (pen, pencils, fine-liner, charcoal) start contact about 10-20 s
      // in: measured 9.8 s (pen_stone, where the force leaves zero; it passes half its level at
      // 10.2 s) to 20.6 s (p2h_stone).
      EXPECT_GT(begin_s, 9.5) << f.name;
      EXPECT_LT(begin_s, 21.0) << f.name;
    } else {
      // Printed, commercial and the newer real-tool records (crayon, stabilo): 2.4-3.9 s.
      EXPECT_GT(begin_s, 2.0) << f.name;
      EXPECT_LT(begin_s, 5.0) << f.name;
    }
    // Independent check of the onset: the force takes 0.3-0.8 s to rise, and the first sample above
    // a quarter of the median force of the record's second half (always in contact) must lie on
    // that rise, within 0.6 s after our start. (Half would not do: on glass μ grows with speed and
    // the late median is twice the early force.)
    std::vector<double> late(f.force_N.begin() + static_cast<std::ptrdiff_t>(f.force_N.size() / 2),
                             f.force_N.end());
    std::nth_element(late.begin(), late.begin() + static_cast<std::ptrdiff_t>(late.size() / 2),
                     late.end());
    const double quarter = 0.25 * late[late.size() / 2];
    std::size_t first = 0;
    while (f.force_N[first] < quarter) ++first;
    EXPECT_GE(static_cast<double>(first), static_cast<double>(fit.contact.begin)) << f.name;
    EXPECT_LT(static_cast<double>(first - fit.contact.begin), 600.0) << f.name;
    lo = std::min(lo, fit.mu);
    hi = std::max(hi, fit.mu);
    table << f.name << ',' << begin_s << ',' << static_cast<double>(fit.contact.end) / 1000.0 << ','
          << fit.mu << ',' << fit.mu_ci_low << ',' << fit.mu_ci_high << ',' << fit.effective_samples
          << ',' << fit.speed_slope_per_m_s << ',' << upstream_mu(f.force_N, kLoad) << '\n';
  }
  EXPECT_EQ(files, 82u);
  std::cout << "friction: " << files << " records, mu " << lo << " - " << hi << "; table in " << out
            << '\n';
}

}  // namespace
}  // namespace nibrig::model::measure
