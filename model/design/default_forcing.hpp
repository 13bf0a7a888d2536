// The forcing model designs are predicted with when no model file is given: Eq. 10 fitted to the
// catalog's printed tools (fit_forcing_for_prediction), their designs simulated at a resolution the
// caller chooses (by default the demo's). Computed once per key, since every design is meshed and
// solved, and kept in the user cache.
#pragma once

#include "model/design/cached_default.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/user_cache.hpp"

namespace nibrig::model::design {

// Bumped whenever the fit or the forcing file changes what a key's file holds.
inline constexpr int kDefaultForcingVersion = 1;

// The demo's designs: 32 modes on a 4 mm mesh (the template's finer mesh changes the responses by
// less than the fit's residual and takes several times longer).
inline constexpr int kDefaultForcingModes = 32;
inline constexpr double kDefaultForcingMeshSize = 0.004;  // m

// The designs' resolution: modes per design and element size in metres; 0 takes the stylus
// design's own.
struct ForcingResolution {
  int modes = kDefaultForcingModes;
  double mesh_size = kDefaultForcingMeshSize;
};

// The fit's inputs for these options: catalog, stylus design and materials (empty: bundled), at
// `resolution`.
forcing::ForcingInputOptions default_forcing_inputs(const DefaultsOptions& options,
                                                    const ForcingResolution& resolution = {});

// Every input the model depends on: the key format version, the catalog's, stylus design's,
// materials' and the bundled threshold curve's bytes (the fit weighs its held-out descriptor errors
// by the bundled curve whatever options.threshold_curve says), the modes and the mesh size.
// Throws std::runtime_error naming an input file that cannot be read.
io::CacheKey default_forcing_key(const DefaultsOptions& options = {},
                                 const ForcingResolution& resolution = {});

// <cache>/default_forcing-<key>.json when it is there and reads as a forcing model; else the
// designs are simulated (step "designs simulated", announced with total 0 until the first design
// says how many) and the model fitted (step "forcing fit", 0 then 1 of 1), and written there
// atomically. A cache file that does not read is computed again, with a warning. Throws what
// load_forcing_inputs throws, and numeric::Cancelled (checked after each design and around the
// fit), leaving no file behind. `each_design`, when given, also hears of every design solved.
Cached<forcing::ForcingModel> default_forcing_model(
    const DefaultsOptions& options = {}, const ForcingResolution& resolution = {},
    const forcing::DesignProgress& each_design = {});

}  // namespace nibrig::model::design
