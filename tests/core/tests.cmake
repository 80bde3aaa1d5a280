# Unit tests of the deck machinery in signorini::core: ParameterTools (validation, --set
# overrides, --print-parameters) and Expression (muParser expressions of x, y, t).
signorini_add_gtest(core_tests
  SOURCES core/ParameterToolsTest.cpp core/ExpressionTest.cpp
  LIBS signorini::core
  NPS 1
  TIMEOUT 60
  LABELS core)
