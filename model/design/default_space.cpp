#include "model/design/default_space.hpp"

#include <stdexcept>

#include "model/io/bundled_assets.hpp"
#include "model/measure/descriptors.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::design {

namespace {

// The demo weighs five band counts; the 2-D study reads only the weighted mean, but a catalog
// handed to space_tools should say what the demo's says.
constexpr int kMaxBands = 5;

std::filesystem::path catalog_of(const DefaultsOptions& o) {
  return io::or_default(o.catalog, io::default_catalog);
}

std::filesystem::path threshold_of(const DefaultsOptions& o) {
  return io::or_default(o.threshold_curve, io::default_threshold_curve);
}

}  // namespace

space::SimulatedStudyOptions default_study_options(const DefaultsOptions& o) {
  space::SimulatedStudyOptions study;
  study.bootstrap_resamples = o.bootstrap_resamples;
  study.threads = o.threads;
  study.progress = o.progress;
  study.stop = o.stop;
  return study;
}

io::CacheKey default_space_key(const DefaultsOptions& o) {
  const space::SimulatedStudyOptions s = default_study_options(o);
  io::CacheKey key;
  key.add("nibrig default space").add(std::int64_t{kDefaultSpaceVersion});
  key.add_file(catalog_of(o)).add_file(threshold_of(o)).add(std::int64_t{kMaxBands});
  key.add(std::int64_t(s.stimuli.size()));
  for (const auto& name : s.stimuli) key.add(name);
  key.add(std::int64_t(s.dims)).add(s.lambda).add(std::int64_t(s.observer_seed));
  key.add(s.stage_one_fraction).add(std::int64_t{s.stage_one_repetitions});
  key.add(std::int64_t(s.stage_one_plan_seed)).add(std::int64_t{s.stage_two_repetitions});
  key.add(std::int64_t(s.stage_two_plan_seed)).add(std::int64_t(s.stage_two_triplets));
  key.add(std::int64_t{s.bootstrap_resamples});
  return key;
}

Cached<DefaultSpace> default_space(const DefaultsOptions& o) {
  DefaultSpace base;
  base.catalog_file = catalog_of(o);
  // Read first, so that a bad catalog or threshold curve fails before anything is computed.
  base.catalog = io::read_catalog(base.catalog_file);
  const auto threshold = measure::ThresholdCurve::load(threshold_of(o));
  measure::weigh_catalog_vibration(base.catalog, threshold, kMaxBands);
  const auto dir = o.cache_dir.empty() ? io::user_cache_dir() : o.cache_dir;
  const auto file = cache_file(dir, "default_space", default_space_key(o));

  return cached_default<DefaultSpace>(
      file, "default space",
      [&](const std::filesystem::path& f) {
        DefaultSpace d = base;
        d.space = space::read_space_file(f);
        // The key names the inputs; this catches a file that parses but is not the study's.
        const space::SimulatedStudyOptions study = default_study_options(o);
        if (d.space.stimuli != study.stimuli ||
            d.space.bootstrap_resamples != study.bootstrap_resamples || !d.space.descriptor_map)
          throw std::runtime_error(
              "not the default study's space (other stimuli, bootstrap count or no descriptor "
              "map)");
        return d;
      },
      [&] {
        DefaultSpace d = base;
        d.space = space::run_simulated_study(d.catalog, d.catalog_file, default_study_options(o))
                      .space;
        return d;
      },
      [](const std::filesystem::path& f, const DefaultSpace& d) {
        space::write_space_file(f, d.space);
      });
}

space::SpaceTools default_space_tools(const DefaultSpace& d) {
  return space::space_tools(d.space, d.catalog, d.catalog_file);
}

}  // namespace nibrig::model::design
