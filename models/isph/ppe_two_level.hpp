// A two-level preconditioner of the pressure Poisson equation (not in the paper; `fluid.ppe_preconditioner =
// "two_level"`): the Jacobi-scaled BiCGSTAB needs ~1.75 sqrt(N) iterations (docs/PERFORMANCE.md, ISPH), the
// slow modes being the smooth ones; a coarse correction on aggregates removes them.
//
//   aggregates: the particles in each cell of side `cell` (a few spacings) of a grid over the tank;
//   P: piecewise constant on the aggregates (prolongation z_i += e_I, I the aggregate of i; P^T sums);
//   Ac = P^T A P, the Galerkin product of the row-scaled operator A the Krylov solver sees, formed from the
//        operator's stored pair coefficients (ghost couplings included) and factorised by a sparse LU
//        on the host (solvers::HostSparseLU) once per step;
//   M^-1 r: z = w r; z += P Ac^-1 P^T (r - A z); z += w (r - A z)   (w = 2/3: Jacobi smoothing of the
//        scaled operator, whose diagonal is 1), two operator products per application.
//
// The coarse matrix is assembled and solved on the host (serial, deterministic: the same result with any
// thread count); the smoothing, restriction and prolongation are Kokkos kernels. On a GPU every
// application copies the coarse residual to the host and the correction back (one value per aggregate).
// The LU is a compiled host unit (kernels/solvers/host_sparse_lu.cpp), as Eigen's SparseLU does not
// compile under nvcc.
#pragma once

#include "core/host_mirror.hpp"
#include "core/kokkos_shim.hpp"
#include "solvers/host_sparse_lu.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "neighbors/neighbor_list.hpp"

namespace polymech::isph {

// Kernels of the two-level preconditioner (public, outside the class: nvcc needs lambdas in public scope).
namespace two_level_detail {
template <class T>
void scale(const View1<T>& r, const View1<T>& z, T w) {
  Kokkos::parallel_for(
      "polymech::isph::two_level_smooth0", range(static_cast<Index>(r.extent(0))),
      KOKKOS_LAMBDA(const Index i) { z(i) = w * r(i); });
}
// z += w (r - Az)
template <class T>
void smooth(const View1<T>& r, const View1<T>& az, const View1<T>& z, T w) {
  Kokkos::parallel_for(
      "polymech::isph::two_level_smooth", range(static_cast<Index>(r.extent(0))),
      KOKKOS_LAMBDA(const Index i) { z(i) += w * (r(i) - az(i)); });
}
// rc(I) = sum over the members i of I of (r - Az)(i), members in index order (deterministic)
template <class T>
void restrict_residual(const View1<T>& r, const View1<T>& az, const Kokkos::View<Index*, MemSpace>& start,
                       const Kokkos::View<Index*, MemSpace>& members, const View1<double>& rc) {
  Kokkos::parallel_for(
      "polymech::isph::two_level_restrict", range(static_cast<Index>(rc.extent(0))), KOKKOS_LAMBDA(const Index I) {
        double s = 0.0;
        for (Index m = start(I); m < start(I + 1); ++m) s += double(r(members(m)) - az(members(m)));
        rc(I) = s;
      });
}
template <class T>
void prolong(const View1<double>& ec, const Kokkos::View<Index*, MemSpace>& agg, const View1<T>& z) {
  Kokkos::parallel_for(
      "polymech::isph::two_level_prolong", range(static_cast<Index>(z.extent(0))),
      KOKKOS_LAMBDA(const Index i) { z(i) += T(ec(agg(i))); });
}
}  // namespace two_level_detail

template <class T, int D, class Op>
class TwoLevelPpe {
 public:
  // The aggregates and the coarse operator for the operator `op` as it is now (its stored coefficients,
  // lists, densities and surface flags): once per step, before the solve. `box`: the tank's inner size.
  void setup(const Op& op, const double* box, double cell) {
    op_ = op;
    const Index n = op.local_size();
    int nc[D];
    long long cells = 1;
    for (int d = 0; d < D; ++d) {
      nc[d] = std::max(1, static_cast<int>(std::ceil(box[d] / cell)));
      cells *= nc[d];
    }
    // aggregate of every particle: its cell (clamped to the grid)
    auto x = Kokkos::create_mirror_view_and_copy(HostSpace(), op.f.x);
    std::vector<Index> agg(static_cast<std::size_t>(n));
    std::vector<Index> count(static_cast<std::size_t>(cells) + 1, 0);
    for (Index i = 0; i < n; ++i) {
      long long id = 0, stride = 1;
      for (int d = 0; d < D; ++d) {
        const int c = std::min(nc[d] - 1, std::max(0, static_cast<int>(std::floor(double(x(i, d)) / cell))));
        id += c * stride;
        stride *= nc[d];
      }
      agg[static_cast<std::size_t>(i)] = static_cast<Index>(id);
      ++count[static_cast<std::size_t>(id) + 1];
    }
    for (std::size_t I = 0; I < static_cast<std::size_t>(cells); ++I) count[I + 1] += count[I];
    std::vector<Index> members(static_cast<std::size_t>(n)), fill(count.begin(), count.end() - 1);
    for (Index i = 0; i < n; ++i) members[static_cast<std::size_t>(fill[static_cast<std::size_t>(agg[static_cast<std::size_t>(i)])]++)] = i;
    coarse_size_ = static_cast<Index>(cells);
    agg_ = to_device("polymech::isph::two_level_aggregate", agg);
    start_ = to_device("polymech::isph::two_level_start", count);
    members_ = to_device("polymech::isph::two_level_members", members);
    rc_ = View1<double>("polymech::isph::two_level_rc", static_cast<std::size_t>(cells));
    rc_host_ = Kokkos::create_mirror_view(rc_);  // rc_ itself in host builds
    az_ = View1<T>("polymech::isph::two_level_az", static_cast<std::size_t>(n));
    assemble(agg, count, members);
  }

