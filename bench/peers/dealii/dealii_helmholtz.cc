// deal.II peer of bench_fem's BM_MatrixFreeApply: the real operator  y = (A - k^2 M) x  of seed 002
// paper 3 eqs. (17), (18) (Laplace minus k^2 mass; polymech applies the same operator to complex
// vectors) on the unit cube with n^3 hexahedra of order p, Gauss quadrature with p + 1 points, zero
// Dirichlet values on the whole boundary (constrained DoFs, as polymech's cube), applied matrix-free
// by deal.II's MatrixFree / FEEvaluation (sum factorization, vectorized across cells with the
// library's VectorizedArray<double>). One thread. Prints one line per run:
//   dealii p=<p> n=<n> dofs=<DoFs> vector_lanes=<W> applies=<k> cpu_seconds_per_apply=<s>
//   wall_seconds_per_apply=<s> dofs_per_second_cpu=<r>
//   dealii_helmholtz <p> <n> [seconds]
// Written for bench/peers/run_peers.sh; deal.II 9.3 or newer (Debian 12: libdeal.ii-dev 9.4.1).
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/revision.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

namespace {

using namespace dealii;
using Vector = LinearAlgebra::distributed::Vector<double>;

template <int p>
class HelmholtzOperator {
 public:
  HelmholtzOperator(const MatrixFree<3, double>& data, double k2) : data_(data), k2_(k2) {}

  void vmult(Vector& dst, const Vector& src) const {
    data_.cell_loop(&HelmholtzOperator::local_apply, this, dst, src, true);
  }

 private:
  void local_apply(const MatrixFree<3, double>& data, Vector& dst, const Vector& src,
                   const std::pair<unsigned int, unsigned int>& cells) const {
    FEEvaluation<3, p, p + 1, 1, double> phi(data);
    for (unsigned int cell = cells.first; cell < cells.second; ++cell) {
      phi.reinit(cell);
      phi.gather_evaluate(src, EvaluationFlags::values | EvaluationFlags::gradients);
      for (unsigned int q = 0; q < phi.n_q_points; ++q) {
        phi.submit_gradient(phi.get_gradient(q), q);
        phi.submit_value(-k2_ * phi.get_value(q), q);
      }
      phi.integrate_scatter(EvaluationFlags::values | EvaluationFlags::gradients, dst);
    }
  }

  const MatrixFree<3, double>& data_;
  double k2_;
};

template <int p>
int run(unsigned int n, double seconds) {
  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_cube(tria, n);
  const FE_Q<3> fe(p);
  DoFHandler<3> dofs(tria);
  dofs.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  VectorTools::interpolate_boundary_values(dofs, 0, Functions::ZeroFunction<3>(), constraints);
  constraints.close();
  typename MatrixFree<3, double>::AdditionalData settings;
  settings.tasks_parallel_scheme = MatrixFree<3, double>::AdditionalData::none;
  settings.mapping_update_flags = update_values | update_gradients | update_JxW_values;
  // deal.II's own renumbering for the cell loop's data locality, then the data structures again
  {
    MatrixFree<3, double> first;
    first.reinit(MappingQ1<3>(), dofs, constraints, QGauss<1>(p + 1), settings);
    DoFRenumbering::matrix_free_data_locality(dofs, first);
  }
  constraints.clear();
  VectorTools::interpolate_boundary_values(dofs, 0, Functions::ZeroFunction<3>(), constraints);
  constraints.close();
  MatrixFree<3, double> data;
  data.reinit(MappingQ1<3>(), dofs, constraints, QGauss<1>(p + 1), settings);

  // 500 Hz in air (seed 002 paper 3 Table 1): k = 2 pi f / c
  const double k = 2.0 * M_PI * 500.0 / 343.0;
  HelmholtzOperator<p> op(data, k * k);
  Vector x, y;
  data.initialize_dof_vector(x);
  data.initialize_dof_vector(y);
  for (unsigned int i = 0; i < x.locally_owned_size(); ++i) x.local_element(i) = std::sin(0.01 * i);
  op.vmult(y, x);  // warm-up
  unsigned int applies = 0;
  const auto w0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  double elapsed = 0.0;
  while (elapsed < seconds || applies < 5) {
    op.vmult(y, x);
    ++applies;
    elapsed = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const double cpu = elapsed / applies;
  std::printf("dealii p=%d n=%u dofs=%u vector_lanes=%u applies=%u cpu_seconds_per_apply=%.6e "
              "wall_seconds_per_apply=%.6e dofs_per_second_cpu=%.6e version=%d.%d.%d y_norm=%.12e\n",
              p, n, dofs.n_dofs(), static_cast<unsigned int>(VectorizedArray<double>::size()), applies, cpu,
              wall / applies, dofs.n_dofs() / cpu, DEAL_II_VERSION_MAJOR, DEAL_II_VERSION_MINOR,
              DEAL_II_VERSION_SUBMINOR, y.l2_norm());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <order 1..4> <elements per direction> [seconds (default 3)]\n", argv[0]);
    return 2;
  }
  dealii::MultithreadInfo::set_thread_limit(1);
  const int p = std::atoi(argv[1]);
  const int n = std::atoi(argv[2]);
  const double seconds = argc > 3 ? std::atof(argv[3]) : 3.0;
  if (n < 1) {
    std::fprintf(stderr, "elements per direction must be >= 1, got '%s'\n", argv[2]);
    return 2;
  }
  switch (p) {
    case 1: return run<1>(n, seconds);
    case 2: return run<2>(n, seconds);
    case 3: return run<3>(n, seconds);
    case 4: return run<4>(n, seconds);
    default: std::fprintf(stderr, "order %s is not supported; allowed: 1..4\n", argv[1]); return 2;
  }
}
