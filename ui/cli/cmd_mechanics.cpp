// `nibrig mechanics modes|ringdown`: a design (or an inline bar, or a mesh file) → its modes,
// damping, participation at tip and sensor and frequency response; a ring-down trace → E and λ.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <iostream>
#include <sstream>

#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/beam_theory.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/mode_report.hpp"
#include "model/mechanics/ring_down.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/modal/frequency_response.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/mechanics_figures.hpp"
#include "ui/cli/mechanics_report.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

namespace mech = model::mechanics;

constexpr const char* kDefaultMaterial = "VeroClear-Piovarci2018";

struct StylusOptions {
  std::filesystem::path design;  // design.json or a mesh file
  std::vector<double> bar;       // LENGTH,WIDTH,THICKNESS
  double clamp = 0.030;
  bool no_cutout = false;
  std::string material;
  int modes = 0;         // 0: the design's
  double mesh_size = 0;  // 0: the design's
  double unit_scale = 0.001;
  std::vector<double> tip, tip_direction, sensor, sensor_axis, clamp_box;
  std::filesystem::path materials;
};

struct ModesOptions {
  StylusOptions design;
  std::filesystem::path output, plots;
  bool no_plots = false;
};

struct RingDownCommandOptions {
  std::filesystem::path trace;
  StylusOptions design;
  double preload = 0.05;
  bool calibrated = false;
  std::filesystem::path output, plots;
  bool no_plots = false;
};

Eigen::Vector3d vector3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// Eigen leaves a zero vector as it is when normalising: the force or sensor would then point
// nowhere and every participation would read 0.
Eigen::Vector3d direction(const std::vector<double>& v, const char* option) {
  const Eigen::Vector3d d = vector3(v);
  if (!(d.norm() > 0))
    throw std::invalid_argument(std::string(option) + " 0,0,0: expected a direction, not zero");
  return d.normalized();
}

mech::MaterialTable load_materials(const StylusOptions& o) {
  return mech::read_material_table(o.materials.empty() ? model::io::default_materials() : o.materials);
}

mech::Design design_from(const StylusOptions& o, const mech::MaterialTable& materials) {
  mech::Design design;
  if (!o.bar.empty()) {
    if (!o.design.empty())
      throw std::invalid_argument("give either a design file or --bar, not both");
    mech::BarGeometry bar;
    bar.length = o.bar[0], bar.width = o.bar[1], bar.thickness = o.bar[2];
    bar.clamp_length = o.clamp;
    bar.end_radius = 0.0;  // an inline bar is plain: square end
    bar.cutout = !o.no_cutout;
    design = mech::bar_design(
        bar, materials.find(o.material.empty() ? kDefaultMaterial : o.material).name);
  } else if (o.design.empty()) {
    throw std::invalid_argument(
        "give a design file (design.json or a mesh) or --bar LENGTH,WIDTH,THICKNESS");
  } else if (o.design.extension() == ".json") {
    design = mech::read_design(o.design, materials);
    if (!o.material.empty())
      for (auto& [region, name] : design.region_materials) name = materials.find(o.material).name;
  } else {
    if (o.tip.empty() || o.sensor.empty())
      throw std::invalid_argument(o.design.string() +
                                  ": a mesh file needs --tip X,Y,Z and --sensor X,Y,Z (metres)");
    mech::MeshFileShape shape{std::filesystem::absolute(o.design), o.unit_scale, std::nullopt};
    if (!o.clamp_box.empty())
      shape.clamp_box =
          std::make_pair(Eigen::Vector3d(o.clamp_box[0], o.clamp_box[1], o.clamp_box[2]),
                         Eigen::Vector3d(o.clamp_box[3], o.clamp_box[4], o.clamp_box[5]));
    design.name = o.design.stem().string();
    design.shape = shape;
    design.region_materials["body"] =
        materials.find(o.material.empty() ? kDefaultMaterial : o.material).name;
    design.tip.point = vector3(o.tip);
    design.sensor.point = vector3(o.sensor);
    if (!o.tip_direction.empty()) design.tip.direction = direction(o.tip_direction, "--tip-direction");
    if (!o.sensor_axis.empty()) design.sensor.direction = direction(o.sensor_axis, "--sensor-axis");
  }
  if (o.modes > 0) design.modes = o.modes;
  if (o.mesh_size > 0) design.mesh_size = o.mesh_size;
  return design;
}