  // z = M^-1 r (kernels/sph/bicgstab.hpp, right preconditioner)
  void apply(const View1<T>& r, const View1<T>& z) const {
    namespace tl = two_level_detail;
    const T w = T(2.0 / 3.0);
    tl::scale(r, z, w);
    op_.apply(z, az_);
    tl::restrict_residual(r, az_, start_, members_, rc_);
    Kokkos::deep_copy(rc_host_, rc_);
    lu_.solve(rc_host_.data());  // in place: the coarse correction
    Kokkos::deep_copy(rc_, rc_host_);
    tl::prolong(rc_, agg_, z);
    op_.apply(z, az_);
    tl::smooth(r, az_, z, w);
  }
  Index coarse_size() const { return coarse_size_; }

 private:
  template <class V>
  static Kokkos::View<Index*, MemSpace> to_device(const char* label, const V& v) {
    Kokkos::View<Index*, MemSpace> out(std::string(label), v.size());
    auto h = Kokkos::create_mirror_view(out);
    for (std::size_t k = 0; k < v.size(); ++k) h(k) = v[k];
    Kokkos::deep_copy(out, h);
    return out;
  }

  // Ac(I, J) = sum of A_ij over i in I, j in J, with the rows of A as the operator forms them
  // (sph::FluidLaplacian, WallLaplacian, GhostPressure):
  //   y_i = x_i at a surface particle; otherwise y_i = s_i [ sum_j c_ij (x_i - x~_j) / rho_i
  //         + sum_k w_ik (x_i - sum_m g_km x~_m) ], x~_j = 0 at surface particles, s_i = 1 / diag_i.
  void assemble(const std::vector<Index>& agg, const std::vector<Index>& start, const std::vector<Index>& members) {
    const auto& o = op_;
    auto surface = Kokkos::create_mirror_view_and_copy(HostSpace(), o.f.surface);
    auto rho = Kokkos::create_mirror_view_and_copy(HostSpace(), o.f.rho);
    auto inv = Kokkos::create_mirror_view_and_copy(HostSpace(), o.f.inv_diag);
    auto ff_off = Kokkos::create_mirror_view_and_copy(HostSpace(), o.ff->offsets);
    auto ff_nb = Kokkos::create_mirror_view_and_copy(HostSpace(), o.ff->neighbors);
    auto fw_off = Kokkos::create_mirror_view_and_copy(HostSpace(), o.fw->offsets);
    auto fw_nb = Kokkos::create_mirror_view_and_copy(HostSpace(), o.fw->neighbors);
    auto gf_off = Kokkos::create_mirror_view_and_copy(HostSpace(), o.gf->offsets);
    auto gf_nb = Kokkos::create_mirror_view_and_copy(HostSpace(), o.gf->neighbors);
    auto fc = Kokkos::create_mirror_view_and_copy(HostSpace(), o.fluid_coef);
    auto wc = Kokkos::create_mirror_view_and_copy(HostSpace(), o.wall_coef);
    auto gc = Kokkos::create_mirror_view_and_copy(HostSpace(), o.ghost_coef);
    if (fc.extent(0) < static_cast<std::size_t>(o.ff->num_pairs))
      throw std::logic_error("isph: the two-level preconditioner needs the stored PPE operator");
    std::vector<std::int64_t> rows, cols;
    std::vector<double> values;
    std::vector<double> row(static_cast<std::size_t>(coarse_size_), 0.0);
    std::vector<char> listed(static_cast<std::size_t>(coarse_size_), 0);
    std::vector<Index> touched;
    auto add = [&](Index J, double v) {
      const auto u = static_cast<std::size_t>(J);
      if (!listed[u]) {
        listed[u] = 1;
        touched.push_back(J);
      }
      row[u] += v;
    };
    for (Index I = 0; I < coarse_size_; ++I) {
      touched.clear();
      for (Index m = start[static_cast<std::size_t>(I)]; m < start[static_cast<std::size_t>(I) + 1]; ++m) {
        const Index i = members[static_cast<std::size_t>(m)];
        if (surface(i)) {
          add(I, 1.0);
          continue;
        }
        const double s = double(inv(i)), ri = 1.0 / double(rho(i));
        double diag = 0.0;
        for (Offset k = ff_off(i); k < ff_off(i + 1); ++k) {
          const Index j = ff_nb(k);
          const double c = double(fc(k)) * ri;
          diag += c;
          if (!surface(j)) add(agg[static_cast<std::size_t>(j)], -s * c);
        }
        for (Offset k = fw_off(i); k < fw_off(i + 1); ++k) {
          const Index q = fw_nb(k);
          const double c = double(wc(k));
          diag += c;
          for (Offset g = gf_off(q); g < gf_off(q + 1); ++g) {
            const Index j = gf_nb(g);
            if (!surface(j)) add(agg[static_cast<std::size_t>(j)], -s * c * double(gc(g)));
          }
        }
        add(I, s * diag);
      }
      if (touched.empty()) add(I, 1.0);  // an empty cell: an identity row
      for (const Index J : touched) {
        rows.push_back(I);
        cols.push_back(J);
        values.push_back(row[static_cast<std::size_t>(J)]);
        row[static_cast<std::size_t>(J)] = 0.0;
        listed[static_cast<std::size_t>(J)] = 0;
      }
    }
    try {
      lu_.factor(coarse_size_, rows, cols, values);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("isph: the two-level preconditioner's coarse matrix (" + std::to_string(coarse_size_) +
                               " aggregates) could not be factorised: " + e.what());
    }
  }
  Op op_;
  Index coarse_size_ = 0;
  Kokkos::View<Index*, MemSpace> agg_, start_, members_;
  View1<double> rc_;
  kx::HostMirror<View1<double>> rc_host_;
  View1<T> az_;
  solvers::HostSparseLU lu_;
};

}  // namespace polymech::isph
