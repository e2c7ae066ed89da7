// The system matrix of seed 002 paper 3 eq. (16), K = A - k^2 M + j rho omega C, as a matrix-free
// operator for the solvers (kernels/solvers/krylov.hpp): volume terms by sum factorization, impedance
// faces, identity rows on Dirichlet DoFs. Complex symmetric: K^T = K.
#pragma once

#include <memory>

#include "fem/boundary_faces.hpp"
#include "fem/dirichlet.hpp"
#include "fem/helmholtz_operator.hpp"
#include "helmholtz/parallel.hpp"

namespace polymech::helmholtz {

template <class T>
class HelmholtzOperator {
 public:
  using value_type = Kokkos::complex<T>;
  using V = value_type;

  HelmholtzOperator() = default;
  HelmholtzOperator(fem::HexElements<T> elements, fem::HexFaces<T, V> impedance, View1<Index> constrained,
                    T mass_coefficient)
      : el_(std::move(elements)), imp_(std::move(impedance)), constrained_(constrained), m_(mass_coefficient) {}

  Index local_size() const { return el_.local_size(); }
  Index owned_size() const { return el_.owned; }

  // A part of a distributed operator: the halo exchange of its vectors and the sums over the parts.
  void distribute(std::shared_ptr<const Halo<V>> halo, std::shared_ptr<const Communicator> comm) {
    halo_ = std::move(halo);
    comm_ = std::move(comm);
  }
  // The same part with another mass coefficient, without the impedance faces (the shifted Laplacian
  // S = A + s k^2 M of the preconditioners).
  HelmholtzOperator shifted(T mass_coefficient) const {
    HelmholtzOperator s(el_, {}, constrained_, mass_coefficient);
    s.distribute(halo_, comm_);
    return s;
  }
  // Sums over the parts (krylov.hpp); nothing with one part.
  void reduce_sum(double* values, int count) const {
    if (comm_) comm_->sum(values, count);
  }
  const Halo<V>* halo() const { return halo_.get(); }

  // y = K x on the free DoFs, y = x on the constrained ones. Distributed: the ghost entries of x are
  // updated first (one halo exchange); y is then complete on the owned rows, its ghost rows are not.
  void apply(const View1<V>& x, const View1<V>& y) const;

  // y = K x with every DoF free (the Dirichlet lifting K g).
  void apply_unconstrained(const View1<V>& x, const View1<V>& y) const;

  // d = diag(K) without forming K (1 on constrained rows); distributed: ghost entries from their owners.
  void diagonal(const View1<V>& d) const;

  const fem::HexElements<T>& elements() const { return el_; }
  const fem::HexFaces<T, V>& impedance_faces() const { return imp_; }
  T mass_coefficient() const { return m_; }

  // Bytes the operator keeps (element map, geometric factors, faces, constraint list).
  std::size_t bytes() const {
    return el_.dofs.span() * sizeof(Index) + el_.geometry.span() * sizeof(T) +
           el_.geometry_slot.span() * sizeof(Index) +
           (el_.affine_batches > 0 ? el_.affine.span() * sizeof(T) : 0) + imp_.dofs.span() * sizeof(Index) +
           imp_.weights.span() * sizeof(T) + imp_.coefficient.span() * sizeof(V) + constrained_.span() * sizeof(Index);
  }

 private:
  fem::HexElements<T> el_;
  fem::HexFaces<T, V> imp_;
  View1<Index> constrained_;
  T m_ = T(0);
  std::shared_ptr<const Halo<V>> halo_;
  std::shared_ptr<const Communicator> comm_;
};

template <class T>
void HelmholtzOperator<T>::apply(const View1<V>& x, const View1<V>& y) const {
  if (halo_) halo_->update(x);
  Kokkos::deep_copy(y, V(0));
  fem::apply_helmholtz_volume(el_, m_, x, y);
  if (imp_.faces() > 0) fem::apply_face_mass(imp_, x, y);
  if (constrained_.extent(0) > 0) fem::copy_constrained_rows(constrained_, x, y);
}

template <class T>
void HelmholtzOperator<T>::apply_unconstrained(const View1<V>& x, const View1<V>& y) const {
  if (halo_) halo_->update(x);
  Kokkos::deep_copy(y, V(0));
  fem::apply_helmholtz_volume_unconstrained(el_, m_, x, y);
  if (imp_.faces() > 0) fem::apply_face_mass_unconstrained(imp_, x, y);
}

template <class T>
void HelmholtzOperator<T>::diagonal(const View1<V>& d) const {
  Kokkos::deep_copy(d, V(0));
  fem::add_helmholtz_volume_diagonal(el_, m_, d);
  if (imp_.faces() > 0) fem::add_face_mass_diagonal(imp_, d);
  if (constrained_.extent(0) > 0) fem::fill_constrained(constrained_, V(1), d);
  if (halo_) halo_->update(d);  // ghost rows: the owners' complete values
}

// Instantiated in models/helmholtz/helmholtz.cpp (see helmholtz.hpp).
extern template class HelmholtzOperator<double>;
extern template class HelmholtzOperator<float>;

}  // namespace polymech::helmholtz