// A mesh file's regions take the design's one material (build_design_model).
mech::DesignModel build(const mech::Design& design, const mech::MaterialTable& materials) {
  spdlog::info("{}: meshing at {:.2f} mm and solving for {} modes", design.name,
               design.mesh_size * 1e3, design.modes);
  mech::DesignModel model = mech::build_design_model(design, materials);
  if (model.damping_source == "none (undamped)")
    spdlog::warn("{}: no damping in the design or its material; damping ratios are 0", design.name);
  spdlog::info(
      "{}: {} nodes, {} elements, {} free DOFs; meshing {:.2f} s, assembly {:.2f} s, modes {:.2f} "
      "s",
      design.name, model.mesh.nodes.cols(), model.mesh.tets.size(), model.free_dofs,
      model.seconds.meshing_s, model.seconds.assembly_s, model.seconds.modes_s);
  return model;
}

std::string modes_table(const mech::DesignModel& m) {
  std::ostringstream out;
  const auto& material = mech::body_material(m);
  out << m.design.name << ": " << material.name << " (E " << material.youngs_modulus / 1e9
      << " GPa, density " << material.density << " kg/m^3), damping alpha " << m.damping.mass
      << " 1/s, lambda " << m.damping.stiffness << " s from " << m.damping_source << "\n";
  out << m.mesh.nodes.cols() << " nodes, " << m.mesh.tets.size() << " quadratic tetrahedra, "
      << m.free_dofs << " free DOFs\n";
  std::vector<double> beam;
  if (const auto* bar = std::get_if<mech::BarGeometry>(&m.design.shape);
      bar && !bar->cutout && bar->end_radius == 0)
    beam = mech::cantilever_bending_frequencies(material.youngs_modulus, material.density,
                                                bar->free_length(), bar->width, bar->thickness, 6);
  char line[160];
  std::snprintf(line, sizeof line, "%4s %12s %10s %12s %12s\n", "mode", "freq (Hz)", "zeta",
                "tip b", "sensor c");
  out << line;
  for (std::size_t i = 0; i < m.modal.size(); ++i) {
    std::snprintf(line, sizeof line, "%4zu %12.4f %10.5f %12.4g %12.4g\n", i + 1,
                  m.modal.omega[i] / (2 * M_PI), m.modal.zeta[i], m.modal.input[i],
                  m.modal.output[i]);
    out << line;
  }
  if (!beam.empty()) {
    out << "Euler-Bernoulli bending (thickness direction) for comparison:";
    for (double f : beam) out << " " << f;
    out << " Hz\n";
  }
  return out.str();
}

std::filesystem::path plot_folder(const std::filesystem::path& plots,
                                  const std::filesystem::path& output) {
  if (!plots.empty()) return plots;
  if (!output.empty())
    return output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
  return ".";
}

void run_modes(const ModesOptions& o) {
  const auto materials = load_materials(o.design);
  const mech::DesignModel model = build(design_from(o.design, materials), materials);
  std::cout << modes_table(model);
  if (!o.output.empty()) {
    ensure_folder(o.output.parent_path());
    mech::write_mode_report(o.output, model);
    say_wrote(o.output);
  }
  if (!o.no_plots) {
    const auto png =
        plot_folder(o.plots, o.output) / (file_stem(model.design.name) + "_frequency_response.png");
    ensure_folder(png.parent_path());
    plot_frequency_responses({{model.design.name, model.modal}},
                             "Frequency response: " + model.design.name, png);
    say_wrote(png);
  }
}

