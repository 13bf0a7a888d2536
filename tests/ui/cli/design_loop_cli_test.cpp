// `nibrig design loop` as a lab runs it: on the simulated rig inside the loop against a hidden
// truth (the prints play a forcing model whose DM85 curve is 4 dB quieter than the loop's model
// knows: the open-loop print misses, and the target turns out out of reach), and
// the lab's own way (the same truth): the loop proposes and waits, the print is captured with
// `rig capture`, and --resume takes it in, keeps a killed capture aside and measures again. Every
// distance a round reports is checked against the space's map applied by hand to the measurement
// it kept.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "model/catalog/analysis.hpp"
#include "model/design/design_point.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/paper_friction.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;

// Tools on glass placed at their own descriptors, scaled so that the printed range spans a few of
// the space's units (μ × 30, log10 of the weighted mean × 10), with the map from descriptors.
fs::path write_glass_space(const fs::path& folder) {
  const auto catalog_file = nibrig::test::assets_dir() / "default_catalog.json";
  const auto catalog = model::io::read_catalog(catalog_file);
  model::space::SpaceFile s;
  s.stimuli = {"vero1/glass", "vero4/glass", "DM851/glass", "DM854/glass",  "DM951/glass",
               "DM954/glass", "m2h/glass",   "wfelt/glass", "apencil/glass"};
  const auto table = model::space::descriptors_for_stimuli(catalog, catalog_file, s.stimuli, 2);
  s.coordinates = table.values.transpose();
  s.coordinates.row(0) *= 30.0;
  s.coordinates.row(1) *= 10.0;
  for (Eigen::Index i = 0; i < s.coordinates.cols(); ++i)
    s.coordinates(1, i) += 0.05 * static_cast<double>(i % 3);
  s.model.scale = 2.0 / 3.0;
  s.descriptor_names = table.names;
  s.descriptors = table.values;
  s.descriptor_source = catalog_file.string();
  s.descriptor_map = model::space::fit_descriptor_map(s.coordinates, table.values, table.names);
  s.judgments = "none: the tools' own descriptors, scaled (the design loop's tests)";
  fs::create_directories(folder);
  const auto file = folder / "glass_space.json";
  model::space::write_space_file(file, s);
  return file;
}

// The prints as made: the catalog's forcing model with DM85 quieter by 4 dB at every knot than the
// loop's model knows.
fs::path write_quieter_dm85(const fs::path& root) {
  const auto paper = root / "paper_forcing.json";
  if (test::run_cli({"-q", "forcing", "fit", "-o", paper.string()}) != 0)
    throw std::runtime_error("forcing fit failed");
  auto truth = model::forcing::read_forcing_model(paper);
  for (double& k : truth.material_log_gain.at("DM85")) k -= 4.0 / (20 / std::log(10.0));
  const auto file = root / "truth_forcing.json";
  model::forcing::write_forcing_model(file, truth);
  return file;
}

// The space's map applied by hand: a pairing's μ and weighted mean through the map's
// coefficients, and its distance to the target's place (DM952 on glass, from the catalog).
double distance_of(const fs::path& space_file, const model::io::Pairing& measured) {
  const auto space = model::space::read_space_file(space_file);
  const auto& map = *space.descriptor_map;
  const auto place = [&](double mu, double weighted_mean) {
    Eigen::VectorXd z(3);
    z << 1.0, (mu - map.descriptor_mean(0)) / map.descriptor_scale(0),
        (std::log10(weighted_mean) - map.descriptor_mean(1)) / map.descriptor_scale(1);
    return Eigen::VectorXd(map.coefficients * z);
  };
  const auto catalog = model::io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  Eigen::VectorXd target;
  for (const auto& p : catalog.pairings)
    if (p.tool == "DM952" && p.surface == "glass")
      target = place(p.friction->mu, p.vibration->weighted_mean);
  return (place(measured.friction->mu, measured.vibration->weighted_mean) - target).norm();
}

// The distance a round reports, recomputed from the measurement it kept.
double distance_by_hand(const fs::path& space_file, const fs::path& measurement) {
  return distance_of(space_file, model::io::read_catalog(measurement).pairings.at(0));
}

