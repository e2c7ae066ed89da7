// Domain decomposition of the Helmholtz model (seed 002 paper 3 §4: the mesh split into parts, one per
// process, MPI between them). Host-side plumbing, free of MPI: the model talks to a Communicator, of
// which SerialCommunicator (one part, no messages) lives here and MpiCommunicator (mpi_communicator.hpp)
// in the MPI build only, so that the kernels, the model and the serial apps never depend on MPI.
//
// Layout of a part (kernels/fem/hex_elements.hpp): local DoFs are the owned ones first, then ghost
// copies of DoFs owned by other parts. A part keeps every element that touches one of its owned DoFs
// (its own elements plus an overlap layer, the paper's Fig. 8 "overlapping region"), so that y = K x
// is complete on the owned rows after one halo exchange of x (Halo::update): ghost rows of y are
// left incomplete and never read. Reductions run over owned entries and are summed by reduce_sum.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/host_mirror.hpp"
#include "core/types.hpp"

namespace polymech::helmholtz {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Element-wise sums and maxima over all parts, in place.
  virtual void sum(double* values, int count) const = 0;
  virtual void max(double* values, int count) const = 0;
  // Point-to-point exchange with the neighbours `ranks`: bytes send[send_offsets[k] ..
  // send_offsets[k + 1]) go to ranks[k], recv[recv_offsets[k] .. recv_offsets[k + 1]) come from it.
  virtual void exchange(const std::vector<int>& ranks, const std::vector<std::size_t>& send_offsets, const char* send,
                        const std::vector<std::size_t>& recv_offsets, char* recv) const = 0;
  // Concatenation of every part's `local` on rank 0 (in rank order); empty elsewhere.
  virtual std::vector<double> gather(const std::vector<double>& local) const = 0;
  virtual std::string name() const = 0;
};

class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void sum(double*, int) const override {}
  void max(double*, int) const override {}
  void exchange(const std::vector<int>& ranks, const std::vector<std::size_t>&, const char*,
                const std::vector<std::size_t>&, char*) const override {
    if (!ranks.empty()) throw std::logic_error("SerialCommunicator: one part has no neighbours");
  }
  std::vector<double> gather(const std::vector<double>& local) const override { return local; }
  std::string name() const override { return "serial"; }
};

// The halo exchange of one part: ghost entries of a vector are overwritten by their owners' values.
// Counts what it moves and the time it takes (the communication term of the speed-up model).
template <class V>
class Halo {
 public:
  Halo() = default;
  // send[k]: owned local indices whose values go to neighbour ranks[k]; recv[k]: ghost local indices
  // that receive from it (both in the order both sides agree on: increasing global index).
  Halo(std::shared_ptr<const Communicator> comm, std::vector<int> ranks, const std::vector<std::vector<Index>>& send,
       const std::vector<std::vector<Index>>& recv)
      : comm_(std::move(comm)), ranks_(std::move(ranks)) {
    std::vector<Index> s, r;
    send_offsets_.push_back(0);
    recv_offsets_.push_back(0);
    for (std::size_t k = 0; k < ranks_.size(); ++k) {
      s.insert(s.end(), send[k].begin(), send[k].end());
      r.insert(r.end(), recv[k].begin(), recv[k].end());
      send_offsets_.push_back(s.size() * sizeof(V));
      recv_offsets_.push_back(r.size() * sizeof(V));
    }
    send_index_ = to_view("polymech::helmholtz::halo_send_index", s);
    recv_index_ = to_view("polymech::helmholtz::halo_recv_index", r);
    send_buffer_ = View1<V>("polymech::helmholtz::halo_send", s.size());
    recv_buffer_ = View1<V>("polymech::helmholtz::halo_recv", r.size());
    send_host_ = Kokkos::create_mirror_view(send_buffer_);
    recv_host_ = Kokkos::create_mirror_view(recv_buffer_);
  }

  bool active() const { return !ranks_.empty(); }
  int neighbours() const { return static_cast<int>(ranks_.size()); }
  Index send_entries() const { return static_cast<Index>(send_index_.extent(0)); }
  Index recv_entries() const { return static_cast<Index>(recv_index_.extent(0)); }
  double seconds() const { return seconds_; }
  long long updates() const { return updates_; }

  void update(const View1<V>& x) const {
    if (!active()) return;
    const auto t0 = std::chrono::steady_clock::now();
    const auto si = send_index_;
    const auto sb = send_buffer_;
    Kokkos::parallel_for(
        "polymech::helmholtz::halo_pack", range(static_cast<Index>(si.extent(0))),
        KOKKOS_LAMBDA(const Index k) { sb(k) = x(si(k)); });
    Kokkos::deep_copy(send_host_, send_buffer_);
    comm_->exchange(ranks_, send_offsets_, reinterpret_cast<const char*>(send_host_.data()), recv_offsets_,
                    reinterpret_cast<char*>(recv_host_.data()));
    Kokkos::deep_copy(recv_buffer_, recv_host_);
    const auto ri = recv_index_;
    const auto rb = recv_buffer_;
    Kokkos::parallel_for(
        "polymech::helmholtz::halo_unpack", range(static_cast<Index>(ri.extent(0))),
        KOKKOS_LAMBDA(const Index k) { x(ri(k)) = rb(k); });
    Kokkos::fence();
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++updates_;
  }

 private:
  static View1<Index> to_view(const std::string& label, const std::vector<Index>& h) {
    View1<Index> v(label, h.size());
    auto m = Kokkos::create_mirror_view(v);
    for (std::size_t i = 0; i < h.size(); ++i) m(i) = h[i];
    Kokkos::deep_copy(v, m);
    return v;
  }

  std::shared_ptr<const Communicator> comm_;
  std::vector<int> ranks_;
  std::vector<std::size_t> send_offsets_, recv_offsets_;
  View1<Index> send_index_, recv_index_;
  View1<V> send_buffer_, recv_buffer_;
  // host copies of the buffers for MPI (the same memory on a host backend)
  kx::HostMirror<View1<V>> send_host_, recv_host_;
  mutable double seconds_ = 0.0;
  mutable long long updates_ = 0;
};

}  // namespace polymech::helmholtz
