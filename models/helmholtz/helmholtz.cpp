// The Helmholtz model's explicit instantiations (see the end of helmholtz.hpp).
#include "helmholtz/helmholtz.hpp"

namespace polymech::helmholtz {

template class HelmholtzOperator<double>;
template class HelmholtzOperator<float>;
template struct Discretization<double>;
template struct Discretization<float>;
template class Helmholtz<double>;
template class Helmholtz<float>;

}  // namespace polymech::helmholtz