// Each measured round's files, and its reported distance against the one recomputed by hand
// (the same linear map and norm: round-off apart).
void expect_measured_round(const fs::path& loop, const fs::path& space, int round) {
  const fs::path folder = loop / ("round-" + std::to_string(round));
  for (const char* file : {"round.json", "print/stylus.3mf", "measurement.json", "forcing.json"})
    EXPECT_TRUE(fs::exists(folder / file)) << folder / file;
  EXPECT_TRUE(fs::is_directory(folder / "session")) << folder / "session";
  const auto record = test::read_json(folder / "round.json");
  ASSERT_TRUE(record.contains("measured")) << folder;
  EXPECT_NEAR(record["measured"]["distance"].get<double>(),
              distance_by_hand(space, folder / "measurement.json"), 1e-9)
      << "round " << round;
}

TEST(DesignLoopCli, OnTheSimulatedRigAgainstAHiddenTruthThePredictionsComeToTheMeasurements) {
  const auto root = nibrig::test::scratch_dir("cli_design_loop_simulated");
  const auto space = write_glass_space(root);
  const auto truth_file = write_quieter_dm85(root);
  const auto truth = model::forcing::read_forcing_model(truth_file);

  const auto loop = root / "loop";
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--target", "DM952/glass", "--surface", "glass",
                           "--space", space.string(), "--rounds", "3", "--simulated",
                           "--simulated-forcing", truth_file.string(), "--seconds", "14", "-o",
                           loop.string()}),
            0);
  const auto request = test::read_json(loop / "loop.json");
  EXPECT_EQ(request["rule"], "likeliest");
  int rounds = 0;
  while (fs::exists(loop / ("round-" + std::to_string(rounds + 1)) / "round.json")) ++rounds;
  ASSERT_GE(rounds, 1);
  ASSERT_LE(rounds, 3);
  for (int r = 1; r <= rounds; ++r) expect_measured_round(loop, space, r);
  // The last round says why the loop stopped, and it is true of the distances kept.
  const auto last = test::read_json(loop / ("round-" + std::to_string(rounds)) / "round.json");
  const std::string why = last["stopped"];
  const double threshold = 0.6744897501960817 * 1.5;  // the probit's 75 % at s = 2/3
  if (why == "within the threshold")
    EXPECT_LE(last["measured"]["distance"].get<double>(), threshold);
  else if (why == "round limit")
    EXPECT_EQ(rounds, 3);
  else
    EXPECT_EQ(why, "no design predicted closer");
  // The open-loop print missed, and the loop's predictions came to its measurements: the last
  // round's predicted distance is within half the first's miss of what it measured.
  const auto first = test::read_json(loop / "round-1" / "round.json");
  EXPECT_GT(first["measured"]["distance"].get<double>(), threshold);
  ASSERT_GE(rounds, 2);
  const auto miss = [](const nlohmann::json& r) {
    return std::abs(r["predicted"]["distance"].get<double>() -
                    r["measured"]["distance"].get<double>());
  };
  EXPECT_LT(miss(last), 0.5 * miss(first));
  // The refitted model took every print in.
  const auto refitted = model::forcing::read_forcing_model(
      loop / ("round-" + std::to_string(rounds)) / "forcing.json");
  EXPECT_EQ(refitted.exemplar_count(), truth.exemplar_count() + static_cast<std::size_t>(rounds));
}

TEST(DesignLoopCli, ALabMeasuresEachPrintItselfAndResumesKeepingAKilledCaptureAside) {
  const auto root = nibrig::test::scratch_dir("cli_design_loop_lab");
  const auto space = write_glass_space(root);
  const auto truth = write_quieter_dm85(root);
  const auto loop = root / "loop";
  const std::vector<std::string> start{
      "-q",        "design", "loop",     "--target", "DM952/glass", "--space",    space.string(),
      "--surface", "glass",  "--rounds", "2",        "-o",          loop.string()};
  // Without a rig the loop proposes round 1, writes its print's files and waits.
  ASSERT_EQ(test::run_cli(start), 0);
  const auto round1 = test::read_json(loop / "round-1" / "round.json");
  EXPECT_FALSE(round1.contains("measured"));
  EXPECT_TRUE(fs::exists(loop / "round-1" / "print" / "stylus.3mf"));
  EXPECT_FALSE(fs::exists(loop / "round-2"));
  // A new loop into it, and a resumed loop given a new target, are refused.
  EXPECT_EQ(test::run_cli(start), 1);
  EXPECT_EQ(test::run_cli({"-q", "design", "loop", "--resume", "--target", "cryon/office", "-o",
                           loop.string()}),
            2);
  // The lab measures the print as the loop said, and resumes.
  ASSERT_EQ(test::run_cli({"-q", "rig", "capture", "--simulated", "--tool",
                           round1["design"].get<std::string>(), "--surface", "glass", "--forcing",
                           truth.string(), "--speedup", "0", "--seconds", "14", "-o",
                           (loop / "round-1" / "session").string()}),
            0);
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--resume", "-o", loop.string()}), 0);
  expect_measured_round(loop, space, 1);
  // The print missed (the truth's DM85 is quieter): round 2 is proposed.
  EXPECT_FALSE(test::read_json(loop / "round-1" / "round.json").contains("stopped"));
  ASSERT_TRUE(fs::exists(loop / "round-2" / "round.json"));
  // A capture of round 2 killed midway left its .partial folder: kept aside, measured again.
  fs::create_directories(loop / "round-2" / "session.partial");
  std::ofstream(loop / "round-2" / "session.partial" / "session.json") << "{}";
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--resume", "--simulated", "--simulated-forcing",
                           truth.string(), "--seconds", "14", "-o", loop.string()}),
            0);
  EXPECT_TRUE(fs::exists(loop / "round-2" / "session-interrupted-1" / "session.json"));
  expect_measured_round(loop, space, 2);
}

