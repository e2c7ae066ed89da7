// Element-free Galerkin model of a cracked plate (seed 004, Hagihara et al.), 2D, unit thickness.
//
// Nodes, support radii, background cells with Gauss points and boundary points come from
// efg::make_layout (setup.hpp, Kokkos-free). Shape functions are MLS (kernels/mls) at every point, the
// nodes of each point found by the two-set neighbour search (points against nodes) and cut by the
// crack (visibility criterion). The stiffness of eq. (8) is assembled by a Kokkos kernel into a block
// CSR pattern (nodes whose supports overlap) and solved by a sparse LDL^T factorisation (Eigen);
// essential conditions by penalty (alpha = penalty x E, on points or boundary Gauss points). The
// J-integral is taken on circles around the tip (20 arcs x 4 Gauss points, eq. (13) without the inertia
// part for a static solution), every value from MLS at the point; K_I = sqrt(J E').
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "common/run.hpp"
#include "common/state.hpp"
#include "core/types.hpp"
#include "efg/config.hpp"
#include "efg/setup.hpp"
#include "mls/mls.hpp"
#include "neighbors/neighbor_search.hpp"

namespace polymech::efg {

struct JResult {
  double radius = 0.0;
  double j = 0.0;
  double k = 0.0;       // sqrt(J E')
  double factor = 0.0;  // k / (stress sqrt(pi a))
};

struct Timings {
  double shape_seconds = 0.0;    // MLS shape functions at the background Gauss points
  double assembly_seconds = 0.0; // stiffness kernel + sparse matrix + penalty and loads
  double solve_seconds = 0.0;    // factorisation and solve
  double factor_seconds = 0.0;   // dynamics: a_0 and the effective stiffness, once per dt
  double step_seconds = 0.0;     // dynamics: all steps (solves and vector updates)
  double evaluations = 0.0;      // shape-function rows evaluated (points)
  double entries = 0.0;          // shape-function values (point-node pairs)
};

namespace detail {

// Index of `col` in the sorted cols[b, e) (the pattern contains it by construction).
KOKKOS_INLINE_FUNCTION Offset find_col(const View1<Index>& cols, Offset b, Offset e, Index col) {
  while (b < e) {
    const Offset m = b + (e - b) / 2;
    if (cols(m) < col)
      b = m + 1;
    else
      e = m;
  }
  return b;
}

// The entries of the shape-function rows that belong to each node, in increasing point order: node I's
// entries are node_entry(node_ptr(I)) .. node_entry(node_ptr(I + 1) - 1), at the points node_point(..).
// (Built on the host: the assembly below runs one node per thread, with no atomics, so the sums are
// in a fixed order whatever the thread count.)
struct NodeEntries {
  Kokkos::View<Offset*, MemSpace> node_ptr;
  View1<Offset> node_entry;
  View1<Index> node_point;
};

template <class T>
NodeEntries node_entries(const mls::ShapeFunctions<T>& sf, Index nodes) {
  auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.offsets);
  auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.neighbors);
  NodeEntries e;
  e.node_ptr = Kokkos::View<Offset*, MemSpace>("polymech::efg::node_ptr", static_cast<std::size_t>(nodes) + 1);
  const auto total = static_cast<std::size_t>(sf.rows.num_pairs);
  e.node_entry = View1<Offset>("polymech::efg::node_entry", total + 1);
  e.node_point = View1<Index>("polymech::efg::node_point", total + 1);
  auto hp = Kokkos::create_mirror_view(e.node_ptr);
  auto he = Kokkos::create_mirror_view(e.node_entry);
  auto hq = Kokkos::create_mirror_view(e.node_point);
  std::vector<Offset> count(static_cast<std::size_t>(nodes) + 1, 0);
  for (std::size_t k = 0; k < total; ++k) ++count[static_cast<std::size_t>(nb(k)) + 1];
  for (std::size_t i = 0; i < static_cast<std::size_t>(nodes); ++i) count[i + 1] += count[i];
  for (std::size_t i = 0; i <= static_cast<std::size_t>(nodes); ++i) hp(i) = count[i];
  for (Index q = 0; q < sf.points; ++q)
    for (Offset k = off(q); k < off(q + 1); ++k) {
      const auto slot = static_cast<std::size_t>(count[static_cast<std::size_t>(nb(k))]++);
      he(slot) = k;
      hq(slot) = q;
    }
  Kokkos::deep_copy(e.node_ptr, hp);
  Kokkos::deep_copy(e.node_entry, he);
  Kokkos::deep_copy(e.node_point, hq);
  return e;
}

// seed 004 eqs. (7), (8): K_IJ += w_q B_I^T D B_J and M_IJ += w_q rho phi_I phi_J at every Gauss point q
// of node I's support, for every node J of q's row, into the 2x2 blocks (4 values per pattern entry,
// row-major) and the mass values (1 per entry) of the node pattern. One node (pattern row) per thread.
template <class T>
void assemble_stiffness_mass(const mls::ShapeFunctions<T>& sf, const NodeEntries& ne, const View1<T>& weight,
                             const Kokkos::View<Offset*, MemSpace>& row_ptr, const View1<Index>& cols, const View1<T>& values,
                             const View1<T>& mass, T lam, T mu, T rho) {
  const auto rows = sf.rows;
  const auto phi = sf.phi;
  const auto dphi = sf.dphi;
  const T c11 = lam + T(2) * mu;
  const auto n = static_cast<std::int64_t>(ne.node_ptr.extent(0)) - 1;
  Kokkos::parallel_for(
      "polymech::efg::stiffness_mass", range(n), KOKKOS_LAMBDA(const std::int64_t ia) {
        const Offset rb = row_ptr(ia), re = row_ptr(ia + 1);
        for (Offset t = ne.node_ptr(ia); t < ne.node_ptr(ia + 1); ++t) {
          const Offset ka = ne.node_entry(t);
          const Index q = ne.node_point(t);
          const T w = weight(q);
          const T ax = dphi(ka, 0) * w, ay = dphi(ka, 1) * w, pa = phi(ka) * w * rho;
          for (Offset kb = rows.offsets(q); kb < rows.offsets(q + 1); ++kb) {
            const T bx = dphi(kb, 0), by = dphi(kb, 1);
            const Offset s = find_col(cols, rb, re, rows.neighbors(kb));
            values(4 * s + 0) += ax * c11 * bx + ay * mu * by;
            values(4 * s + 1) += ax * lam * by + ay * mu * bx;
            values(4 * s + 2) += ay * lam * bx + ax * mu * by;
            values(4 * s + 3) += ay * c11 * by + ax * mu * bx;
            mass(s) += pa * phi(kb);
          }
        }
      });
}

