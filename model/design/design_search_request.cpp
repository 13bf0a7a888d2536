#include "model/design/design_search_request.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "model/design/grid_guided_search.hpp"
#include "model/design/printability.hpp"
#include "model/numeric/cancellation.hpp"

namespace nibrig::model::design {

namespace {

using Field = DesignSearchField;

[[noreturn]] void refuse(Field field, const DesignSearchNames& names, const std::string& why) {
  throw DesignSearchRefused(field, names(field) + ": " + why);
}

// check_constraints on the part of the constraints one field holds, one field after another, so
// that its message (in the face's names) comes with the field at fault.
void check_constraint_fields(const DesignConstraints& c, const DesignSearchNames& names) {
  const ConstraintNames as{names(Field::min_tip), names(Field::max_tip), names(Field::cost),
                           names(Field::max_cost)};
  const auto part = [&](Field field, const DesignConstraints& only) {
    try {
      check_constraints(only, as);
    } catch (const std::invalid_argument& e) {
      throw DesignSearchRefused(field, e.what());
    }
  };
  DesignConstraints only;
  only.min_tip_m = c.min_tip_m;
  part(Field::min_tip, only);
  only = {};
  only.max_tip_m = c.max_tip_m;
  part(Field::max_tip, only);
  only.min_tip_m = c.min_tip_m;
  part(Field::min_tip, only);  // the smallest tip above the largest
  only = {};
  only.materials = c.materials;
  part(Field::allow, only);
  only = {};
  only.cost = c.cost;
  part(Field::cost, only);
  part(Field::max_cost, c);  // what is left: the limit, and a limit without costs
}

}  // namespace

DesignSearchRefused::DesignSearchRefused(Field field, const std::string& what)
    : std::invalid_argument(what), field_(field) {}

const char* field_name(DesignSearchField field) {
  switch (field) {
    case Field::targets:
      return "targets";
    case Field::surface:
      return "surface";
    case Field::space:
      return "space";
    case Field::aim:
      return "aim";
    case Field::between:
      return "between";
    case Field::mix:
      return "mix";
    case Field::min_tip:
      return "min_tip_mm";
    case Field::max_tip:
      return "max_tip_mm";
    case Field::allow:
      return "allow";
    case Field::cost:
      return "cost";
    case Field::max_cost:
      return "max_cost";
    case Field::printer:
      return "printer";
  }
  return "?";
}

space::GroupAim parse_group_aim(const std::string& words, const DesignSearchNames& names) {
  if (words == "largest") return space::GroupAim::largest;
  if (words == "mean") return space::GroupAim::mean;
  refuse(Field::aim, names, "'" + words + "' is not largest or mean");
}

const char* group_aim_name(space::GroupAim aim) {
  return aim == space::GroupAim::mean ? "mean" : "largest";
}

DesignSearch::DesignSearch(DesignSearchRequest request, const DesignSearchNames& names)
    : request_(std::move(request)), names_(names) {
  const auto& r = request_;
  check_constraint_fields(r.constraints, names);
  if (r.surface.empty())
    refuse(Field::surface, names, "none given: expected the surface the stylus is for");
  if (r.between) {
    const auto& [a, b] = *r.between;
    try {
      feasible_segment(a, b,
                       r.constraints);  // names the constraint that leaves nothing of the line
    } catch (const std::invalid_argument& e) {
      refuse(Field::between, names, e.what());
    }
    if (r.printer)
      if (const std::string why = unprintable_line(*r.printer, a, b); !why.empty())
        refuse(Field::printer, names, why);
  } else {
    if (r.first_material.empty() || r.second_material.empty() ||
        r.first_material == r.second_material)
      refuse(Field::mix, names,
             "'" + r.first_material + "' and '" + r.second_material +
                 "': expected two different materials");
    // The allowed materials and the cost limit hold alike at every tip: whether any mix is left
    // is known now (the tips are checked against the fitted ones once the model is loaded).
    DesignConstraints mix_only = r.constraints;
    mix_only.min_tip_m.reset(), mix_only.max_tip_m.reset();
    const auto pure = [](const std::string& material) {
      DesignPoint p;
      p.mix = {{material, 1.0}};
      p.tip_diameter_m = 0.002;
      return p;
    };
    try {
      feasible_segment(pure(r.first_material), pure(r.second_material), mix_only);
    } catch (const std::invalid_argument& e) {
      refuse(Field::mix, names,
             "no mix of " + r.first_material + " and " + r.second_material +
                 " is allowed: " + e.what());
    }
  }
  if (!r.targets) refuse(Field::targets, names, "none given");
  targets_ = r.targets();
  if (!targets_.descriptor_map)
    refuse(Field::space, names,
           "has no descriptor map: designs are placed from their predicted descriptors (fit the "
           "space with them)");
  if (targets_.placements.empty())
    refuse(Field::targets, names, "none given: expected at least one target");
  if (targets_.names.size() != targets_.placements.size())
    refuse(Field::targets, names,
           fmt::format("{} names for {} targets: expected one each", targets_.names.size(),
                       targets_.placements.size()));
  const auto dims = targets_.descriptor_map->coefficients.rows();
  for (std::size_t t = 0; t < targets_.placements.size(); ++t)
    if (targets_.placements[t].mean.size() != dims)
      refuse(Field::targets, names,
             fmt::format("'{}' lies in {} dimensions, the space in {}", targets_.names[t],
                         targets_.placements[t].mean.size(), dims));
}

void DesignSearch::check_surface(const forcing::ForcingModel& model) const {
  if (model.surface_forcing.contains(request_.surface)) return;
  std::string surfaces;
  for (const auto& [name, forcing] : model.surface_forcing)
    surfaces += (surfaces.empty() ? "" : ", ") + name;
  refuse(
      Field::surface, names_,
      "'" + request_.surface + "' is not a surface of the forcing model (it has " + surfaces + ")");
}

DesignSearchOutcome DesignSearch::run(const PredictionInputs& inputs, std::stop_token stop,
                                      const SearchProgress& progress) const {
  const auto& model = inputs.model;
  check_surface(model);
  const Predict predict = [&setup = inputs.setup, surface = request_.surface](
                              const DesignPoint& p) { return predict_tool(setup, p, surface); };
  return run(predict, model.tip_log_gain.begin()->first, model.tip_log_gain.rbegin()->first, stop,
             progress);
}

DesignSearchOutcome DesignSearch::run(const PredictionInputs& inputs,
                                      const DesignResponseGrid& grid, std::stop_token stop,
                                      const SearchProgress& progress) const {
  check_surface(inputs.model);
  const auto& r = request_;
  const auto& axes = grid.axes;
  auto mixed_by_grid = [&](const std::string& material) {
    return material == axes.material_a || material == axes.material_b;
  };
  if (r.between) {
    for (const DesignPoint* end : {&r.between->first, &r.between->second})
      for (const auto& share : end->mix)
        if (!mixed_by_grid(share.material))
          refuse(Field::between, names_,
                 to_string(*end) + " is not a mix of the design grid's " + axes.material_a +
                     " and " + axes.material_b);
  } else if (!mixed_by_grid(r.first_material) || !mixed_by_grid(r.second_material)) {
    refuse(Field::mix, names_,
           r.first_material + " and " + r.second_material + " are not the design grid's " +
               axes.material_a + " and " + axes.material_b);
  }
  const auto start = std::chrono::steady_clock::now();
  DesignSearchOutcome out = run(grid_predictor(inputs.setup, grid, r.surface), axes.tips_m.front(),
                                axes.tips_m.back(), stop, progress);
  const Evaluate by_fem = group() ? distance_to_targets(inputs.setup, r.surface, descriptor_map(),
                                                        targets_.placements, r.aim)
                                  : distance_to_target(inputs.setup, r.surface, descriptor_map(),
                                                       targets_.placements.front());
  GuidedSearch guided = guide_by_fem(std::move(out.result), inputs.setup, grid, r.surface,
                                     descriptor_map(), by_fem, 0, stop);
  out.result = std::move(guided.result);
  out.fem_solved = std::move(guided.fem_solved);
  out.grid_error = guided.grid_error;
  out.fem_solves = guided.fem_solves;
  out.how += " through the design grid";
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

DesignSearchOutcome DesignSearch::run(const Predict& predict, double min_tip_m, double max_tip_m,
                                      std::stop_token stop, const SearchProgress& progress) const {
  const auto& r = request_;
  const Evaluate distance =
      group() ? distance_to_targets(predict, descriptor_map(), targets_.placements, r.aim)
              : distance_to_target(predict, descriptor_map(), targets_.placements.front());
  DesignSearchOutcome out;
  // Every candidate passes here: counted, logged, and the one place a stop is seen.
  const Evaluate counted = [&](const DesignPoint& p) {
    numeric::throw_if_cancelled(stop, "design search");
    auto c = distance(p);
    spdlog::debug("{}: distance {:.3f}", to_string(p), c.distance);
    ++out.evaluations;
    return c;
  };
  const auto start = std::chrono::steady_clock::now();
  if (r.between) {
    LineSearchOptions line;
    line.constraints = r.constraints;
    out.result = line_search(r.between->first, r.between->second, counted, line, progress);
    out.how =
        "along the line " + to_string(r.between->first) + " -> " + to_string(r.between->second);
    if (const auto last = static_cast<std::size_t>(line.scan_points - 1);
        out.result.evaluated.size() > last)
      out.line_ends = {0, last};
  } else {
    RangeSearchOptions range;
    range.first_material = r.first_material, range.second_material = r.second_material;
    range.min_tip_m = min_tip_m, range.max_tip_m = max_tip_m;
    range.constraints = r.constraints;
    out.result = range_search(counted, range, progress);
    out.how = fmt::format("over {} to {} x tips {:g}-{:g} mm", r.first_material, r.second_material,
                          min_tip_m * 1e3, max_tip_m * 1e3);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace nibrig::model::design
