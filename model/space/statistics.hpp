// The small statistics the validation of a space reports (Sec. 4.5, 6.1): Pearson and Spearman
// correlation with their p-values, and the z-test of an agreement count against chance.
#pragma once

#include <cstddef>
#include <vector>

namespace nibrig::model::space {

struct Correlation {
  double r = 0.0;
  double p_value = 1.0;  // two-sided, against r = 0 (Student t with n − 2 degrees of freedom)
  std::size_t n = 0;
};

// Throws std::invalid_argument for lengths that differ, fewer than 3 pairs, or a constant series.
Correlation pearson(const std::vector<double>& x, const std::vector<double>& y);
// Pearson of the ranks (ties get their mean rank); the p-value uses the same t approximation.
Correlation spearman(const std::vector<double>& x, const std::vector<double>& y);

struct AgreementTest {
  double agreements = 0.0;  // may hold halves (a prediction of exactly 0.5 counts as half right)
  double trials = 0.0;
  double fraction = 0.0;
  double z = 0.0;        // (k − n/2) / √(n/4): the normal approximation of Binomial(n, ½)
  double p_value = 1.0;  // one-sided: P(Z ≥ z), better than chance
};

AgreementTest agreement_test(double agreements, double trials);

}  // namespace nibrig::model::space
