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
//
// This header declares the model; its parts are defined, one job per header, in
//   efg/shape_functions.hpp  MLS shape functions at points, fields and crack opening from them
//   efg/assembly.hpp         node pattern, stiffness, mass, penalty and loads (eqs. (7)-(9)), static solve
//   efg/newmark.hpp          Newmark time stepping (eqs. (6)-(11)), energies, health
//   efg/crack_growth.hpp     prescribed crack growth (§3.3), path-node splitting and ties
//   efg/j_integral.hpp       static and dynamic J-integrals (eq. (13)) and the velocity factor
//   efg/checkpoint.hpp       save / load of a dynamic run
// all included at the end of this file (each may also be included on its own). Device kernels:
// kernels/mls/ (mls.hpp, assembly.hpp, interpolation.hpp).
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstdint>
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
    upload_crack();
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

  // ---- shape functions (efg/shape_functions.hpp) ----
  // MLS shape functions at points (x, y pairs in `flat`, `stride` values per point). Throws naming the
  // first point whose moment matrix is nearly singular.
  mls::ShapeFunctions<T> shape_functions(const std::vector<double>& flat, int stride, const std::string& what) const;
  mls::ShapeFunctions<T> shape_functions(const VecView<T, 2>& pts, const std::string& what) const;
  // (ux, uy, ux_x, ux_y, uy_x, uy_y) at each point (x, y pairs).
  std::vector<double> fields_at(const std::vector<double>& xy, const std::string& what = "field") const;
  // Crack-opening displacement at x (u_y just above minus just below the crack line).
  double opening_at(double x) const;
  // Crack opening at x of the current (dynamic or static) solution.
  double dynamic_opening_at(double x);

  // ---- assembly and the static solve (efg/assembly.hpp) ----
  // Shape functions at the Gauss points, stiffness (with the penalty terms), consistent mass, loads.
  void assemble();
  // The static solution K u = f.
  void solve_static();

  // ---- dynamics: Newmark (efg/newmark.hpp) ----
  // Starts a run from rest under the load f and factorises the effective stiffness once for this dt.
  void start_dynamic(double dt);
  // One step of eq. (11) (and first the prescribed growth, when on).
  void step();
  // models::run's protocol: a 2D model whose state is the nodal coefficients (host vectors: no Views to
  // register for the watchdog's last good copy); health: the first coefficient of u or v not finite.
  static constexpr int dimension = 2;
  void prepare() {}
  const models::StateRegistry& state() const { return no_views_; }
  void set_step_index(std::int64_t k) { step_ = k; }
  models::Health health() const;
  double time() const { return time_; }
  std::int64_t step_index() const { return step_; }
  double dt() const { return dt_; }
  // Kinetic, strain (with the penalty springs) and load-potential energies: their sum stays 0 for the
  // average-acceleration rule under a constant load (it conserves energy).
  double kinetic_energy() const { return 0.5 * vd_.dot(M_ * vd_); }
  double strain_energy() const { return 0.5 * ud_.dot(K_ * ud_); }
  double load_work() const { return f_.dot(ud_); }

  // ---- checkpoints (efg/checkpoint.hpp) ----
  void save(models::Archive& ar, const std::string& prefix) const;
  void load(const models::Archive& ar, const std::string& prefix);

  // ---- crack growth (efg/crack_growth.hpp) ----
  // The prescribed growth of seed 004 §3.3: the tips moved to where they are at the end of the coming step.
  void grow_crack();
  void set_prescribed_growth(bool on) { prescribed_growth_ = on; }
  // Moves the tip(s) to half-length (or length) a running at `speed` and rebuilds what depends on it.
  void set_crack_length(double a, double speed);
  double crack_length() const { return config_.crack_length; }
  // Nodes added by splitting path nodes the tip has passed (Config::path_nodes).
  Index split_nodes() const { return split_nodes_; }

  // ---- J-integrals (efg/j_integral.hpp) ----
  // seed 004 eq. (13) on the path of `radius` (mean over the band of radii when Config::j_band > 0).
  JResult dynamic_j(double radius, int cells = 20);
  JResult dynamic_j_at(double radius, int cells = 20);
  // J' = A_I(v) K_I^2 / E' for a crack running at v; 1 at v = 0.
  double velocity_factor(double v) const;
  // The static J on the path of `radius` (mean over the band of radii when Config::j_band > 0).
  JResult j_integral(double radius) const;
  JResult j_integral_at(double radius) const;
  // The 1D Gauss-Legendre rule on [-1, 1] with n points (fem::gauss_legendre).
  static void gauss_rule(int n, std::vector<double>& x, std::vector<double>& w);

 private:
  struct ContourCache {
    double radius = 0.0;
    int cells = 0;
    mls::ShapeFunctions<T> contour, domain;
    std::vector<double> w, th, dw;
  };
  struct Tie {
    Index upper, lower;  // the split node (upper face) and its twin (lower face)
    double x, length;    // the node's distance along the crack, and the spacing over which the tie fades
    enum State { fresh, tied, released } state = fresh;
    double f0[2] = {0.0, 0.0};  // the spring's force when it was released
  };
  using Triplets = std::vector<Eigen::Triplet<double, int>>;

  // efg/shape_functions.hpp
  std::vector<double> probe(const mls::ShapeFunctions<T>& sf, const View1<T>& coeff) const;
  void upload_nodes();
  // efg/assembly.hpp
  void build_pattern();
  void add_penalty(Triplets& trip, Eigen::VectorXd& f) const;
  void add_traction(Eigen::VectorXd& f) const;
  // efg/newmark.hpp
  void factor_effective_stiffness();
  void sync_dynamic();
  // efg/crack_growth.hpp
  void upload_crack();
  void split_passed_nodes();
  void add_ties(Triplets& trip, Eigen::VectorXd& f);
  // the tie's stiffness at the split: Config::penalty x E (the essential conditions' penalty)
  double tie_stiffness() const { return config_.penalty * config_.young; }
  // efg/j_integral.hpp
  template <class F>
  JResult banded(double radius, F&& at_radius, double modulus, double a_ref) const;
  ContourCache& contour_cache(double radius, int cells);

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
  std::vector<Tie> ties_;
  bool restore_ties_ = false;  // assemble() during load(): the ties' states as saved, none moved on
  models::StateRegistry no_views_;
};

}  // namespace polymech::efg

#include "efg/assembly.hpp"
#include "efg/checkpoint.hpp"
#include "efg/crack_growth.hpp"
#include "efg/j_integral.hpp"
#include "efg/newmark.hpp"
#include "efg/shape_functions.hpp"
