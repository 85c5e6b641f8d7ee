#pragma once
// Real roots of polynomials of degree at most 4, for the quartic surfaces of
// turned ellipses (tori). No closed form: the closed-form quartic loses most
// of its digits near double roots. Instead each polynomial's roots are
// isolated between the roots of its derivative (found the same way, down to
// the exact quadratic), where it is monotonic, and found there by bisection
// safeguarded Newton steps to the last bit. Deterministic, no tolerances.

#include <array>

namespace capsim {

// The polynomial c[0] + c[1] t + ... + c[degree] t^degree.
struct Polynomial {
  std::array<double, 5> c{};
  int degree = 0;
  double operator()(double t) const;
  Polynomial derivative() const;
};

// The real roots, ascending, written to `roots`; returns how many (at most
// the degree). A root of even multiplicity that the polynomial only touches
// is returned when the polynomial is exactly 0 there, else missed (a line
// grazing a surface). Leading zero coefficients lower the degree.
int real_roots(const Polynomial& p, std::array<double, 4>& roots);

}  // namespace capsim
