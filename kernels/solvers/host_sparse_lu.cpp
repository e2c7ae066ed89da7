// Eigen's SparseLU behind solvers::HostSparseLU (host_sparse_lu.hpp: why this is a compiled unit).
#include "solvers/host_sparse_lu.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <limits>
#include <stdexcept>
#include <string>

namespace polymech::solvers {

namespace {

template <class S>
using EigenLU = Eigen::SparseLU<Eigen::SparseMatrix<S>, Eigen::COLAMDOrdering<int>>;

// Checks the entries, builds the matrix and factorises it into lu (the name says which class reports).
template <class S, class V = S>
void factor_into(const char* name, EigenLU<S>& lu, std::int64_t n, const std::vector<std::int64_t>& rows,
                 const std::vector<std::int64_t>& cols, const std::vector<V>& values) {
  const std::string who = name;
  if (n <= 0 || n > std::numeric_limits<int>::max())
    throw std::invalid_argument(who + ": matrix size " + std::to_string(n) + " outside 1 .. 2^31 - 1");
  if (rows.size() != cols.size() || rows.size() != values.size())
    throw std::invalid_argument(who + ": " + std::to_string(rows.size()) + " rows, " + std::to_string(cols.size()) +
                                " columns and " + std::to_string(values.size()) + " values given for the entries");
  std::vector<Eigen::Triplet<S>> entries;
  entries.reserve(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (rows[k] < 0 || rows[k] >= n || cols[k] < 0 || cols[k] >= n)
      throw std::invalid_argument(who + ": entry (" + std::to_string(rows[k]) + ", " + std::to_string(cols[k]) +
                                  ") outside the " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
    entries.emplace_back(static_cast<int>(rows[k]), static_cast<int>(cols[k]), static_cast<S>(values[k]));
  }
  Eigen::SparseMatrix<S> a(static_cast<int>(n), static_cast<int>(n));
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  lu.compute(a);
  if (lu.info() != Eigen::Success)
    throw std::runtime_error(who + ": the " + std::to_string(n) + " x " + std::to_string(n) +
                             " matrix could not be factorised (" + lu.lastErrorMessage() + ")");
}

template <class S>
void solve_in_place(const EigenLU<S>& lu, std::int64_t n, S* x) {
  Eigen::Map<Eigen::Matrix<S, Eigen::Dynamic, 1>> v(x, static_cast<Eigen::Index>(n));
  const Eigen::Matrix<S, Eigen::Dynamic, 1> e = lu.solve(v);
  v = e;
}

}  // namespace

struct HostSparseLU::Impl {
  EigenLU<double> lu;
  EigenLU<float> lu_single;  // factor(..., single = true)
  bool single = false;
};

HostSparseLU::HostSparseLU() = default;
HostSparseLU::~HostSparseLU() = default;
HostSparseLU::HostSparseLU(HostSparseLU&&) noexcept = default;
HostSparseLU& HostSparseLU::operator=(HostSparseLU&&) noexcept = default;

void HostSparseLU::factor(std::int64_t n, const std::vector<std::int64_t>& rows, const std::vector<std::int64_t>& cols,
                          const std::vector<double>& values, bool single) {
  impl_.reset();
  n_ = 0;
  auto impl = std::make_unique<Impl>();
  impl->single = single;
  if (single)
    factor_into("HostSparseLU", impl->lu_single, n, rows, cols, values);
  else
    factor_into("HostSparseLU", impl->lu, n, rows, cols, values);
  impl_ = std::move(impl);
  n_ = n;
}

void HostSparseLU::solve(double* x) const {
  if (!impl_) throw std::logic_error("HostSparseLU: solve() before a successful factor()");
  if (!impl_->single) {
    solve_in_place(impl_->lu, n_, x);
    return;
  }
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 1>> v(x, static_cast<Eigen::Index>(n_));
  const Eigen::VectorXf e = impl_->lu_single.solve(v.cast<float>());
  v = e.cast<double>();
}

struct HostSparseLUComplex::Impl {
  EigenLU<Complex> lu;
};

HostSparseLUComplex::HostSparseLUComplex() = default;
HostSparseLUComplex::~HostSparseLUComplex() = default;
HostSparseLUComplex::HostSparseLUComplex(HostSparseLUComplex&&) noexcept = default;
HostSparseLUComplex& HostSparseLUComplex::operator=(HostSparseLUComplex&&) noexcept = default;

void HostSparseLUComplex::factor(std::int64_t n, const std::vector<std::int64_t>& rows,
                                 const std::vector<std::int64_t>& cols, const std::vector<Complex>& values) {
  impl_.reset();
  n_ = 0;
  auto impl = std::make_unique<Impl>();
  factor_into("HostSparseLUComplex", impl->lu, n, rows, cols, values);
  impl_ = std::move(impl);
  n_ = n;
}

void HostSparseLUComplex::solve(Complex* x) const {
  if (!impl_) throw std::logic_error("HostSparseLUComplex: solve() before a successful factor()");
  solve_in_place(impl_->lu, n_, x);
}

}  // namespace polymech::solvers