// u and its gradient at the points: out(i) = (ux, uy, ux_x, ux_y, uy_x, uy_y), u_h = sum_I phi_I u_I.
template <class T>
void interpolate(const mls::ShapeFunctions<T>& sf, const View1<T>& u, const Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>& out) {
  const auto rows = sf.rows;
  const auto phi = sf.phi;
  const auto dphi = sf.dphi;
  Kokkos::parallel_for(
      "polymech::efg::interpolate", range(sf.points), KOKKOS_LAMBDA(const Index i) {
        T v[6] = {};
        for (Offset k = rows.offsets(i); k < rows.offsets(i + 1); ++k) {
          const Index n = rows.neighbors(k);
          const T ux = u(2 * n), uy = u(2 * n + 1);
          v[0] += phi(k) * ux;
          v[1] += phi(k) * uy;
          v[2] += dphi(k, 0) * ux;
          v[3] += dphi(k, 1) * ux;
          v[4] += dphi(k, 0) * uy;
          v[5] += dphi(k, 1) * uy;
        }
        for (int c = 0; c < 6; ++c) out(i, c) = v[c];
      });
}

template <class T>
VecView<T, 2> to_points(const std::vector<double>& flat, int stride, const char* label) {
  const std::size_t n = flat.size() / static_cast<std::size_t>(stride);
  VecView<T, 2> v(std::string(label), n);
  auto h = Kokkos::create_mirror_view(v);
  for (std::size_t i = 0; i < n; ++i) {
    h(i, 0) = static_cast<T>(flat[i * static_cast<std::size_t>(stride)]);
    h(i, 1) = static_cast<T>(flat[i * static_cast<std::size_t>(stride) + 1]);
  }
  Kokkos::deep_copy(v, h);
  return v;
}

}  // namespace detail

template <class T = double>
class Efg {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  explicit Efg(const Config& c)
      : config_(c),
        layout_(make_layout(c)),
        beta_(0.25 * (c.newmark_gamma + 0.5) * (c.newmark_gamma + 0.5)),
        gamma_(c.newmark_gamma),
        initial_a_(c.crack_length) {
    if (c.gauss < 1) throw std::invalid_argument("efg: gauss must be >= 1");
    upload_nodes();
    for (const double d : layout_.dm) max_dm_ = std::max(max_dm_, d);
    crack_ = mls::Segments<T>("polymech::efg::crack", layout_.crack.size() / 4);
    auto hc = Kokkos::create_mirror_view(crack_);
    for (std::size_t s = 0; s < layout_.crack.size() / 4; ++s)
      for (int k = 0; k < 4; ++k) hc(s, k) = static_cast<T>(layout_.crack[4 * s + static_cast<std::size_t>(k)]);
    Kokkos::deep_copy(crack_, hc);
    const double nu = c.poisson;
    mu_ = c.young / (2 * (1 + nu));
    const double lam = c.young * nu / ((1 + nu) * (1 - 2 * nu));
    lam_ = c.plane_strain ? lam : 2 * lam * mu_ / (lam + 2 * mu_);
  }

  const Config& config() const { return config_; }
  // The J-integral band (Config::j_band) of later J and J' evaluations; the solution is untouched.
  void set_j_band(double band) { config_.j_band = band; }
  const Layout& layout() const { return layout_; }
  Index nodes() const { return static_cast<Index>(layout_.node_count()); }
  const Timings& timings() const { return timings_; }
  const std::vector<double>& coefficients() const { return u_host_; }