// The paper's recorded prints stand in for printing: the loop proposes only the VeroClear and DM85
// prints recorded on glass, starts from a model without their own measurements, and takes each
// round's print in as its two recordings replayed on the rig.
TEST(DesignLoopCli, ThePapersRecordedPrintsStandInForPrinting) {
  const auto root = nibrig::test::scratch_dir("cli_design_loop_replay");
  const auto space = write_glass_space(root);
  const auto data = nibrig::test::shared_data() / "piovarci2018";
  const auto loop = root / "loop";
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--target", "DM952/glass", "--surface", "glass",
                           "--space", space.string(), "--rounds", "3", "--replay-prints",
                           (root / "nothing-recorded").string(), "-o", loop.string()}),
            1);  // not a folder of recordings
  EXPECT_FALSE(fs::exists(loop));
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--target", "DM952/glass", "--surface", "glass",
                           "--space", space.string(), "--rounds", "3", "--replay-prints",
                           data.string(), "-o", loop.string(), "--speedup", "0"}),
            0);
  const auto request = test::read_json(loop / "loop.json");
  std::vector<std::string> recorded;
  for (const auto& c : request["candidates"]) recorded.push_back(c.get<std::string>());
  EXPECT_THAT(recorded, ::testing::UnorderedElementsAre("vero:1,tip=1mm", "vero:1,tip=2mm",
                                                        "vero:1,tip=4mm", "DM85:1,tip=1mm",
                                                        "DM85:1,tip=2mm", "DM85:1,tip=4mm"));
  const auto count_rounds = [&] {
    int n = 0;
    while (fs::exists(loop / ("round-" + std::to_string(n + 1)) / "round.json")) ++n;
    return n;
  };
  // DM952 is out of the recorded prints' reach: the loop spends its three rounds.
  ASSERT_EQ(count_rounds(), 3);
  EXPECT_EQ(test::read_json(loop / "round-3" / "round.json")["stopped"], "round limit");
  // Resumed with a limit below the rounds made: refused. With a higher one it goes on, and the
  // third round no longer says it stopped at the limit.
  EXPECT_EQ(test::run_cli({"-q", "design", "loop", "--resume", "--replay-prints", data.string(),
                           "--rounds", "2", "-o", loop.string()}),
            1);
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--resume", "--replay-prints", data.string(),
                           "--rounds", "5", "-o", loop.string(), "--speedup", "0"}),
            0);
  EXPECT_EQ(test::read_json(loop / "loop.json")["max_rounds"], 5);
  EXPECT_NE(test::read_json(loop / "round-3" / "round.json").value("stopped", ""), "round limit");
  const int rounds = count_rounds();
  ASSERT_LE(rounds, 5);
  const auto catalog = model::io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  std::set<std::string> printed;
  for (int r = 1; r <= rounds; ++r) {
    expect_measured_round(loop, space, r);
    const auto folder = loop / ("round-" + std::to_string(r));
    const std::string design = test::read_json(folder / "round.json")["design"];
    EXPECT_THAT(recorded, ::testing::Contains(design));
    EXPECT_TRUE(printed.insert(design).second) << design << " printed twice";
    // The print's recordings by their paper names: <material><tip mm> on glass.
    const auto point = model::design::parse_design_point(design);
    const std::string tool =
        point.mix.front().material + std::to_string(std::lround(point.tip_diameter_m * 1e3));
    const auto measured = model::io::read_catalog(folder / "measurement.json").pairings.at(0);
    // μ: the friction run's, as the catalog analysis finds it in the paper's file. The replay
    // holds the run's samples on the accelerometer's frame clock (the two ~1 kHz rates differ by
    // up to 0.1 %), which moves μ by about 0.1 %: a fifth of the 95 % interval's half-width.
    fs::path friction;
    for (const auto& f : fs::directory_iterator(data / "friction/printed"))
      if (f.path().filename().string().starts_with(tool + "_glass_")) friction = f.path();
    ASSERT_FALSE(friction.empty()) << tool;
    const auto run = model::catalog::analyze_friction(model::io::read_paper_friction(friction), {});
    EXPECT_NEAR(measured.friction->mu, run.fit.mu, (run.fit.mu_ci_high - run.fit.mu_ci_low) / 10)
        << design;
    // Placed where the catalog's own analysis of the same recordings places it: the replay's
    // session stores float32 samples and the bundled catalog 4 significant digits on a 2 Hz grid.
    for (const auto& p : catalog.pairings)
      if (p.tool == tool && p.surface == "glass")
        EXPECT_NEAR(test::read_json(folder / "round.json")["measured"]["distance"].get<double>(),
                    distance_of(space, p), 0.01)
            << design;
  }
  // It ends stopped short of its new limit, saying why.
  ASSERT_NE(test::read_json(loop / ("round-" + std::to_string(rounds)) / "round.json")
                .value("stopped", ""),
            "");
  // The loop started without the recorded prints' own measurements on glass, and took each
  // round's print in.
  const auto first = model::forcing::read_forcing_model(loop / "round-1" / "forcing.json");
  const auto last = model::forcing::read_forcing_model(loop / ("round-" + std::to_string(rounds)) /
                                                       "forcing.json");
  EXPECT_EQ(last.exemplar_count(), first.exemplar_count() + static_cast<std::size_t>(rounds - 1));
  for (const auto& e : last.exemplar_fits)
    if (e.surface == "glass")
      for (const char* held : {"vero1", "vero2", "vero4", "DM851", "DM852", "DM854"})
        EXPECT_NE(e.tool, held);
}

