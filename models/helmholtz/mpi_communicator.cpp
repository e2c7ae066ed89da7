#include "helmholtz/mpi_communicator.hpp"

#include <mpi.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace polymech::helmholtz {

namespace {

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed (error " + std::to_string(status) + ")");
}

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void sum(double* v, int n) const override {
    if (size_ > 1) check(MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce(sum)");
  }
  void max(double* v, int n) const override {
    if (size_ > 1) check(MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce(max)");
  }
  void exchange(const std::vector<int>& ranks, const std::vector<std::size_t>& so, const char* send,
                const std::vector<std::size_t>& ro, char* recv) const override {
    std::vector<MPI_Request> req(2 * ranks.size());
    for (std::size_t k = 0; k < ranks.size(); ++k)
      check(MPI_Irecv(recv + ro[k], static_cast<int>(ro[k + 1] - ro[k]), MPI_BYTE, ranks[k], 71, MPI_COMM_WORLD, &req[k]),
            "MPI_Irecv");
    for (std::size_t k = 0; k < ranks.size(); ++k)
      check(MPI_Isend(send + so[k], static_cast<int>(so[k + 1] - so[k]), MPI_BYTE, ranks[k], 71, MPI_COMM_WORLD,
                      &req[ranks.size() + k]),
            "MPI_Isend");
    check(MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  }
  std::vector<double> gather(const std::vector<double>& local) const override {
    int n = static_cast<int>(local.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), displs(static_cast<std::size_t>(size_));
    check(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::vector<double> all;
    if (rank_ == 0) {
      int total = 0;
      for (int r = 0; r < size_; ++r) {
        displs[r] = total;
        total += counts[r];
      }
      all.resize(static_cast<std::size_t>(total));
    }
    check(MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD),
          "MPI_Gatherv");
    return all;
  }
  std::string name() const override { return "mpi"; }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  world_ = std::make_shared<MpiCommunicator>();
}

MpiSession::~MpiSession() {
  world_.reset();
  MPI_Finalize();
}

std::shared_ptr<const Communicator> mpi_world() { return std::make_shared<MpiCommunicator>(); }

}  // namespace polymech::helmholtz
