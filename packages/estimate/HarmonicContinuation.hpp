#pragma once
/// \file HarmonicContinuation.hpp
/// s1 = ||w||_{1/2, Gamma_C} of the paper's Remark 4.1 for nodal boundary data w on Gamma_C,
/// evaluated as the H^1 norm of the discrete harmonic continuation: the minimiser d of
/// ||v||_1^2 = int |grad v|^2 + v^2 over the Q1 functions with v = w at the contact nodes and
/// v = 0 at the Dirichlet nodes of \p scalar. Every extension of w bounds s1 from above, so an
/// iterative solve approaches s1 from above.
#include <functional>
#include <vector>

#include "Q1Assembler.hpp"

namespace signorini::estimate {

/// \param scalar    a scalar Q1 assembler on the mesh; its Dirichlet nodes hold v = 0
/// \param contact   flags on the overlap nodes of Gamma_C (where v = w)
/// \param boundary  w at the owned nodes (zero away from Gamma_C)
/// \param solveSPD  solves A x = b for an SPD matrix (x holds the initial guess)
double harmonicContinuationNorm(const fem::Q1Assembler& scalar, const std::vector<char>& contact, const Vector& boundary,
                                const std::function<void(const RCP<const CrsMatrix>&, const Vector&, Vector&)>& solveSPD);

}  // namespace signorini::estimate
