// The piecewise cubic Hermite curves of the forcing model's tip and material scaling factors
// (Sec. 5.2: knots every 50 Hz over 0-500 Hz). Tangents are finite differences of the knot values
// (Catmull-Rom inside, one-sided at the two ends), so a curve's value at any frequency is a fixed
// linear combination of its knot values: the weights below. That linearity is what makes the fit of
// Eq. 10 a linear least-squares problem; PCHIP's monotone limiter (Fritsch-Carlson) would make the
// tangents, and so the fit, nonlinear in the knot values.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace nibrig::model::forcing {

// 0, 50, …, 500 Hz: the paper's eleven control points.
std::vector<double> default_knot_frequencies();

// The nonzero weights w_k(x) with curve(x) = Σ_k w_k(x)·value_k, as (knot index, weight) pairs in
// ascending knot order (at most four: the two knots of x's interval and, through the tangents,
// their outer neighbours). Knots must be at least two and strictly increasing; x must lie within
// [knots.front(), knots.back()] (the model is not extrapolated). Throws std::invalid_argument
// otherwise.
std::vector<std::pair<std::size_t, double>> hermite_weights(std::span<const double> knots,
                                                            double x);

// Σ_k w_k(x)·values[k]; values has one entry per knot.
double hermite_value(std::span<const double> knots, std::span<const double> values, double x);

}  // namespace nibrig::model::forcing
