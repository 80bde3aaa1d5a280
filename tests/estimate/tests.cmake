# The residual error estimator (paper Sec. 4, DESIGN 1.3): exactness, localisation, rate,
# Laplacian on general quadrilaterals, s0/s1, and agreement of 1, 2 and 3 ranks.
signorini_add_gtest(estimate_tests SOURCES estimate/ResidualEstimatorTest.cpp estimate/ElasticityEstimatorTest.cpp
                   LIBS signorini::estimate NPS 1 2 3)
