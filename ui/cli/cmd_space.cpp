// `nibrig space ...`: registers the perceptual-space subcommands; the work is in
// cmd_space_fit.cpp, cmd_space_validate.cpp, cmd_space_query.cpp and cmd_space_design.cpp.
#include "model/space/fit.hpp"
#include "model/space/judgment_model.hpp"
#include "model/space/objective.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/space_commands.hpp"

namespace nibrig::ui::cli {
namespace {

// A judgment model's name (model/space/judgment_model.hpp), refused while parsing with the names
// that exist; "auto" and "all" where the option takes them.
CLI::Validator judgment_model_name(bool auto_allowed, bool all_allowed = false) {
  return CLI::Validator(
      [auto_allowed, all_allowed](std::string& text) {
        if ((auto_allowed && text == "auto") || (all_allowed && text == "all")) return std::string();
        try {
          model::space::parse_family(text);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what()) + (auto_allowed ? ", or auto" : "") + (all_allowed ? ", or all" : "");
        }
      },
      "MODEL");
}

void add_fit(CLI::App& cmd, const std::shared_ptr<const GlobalOptions>& global) {
  auto o = std::make_shared<SpaceFitOptions>();
  auto* fit = cmd.add_subcommand("fit", "Fit a space to judgments -> space.json");
  fit->footer(
      "Maximum likelihood from many starts (L-BFGS), the best kept: the first from the judgments'\n"
      "own MDS, the others random; stimulus 1 at the origin.\n"
      "--descriptors names a catalog whose pairings \"tool/surface\" are the judged stimuli: axis 1 "
      "is\n"
      "tied to friction mu, axis 2 to log10 weighted vibration (D >= 3: band energies) with weight\n"
      "--lambda, and a map from descriptors to coordinates is learnt so new tools can be placed.");
  fit->add_option("judgments", o->judgments, "Judgments file")->required()->check(CLI::ExistingFile);
  fit->add_option("--descriptors", o->descriptors, "Catalog with the stimuli's descriptors")
      ->check(CLI::ExistingFile);
  fit->add_option("--dims", o->dims, "Dimensions (default 2)")
      ->check(whole_in_range(1, model::space::kMostSpaceDims, "a number of dimensions"));
  fit->add_option("--lambda", o->lambda, "Weight of the descriptor correlation (default 0)")
      ->check(in_range(0, model::space::kMaxLambda, "a weight"));
  fit->add_option("--starts", o->starts, "Random starts (default 16)")
      ->check(whole_in_range(1, model::space::kMostFitStarts, "a number of starts"));
  fit->add_option("--seed", o->seed, "Seed of the first start (default 1)")->check(any_seed());
  fit->add_option("--bootstrap", o->bootstrap,
                  "Resamples for 68/95 % confidence regions (paper: 1000; default 0 = none)")
      ->check(whole_in_range(0, model::space::kMostBootstrapResamples, "a number of resamples"));
  fit->add_option("--model", o->model,
                  "Judgment model: probit (the paper's, default), logistic or student-t, each optionally with "
                  "+lapse and then +noise; or auto: the one that predicts held-out judgments best")
      ->check(judgment_model_name(true));
  fit->add_option("--models", o->models, "Candidates of --model auto (default: all twelve)")
      ->delimiter(',')
      ->check(judgment_model_name(false));
  fit->add_option("--folds", o->folds, "Folds of --model auto's cross-validation (default 5)")
      ->check(whole_in_range(2, model::space::kMostFolds, "a number of folds"));
  fit->add_option("--plot", o->plot, "PNG of the space (first two axes)")
      ->check(file_to_write());
  fit->add_option("-o,--output", o->output, "Output space file (default space.json)")
      ->check(file_to_write());
  fit->callback([o, global] {
    configure_logging(global->verbosity);
    run_space_fit(*o, worker_threads(*global));
  });
}

void add_validate(CLI::App& cmd, const std::shared_ptr<const GlobalOptions>& global) {
  auto o = std::make_shared<SpaceValidateOptions>();
  auto* v = cmd.add_subcommand("validate", "Cross-validate spaces of several dimensions and lambdas");
  v->footer(
      "Error = mean over held-out triplets of |predicted - observed probability| (the paper's 17 % "
      "for\n"
      "5-fold, 2-D). Agreement: with each triplet's majority answer and with every individual "
      "answer;\n"
      "a prediction of exactly 0.5 counts as half right.");
  v->add_option("judgments", o->judgments, "Judgments file")->required()->check(CLI::ExistingFile);
  v->add_option("--descriptors", o->descriptors, "Catalog (needed for lambdas above 0)")
      ->check(CLI::ExistingFile);
  v->add_option("--folds", o->folds, "Folds (default 5)")
      ->check(whole_in_range(2, model::space::kMostFolds, "a number of folds"));
  v->add_option("--dims", o->dims, "Dimensions to try (default 1,2,3)")
      ->delimiter(',')
      ->check(whole_in_range(1, model::space::kMostSpaceDims, "a number of dimensions"));
  v->add_option("--lambdas", o->lambdas, "Lambdas to try (default 0)")
      ->delimiter(',')
      ->check(in_range(0, model::space::kMaxLambda, "a weight"));
  v->add_option("--models", o->models,
                "Judgment models to try: names as for space fit --model, or all (default probit)")
      ->delimiter(',')
      ->check(judgment_model_name(false, true));
  v->add_option("--starts", o->starts, "Random starts per fit (default 8)")
      ->check(whole_in_range(1, model::space::kMostFitStarts, "a number of starts"));
  v->add_option("--seed", o->seed, "Seed of folds and starts (default 1)")->check(any_seed());
  v->add_option("-o,--output", o->output, "Write the results as JSON")->check(file_to_write());
  v->add_option("--plots", o->plots, "Folder for the scan plot (dimension_scan.png)");
  v->callback([o, global] {
    configure_logging(global->verbosity);
    run_space_validate(*o, worker_threads(*global));
  });
}

void add_queries(CLI::App& cmd, const std::shared_ptr<const GlobalOptions>& global) {
  auto p = std::make_shared<SpaceQueryOptions>();
  auto* predict = cmd.add_subcommand(
      "predict", "Probability that the first candidate is chosen, per query, as CSV");
  predict->footer(
      "Writes reference,a,b,p_first, one row per query in input order; queries in any judgment "
      "format\n"
      "(counts ignored, and a CSV may leave them out: reference,a,b is enough; for Salmon the "
      "first\n"
      "candidate is Left, for Lagunas answers[i][1]). With\n"
      "--catalog, tools not in the space are placed from their descriptors and a column p_first_sd\n"
      "gives the spread of p over their placement uncertainty.");
  predict->add_option("space", p->space_file, "space.json from `space fit`")
      ->required()
      ->check(CLI::ExistingFile);
  predict->add_option("queries", p->queries, "Triplets to predict")
      ->required()
      ->check(CLI::ExistingFile);
  predict->add_option("--catalog", p->catalog, "Place unjudged tools from this catalog")
      ->check(CLI::ExistingFile);
  predict->add_option("-o,--output", p->output, "Output CSV (default: standard output)")
      ->check(file_to_write());
  predict->callback([p, global] {
    configure_logging(global->verbosity);
    run_space_predict(*p);
  });

  auto e = std::make_shared<SpaceQueryOptions>();
  auto* evaluate = cmd.add_subcommand(
      "evaluate", "Score a space's predictions against judgments (agreement, z-test, Pearson r)");
  evaluate->add_option("space", e->space_file, "space.json")->required()->check(CLI::ExistingFile);
  evaluate->add_option("judgments", e->queries, "Judgments to predict")
      ->required()
      ->check(CLI::ExistingFile);
  evaluate->add_option("--catalog", e->catalog, "Place unjudged tools from this catalog")
      ->check(CLI::ExistingFile);
  evaluate->add_option("-o,--output", e->output, "Write the scores as JSON")
      ->check(file_to_write());
  evaluate->callback([e, global] {
    configure_logging(global->verbosity);
    run_space_evaluate(*e);
  });

  auto m = std::make_shared<SpaceEmbedOptions>();
  auto* embed =
      cmd.add_subcommand("embed", "Place every catalog tool in a space from its descriptors");
  embed->add_option("space", m->space_file, "space.json fitted with --descriptors")
      ->required()
      ->check(CLI::ExistingFile);
  embed->add_option("catalog", m->catalog, "Catalog")->required()->check(CLI::ExistingFile);
  embed->add_option("-o,--output", m->output, "Output CSV (default: standard output)")
      ->check(file_to_write());
  embed->add_option("--plot", m->plot, "PNG of the space with the placed tools")
      ->check(file_to_write());
  embed->add_option("--predicted", m->predicted,
                    "Predictions (`nibrig predict -o`) to place beside the catalog's tools")
      ->check(CLI::ExistingFile);
  embed->callback([m, global] {
    configure_logging(global->verbosity);
    run_space_embed(*m);
  });
}

void add_design(CLI::App& cmd, const std::shared_ptr<const GlobalOptions>& global) {
  auto s = std::make_shared<SpaceSynthOptions>();
  auto* synth = cmd.add_subcommand(
      "synth", "Synthetic validation (Fig. 10): recover random spaces from simulated experiments");
  synth->footer(
      "Each trial: a random truth, a Thurstonian observer, the paper's two-stage experiment (half "
      "the\n"
      "triplets twice, 60 ties ten times), a fit, alignment by Procrustes. --compare also runs the\n"
      "adaptive design (expected information gain) against two-stage at equal numbers of trials.");
  synth->add_option("--dims", s->dims, "Dimensions (default 1,2,3,4,5)")
      ->delimiter(',')
      ->check(whole_in_range(1, model::space::kMostSpaceDims, "a number of dimensions"));
  synth->add_option("--trials", s->trials, "Random truths per dimension (default 100)")
      ->check(whole_in_range(1, 100000, "a number of trials"));
  synth->add_option("--stimuli", s->stimuli, "Stimuli (default 15)")
      ->check(whole_in_range(3, 200, "a number of stimuli"));
  synth->add_option("--starts", s->starts, "Fit starts (default 4)")
      ->check(whole_in_range(1, 1000, "a number of starts"));
  synth->add_option("--seed", s->seed, "Seed (default 1)")->check(any_seed());
  synth->add_flag("--all-judgments", s->all_judgments,
                  "Fit every answer, not the paper's selection (stage 2 + non-tied stage 1)");
  synth->add_flag("--compare", s->compare, "Also compare adaptive and two-stage designs");
  synth->add_option("--budgets", s->budgets, "Trial budgets compared (default 500,1000,1966)")
      ->delimiter(',')
      ->check(whole_in_range(1, 1000000, "a number of trials"));
  synth->add_option("--compare-trials", s->compare_trials, "Truths per budget (default 20)")
      ->check(whole_in_range(1, 100000, "a number of trials"));
  synth->add_option("-o,--output", s->output, "Write the results as JSON")
      ->check(file_to_write());
  synth->add_option("--plots", s->plots, "Folder for the recovery chart (synthetic_recovery.png)");
  synth->callback([s, global] {
    configure_logging(global->verbosity);
    run_space_synth(*s, worker_threads(*global));
  });

  auto p = std::make_shared<SpacePlanOptions>();
  auto* plan = cmd.add_subcommand("plan", "Trial lists of the two-stage experiment (Sec. 4.2)");
  plan->footer(
      "Stage 1: INPUT is a text file of stimulus names, one per line; a random FRACTION of all\n"
      "triplets, each REPETITIONS times (default 2), random order, left/right balanced. Stage 2: "
      "INPUT\n"
      "is the answered stage-1 list; its ties (|count_a - count_b| <= 1) are repeated (default 10\n"
      "times, at most --max-triplets of them). Lists: trial,stage,reference,left,right,chosen.");
  plan->add_option("input", p->input, "Stimulus list (stage 1) or answered stage-1 list")
      ->required()
      ->check(CLI::ExistingFile);
  plan->add_option("--stage", p->stage, "1 or 2 (default 1)")
      ->check(whole_in_range(1, 2, "a stage"));
  plan->add_option("--repetitions", p->repetitions, "Presentations per triplet")
      ->check(whole_in_range(1, 1000, "a number of repetitions"));
  plan->add_option("--fraction", p->fraction, "Share of all triplets in stage 1 (default 0.5)")
      ->check(in_range(1e-9, 1.0, "a fraction"));
  plan->add_option("--max-triplets", p->max_triplets, "Ties repeated in stage 2 (default 60)")
      ->check(whole_in_range(1, 1000000, "a number of triplets"));
  plan->add_option("--seed", p->seed, "Seed (default 1)")->check(any_seed());
  plan->add_option("-o,--output", p->output, "Trial list to write")
      ->required()
      ->check(file_to_write());
  plan->callback([p, global] {
    configure_logging(global->verbosity);
    run_space_plan(*p);
  });

  auto m = std::make_shared<SpaceMergeOptions>();
  auto* merge =
      cmd.add_subcommand("merge", "Answered trial lists -> judgments (reference,a,b,count_a,count_b)");
  merge->add_option("lists", m->lists, "Answered lists: stage 1, then stage 2")
      ->required()
      ->check(CLI::ExistingFile);
  merge->add_flag("--all-judgments", m->all_judgments,
                  "Keep every answer (default: stage 2 and the stage-1 triplets that were no tie)");
  merge->add_option("-o,--output", m->output, "Judgments CSV to write")
      ->required()
      ->check(file_to_write());
  merge->callback([m, global] {
    configure_logging(global->verbosity);
    run_space_merge(*m);
  });
}

}  // namespace

void add_space_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* cmd = app.add_subcommand(
      "space", "Perceptual space: fit, validate, predict, evaluate and place tools");
  cmd->require_subcommand(1);
  cmd->footer(
      "Judgments: our CSV (reference,a,b,count_a,count_b[,observer]), the Lagunas et al. 2019 JSON "
      "or\n"
      "the Salmon responses CSV, told apart by content. The model (Sec. 4): P(a closer to the\n"
      "reference than b) = Phi(-2/3 (|Q_a - Q_r| - |Q_b - Q_r|)), one unit = 75 % preference.");
  add_fit(*cmd, global);
  add_validate(*cmd, global);
  add_queries(*cmd, global);
  add_design(*cmd, global);
}

}  // namespace nibrig::ui::cli
