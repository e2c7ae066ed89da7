// The Communicator of models/helmholtz/parallel.hpp over MPI (MPI build only: POLYMECH_WITH_MPI, preset
// `mpi`). One object per process; MpiSession initializes MPI (thread level funneled: only the
// master thread of each rank calls MPI, Kokkos' OpenMP threads never do) and finalizes it.
#pragma once

#include <memory>

#include "helmholtz/parallel.hpp"

namespace polymech::helmholtz {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  std::shared_ptr<const Communicator> world() const { return world_; }

 private:
  std::shared_ptr<const Communicator> world_;
};

// Communicator of MPI_COMM_WORLD (MPI initialized).
std::shared_ptr<const Communicator> mpi_world();

}  // namespace polymech::helmholtz