void run_ring_down(const RingDownCommandOptions& o) {
  const auto materials = load_materials(o.design);
  const model::io::AccelerationTrace trace = model::io::read_acceleration_trace(o.trace);
  const mech::DesignModel model = build(design_from(o.design, materials), materials);
  mech::RingDownOptions fit_options;
  fit_options.reference_modulus = mech::body_material(model).youngs_modulus;
  fit_options.preload = o.preload;
  fit_options.mass_damping = model.damping.mass;
  fit_options.fit_gain = !o.calibrated;
  const mech::RingDownFit fit = mech::fit_ring_down(model.modal, fit_options, trace);
  std::printf("Young's modulus     %.4g GPa\n", fit.youngs_modulus / 1e9);
  std::printf("Rayleigh stiffness  %.4g s (mass term held at %.4g 1/s)\n", fit.rayleigh_stiffness,
              fit_options.mass_damping);
  std::printf("first mode          %.4f Hz, damping ratio %.5f\n", fit.first_mode_hz,
              fit.first_mode_damping_ratio);
  std::printf("release at          %.4f s into the trace\n", fit.release_time);
  std::printf("gain                %.4f%s\n", fit.gain,
              o.calibrated ? " (calibrated trace: fixed)" : "");
  std::printf("residual            %.2f %% of the trace's RMS (%d simulations)\n",
              100 * fit.relative_residual, fit.evaluations);
  const std::string stem = file_stem(o.trace.stem().string());
  if (!o.output.empty()) {
    write_json_file(o.output, {{"design", model.design.name},
                             {"trace", o.trace.string()},
                             {"sample_rate_hz", trace.sample_rate_hz},
                             {"preload", o.preload},
                             {"youngs_modulus", fit.youngs_modulus},
                             {"rayleigh_stiffness", fit.rayleigh_stiffness},
                             {"rayleigh_mass", fit_options.mass_damping},
                             {"release_time", fit.release_time},
                             {"gain", fit.gain},
                             {"relative_residual", fit.relative_residual},
                             {"first_mode_hz", fit.first_mode_hz},
                             {"first_mode_damping_ratio", fit.first_mode_damping_ratio},
                             {"reference_modulus", fit_options.reference_modulus}});
    say_wrote(o.output);
  }
  if (!o.no_plots) {
    const auto png = plot_folder(o.plots, o.output) / (stem + "_ring_down.png");
    ensure_folder(png.parent_path());
    plot_ring_down(trace.acceleration_m_s2, "measured", fit.fitted, trace.sample_rate_hz,
                   "Ring-down: " + model.design.name + ", E " +
                       std::to_string(fit.youngs_modulus / 1e9).substr(0, 5) + " GPa",
                   png);
    say_wrote(png);
  }
}

void add_design_options(CLI::App* cmd, StylusOptions& o, bool positional) {
  if (positional)
    cmd->add_option("design", o.design, "design.json, or a mesh file (.msh, .stl, .step)");
  cmd->add_option("--bar", o.bar,
                  "Plain bar inline instead of a design: LENGTH,WIDTH,THICKNESS in metres")
      ->expected(3)
      ->delimiter(',')
      ->check(stylus_metres("a bar length").application_index(0))
      ->check(stylus_metres("a bar width").application_index(1))
      ->check(stylus_metres("a bar thickness").application_index(2));
  cmd->add_option("--clamp", o.clamp, "With --bar: clamped length in metres (default 0.03)")
      ->check(stylus_metres("a clamped length"));
  cmd->add_flag("--no-cutout", o.no_cutout,
                "With --bar: no hole (default: the paper's R5 hole 10 mm from the end)");
  cmd->add_option(
      "--material", o.material,
      "Material of every region (a name in the material table; default for --bar and meshes: "
      "VeroClear-Piovarci2018)");
  cmd->add_option("--modes", o.modes, "Number of modes (default: the design's; 12 for --bar)")
      ->check(whole_in_range(1, 1000, "a number of modes"));
  cmd->add_option("--mesh-size", o.mesh_size, "Element size in metres (default: the design's)")
      ->check(stylus_metres("an element size"));
  cmd->add_option("--materials", o.materials,
                  "Material table (default: the bundled assets/materials.json)")
      ->check(CLI::ExistingFile);
  // A file unit above a metre is no CAD unit; 1000 is mm-per-m typed the wrong way round.
  cmd->add_option("--unit-scale", o.unit_scale,
                  "Mesh files: metres per file unit (default 0.001, millimetres)")
      ->check(stylus_metres("a file unit"));
  cmd->add_option("--tip", o.tip, "Mesh files: tip point X,Y,Z in metres")
      ->expected(3)
      ->delimiter(',')
      ->check(in_range(-10, 10, "a coordinate in metres"));
  cmd->add_option("--tip-direction", o.tip_direction,
                  "Mesh files: tip force direction (default 0,0,1)")
      ->expected(3)
      ->delimiter(',')
      ->check(in_range(-1e6, 1e6, "a direction component"));
  cmd->add_option("--sensor", o.sensor, "Mesh files: sensor point X,Y,Z in metres")
      ->expected(3)
      ->delimiter(',')
      ->check(in_range(-10, 10, "a coordinate in metres"));
  cmd->add_option("--sensor-axis", o.sensor_axis, "Mesh files: sensor axis (default 0,0,1)")
      ->expected(3)
      ->delimiter(',')
      ->check(in_range(-1e6, 1e6, "a direction component"));
  cmd->add_option("--clamp-box", o.clamp_box,
                  "Mesh files: clamp every node in XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX (metres); .msh "
                  "files may instead "
                  "carry a physical group \"clamp\"")
      ->expected(6)
      ->delimiter(',')
      ->check(in_range(-10, 10, "a coordinate in metres"));
}

}  // namespace

