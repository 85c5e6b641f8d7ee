#pragma once
// Linear least squares for the calibration's small problems (a handful of
// unknowns, tens of equations).

#include <vector>

namespace capsim::sim {

// Minimises |A x - b|^2 over x >= 0 (every unknown non-negative). A has one
// row per equation, each of the same length n (1 to 16 unknowns). Exact for
// small n: the optimum is the unconstrained least-squares solution on its
// support, so every subset of unknowns is solved (Householder QR) and the best
// one whose solution is non-negative is kept. Unknowns whose columns are all
// zero come out 0. Throws std::invalid_argument for ragged or empty input.
std::vector<double> nonnegative_least_squares(const std::vector<std::vector<double>>& a,
                                              const std::vector<double>& b);

}  // namespace capsim::sim
