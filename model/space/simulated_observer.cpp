#include "model/space/simulated_observer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::model::space {

double rms_distance_difference(const Eigen::MatrixXd& q) {
  const Eigen::Index n = q.cols();
  double sum = 0.0;
  std::size_t count = 0;
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index a = 0; a < n; ++a)
      for (Eigen::Index b = a + 1; b < n; ++b) {
        if (a == r || b == r) continue;
        const double d = (q.col(a) - q.col(r)).norm() - (q.col(b) - q.col(r)).norm();
        sum += d * d;
        ++count;
      }
  return count ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
}

Eigen::MatrixXd random_space(std::size_t dims, std::size_t stimuli, std::mt19937_64& generator,
                             double rms_difference) {
  if (dims < 1) throw std::invalid_argument("a random space needs at least one dimension");
  if (stimuli < 3) throw std::invalid_argument("a random space needs at least 3 stimuli");
  if (!(rms_difference > 0) || !std::isfinite(rms_difference))
    throw std::invalid_argument("the RMS distance difference of a random space must be positive");
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd q(static_cast<Eigen::Index>(dims), static_cast<Eigen::Index>(stimuli));
  for (Eigen::Index i = 0; i < q.size(); ++i) q.data()[i] = normal(generator);
  const double current = rms_distance_difference(q);
  // Only a degenerate draw (all points equidistant) has no difference at all; never in practice.
  if (!(current > 0)) throw std::runtime_error("random space: degenerate draw");
  return q * (rms_difference / current);
}

Eigen::MatrixXd space_from_descriptors(const Eigen::MatrixXd& descriptors, double rms_difference) {
  if (descriptors.rows() < 3 || descriptors.cols() < 1)
    throw std::invalid_argument("a space from descriptors needs at least 3 stimuli and a descriptor");
  if (!descriptors.allFinite()) throw std::invalid_argument("descriptors must be finite");
  const Eigen::RowVectorXd mean = descriptors.colwise().mean();
  Eigen::MatrixXd q = (descriptors.rowwise() - mean).transpose();  // descriptors × stimuli
  for (Eigen::Index d = 0; d < q.rows(); ++d) {
    const double sd = std::sqrt(q.row(d).squaredNorm() / static_cast<double>(q.cols() - 1));
    if (!(sd > 0))
      throw std::invalid_argument("descriptor " + std::to_string(d) +
                                  " is the same for every stimulus");
    q.row(d) /= sd;
  }
  return q * (rms_difference / rms_distance_difference(q));
}

SimulatedObserver::SimulatedObserver(Eigen::MatrixXd truth, double scale)
    : SimulatedObserver(std::move(truth), [scale] {
        JudgmentModel paper;
        paper.scale = scale;
        return paper;
      }()) {}

SimulatedObserver::SimulatedObserver(Eigen::MatrixXd truth, JudgmentModel model)
    : truth_(std::move(truth)), model_(std::move(model)) {
  if (truth_.cols() < 3 || truth_.rows() < 1)
    throw std::invalid_argument("a simulated observer needs a space with at least 3 stimuli");
  if (!(model_.scale > 0)) throw std::invalid_argument("the Thurstone scale must be positive");
  if (model_.log_noise.size() > 0 && model_.log_noise.size() != truth_.cols())
    throw std::invalid_argument("a simulated observer's model needs a noise per stimulus of its space");
}

double SimulatedObserver::probability_first(std::size_t reference, std::size_t a,
                                            std::size_t b) const {
  return space::probability_first(model_, truth_, reference, a, b);
}

bool SimulatedObserver::chooses_first(std::size_t reference, std::size_t a, std::size_t b,
                                      std::mt19937_64& generator) const {
  return std::bernoulli_distribution(probability_first(reference, a, b))(generator);
}

std::vector<Choice> SimulatedObserver::answer(const std::vector<Trial>& trials,
                                              std::mt19937_64& generator) const {
  const auto n = static_cast<std::size_t>(truth_.cols());
  std::vector<Choice> choices;
  choices.reserve(trials.size());
  for (const Trial& t : trials) {
    if (t.reference >= n || t.left >= n || t.right >= n)
      throw std::invalid_argument("simulated observer: a trial names a stimulus beyond the " +
                                  std::to_string(n) + " of the space");
    choices.push_back(chooses_first(t.reference, t.left, t.right, generator) ? Choice::left
                                                                             : Choice::right);
  }
  return choices;
}

}  // namespace nibrig::model::space
