// The design searches' tests search objectives whose minimum is known: a candidate's distance is a
// given function of the DM85 fraction and the tip in mm, with no FEM and no space.
#pragma once

#include "model/design/design_search.hpp"

namespace nibrig::model::design::search_testing {

template <typename F>
Evaluate objective(F f) {
  return [f](const DesignPoint& p) {
    Candidate c;
    c.point = p;
    c.distance = f(p.fraction_of("DM85"), p.tip_diameter_m * 1e3);
    return c;
  };
}

}  // namespace nibrig::model::design::search_testing
