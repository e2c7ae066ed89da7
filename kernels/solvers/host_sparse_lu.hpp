// A sparse LU factorisation on the host behind an interface free of Eigen and Kokkos (Eigen's SparseLU
// with the COLAMD ordering, in host_sparse_lu.cpp).
//
// Why a compiled unit: under nvcc Eigen's SparseLU does not compile (its supernodal solve instantiates
// dense triangular solves marked __host__ __device__ that call host functions, error 20014-D; see
// docs/DEVELOPING.md). host_sparse_lu.cpp is compiled by the host compiler in every build (nvcc_wrapper
// --host-only in CUDA builds), so a caller in a CUDA translation unit (ISPH's two-level preconditioner,
// models/isph/ppe_two_level.hpp) includes only this header.
#pragma once

#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

namespace polymech::solvers {

class HostSparseLU {
 public:
  HostSparseLU();
  ~HostSparseLU();
  HostSparseLU(HostSparseLU&&) noexcept;
  HostSparseLU& operator=(HostSparseLU&&) noexcept;
  HostSparseLU(const HostSparseLU&) = delete;
  HostSparseLU& operator=(const HostSparseLU&) = delete;

  // Factorise the n x n matrix with the entries (rows[k], cols[k], values[k]) (repeated entries are
  // summed). Throws std::invalid_argument for inconsistent input, std::runtime_error when the
  // factorisation fails (a singular matrix); the previous factorisation is then gone. single = true
  // factorises and solves in float (half the factors' memory traffic: for a preconditioner's coarse level,
  // whose solve reads the whole factors at every application; docs/PERFORMANCE.md has the measured gain).
  void factor(std::int64_t n, const std::vector<std::int64_t>& rows, const std::vector<std::int64_t>& cols,
              const std::vector<double>& values, bool single = false);
  // x <- A^-1 x, x holding size() values. Throws std::logic_error before a successful factor().
  void solve(double* x) const;
  std::int64_t size() const { return n_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::int64_t n_ = 0;
};

// The same for a complex matrix (the harmonic solves of the piezoelectric harvester, models/piezo: the
// dynamic stiffness -w^2 M + i w C + K with the circuit's admittance is complex symmetric, not Hermitian).
class HostSparseLUComplex {
 public:
  using Complex = std::complex<double>;
  HostSparseLUComplex();
  ~HostSparseLUComplex();
  HostSparseLUComplex(HostSparseLUComplex&&) noexcept;
  HostSparseLUComplex& operator=(HostSparseLUComplex&&) noexcept;
  HostSparseLUComplex(const HostSparseLUComplex&) = delete;
  HostSparseLUComplex& operator=(const HostSparseLUComplex&) = delete;

  void factor(std::int64_t n, const std::vector<std::int64_t>& rows, const std::vector<std::int64_t>& cols,
              const std::vector<Complex>& values);
  void solve(Complex* x) const;
  std::int64_t size() const { return n_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::int64_t n_ = 0;
};

}  // namespace polymech::solvers