  // MLS shape functions at points (x, y pairs in `flat`, `stride` values per point). Throws naming the
  // first point whose moment matrix is nearly singular.
  mls::ShapeFunctions<T> shape_functions(const std::vector<double>& flat, int stride, const std::string& what) const {
    const auto pts = detail::to_points<T>(flat, stride, "polymech::efg::points");
    return shape_functions(pts, what);
  }
  mls::ShapeFunctions<T> shape_functions(const VecView<T, 2>& pts, const std::string& what) const {
    neighbors::NeighborSearch<T, 2> search;
    neighbors::NeighborList candidates;
    search.build_between(pts, nodes_, static_cast<T>(max_dm_), candidates);
    mls::ShapeFunctions<T> sf;
    sf.rows = mls::support_rows(candidates, pts, nodes_, dm_, crack_);
    mls::evaluate(pts, nodes_, dm_, static_cast<T>(config_.min_moment_ratio), sf);
    Index count = 0;
    const Index first = mls::first_flagged(sf.status, sf.points, count);
    if (first >= 0) {
      auto hp = Kokkos::create_mirror_view_and_copy(HostSpace(), pts);
      auto hr = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.ratio);
      auto ho = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.offsets);
      char buf[400];
      std::snprintf(buf, sizeof buf,
                    "EFG: nearly singular MLS moment matrix at %s point %d (x = %.9g, y = %.9g): det(A)/(A00 A11 A22) = "
                    "%.3g < min_moment_ratio %.3g, %lld nodes in its support (%d such points; too few or nearly collinear "
                    "nodes: raise support_factor or move the nodes)",
                    what.c_str(), static_cast<int>(first), static_cast<double>(hp(first, 0)), static_cast<double>(hp(first, 1)),
                    static_cast<double>(hr(first)), config_.min_moment_ratio,
                    static_cast<long long>(ho(first + 1) - ho(first)), static_cast<int>(count));
      throw std::runtime_error(buf);
    }
    return sf;
  }

  // Shape functions at the Gauss points, stiffness (with the penalty terms), consistent mass, loads.
  void assemble() {
    using clock = std::chrono::steady_clock;
    auto t0 = clock::now();
    const auto& L = layout_;
    const Index n = nodes();
    const auto qpts = detail::to_points<T>(L.quad, 3, "polymech::efg::gauss_points");
    View1<T> qw("polymech::efg::gauss_weights", L.quad_count());
    {
      auto h = Kokkos::create_mirror_view(qw);
      for (std::size_t q = 0; q < L.quad_count(); ++q) h(q) = static_cast<T>(L.quad[3 * q + 2]);
      Kokkos::deep_copy(qw, h);
    }
    const auto sf = shape_functions(qpts, "background Gauss");
    Kokkos::fence();
    auto t1 = clock::now();
    timings_.shape_seconds = std::chrono::duration<double>(t1 - t0).count();
    timings_.evaluations = static_cast<double>(sf.points);
    timings_.entries = static_cast<double>(sf.rows.num_pairs);

    build_pattern();
    View1<T> values("polymech::efg::stiffness_values", static_cast<std::size_t>(4 * cols_host_.size()));
    View1<T> mvalues("polymech::efg::mass_values", cols_host_.size());
    const auto entries = detail::node_entries(sf, n);
    detail::assemble_stiffness_mass(sf, entries, qw, row_ptr_, cols_, values, mvalues, static_cast<T>(lam_), static_cast<T>(mu_),
                                    static_cast<T>(config_.density));
    auto hm = Kokkos::create_mirror_view_and_copy(HostSpace(), mvalues);
    {
      std::vector<Eigen::Triplet<double, int>> mt;
      mt.reserve(2 * cols_host_.size());
      for (Index a = 0; a < n; ++a)
        for (Offset s = row_ptr_host_[static_cast<std::size_t>(a)]; s < row_ptr_host_[static_cast<std::size_t>(a) + 1]; ++s) {
          const Index b = cols_host_[static_cast<std::size_t>(s)];
          for (int r = 0; r < 2; ++r) mt.emplace_back(2 * a + r, 2 * b + r, static_cast<double>(hm(s)));
        }
      M_ = SparseMatrix(2 * n, 2 * n);
      M_.setFromTriplets(mt.begin(), mt.end());
    }
    auto hv = Kokkos::create_mirror_view_and_copy(HostSpace(), values);
    std::vector<Eigen::Triplet<double, int>> trip;
    trip.reserve(4 * cols_host_.size() + 64);
    for (Index a = 0; a < n; ++a)
      for (Offset s = row_ptr_host_[static_cast<std::size_t>(a)]; s < row_ptr_host_[static_cast<std::size_t>(a) + 1]; ++s) {
        const Index b = cols_host_[static_cast<std::size_t>(s)];
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) trip.emplace_back(2 * a + r, 2 * b + c, static_cast<double>(hv(4 * s + 2 * r + c)));
      }
    Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
    // penalty: alpha sum_p N_I N_J (held component) and alpha N_I value on the right-hand side
    if (!L.penalty.empty()) {
      const auto ps = shape_functions(L.penalty, 5, "penalty");
      auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), ps.rows.offsets);
      auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), ps.rows.neighbors);
      auto ph = Kokkos::create_mirror_view_and_copy(HostSpace(), ps.phi);
      for (std::size_t p = 0; p < L.penalty.size() / 5; ++p) {
        const double k = L.penalty[5 * p + 2];
        const int comp = static_cast<int>(L.penalty[5 * p + 3]);
        const double val = L.penalty[5 * p + 4];
        for (Offset ka = off(p); ka < off(p + 1); ++ka) {
          f(2 * nb(ka) + comp) += k * static_cast<double>(ph(ka)) * val;
          for (Offset kb = off(p); kb < off(p + 1); ++kb)
            trip.emplace_back(2 * nb(ka) + comp, 2 * nb(kb) + comp, k * static_cast<double>(ph(ka)) * static_cast<double>(ph(kb)));
        }
      }
    }
    // seed 004 eq. (9): f_I = sum over boundary Gauss points of N_I t w
    if (!L.traction.empty()) {
      const auto ts = shape_functions(L.traction, 5, "traction");
      auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), ts.rows.offsets);
      auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), ts.rows.neighbors);
      auto ph = Kokkos::create_mirror_view_and_copy(HostSpace(), ts.phi);
      for (std::size_t p = 0; p < L.traction.size() / 5; ++p)
        for (Offset k = off(p); k < off(p + 1); ++k)
          for (int c = 0; c < 2; ++c) f(2 * nb(k) + c) += L.traction[5 * p + 2] * static_cast<double>(ph(k)) * L.traction[5 * p + 3 + static_cast<std::size_t>(c)];
    }
    // Config::path_release_gradual (the finite-element node-release remedy, not in the paper): a split
    // pair stays tied (a penalty spring k (u+ - u-)^2 / 2 per component, k = tie_stiffness()) for the step
    // that splits it; from the next growth step on the spring is replaced by the force it carried then,
    // F0 = k (u+ - u-), applied to the twins and falling linearly to 0 while the tip runs the next node
    // spacing past the node: F = F0 (1 - s), s = (a - x_node) / spacing.
    for (auto& t : ties_) {
      if (t.state == Tie::tied && !restore_ties_ && ud_.size() == static_cast<Eigen::Index>(2 * n)) {
        for (int c = 0; c < 2; ++c) t.f0[c] = tie_stiffness() * (ud_(2 * t.upper + c) - ud_(2 * t.lower + c));
        t.state = Tie::released;
      }
      if (t.state == Tie::fresh || t.state == Tie::tied) {  // (tied: only when a checkpoint is restored)
        for (int c = 0; c < 2; ++c) {
          const int a = static_cast<int>(2 * t.upper + c), b = static_cast<int>(2 * t.lower + c);
          trip.emplace_back(a, a, tie_stiffness());
          trip.emplace_back(b, b, tie_stiffness());
          trip.emplace_back(a, b, -tie_stiffness());
          trip.emplace_back(b, a, -tie_stiffness());
        }
        t.state = Tie::tied;
      } else if (t.state == Tie::released) {
        const double left = std::max(0.0, 1.0 - (config_.crack_length - t.x) / t.length);
        for (int c = 0; c < 2; ++c) {
          f(2 * t.upper + c) -= left * t.f0[c];
          f(2 * t.lower + c) += left * t.f0[c];
        }
      }
    }
    K_ = SparseMatrix(2 * n, 2 * n);
    K_.setFromTriplets(trip.begin(), trip.end());
    f_ = f;
    timings_.assembly_seconds = std::chrono::duration<double>(clock::now() - t1).count();
    assembled_ = true;
  }

  // The static solution K u = f.
  void solve_static() {
    if (!assembled_) assemble();
    const auto t2 = std::chrono::steady_clock::now();
    const auto& K = K_;
    const auto& f = f_;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt;
    ldlt.compute(K);
    if (ldlt.info() != Eigen::Success) throw std::runtime_error("EFG: the stiffness factorisation failed (a rigid-body mode not held?)");
    const Eigen::VectorXd u = ldlt.solve(f);
    if (ldlt.info() != Eigen::Success || !u.allFinite()) throw std::runtime_error("EFG: the static solve failed");
    timings_.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
    u_host_.assign(u.data(), u.data() + u.size());
    to_device(u, u_, "polymech::efg::coefficients");
  }

  // ---- dynamics: Newmark beta = 1/4, gamma = 1/2 in the incremental form of seed 004 eqs. (6)-(11) ----
  // (config newmark_gamma > 1/2: beta = (gamma + 1/2)^2 / 4, numerically damped; gamma enters dv only)

  // Starts a run from rest under the load f (a Heaviside step at t = 0: a_0 = M^-1 f) and factorises the
  // effective stiffness K + M / (beta dt^2) once for this dt.
  void start_dynamic(double dt) {
    if (!assembled_) assemble();
    const auto t0 = std::chrono::steady_clock::now();
    dt_ = dt;
    const Index n2 = 2 * nodes();
    ud_ = Eigen::VectorXd::Zero(n2);
    vd_ = Eigen::VectorXd::Zero(n2);
    Eigen::SimplicialLDLT<SparseMatrix> mass;
    mass.compute(M_);
    if (mass.info() != Eigen::Success) throw std::runtime_error("EFG: the mass matrix factorisation failed");
    ad_ = mass.solve(f_);
    SparseMatrix keff = K_ + M_ * (1.0 / (beta_ * dt * dt));
    keff_.compute(keff);
    if (keff_.info() != Eigen::Success) throw std::runtime_error("EFG: the effective stiffness factorisation failed");
    time_ = 0.0;
    step_ = 0;
    timings_.factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    sync_dynamic();
  }

  // One step: K_eff du = df + r + M (v_n / (beta dt) + a_n / (2 beta)), r = f_n - K u_n - M a_n (eq. (11),
  // the residual of the previous step); then da, dv from Newmark's relations. The load is constant
  // after t = 0 (df = 0).
  void step() {
    if (prescribed_growth_) grow_crack();
    const auto t0 = std::chrono::steady_clock::now();
    const double b = beta_, dt = dt_;
    const Eigen::VectorXd r = f_ - K_ * ud_ - M_ * ad_;
    const Eigen::VectorXd rhs = r + M_ * (vd_ * (1.0 / (b * dt)) + ad_ * (1.0 / (2 * b)));
    const Eigen::VectorXd du = keff_.solve(rhs);
    const Eigen::VectorXd da = du * (1.0 / (b * dt * dt)) - vd_ * (1.0 / (b * dt)) - ad_ * (1.0 / (2 * b));
    vd_ += dt * ad_ + gamma_ * dt * da;
    ud_ += du;
    ad_ += da;
    time_ += dt;
    ++step_;
    timings_.step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    sync_dynamic();
  }

  // The prescribed growth of seed 004 §3.3 (config growth_start, growth_speed, final_crack_length): from
  // growth_start both tips run at growth_speed up to final_crack_length. grow_crack() moves them to where
  // they are at the END of the coming step, t_n + dt (nothing before growth_start or once there): the
  // implicit step solves the balance at t_n + dt, so the solution at time t has the crack a(t) (moving
  // it to a(t_n) instead lags the crack by one step: the first step after growth_start then still has
  // the stationary crack). With set_prescribed_growth(true) every step() does it first (models::run).
  void grow_crack() {
    const auto& c = config_;
    const double t = time_ + dt_;
    if (!(c.growth_speed > 0) || t <= c.growth_start + 1e-3 * dt_) return;
    const double a = std::min(c.final_crack_length, initial_a_ + c.growth_speed * (t - c.growth_start));
    if (a > c.crack_length) set_crack_length(a, a < c.final_crack_length ? c.growth_speed : 0.0);
  }
  void set_prescribed_growth(bool on) { prescribed_growth_ = on; }

  // models::run's protocol: a 2D model whose state is the nodal coefficients (host vectors: no Views to
  // register for the watchdog's last good copy); health: the first coefficient of u or v not finite.
  static constexpr int dimension = 2;
  void prepare() {}
  const models::StateRegistry& state() const { return no_views_; }
  void set_step_index(std::int64_t k) { step_ = k; }
  models::Health health() const {
    models::Health h;
    h.what = "DoF";
    for (const Eigen::VectorXd* x : {&ud_, &vd_})
      for (Eigen::Index i = 0; i < x->size(); ++i)
        if (!std::isfinite((*x)(i))) {
          h.finite = false;
          h.first_bad = static_cast<std::int64_t>(i);
          h.problem = std::string(x == &ud_ ? "(displacement coefficient)" : "(velocity coefficient)") + " is not finite";
          return h;
        }
    return h;
  }

  // Checkpoint of a dynamic run (models::run's protocol): the nodal coefficients of u, v, a, the time,
  // the step and the crack (half-)length and tip speed; the matrices are rebuilt from the configuration
  // and that crack, the factorisation from dt on load.
  void save(models::Archive& ar, const std::string& prefix) const {
    auto vec = [](const Eigen::VectorXd& x) { return std::vector<double>(x.data(), x.data() + x.size()); };
    ar.put_vector(prefix + "u", vec(ud_));
    ar.put_vector(prefix + "v", vec(vd_));
    ar.put_vector(prefix + "a", vec(ad_));
    ar.put(prefix + "time", time_);
    ar.put(prefix + "dt", dt_);
    ar.put(prefix + "step", step_);
    ar.put(prefix + "crack_length", config_.crack_length);
    ar.put(prefix + "tip_speed", speed_);
    if (!ties_.empty()) {  // gradual release: each tie's state and released force
      std::vector<double> t;
      for (const auto& x : ties_) t.insert(t.end(), {static_cast<double>(x.state), x.f0[0], x.f0[1]});
      ar.put_vector(prefix + "ties", t);
    }
  }
  void load(const models::Archive& ar, const std::string& prefix) {
    const double dt = ar.get<double>(prefix + "dt");
    start_dynamic(dt);
    const double a = ar.get<double>(prefix + "crack_length"), speed = ar.get<double>(prefix + "tip_speed");
    if (a != config_.crack_length) set_crack_length(a, speed);
    speed_ = speed;
    auto vec = [&](const std::string& k, Eigen::VectorXd& x) {
      const auto v = ar.get_vector<double>(prefix + k);
      if (v.size() != static_cast<std::size_t>(x.size())) throw std::runtime_error("EFG checkpoint: '" + prefix + k + "' has the wrong size");
      for (std::size_t i = 0; i < v.size(); ++i) x(static_cast<Eigen::Index>(i)) = v[i];
    };
    vec("u", ud_);
    vec("v", vd_);
    vec("a", ad_);
    if (!ties_.empty()) {  // the ties as they were (set_crack_length above made them fresh): reassemble
      const auto t = ar.get_vector<double>(prefix + "ties");
      if (t.size() != 3 * ties_.size()) throw std::runtime_error("EFG checkpoint: '" + prefix + "ties' has the wrong size");
      for (std::size_t k = 0; k < ties_.size(); ++k) {
        ties_[k].state = static_cast<typename Tie::State>(static_cast<int>(t[3 * k]));
        ties_[k].f0[0] = t[3 * k + 1];
        ties_[k].f0[1] = t[3 * k + 2];
      }
      restore_ties_ = true;
      assemble();
      restore_ties_ = false;
      SparseMatrix keff = K_ + M_ * (1.0 / (beta_ * dt_ * dt_));
      keff_.compute(keff);
      if (keff_.info() != Eigen::Success) throw std::runtime_error("EFG: the effective stiffness factorisation failed");
    }
    time_ = ar.get<double>(prefix + "time");
    step_ = ar.get<std::int64_t>(prefix + "step");
    sync_dynamic();
  }

  double time() const { return time_; }
  std::int64_t step_index() const { return step_; }
  double dt() const { return dt_; }

  // Kinetic, strain (with the penalty springs) and load-potential energies: their sum stays 0 for the
  // average-acceleration rule under a constant load (it conserves energy).
  double kinetic_energy() const { return 0.5 * vd_.dot(M_ * vd_); }
  double strain_energy() const { return 0.5 * ud_.dot(K_ * ud_); }
  double load_work() const { return f_.dot(ud_); }

  // seed 004 eq. (13) on the path of `radius`: dynamic_j_at(radius) (the paper's single circle) when
  // Config::j_band is 0, else the mean of dynamic_j_at over the band of radii [r - d/2, r + d/2],
  // d = j_band_width(r), at 4 radial Gauss points. The mean over r of eq. (13) equals the equivalent
  // domain integral with q(r) falling linearly across the band; it cancels the error of the MLS
  // stresses that oscillates with r at the period of the node lines (docs/METHODS.md, 'J-integral band').
  JResult dynamic_j(double radius, int cells = 20) {
    return banded(radius, [&](double r) { return dynamic_j_at(r, cells); }, effective_modulus(config_) / velocity_factor(speed_), initial_a_);
  }

  // seed 004 eq. (13): J' = int_Gamma [(W + K) n_1 - t_i u_i,1] dS + int_V [rho a_i u_i,1 - rho v_i v_i,1] dV
  // on the circle of `radius` around the tip and the disc inside it (radial x angular cells of `cells`
  // each, 4 x 4 Gauss points: the paper's 20 x 20).
  JResult dynamic_j_at(double radius, int cells = 20) {
    auto& c = contour_cache(radius, cells);
    double j = 0.0;
    const auto u = probe(c.contour, u_), v = probe(c.contour, v_);
    for (std::size_t p = 0; p < c.w.size(); ++p) {
      const double* g = &u[6 * p];
      const double* h = &v[6 * p];
      const double exx = g[2], eyy = g[5], gxy = g[3] + g[4];
      const double sxx = (lam_ + 2 * mu_) * exx + lam_ * eyy, syy = lam_ * exx + (lam_ + 2 * mu_) * eyy, sxy = mu_ * gxy;
      const double W = 0.5 * (sxx * exx + syy * eyy + sxy * gxy);
      const double Kd = 0.5 * config_.density * (h[0] * h[0] + h[1] * h[1]);
      const double n1 = std::cos(c.th[p]), n2 = std::sin(c.th[p]);
      const double t1 = sxx * n1 + sxy * n2, t2 = sxy * n1 + syy * n2;
      j += c.w[p] * ((W + Kd) * n1 - (t1 * g[2] + t2 * g[4]));
    }
    const auto du = probe(c.domain, u_), dv = probe(c.domain, v_), da = probe(c.domain, a_);
    for (std::size_t p = 0; p < c.dw.size(); ++p) {
      const double* g = &du[6 * p];
      const double* h = &dv[6 * p];
      const double* q = &da[6 * p];
      j += c.dw[p] * config_.density * (q[0] * g[2] + q[1] * g[4] - (h[0] * h[2] + h[1] * h[4]));
    }
    constexpr double pi = 3.14159265358979323846;
    JResult r;
    r.radius = radius;
    r.j = j;
    r.k = std::sqrt(std::max(0.0, j) * effective_modulus(config_) / velocity_factor(speed_));
    r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * initial_a_)) : 0.0;
    return r;
  }

  // J' = A_I(v) K_I^2 / E' for a crack running at v (Freund; Nishioka & Atluri): A_I = v^2 alpha_d /
  // ((1 - nu) c_s^2 D), D = 4 alpha_d alpha_s - (1 + alpha_s^2)^2, alpha = sqrt(1 - v^2 / c^2); with the
  // plane-stress nu' = nu / (1 + nu) in plane stress. 1 at v = 0.
  double velocity_factor(double v) const {
    if (!(v > 0)) return 1.0;
    const double nu = config_.plane_strain ? config_.poisson : config_.poisson / (1 + config_.poisson);
    const double cs2 = mu_ / config_.density, cd2 = (lam_ + 2 * mu_) / config_.density;
    const double ad = std::sqrt(std::max(0.0, 1 - v * v / cd2)), as = std::sqrt(std::max(0.0, 1 - v * v / cs2));
    const double D = 4 * ad * as - (1 + as * as) * (1 + as * as);
    return v * v * ad / ((1 - nu) * cs2 * D);
  }

  // Moves the tip(s) to half-length (or length) a running at `speed`: the crack segment, the shape
  // functions, K and M are rebuilt (the nodal coefficients stay), K_eff refactorised, the J' paths and the
  // opening probe follow the tip. The residual r of the next step carries the released forces.
  void set_crack_length(double a, double speed) {
    config_.crack_length = a;
    speed_ = speed;
    if (config_.crack == CrackKind::edge) {
      layout_.crack[2] = a;
    } else if (config_.crack == CrackKind::centre) {
      layout_.crack[0] = -a;
      layout_.crack[2] = a;
    }
    layout_.tip_x = a;
    split_passed_nodes();
    auto hc = Kokkos::create_mirror_view(crack_);
    for (std::size_t s = 0; s < layout_.crack.size() / 4; ++s)
      for (int k = 0; k < 4; ++k) hc(s, k) = static_cast<T>(layout_.crack[4 * s + static_cast<std::size_t>(k)]);
    Kokkos::deep_copy(crack_, hc);
    contours_.clear();
    cod_ready_ = false;
    assemble();
    SparseMatrix keff = K_ + M_ * (1.0 / (beta_ * dt_ * dt_));
    keff_.compute(keff);
    if (keff_.info() != Eigen::Success) throw std::runtime_error("EFG: the effective stiffness factorisation failed");
  }
  double crack_length() const { return config_.crack_length; }
  // Nodes added by splitting path nodes the tip has passed (Config::path_nodes).
  Index split_nodes() const { return split_nodes_; }

  // Crack opening at x of the current (dynamic or static) solution.
  double dynamic_opening_at(double x) {
    if (!cod_ready_ || cod_x_ != x) {
      const double e = 1e-6 * config_.h_min;
      cod_sf_ = shape_functions(std::vector<double>{x, e, x, -e}, 2, "crack-opening");
      cod_ready_ = true;
      cod_x_ = x;
    }
    const auto v = probe(cod_sf_, u_);
    return v[1] - v[6 + 1];
  }

  // (ux, uy, ux_x, ux_y, uy_x, uy_y) at each point (x, y pairs).
  std::vector<double> fields_at(const std::vector<double>& xy, const std::string& what = "field") const {
    const auto sf = shape_functions(xy, 2, what);
    Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace> out("polymech::efg::fields", static_cast<std::size_t>(sf.points));
    detail::interpolate(sf, u_, out);
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), out);
    std::vector<double> r(static_cast<std::size_t>(sf.points) * 6);
    for (Index i = 0; i < sf.points; ++i)
      for (int c = 0; c < 6; ++c) r[static_cast<std::size_t>(i) * 6 + static_cast<std::size_t>(c)] = static_cast<double>(h(i, c));
    return r;
  }

  // The static J on the path of `radius`: j_integral_at(radius) when Config::j_band is 0, else its mean
  // over the band of radii as in dynamic_j.
  JResult j_integral(double radius) const {
    return banded(radius, [&](double r) { return j_integral_at(r); }, effective_modulus(config_), config_.crack_length);
  }

  // seed 004 eq. (13), static part: J = int_Gamma (W n_1 - t_i u_i,1) dS on the circle of `radius`
  // around the tip, counter-clockwise from the lower crack face to the upper one (the crack faces are
  // traction-free); `arcs` arcs x `gauss` Gauss points.
  JResult j_integral_at(double radius) const {
    const int arcs = config_.j_arcs;
    std::vector<double> gx, gw;
    gauss_rule(config_.j_gauss, gx, gw);
    constexpr double pi = 3.14159265358979323846;
    std::vector<double> xy, w, th;
    const double d = 2 * pi / arcs;
    for (int m = 0; m < arcs; ++m)
      for (std::size_t g = 0; g < gx.size(); ++g) {
        const double t = -pi + d * (m + 0.5 * (1 + gx[g]));
        xy.push_back(layout_.tip_x + radius * std::cos(t));
        xy.push_back(layout_.tip_y + radius * std::sin(t));
        w.push_back(0.5 * d * gw[g] * radius);
        th.push_back(t);
      }
    const auto v = fields_at(xy, "J-contour");
    double j = 0.0;
    for (std::size_t p = 0; p < w.size(); ++p) {
      const double* g = &v[6 * p];
      const double exx = g[2], eyy = g[5], gxy = g[3] + g[4];
      const double sxx = (lam_ + 2 * mu_) * exx + lam_ * eyy, syy = lam_ * exx + (lam_ + 2 * mu_) * eyy, sxy = mu_ * gxy;
      const double W = 0.5 * (sxx * exx + syy * eyy + sxy * gxy);
      const double n1 = std::cos(th[p]), n2 = std::sin(th[p]);
      const double t1 = sxx * n1 + sxy * n2, t2 = sxy * n1 + syy * n2;
      j += w[p] * (W * n1 - (t1 * g[2] + t2 * g[4]));
    }
    JResult r;
    r.radius = radius;
    r.j = j;
    r.k = std::sqrt(std::max(0.0, j) * effective_modulus(config_));
    r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * config_.crack_length)) : 0.0;
    return r;
  }

  // Crack-opening displacement at x (u_y just above minus just below the crack line).
  double opening_at(double x) const {
    const double e = 1e-6 * config_.h_min;
    const auto v = fields_at({x, e, x, -e}, "crack-opening");
    return v[1] - v[6 + 1];
  }

  static void gauss_rule(int n, std::vector<double>& x, std::vector<double>& w) {
    // the 1D rule of the layout (a one-cell layout would do; the closed forms suffice for n <= 5)
    x.clear();
    w.clear();
    if (n == 1) {
      x = {0.0};
      w = {2.0};
    } else if (n == 2) {
      const double a = 1 / std::sqrt(3.0);
      x = {-a, a};
      w = {1.0, 1.0};
    } else if (n == 3) {
      const double a = std::sqrt(0.6);
      x = {-a, 0.0, a};
      w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    } else {
      const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(1.2)), b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(1.2));
      const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
      x = {-b, -a, a, b};
      w = {wb, wa, wa, wb};
    }
  }

 private:
  // J (and K from it) on the path of `radius`: at_radius(radius) without a band, else the mean of
  // at_radius over the 4 radial Gauss points of [radius - d/2, radius + d/2], d = j_band_width(radius).
  // `modulus`: K^2 = J x modulus; `a_ref`: the length of K / (stress sqrt(pi a_ref)).
  template <class F>
  JResult banded(double radius, F&& at_radius, double modulus, double a_ref) const {
    const double d = j_band_width(config_, radius);
    if (!(d > 0)) return at_radius(radius);
    std::vector<double> gx, gw;
    gauss_rule(4, gx, gw);
    double j = 0.0;
    for (std::size_t g = 0; g < gx.size(); ++g) j += 0.5 * gw[g] * at_radius(radius + 0.5 * d * gx[g]).j;
    constexpr double pi = 3.14159265358979323846;
    JResult r;
    r.radius = radius;
    r.j = j;
    r.k = std::sqrt(std::max(0.0, j) * modulus);
    r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * a_ref)) : 0.0;
    return r;
  }

  struct ContourCache {
    double radius = 0.0;
    int cells = 0;
    mls::ShapeFunctions<T> contour, domain;
    std::vector<double> w, th, dw;
  };

  ContourCache& contour_cache(double radius, int cells) {
    for (auto& c : contours_)
      if (c.radius == radius && c.cells == cells) return c;
    ContourCache c;
    c.radius = radius;
    c.cells = cells;
    std::vector<double> gx, gw;
    gauss_rule(config_.j_gauss, gx, gw);
    constexpr double pi = 3.14159265358979323846;
    std::vector<double> xy;
    const int arcs = config_.j_arcs;
    const double d = 2 * pi / arcs;
    for (int m = 0; m < arcs; ++m)
      for (std::size_t g = 0; g < gx.size(); ++g) {
        const double t = -pi + d * (m + 0.5 * (1 + gx[g]));
        xy.insert(xy.end(), {layout_.tip_x + radius * std::cos(t), layout_.tip_y + radius * std::sin(t)});
        c.w.push_back(0.5 * d * gw[g] * radius);
        c.th.push_back(t);
      }
    c.contour = shape_functions(xy, 2, "J-contour");
    std::vector<double> g4x, g4w;
    gauss_rule(4, g4x, g4w);
    std::vector<double> dxy;
    const double dr = radius / cells, dt = 2 * pi / cells;
    for (int i = 0; i < cells; ++i)
      for (int k = 0; k < cells; ++k)
        for (std::size_t p = 0; p < 4; ++p)
          for (std::size_t q = 0; q < 4; ++q) {
            const double r = dr * (i + 0.5 * (1 + g4x[p]));
            const double t = -pi + dt * (k + 0.5 * (1 + g4x[q]));
            dxy.insert(dxy.end(), {layout_.tip_x + r * std::cos(t), layout_.tip_y + r * std::sin(t)});
            c.dw.push_back(0.25 * dr * dt * g4w[p] * g4w[q] * r);
          }
    c.domain = shape_functions(dxy, 2, "J-domain");
    contours_.push_back(std::move(c));
    return contours_.back();
  }

  std::vector<double> probe(const mls::ShapeFunctions<T>& sf, const View1<T>& coeff) const {
    Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace> out("polymech::efg::fields", static_cast<std::size_t>(sf.points));
    detail::interpolate(sf, coeff, out);
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), out);
    std::vector<double> r(static_cast<std::size_t>(sf.points) * 6);
    for (Index i = 0; i < sf.points; ++i)
      for (int c = 0; c < 6; ++c) r[static_cast<std::size_t>(i) * 6 + static_cast<std::size_t>(c)] = static_cast<double>(h(i, c));
    return r;
  }

  // A node on the crack line (y = 0 exactly: a path node of Config::path_nodes) that the crack now
  // covers would be seen from both faces and tie them together: it becomes two, the node itself moved
  // onto the upper face and a twin on the lower one (y = +- Layout::face_offset, as the layout puts
  // crack-face nodes), same support radius, the twin appended with a copy of the node's u, v, a
  // coefficients (the field is continuous there until the faces separate). A node at the tip (within
  // 1e-9 h_min) stays whole: the visibility criterion lets a segment through the tip see it.
  void split_passed_nodes() {
    const double a = config_.crack_length, tol = 1e-9 * config_.h_min, eps = layout_.face_offset;
    if (config_.crack == CrackKind::none) return;
    std::vector<std::size_t> passed;
    for (std::size_t i = 0; i < layout_.node_count(); ++i) {
      const double x = layout_.nodes[2 * i], y = layout_.nodes[2 * i + 1];
      const double ax = config_.crack == CrackKind::centre ? std::abs(x) : x;
      if (y == 0.0 && ax < a - tol) passed.push_back(i);
    }
    if (passed.empty()) return;
    // twins appended in the order the tips pass them (|x|, then x), so a restart that splits all the
    // passed nodes at once numbers them as the run that split them step by step did
    std::sort(passed.begin(), passed.end(), [&](std::size_t i, std::size_t j) {
      const double xi = layout_.nodes[2 * i], xj = layout_.nodes[2 * j];
      const double ai = config_.crack == CrackKind::centre ? std::abs(xi) : xi, aj = config_.crack == CrackKind::centre ? std::abs(xj) : xj;
      return ai < aj || (ai == aj && xi < xj);
    });
    const Eigen::Index n0 = static_cast<Eigen::Index>(2 * layout_.node_count());
    for (const std::size_t i : passed) {
      layout_.nodes[2 * i + 1] = eps;
      layout_.nodes.insert(layout_.nodes.end(), {layout_.nodes[2 * i], -eps});
      layout_.dm.push_back(layout_.dm[i]);
      if (config_.path_release_gradual) {
        const double ax = config_.crack == CrackKind::centre ? std::abs(layout_.nodes[2 * i]) : layout_.nodes[2 * i];
        const auto next = std::upper_bound(layout_.xs.begin(), layout_.xs.end(), ax + tol);
        const double length = next != layout_.xs.end() ? *next - ax : config_.h_min;
        ties_.push_back({static_cast<Index>(i), static_cast<Index>(layout_.dm.size() - 1), ax, length, Tie::fresh, {0.0, 0.0}});
      }
    }
    const auto grow = [&](Eigen::VectorXd& x) {
      if (x.size() != n0) return;  // not started: start_dynamic sizes it
      x.conservativeResize(n0 + static_cast<Eigen::Index>(2 * passed.size()));
      for (std::size_t k = 0; k < passed.size(); ++k)
        for (int c = 0; c < 2; ++c)
          x(n0 + static_cast<Eigen::Index>(2 * k) + c) = x(static_cast<Eigen::Index>(2 * passed[k]) + c);
    };
    grow(ud_);
    grow(vd_);
    grow(ad_);
    split_nodes_ += static_cast<Index>(passed.size());
    upload_nodes();
    if (ud_.size() == static_cast<Eigen::Index>(2 * layout_.node_count())) sync_dynamic();
  }

  // The layout's node positions and support radii to the device.
  void upload_nodes() {
    nodes_ = detail::to_points<T>(layout_.nodes, 2, "polymech::efg::nodes");
    dm_ = View1<T>("polymech::efg::support_radius", layout_.dm.size());
    auto hd = Kokkos::create_mirror_view(dm_);
    for (std::size_t i = 0; i < layout_.dm.size(); ++i) hd(i) = static_cast<T>(layout_.dm[i]);
    Kokkos::deep_copy(dm_, hd);
  }

  static void to_device(const Eigen::VectorXd& x, View1<T>& v, const char* label) {
    if (v.extent(0) != static_cast<std::size_t>(x.size())) v = View1<T>(std::string(label), static_cast<std::size_t>(x.size()));
    auto h = Kokkos::create_mirror_view(v);
    for (Eigen::Index i = 0; i < x.size(); ++i) h(static_cast<std::size_t>(i)) = static_cast<T>(x(i));
    Kokkos::deep_copy(v, h);
  }

  void sync_dynamic() {
    to_device(ud_, u_, "polymech::efg::coefficients");
    to_device(vd_, v_, "polymech::efg::velocity_coefficients");
    to_device(ad_, a_, "polymech::efg::acceleration_coefficients");
  }

  // Node pairs whose supports overlap (|x_I - x_J| < dm_I + dm_J), each row sorted, the diagonal included.
  void build_pattern() {
    const Index n = nodes();
    neighbors::NeighborSearch<T, 2> search;
    neighbors::NeighborList list;
    search.build(nodes_, static_cast<T>(2 * max_dm_), neighbors::ListKind::full, list);
    auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), list.offsets);
    auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), list.neighbors);
    const auto& X = layout_.nodes;
    const auto& D = layout_.dm;
    row_ptr_host_.assign(static_cast<std::size_t>(n) + 1, 0);
    cols_host_.clear();
    std::vector<Index> row;
    for (Index i = 0; i < n; ++i) {
      row.clear();
      row.push_back(i);
      const auto si = static_cast<std::size_t>(i);
      for (Offset k = off(i); k < off(i + 1); ++k) {
        const auto j = static_cast<std::size_t>(nb(k));
        const double dx = X[2 * si] - X[2 * j], dy = X[2 * si + 1] - X[2 * j + 1];
        const double r = D[si] + D[j];
        if (dx * dx + dy * dy < r * r) row.push_back(nb(k));
      }
      std::sort(row.begin(), row.end());
      cols_host_.insert(cols_host_.end(), row.begin(), row.end());
      row_ptr_host_[si + 1] = static_cast<Offset>(cols_host_.size());
    }
    row_ptr_ = Kokkos::View<Offset*, MemSpace>("polymech::efg::row_ptr", row_ptr_host_.size());
    cols_ = View1<Index>("polymech::efg::cols", cols_host_.size());
    auto hr = Kokkos::create_mirror_view(row_ptr_);
    auto hc = Kokkos::create_mirror_view(cols_);
    for (std::size_t i = 0; i < row_ptr_host_.size(); ++i) hr(i) = row_ptr_host_[i];
    for (std::size_t i = 0; i < cols_host_.size(); ++i) hc(i) = cols_host_[i];
    Kokkos::deep_copy(row_ptr_, hr);
    Kokkos::deep_copy(cols_, hc);
  }

  Config config_;
  Layout layout_;
  VecView<T, 2> nodes_;
  View1<T> dm_;
  mls::Segments<T> crack_;
  double max_dm_ = 0.0;
  double lam_ = 0.0, mu_ = 0.0;
  std::vector<Offset> row_ptr_host_;
  std::vector<Index> cols_host_;
  Kokkos::View<Offset*, MemSpace> row_ptr_;
  View1<Index> cols_;
  View1<T> u_, v_, a_;
  std::vector<double> u_host_;
  Timings timings_;
  bool assembled_ = false;
  SparseMatrix K_, M_;
  Eigen::VectorXd f_, ud_, vd_, ad_;
  Eigen::SimplicialLDLT<SparseMatrix> keff_;
  double beta_ = 0.25, gamma_ = 0.5, dt_ = 0.0, time_ = 0.0;
  std::int64_t step_ = 0;
  std::vector<ContourCache> contours_;
  double speed_ = 0.0;
  double initial_a_ = 0.0;
  mls::ShapeFunctions<T> cod_sf_;
  bool cod_ready_ = false;
  double cod_x_ = 0.0;
  bool prescribed_growth_ = false;
  Index split_nodes_ = 0;
  struct Tie {
    Index upper, lower;  // the split node (upper face) and its twin (lower face)
    double x, length;    // the node's distance along the crack, and the spacing over which the tie fades
    enum State { fresh, tied, released } state = fresh;
    double f0[2] = {0.0, 0.0};  // the spring's force when it was released
  };
  std::vector<Tie> ties_;
  bool restore_ties_ = false;  // assemble() during load(): the ties' states as saved, none moved on
  // the tie's stiffness at the split: Config::penalty x E (the essential conditions' penalty)
  double tie_stiffness() const { return config_.penalty * config_.young; }
  models::StateRegistry no_views_;
};

}  // namespace polymech::efg
