// Settings of the Krylov solvers (kernels/solvers/krylov.hpp), as plain data: scenes fill them on the
// host without compiling the solvers.
#pragma once

#include <functional>

namespace polymech::solvers {

struct SolverOptions {
  double tolerance = 1e-10;      // on |r| / |b| (seed 002 paper 3 Table 1)
  int max_iterations = 10000;    // Table 1
  double breakdown_tolerance = -1.0;  // relative; < 0: 64 x the machine epsilon of the precision
  int stagnation_window = 1000;  // iterations without a 10 % reduction of the best residual
  int max_restarts = 3;          // restarts from the true residual
  std::function<void(int iteration, double relative_residual)> monitor;  // called every iteration
};

}  // namespace polymech::solvers
