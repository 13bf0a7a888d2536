#include "ui/cli/demo_mechanics.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <optional>
#include <random>
#include <sstream>

#include "model/modal/tip_driven_modes.hpp"
#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/beam_theory.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/mode_report.hpp"
#include "model/mechanics/ring_down.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/numeric/parallel_for.hpp"
#include "ui/cli/mechanics_figures.hpp"
#include "ui/cli/mechanics_report.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {
namespace {

namespace mech = model::mechanics;

void bar_against_beam_theory(const mech::MaterialTable& materials, const std::filesystem::path& dir,
                             std::ostringstream& summary, nlohmann::json& numbers) {
  // The paper's material, and the same with ν = 0: a 3-D bar with ν > 0 is held against
  // anticlastic bending at its clamp and comes out about 1 % stiffer than beam theory; with ν = 0
  // Euler-Bernoulli is its exact thin limit, so that row shows the discretisation error alone.
  mech::Material paper = materials.find("VeroClear-Piovarci2018");
  mech::Material no_poisson = paper;
  no_poisson.name = "VeroClear-Piovarci2018, nu = 0";
  no_poisson.poisson_ratio = 0.0;
  const mech::MaterialTable table({paper, no_poisson});

  mech::Design design;
  design.name = "plain bar";
  mech::BarGeometry bar;
  bar.cutout = false;
  bar.end_radius = 0;
  design.shape = bar;
  design.tip = mech::default_tip(bar);
  design.sensor = mech::default_sensor(bar);
  design.modes = 10;
  const auto beam = mech::cantilever_bending_frequencies(
      paper.youngs_modulus, paper.density, bar.free_length(), bar.width, bar.thickness, 3);
  nlohmann::json meshes = nlohmann::json::array();
  std::ostringstream csv;
  csv << "poisson_ratio,mesh_size_mm,nodes,free_dofs,f1_hz,f2_hz,f3_hz,f1_error,f2_error,f3_"
         "error\n";
  summary << "  plain 180 x 20 x 2 mm cantilever, Euler-Bernoulli " << std::setprecision(4)
          << beam[0] << ", " << beam[1] << ", " << beam[2] << " Hz; FEM (quadratic tetrahedra):\n";
  // The six meshes solved side by side (Gmsh itself is serialised inside build_design_model); the
  // rows are written in order afterwards.
  const std::array<const mech::Material*, 2> poisson_cases{&no_poisson, &paper};
  const std::array<double, 3> sizes{0.008, 0.004, 0.002};
  std::vector<std::array<double, 3>> fem_hz(poisson_cases.size() * sizes.size());
  std::vector<std::pair<long, long>> counts(fem_hz.size());  // nodes, free DOFs
  model::numeric::parallel_for(fem_hz.size(), 0, [&](std::size_t n) {
    mech::Design case_design = design;
    case_design.region_materials["body"] = poisson_cases[n / sizes.size()]->name;
    case_design.mesh_size = sizes[n % sizes.size()];
    const auto model = mech::build_design_model(case_design, table);
    const auto f = model::modal::tip_driven_frequencies_hz(model.modal, 3);
    std::copy_n(f.begin(), 3, fem_hz[n].begin());
    counts[n] = {static_cast<long>(model.mesh.nodes.cols()), static_cast<long>(model.free_dofs)};
  });
  for (std::size_t n = 0; n < fem_hz.size(); ++n) {
    const mech::Material& material = *poisson_cases[n / sizes.size()];
    const double size = sizes[n % sizes.size()];
    const auto& f = fem_hz[n];
    csv << material.poisson_ratio << ',' << size * 1e3 << ',' << counts[n].first << ','
        << counts[n].second;
    for (double x : f) csv << ',' << x;
    std::vector<double> errors;
    for (std::size_t k = 0; k < 3; ++k) errors.push_back((f[k] - beam[k]) / beam[k]);
    for (double e : errors) csv << ',' << e;
    csv << '\n';
    meshes.push_back({{"poisson_ratio", material.poisson_ratio},
                      {"mesh_size_mm", size * 1e3},
                      {"free_dofs", counts[n].second},
                      {"fem_hz", f},
                      {"relative_error", errors}});
    summary << "    nu " << material.poisson_ratio << ", " << size * 1e3 << " mm elements ("
            << counts[n].second << " DOFs): " << f[0] << ", " << f[1] << ", " << f[2] << " Hz ("
            << std::showpos << 100 * (f[0] - beam[0]) / beam[0] << " %, "
            << 100 * (f[1] - beam[1]) / beam[1] << " %, " << 100 * (f[2] - beam[2]) / beam[2]
            << " %)" << std::noshowpos << "\n";
  }
  write_text_file(dir / "cantilever_convergence.csv", csv.str());
  numbers["cantilever"] = {{"euler_bernoulli_hz", beam}, {"meshes", meshes}};
}

void paper_bar_ring_down(const mech::MaterialTable& materials, const std::filesystem::path& dir,
                         std::ostringstream& summary, nlohmann::json& numbers) {
  mech::Design design = mech::read_design(model::io::asset("designs/paper_bar.json"), materials);
  const auto bar = mech::build_design_model(design, materials);
  mech::write_mode_report(dir / "paper_bar.json", bar);

  // The paper publishes its fitted values but not its trace: a trace simulated at those values,
  // with 3 % sensor noise, stands in for it and is fitted from the datasheet modulus.
  const double rate = 1000.0;
  model::io::AccelerationTrace trace{rate,
                                     mech::simulate_release(bar.modal, 0.05, rate, 4000, 0.2)};
  mech::add_relative_noise(trace.acceleration_m_s2, 0.03, 2018);
  model::io::write_acceleration_trace(dir / "paper_bar_ring_down_simulated.csv", trace);

  mech::Design start = design;
  start.region_materials["body"] = "VeroClear";  // the datasheet modulus as the starting point
  const auto reference = mech::build_design_model(start, materials);
  mech::RingDownOptions options;
  options.reference_modulus = materials.find("VeroClear").youngs_modulus;
  const auto fit = mech::fit_ring_down(reference.modal, options, trace);
  plot_ring_down(trace.acceleration_m_s2, "simulated trace, 3 % noise", fit.fitted, rate,
                 "Paper bar ring-down (simulated trace, 3 % noise) and the fitted model",
                 dir / "paper_bar_ring_down.png");
  summary << std::setprecision(4) << "  paper bar (rounded end, R5 hole): first modes "
          << bar.modal.omega[0] / (2 * M_PI) << ", " << bar.modal.omega[1] / (2 * M_PI)
          << " Hz; ring-down fit on a "
          << "SIMULATED trace (the paper's is not published): E " << fit.youngs_modulus / 1e9
          << " GPa, lambda " << fit.rayleigh_stiffness << " s (paper: 0.45 GPa, 0.00125 s)\n";
  numbers["paper_bar"] = {
      {"first_modes_hz", {bar.modal.omega[0] / (2 * M_PI), bar.modal.omega[1] / (2 * M_PI)}},
      {"simulated_trace", true},
      {"fitted_youngs_modulus_gpa", fit.youngs_modulus / 1e9},
      {"fitted_rayleigh_stiffness_s", fit.rayleigh_stiffness}};
}

void stylus_responses(const mech::MaterialTable& materials, const std::filesystem::path& dir,
                      std::ostringstream& summary, nlohmann::json& numbers, bool progress_bar) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(model::io::asset("designs")))
    if (e.path().filename().string().rfind("stylus_", 0) == 0) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  // Solved side by side; reported in file order.
  std::vector<mech::Design> designs;
  for (const auto& file : files) designs.push_back(mech::read_design(file, materials));
  std::vector<std::optional<mech::DesignModel>> solved(designs.size());
  std::optional<Progress> progress;
  if (progress_bar) progress.emplace("stylus designs", designs.size());
  model::numeric::parallel_for(designs.size(), 0, [&](std::size_t n) {
    solved[n] = mech::build_design_model(designs[n], materials);
    if (progress) progress->advance(designs[n].name);
  });
  std::vector<std::pair<std::string, model::modal::ModalModel>> models;
  for (std::size_t n = 0; n < designs.size(); ++n) {
    const auto& design = designs[n];
    const auto& model = *solved[n];
    mech::write_mode_report(dir / (file_stem(design.name) + ".json"), model);
    summary << "  " << design.name << ": first mode " << std::setprecision(4)
            << model.modal.omega[0] / (2 * M_PI) << " Hz (damping ratio " << model.modal.zeta[0]
            << "), " << model.free_dofs << " DOFs, "
            << model.seconds.meshing_s + model.seconds.assembly_s + model.seconds.modes_s << " s\n";
    numbers["stylus_designs"].push_back({{"name", design.name},
                                         {"first_mode_hz", model.modal.omega[0] / (2 * M_PI)},
                                         {"damping_ratio", model.modal.zeta[0]},
                                         {"free_dofs", model.free_dofs}});
    models.emplace_back(design.name, model.modal);
  }
  plot_frequency_responses(models, "Bundled stylus designs: tip force to sensor acceleration",
                           dir / "stylus_frequency_responses.png");
}

}  // namespace

DemoSection run_mechanics_demo(const std::filesystem::path& report, bool progress_bar) {
  const auto dir = report / "mechanics";
  ensure_folder(dir);
  const auto materials = mech::read_material_table(model::io::default_materials());
  std::ostringstream summary;
  summary << "mechanics (Sec. 5.1): " << dir.string()
          << "/ (cantilever_convergence.csv, paper_bar*.{json,csv,png}, stylus JSON, "
             "stylus_frequency_responses.png)\n";
  DemoSection section;
  bar_against_beam_theory(materials, dir, summary, section.numbers);
  paper_bar_ring_down(materials, dir, summary, section.numbers);
  stylus_responses(materials, dir, summary, section.numbers, progress_bar);
  section.text = summary.str();
  return section;
}

}  // namespace nibrig::ui::cli
