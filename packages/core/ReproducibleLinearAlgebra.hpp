#pragma once
/// \file ReproducibleLinearAlgebra.hpp
/// Matrix applies and dot products whose bits do not depend on the number of ranks (reproducible
/// arithmetic, docs/reproducibility.md), and the switches that use them only when
/// core::reproducibleArithmetic() is on.
#include <array>
#include <vector>

#include "signorini/core/Types.hpp"

namespace signorini::core {

/// Y = A X with every row summed so that its bits depend only on the values of A and X, not on the
/// column map or the number of ranks (X is imported to the column map first when A has an importer).
/// A matrix whose local graph has a canonical row order (registerCanonicalRowOrder) is summed row
/// by row in that order, left to right; any other matrix by exact pre-rounded row sums (the sum of
/// a row's products is then independent of their order, at about 3 times the cost).
void applyCanonical(const CrsMatrix& A, const Vector& X, Vector& Y);

/// Y(:, c) = A X(:, c) for the columns c in \p columns (1 to 3 distinct ones; X and Y distinct, with
/// the same number of columns at a constant stride; Y's other columns are left alone), each with
/// exactly the bits applyCanonical gives that column alone. X is imported once (collective). With a
/// registered order the columns share one sweep over the matrix (each entry and its place in the
/// order read once); otherwise they are applied one after the other.
void applyCanonicalColumns(const CrsMatrix& A, const MultiVector& X, MultiVector& Y, const std::vector<int>& columns);

/// Gives the rows of \p A, and of every matrix built on the same local graph arrays and column map
/// (a discretisation's M, K, step matrix and estimator operators), a partition-independent order:
/// each row's entries sorted by the keys of their columns. \p ownedKeys holds one key per owned
/// row (the domain map equals the row map), the same for the same unknown on any partition (a
/// node's coordinates on a fine grid, then its component); the column keys are imported. Collective.
/// Nothing is registered if two entries of a row have one key (applyCanonical then uses exact row
/// sums). The order lives as long as the graph arrays (checked on each registration).
void registerCanonicalRowOrder(const CrsMatrix& A, const std::vector<std::array<long long, 3>>& ownedKeys);
/// Whether applyCanonical sums \p A's rows in a registered order (for tests).
bool hasCanonicalRowOrder(const CrsMatrix& A);

/// y = A x: applyCanonical under reproducibleArithmetic(), Tpetra's apply otherwise.
void apply(const CrsMatrix& A, const Vector& x, Vector& y);
/// a . b over all ranks: a reproducible sum under reproducibleArithmetic(), Tpetra's dot otherwise.
double dot(const Vector& a, const Vector& b);

}  // namespace signorini::core
