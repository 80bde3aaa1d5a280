#pragma once
/// \file ReproducibleLinearAlgebra.hpp
/// Matrix applies and dot products whose bits do not depend on the number of ranks (reproducible
/// arithmetic, docs/reproducibility.md), and the switches that use them only when
/// core::reproducibleArithmetic() is on.
#include "Types.hpp"

namespace signorini::core {

/// Y = A X with every row summed in a partition-independent order: the products of a row sorted
/// by value, then added left to right. Its bits depend only on the values of A and X, not on the
/// column map or the number of ranks (X is imported to the column map first when A has an importer).
void applyCanonical(const CrsMatrix& A, const Vector& X, Vector& Y);

/// y = A x: applyCanonical under reproducibleArithmetic(), Tpetra's apply otherwise.
void apply(const CrsMatrix& A, const Vector& x, Vector& y);
/// a . b over all ranks: a reproducible sum under reproducibleArithmetic(), Tpetra's dot otherwise.
double dot(const Vector& a, const Vector& b);

}  // namespace signorini::core
