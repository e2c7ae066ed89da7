// solvers::HostSparseLU (the host LU behind ISPH's two-level preconditioner): an unsymmetric system solved
// to round-off, repeated entries summed, and every refusal (singular matrix, entries outside the matrix,
// inconsistent arrays, a solve before a factorisation) says why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "solvers/host_sparse_lu.hpp"

namespace sv = polymech::solvers;

namespace {
// 1D convection-diffusion, central differences (unsymmetric): -1.3 x_{i-1} + 2.5 x_i - 0.7 x_{i+1}; the
// diagonal given as two entries (1.0 + 1.5) that the factorisation must sum.
void convection_diffusion(std::int64_t n, std::vector<std::int64_t>& r, std::vector<std::int64_t>& c,
                          std::vector<double>& v) {
  for (std::int64_t i = 0; i < n; ++i) {
    r.push_back(i), c.push_back(i), v.push_back(1.0);
    r.push_back(i), c.push_back(i), v.push_back(1.5);
    if (i > 0) r.push_back(i), c.push_back(i - 1), v.push_back(-1.3);
    if (i + 1 < n) r.push_back(i), c.push_back(i + 1), v.push_back(-0.7);
  }
}
}  // namespace

TEST(HostSparseLU, SolvesAnUnsymmetricSystemToRoundOff) {
  const std::int64_t n = 200;
  std::vector<std::int64_t> r, c;
  std::vector<double> v;
  convection_diffusion(n, r, c, v);
  std::vector<double> x(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n), 0.0);
  for (std::int64_t i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = std::sin(0.1 * double(i)) + 0.01 * double(i);
  for (std::size_t k = 0; k < v.size(); ++k)
    b[static_cast<std::size_t>(r[k])] += v[k] * x[static_cast<std::size_t>(c[k])];
  sv::HostSparseLU lu;
  lu.factor(n, r, c, v);
  EXPECT_EQ(lu.size(), n);
  lu.solve(b.data());
  double err = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) err = std::max(err, std::abs(b[i] - x[i]));
  EXPECT_LT(err, 1e-12);
  // a moved-to factorisation solves the same way
  sv::HostSparseLU moved = std::move(lu);
  std::vector<double> e1(static_cast<std::size_t>(n), 0.0);
  e1[0] = 2.5;  // A e_0 has 2.5 in row 0 and -1.3 in row 1
  e1[1] = -1.3;
  moved.solve(e1.data());
  EXPECT_NEAR(e1[0], 1.0, 1e-13);
  EXPECT_NEAR(e1[1], 0.0, 1e-13);
}

TEST(HostSparseLU, RefusesWhatItCannotFactorise) {
  sv::HostSparseLU lu;
  std::vector<double> x(3, 1.0);
  EXPECT_THROW(lu.solve(x.data()), std::logic_error);
  // a zero row: singular
  try {
    lu.factor(3, {0, 1, 1}, {0, 0, 1}, {1.0, 2.0, 3.0});
    ADD_FAILURE() << "a singular matrix was factorised";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("could not be factorised"), std::string::npos) << e.what();
  }
  EXPECT_THROW(lu.solve(x.data()), std::logic_error);  // the failed factorisation left nothing to solve with
  EXPECT_THROW(lu.factor(2, {0, 2}, {0, 1}, {1.0, 1.0}), std::invalid_argument);     // row 2 of a 2 x 2
  EXPECT_THROW(lu.factor(2, {0, 1}, {0, -1}, {1.0, 1.0}), std::invalid_argument);    // column -1
  EXPECT_THROW(lu.factor(2, {0, 1}, {0, 1}, {1.0}), std::invalid_argument);          // one value for two entries
  EXPECT_THROW(lu.factor(0, {}, {}, {}), std::invalid_argument);                     // empty
  lu.factor(2, {0, 1}, {0, 1}, {2.0, 4.0});
  std::vector<double> y{1.0, 1.0};
  lu.solve(y.data());
  EXPECT_DOUBLE_EQ(y[0], 0.5);
  EXPECT_DOUBLE_EQ(y[1], 0.25);
}
