// Costs of the two MPI operations of a distributed COCG iteration on this machine, for the speed-up
// model of tools/helmholtz_scaling.py: an MPI_Allreduce of 4 doubles and a neighbour exchange of b bytes
// (MPI_Isend / MPI_Irecv / MPI_Waitall between rank pairs, as Halo::update does). Each is timed
// `repeat` times after a warm-up; the minimum and the median are printed as key=value lines (the
// minimum is what the machine does when the partner's core is free; on a shared machine the median
// also holds the time the partner waited to be scheduled).
//   mpirun -np 2 mpi_probe [repeat]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int repeat = argc > 1 ? std::atoi(argv[1]) : 2000;
  std::vector<double> t(static_cast<std::size_t>(repeat));
  double v[4] = {1, 2, 3, 4};
  for (int k = -100; k < repeat; ++k) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    MPI_Allreduce(MPI_IN_PLACE, v, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    if (k >= 0) t[k] = MPI_Wtime() - t0;
  }
  if (rank == 0) std::printf("probe allreduce ranks=%d min_seconds=%.3e median_seconds=%.3e\n", size, *std::min_element(t.begin(), t.end()), median(t));
  const int partner = rank ^ 1;
  for (int bytes : {1 << 10, 1 << 14, 1 << 18}) {
    std::vector<char> s(static_cast<std::size_t>(bytes), 1), r(static_cast<std::size_t>(bytes));
    for (int k = -100; k < repeat; ++k) {
      MPI_Barrier(MPI_COMM_WORLD);
      const double t0 = MPI_Wtime();
      if (partner < size) {
        MPI_Request q[2];
        MPI_Irecv(r.data(), bytes, MPI_BYTE, partner, 7, MPI_COMM_WORLD, &q[0]);
        MPI_Isend(s.data(), bytes, MPI_BYTE, partner, 7, MPI_COMM_WORLD, &q[1]);
        MPI_Waitall(2, q, MPI_STATUSES_IGNORE);
      }
      if (k >= 0) t[k] = MPI_Wtime() - t0;
    }
    if (rank == 0)
      std::printf("probe exchange bytes=%d min_seconds=%.3e median_seconds=%.3e\n", bytes, *std::min_element(t.begin(), t.end()), median(t));
  }
  MPI_Finalize();
  return 0;
}
