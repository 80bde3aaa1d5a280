#include "signorini/core/ReproducibleSum.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace signorini::core {

namespace {
bool reproducible = false;
}

void setReproducibleArithmetic(bool on) { reproducible = on; }
bool reproducibleArithmetic() { return reproducible; }

namespace detail {

void maxAll(const Comm& comm, int count, double* values) {
  double global[32];
  SIGNORINI_ASSERT(count <= 32, "maxAll: too many values");
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, count, values, global);
  for (int k = 0; k < count; ++k) values[k] = global[k];
}

void sumAll(const Comm& comm, int count, double* values) {
  double global[32];
  SIGNORINI_ASSERT(count <= 32, "sumAll: too many values");
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, count, values, global);
  for (int k = 0; k < count; ++k) values[k] = global[k];
}

}  // namespace detail
}  // namespace signorini::core