// A printer that cannot mix makes each material alone: the loop proposes only such prints, at
// the design grid's tips (1 to 4 mm in 0.5 mm steps). One that prints neither of the mix's
// materials is refused before anything is solved, naming it.
TEST(DesignLoopCli, APrinterThatCannotMixIsGivenOneMaterialPrints) {
  const auto root = nibrig::test::scratch_dir("cli_design_loop_printer");
  const auto space = write_glass_space(root);
  // The paper's PolyJet as one that prints one material at a time.
  auto profile =
      test::read_json(nibrig::test::assets_dir() / "printers" / "stratasys-objet260-connex.json");
  profile["name"] = "polyjet-one-material";
  profile["mixes_materials"] = false;
  profile["materials_per_print"] = 1;
  const auto printer = root / "polyjet-one-material.json";
  std::ofstream(printer) << profile.dump(2);
  const auto loop = root / "loop";
  ASSERT_EQ(test::run_cli({"-q", "design", "loop", "--target", "DM952/glass", "--surface", "glass",
                           "--space", space.string(), "--printer", printer.string(), "-o",
                           loop.string()}),
            0);
  const auto round1 = test::read_json(loop / "round-1" / "round.json");
  const auto point = model::design::parse_design_point(round1["design"].get<std::string>());
  ASSERT_EQ(point.mix.size(), 1u) << round1["design"];
  const double half_mm = point.tip_diameter_m / 0.0005;
  EXPECT_NEAR(half_mm, std::round(half_mm), 1e-9) << round1["design"];
  EXPECT_TRUE(fs::exists(loop / "round-1" / "print" / "stylus.3mf"));

  const auto refused = nibrig::test::run_program(
      {NIBRIG_CLI_BINARY, "design", "loop", "--target", "DM952/glass", "--surface", "glass",
       "--space", space.string(), "--printer", "prusa-mk3s", "-o", (root / "fdm").string()},
      root);
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_THAT(refused.output, ::testing::HasSubstr("printer prusa-mk3s cannot mix vero and DM85"));
  EXPECT_FALSE(fs::exists(root / "fdm" / "round-1"));
}

TEST(DesignLoopCli, TheSearchWithoutALoopStillNeedsItsTarget) {
  EXPECT_EQ(test::run_cli({"-q", "design", "--surface", "glass", "--space", "nothere.json"}), 2);
}

}  // namespace
}  // namespace nibrig::ui::cli
