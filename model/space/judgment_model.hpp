// How a perceptual space turns distances into triplet judgments. The paper's model (Sec. 4, Eq. 1):
// Thurstone case V, P(a closer to r) = Φ(s·(‖Q_b−Q_r‖ − ‖Q_a−Q_r‖)), one noise for every stimulus.
// Beside it, the parts a fit may add, each chosen only where it predicts unseen judgments better
// (space validate, space fit --model auto):
// - the link: logistic (heavier tails than probit's: a confidently wrong answer costs less), or
//   Student-t kernels as t-STE uses (van der Maaten & Weinberger 2012),
//   P(a) = K(x_a)/(K(x_a)+K(x_b)), K(x) = (1 + x²/α)^−(α+1)/2 with α = dims − 1 (at least 1),
//   x = s·distance;
// - a lapse rate ε: a share of answers given at random, P' = ε/2 + (1−ε)·P;
// - a noise per stimulus σ_i = e^{η_i} (the paper notes that pencils and charcoal wear and are
//   judged less consistently): a triplet's distances are divided by
//   σ_t = √((σ_r² + σ_a² + σ_b²)/3), with a weak prior η_i ~ N(0, 0.5²) that keeps a rarely
//   judged stimulus's noise near the others'.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace nibrig::model::space {

// s = 2/3 makes one unit of distance difference 75 % preference (Φ(2/3) = 0.748), the scale of the
// authors' released code; the paper's Eq. 2 is a garbled fast approximation of Φ (ARCHITECTURE.md,
// "Science notes").
inline constexpr double kThurstoneScale = 2.0 / 3.0;

enum class Link { probit, logistic, student_t };

// What a fit chooses: the link and which parts it fits beside the coordinates.
struct ModelFamily {
  Link link = Link::probit;
  bool lapse = false;           // a fitted share of answers at random
  bool stimulus_noise = false;  // a fitted noise per stimulus
  bool operator==(const ModelFamily&) const = default;
};

inline constexpr ModelFamily kPaperModel{};

// "probit", "logistic", "student-t", each optionally followed by "+lapse" and then "+noise".
std::string family_name(const ModelFamily& family);
// Throws std::invalid_argument naming the text and the names that exist.
ModelFamily parse_family(const std::string& name);
// The twelve families (three links × lapse or not × noise or not), the paper's first.
std::vector<ModelFamily> every_family();

// The prior's sd on η_i = log σ_i.
inline constexpr double kNoisePriorSd = 0.5;
// The logistic link's z is multiplied by this so that its slope at 0 matches the probit's closely
// over the range that matters (1.702: the classic scaled-logistic approximation of Φ, |Δ| < 0.01).
inline constexpr double kLogisticSlope = 1.702;

// A model's values: the family, the scale, and the fitted lapse and noises.
struct JudgmentModel {
  ModelFamily family;
  double scale = kThurstoneScale;
  double lapse = 0.0;         // ε in [0, 0.5)
  Eigen::VectorXd log_noise;  // η per stimulus; empty: every σ_i = 1
};

// The family and its fitted parts in words, for a person reading a report or a window:
// "logistic+lapse+noise, lapse 0.043, noise per stimulus 0.71 to 1.52 (sigma, 1 = typical)".
std::string describe_model(const JudgmentModel& model);

// A family's cross-validated predictions of held-out judgments (what a choice of model rests on).
struct ModelScore {
  std::string family;
  double log_loss = 0.0;  // mean −log P(answer given) per held-out response, nats
  double majority_agreement = 0.0, individual_agreement = 0.0;
  double mean_error = 0.0;  // mean |p_predicted − p_observed| over held-out triplets
};

// Far out, Student-t kernels judge by the ratio of the two distances alone, so a space fitted with
// them can grow without bound at no cost to the likelihood; with a lapse it did (Lagunas, 3-D: an
// RMS radius of 297 units against 3.7 without the lapse, at a worse optimum). A weak prior N(0,
// 10²) on every coordinate closes that direction where none is given; a fitted space of the usual
// few units' radius pays a few nats for it against tens of thousands of likelihood.
inline constexpr double kStudentCoordinatePriorSd = 10.0;

// The Student-t kernel's α for a space of `dims` dimensions (t-STE's choice).
double student_degrees_of_freedom(std::size_t dims);

// One triplet's negative log-likelihood, −(n_a log P'(a) + n_b log P'(b)), from the two distances
// to the reference and the triplet's log σ_t, with its derivatives when `gradient` is given:
// ∂/∂d_a, ∂/∂d_b, ∂/∂log σ_t, ∂/∂ε (0 at ε = 0: no lapse fitted). Finite for every finite input
// (log Φ and softplus in their tails).
struct TripletGradient {
  double distance_a = 0.0, distance_b = 0.0, log_sigma = 0.0, lapse = 0.0;
};
double triplet_negative_log_likelihood(const JudgmentModel& model, std::size_t dims,
                                       double distance_a, double distance_b, double log_sigma,
                                       double count_a, double count_b, TripletGradient* gradient);

// P(a judged closer to the reference than b), lapse included.
double probability_first(const JudgmentModel& model, std::size_t dims, double distance_a,
                         double distance_b, double log_sigma);
// The same for stimuli of a space (columns of q, dims × stimuli); their noises are the model's when
// it has them (then q has one column per noise).
double probability_first(const JudgmentModel& model, const Eigen::MatrixXd& q,
                         std::size_t reference, std::size_t a, std::size_t b);
// log σ_t of a triplet of the space's stimuli (0 without per-stimulus noise).
double triplet_log_sigma(const JudgmentModel& model, std::size_t reference, std::size_t a,
                         std::size_t b);
// log σ_t for stimuli the space has no noise for (placed from descriptors): the typical noise,
// e^{mean η}.
double typical_log_sigma(const JudgmentModel& model);

}  // namespace nibrig::model::space