void add_mechanics_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* cmd =
      app.add_subcommand("mechanics", "Stylus mechanics: modes, frequency response, ring-down fit");
  cmd->require_subcommand(1);
  cmd->footer(
      "A design (design.json: see model/io/FORMATS.md, \"Stylus design\") is meshed with quadratic "
      "tetrahedra "
      "(Gmsh),\n"
      "its lowest modes are found (Spectra, shift-invert), damped with Rayleigh damping, and read "
      "at\n"
      "the tip (where the surface force acts) and the sensor (where acceleration is measured).");

  auto modes = std::make_shared<ModesOptions>();
  auto* modes_cmd = cmd->add_subcommand(
      "modes", "Modes, damping, tip/sensor participation and frequency response");
  modes_cmd->footer(
      "Prints the modes (frequency, damping ratio, participation b at the tip and c at the "
      "sensor)\n"
      "and writes a PNG of the frequency response from tip force to sensor acceleration (1-500 "
      "Hz).\n"
      "-o FILE writes material.youngs_modulus, material.density, free_length, width, "
      "thickness\n"
      "(bars), modes[].frequency (Hz) and modes[].damping_ratio, and the frequency response.\n"
      "Example: nibrig mechanics modes --bar 0.21,0.02,0.002 --clamp 0.03 --no-cutout --material "
      "steel");
  add_design_options(modes_cmd, modes->design, true);
  modes_cmd->add_option("-o,--output", modes->output, "Write the results as JSON")
      ->check(file_to_write());
  modes_cmd->add_option("--plots", modes->plots, "Folder for the PNG (default: beside -o, or .)");
  modes_cmd->add_flag("--no-plots", modes->no_plots, "Do not write the PNG");
  modes_cmd->callback([modes, global] {
    configure_logging(global->verbosity);
    run_modes(*modes);
  });

  auto ring = std::make_shared<RingDownCommandOptions>();
  auto* ring_cmd = cmd->add_subcommand(
      "ringdown", "Fit Young's modulus and Rayleigh damping to a ring-down trace");
  ring_cmd->footer(
      "The test of the paper's Sec. 5.1: the design is clamped, its tip pushed aside by --preload "
      "and\n"
      "released; <trace> is the sensor's acceleration (CSV time_s,acceleration_m_s2, a mono WAV\n"
      "from an audio input, or a session folder). Fits E (all regions scaled together) and the Rayleigh stiffness term, with the "
      "release\n"
      "time and, unless --calibrated, the sensor gain; writes a PNG of measured vs simulated (Fig. "
      "11).");
  ring_cmd->add_option("trace", ring->trace, "Acceleration trace: CSV, mono WAV or session folder")
      ->required();
  ring_cmd->add_option("design", ring->design.design, "design.json or mesh file");
  add_design_options(ring_cmd, ring->design, false);
  ring_cmd->add_option("--preload", ring->preload,
                       "Tip displacement before release, metres (default 0.05)")
      ->check(stylus_metres("a tip displacement"));
  ring_cmd->add_flag("--calibrated", ring->calibrated,
                     "The trace is m/s^2 along the sensor axis: do not fit a gain");
  ring_cmd->add_option("-o,--output", ring->output, "Write the fit as JSON")
      ->check(file_to_write());
  ring_cmd->add_option("--plots", ring->plots, "Folder for the PNG (default: beside -o, or .)");
  ring_cmd->add_flag("--no-plots", ring->no_plots, "Do not write the PNG");
  ring_cmd->callback([ring, global] {
    configure_logging(global->verbosity);
    run_ring_down(*ring);
  });
}

}  // namespace nibrig::ui::cli
