// Uses an installed signorini library: evaluates a deck expression. Types.hpp (Tpetra, Kokkos and
// MPI headers; C++17) checks that the package passes on the include paths, flags and standard.
#include <cmath>
#include <cstdio>

#include <signorini/core/Expression.hpp>
#include <signorini/core/Types.hpp>
#include <signorini/io/DeckReader.hpp>  // includes core's Types.hpp from another package's folder

int main() {
  static_assert(std::is_same_v<signorini::Scalar, double>);
  signorini::core::Expression g("sin(pi*y) - 1.05", "consumer");
  const double v = g(1.0, 0.5, 0.0);
  std::printf("g(1, 0.5) = %g\n", v);
  return std::abs(v + 0.05) < 1e-14 ? 0 : 1;
}
