# Unit tests of the deck machinery in signorini::core: ParameterTools (validation, --set
# overrides, --print-parameters), Expression (muParser expressions of x, y, t) and PhaseTimers.
signorini_add_gtest(core_tests
  SOURCES core/ParameterToolsTest.cpp core/ExpressionTest.cpp core/PhaseTimersTest.cpp
  LIBS signorini::core
  NPS 1
  TIMEOUT 60
  LABELS core)
# Reproducible global sums on 1-3 ranks (bitwise the same for any distribution of the terms).
signorini_add_gtest(reproducible_sum_tests
  SOURCES core/ReproducibleSumTest.cpp
  LIBS signorini::core
  NPS 1 2 3
  TIMEOUT 60
  LABELS core)
