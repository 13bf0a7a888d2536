// `nibrig space fit|predict`: triplet judgments → a perceptual space (space.json), and the
// probability that the first candidate is chosen for any list of triplets.
#include <spdlog/spdlog.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "model/io/triplets.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_file.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

namespace space = model::space;

struct FitCommandOptions {
  std::filesystem::path judgments, output = "space.json";
  std::size_t dims = 2;
  double lambda = 0.0;
  int starts = 16;
  unsigned seed = 1;
};

struct PredictCommandOptions {
  std::filesystem::path space_file, queries, output;
};

void run_fit(const FitCommandOptions& o, const GlobalOptions& global) {
  if (o.lambda > 0)
    throw std::invalid_argument(
        "--lambda > 0 ties the axes to descriptors, which `space fit` does not read yet; use "
        "--lambda 0");
  const model::io::TripletSet set = model::io::read_triplets(o.judgments);
  space::SpaceProblem problem;
  problem.dims = o.dims;
  problem.stimuli = set.stimuli.size();
  problem.triplets = set.triplets;
  problem.lambda = o.lambda;
  space::FitOptions options;
  options.starts = o.starts;
  options.seed = o.seed;
  options.threads = worker_threads(global);
  spdlog::info("{}: {} stimuli, {} triplets, {} responses; {}-D fit from {} starts",
               o.judgments.string(), set.stimuli.size(), set.triplets.size(),
               model::io::response_count(set), o.dims, o.starts);
  const space::FitResult fit = space::fit_space(problem, options);
  space::SpaceFile file;
  file.stimuli = set.stimuli;
  file.coordinates = fit.coordinates;
  file.scale = problem.scale;
  file.lambda = problem.lambda;
  file.objective = fit.objective;
  file.negative_log_likelihood = fit.negative_log_likelihood;
  file.start_objectives = fit.start_objectives;
  file.triplets = set.triplets.size();
  file.responses = model::io::response_count(set);
  file.judgments = o.judgments.string();
  space::write_space_file(o.output, file);
  std::cout << "fitted " << o.dims << "-D space of " << set.stimuli.size()
            << " stimuli: -log likelihood " << fit.negative_log_likelihood << " (best of "
            << o.starts << " starts; worst start " << fit.start_objectives.back() << ") -> "
            << o.output.string() << "\n";
}

void run_predict(const PredictCommandOptions& o) {
  const space::SpaceFile s = space::read_space_file(o.space_file);
  const model::io::TripletSet queries = model::io::read_triplet_queries(o.queries);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < s.stimuli.size(); ++i) index[s.stimuli[i]] = i;
  auto find = [&](const std::string& name) {
    const auto it = index.find(name);
    if (it == index.end())
      throw std::invalid_argument(o.queries.string() + ": stimulus '" + name + "' is not in " +
                                  o.space_file.string());
    return it->second;
  };
  std::ostringstream csv;
  csv << "reference,a,b,p_first\n" << std::setprecision(10);
  for (const auto& t : queries.triplets) {
    const std::string& r = queries.stimuli[t.reference];
    const std::string& a = queries.stimuli[t.a];
    const std::string& b = queries.stimuli[t.b];
    csv << r << ',' << a << ',' << b << ','
        << space::probability_first(s.coordinates, find(r), find(a), find(b), s.scale) << '\n';
  }
  if (o.output.empty()) {
    std::cout << csv.str();
  } else {
    write_text_file(o.output, csv.str());
    spdlog::info("wrote {} predictions to {}", queries.triplets.size(), o.output.string());
  }
}

}  // namespace

void add_space_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* cmd =
      app.add_subcommand("space", "Perceptual space: fit triplet judgments, predict preferences");
  cmd->require_subcommand(1);
  cmd->footer(
      "Judgments: our CSV (reference,a,b,count_a,count_b[,observer]), the Lagunas et al. 2019 JSON "
      "or\n"
      "the Salmon responses CSV, told apart by content. The model (Sec. 4): P(a closer to the\n"
      "reference than b) = Phi(-2/3 (|Q_a - Q_r| - |Q_b - Q_r|)), one unit = 75 % preference.");

  auto fit = std::make_shared<FitCommandOptions>();
  auto* fit_cmd = cmd->add_subcommand("fit", "Fit a space to judgments -> space.json");
  fit_cmd->footer(
      "Maximum likelihood from many random starts (L-BFGS), the best kept; stimulus 1 at the "
      "origin.");
  fit_cmd->add_option("judgments", fit->judgments, "Judgments file")
      ->required()
      ->check(CLI::ExistingFile);
  fit_cmd->add_option("--dims", fit->dims, "Dimensions (default 2)")->check(CLI::Range(1, 10));
  fit_cmd->add_option("--lambda", fit->lambda, "Weight of the descriptor correlation (default 0)");
  fit_cmd->add_option("--starts", fit->starts, "Random starts (default 16)")
      ->check(CLI::Range(1, 10000));
  fit_cmd->add_option("--seed", fit->seed, "Seed of the first start (default 1)");
  fit_cmd->add_option("-o,--output", fit->output, "Output space file (default space.json)");
  fit_cmd->callback([fit, global] {
    configure_logging(global->verbosity);
    run_fit(*fit, *global);
  });

  auto predict = std::make_shared<PredictCommandOptions>();
  auto* predict_cmd = cmd->add_subcommand(
      "predict", "Probability that the first candidate is chosen, per query, as CSV");
  predict_cmd->footer(
      "Writes reference,a,b,p_first, one row per query in input order; queries in any judgment "
      "format\n"
      "(counts ignored; for Salmon the first candidate is Left, for Lagunas answers[i][1]).");
  predict_cmd->add_option("space", predict->space_file, "space.json from `space fit`")
      ->required()
      ->check(CLI::ExistingFile);
  predict_cmd->add_option("queries", predict->queries, "Triplets to predict")
      ->required()
      ->check(CLI::ExistingFile);
  predict_cmd->add_option("-o,--output", predict->output, "Output CSV (default: standard output)");
  predict_cmd->callback([predict, global] {
    configure_logging(global->verbosity);
    run_predict(*predict);
  });
}

}  // namespace nibrig::ui::cli
