#pragma once
/// \file ProblemData.hpp
/// The deck's "Problem" sublist: material, data functions (muParser expressions in x, y, t)
/// and the roles of the named boundary segments (DESIGN 1.1).
#include <optional>
#include <string>

#include "BoundarySegments.hpp"
#include "Expression.hpp"
#include "ParameterTools.hpp"

namespace signorini::fem {

struct ProblemData {
  /// Valid "Problem" parameters.
  static core::ParameterList getValidParameters();
  /// Reads a validated "Problem" sublist; resolves segment names against \p segments.
  /// Throws core::UserError naming the key for an expression that does not parse or an unknown segment.
  ProblemData(const core::ParameterList& p, const mesh::BoundarySegments& segments);

  double density = 1.0;    ///< rho [mass / area]
  double stiffness = 1.0;  ///< kappa [force] (wave speed sqrt(kappa / rho))
  core::Expression bodyForce, initialDisplacement, initialVelocity, neumannData, obstacle;
  std::optional<core::Expression> exactSolution;
  bool hasObstacle = true;
  unsigned dirichletMask = 0, contactMask = 0, neumannMask = 0;
  double waveSpeed() const;
};

}  // namespace signorini::fem
