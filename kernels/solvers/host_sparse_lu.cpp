// Eigen's SparseLU behind solvers::HostSparseLU (host_sparse_lu.hpp: why this is a compiled unit).
#include "solvers/host_sparse_lu.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <limits>
#include <stdexcept>
#include <string>

namespace polymech::solvers {

struct HostSparseLU::Impl {
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
};

HostSparseLU::HostSparseLU() = default;
HostSparseLU::~HostSparseLU() = default;
HostSparseLU::HostSparseLU(HostSparseLU&&) noexcept = default;
HostSparseLU& HostSparseLU::operator=(HostSparseLU&&) noexcept = default;

void HostSparseLU::factor(std::int64_t n, const std::vector<std::int64_t>& rows, const std::vector<std::int64_t>& cols,
                          const std::vector<double>& values) {
  impl_.reset();
  n_ = 0;
  if (n <= 0 || n > std::numeric_limits<int>::max())
    throw std::invalid_argument("HostSparseLU: matrix size " + std::to_string(n) + " outside 1 .. 2^31 - 1");
  if (rows.size() != cols.size() || rows.size() != values.size())
    throw std::invalid_argument("HostSparseLU: " + std::to_string(rows.size()) + " rows, " +
                                std::to_string(cols.size()) + " columns and " + std::to_string(values.size()) +
                                " values given for the entries");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (rows[k] < 0 || rows[k] >= n || cols[k] < 0 || cols[k] >= n)
      throw std::invalid_argument("HostSparseLU: entry (" + std::to_string(rows[k]) + ", " + std::to_string(cols[k]) +
                                  ") outside the " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
    entries.emplace_back(static_cast<int>(rows[k]), static_cast<int>(cols[k]), values[k]);
  }
  Eigen::SparseMatrix<double> a(static_cast<int>(n), static_cast<int>(n));
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  auto impl = std::make_unique<Impl>();
  impl->lu.compute(a);
  if (impl->lu.info() != Eigen::Success)
    throw std::runtime_error("HostSparseLU: the " + std::to_string(n) + " x " + std::to_string(n) +
                             " matrix could not be factorised (" + impl->lu.lastErrorMessage() + ")");
  impl_ = std::move(impl);
  n_ = n;
}

void HostSparseLU::solve(double* x) const {
  if (!impl_) throw std::logic_error("HostSparseLU: solve() before a successful factor()");
  Eigen::Map<Eigen::VectorXd> v(x, static_cast<Eigen::Index>(n_));
  const Eigen::VectorXd e = impl_->lu.solve(v);
  v = e;
}

}  // namespace polymech::solvers
