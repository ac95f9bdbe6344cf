// Cortex-M7 instantiation unit 5 of 5 (see instantiate_attitude.cpp): Algorithm 1 on the whole
// 27-state model (the reference the two-block DragFreeEskf is tested against), with its PSD
// projection at 27 states. Alone because it is the costliest unit to compile.
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"

namespace adcs {
template class Eskf<27, 9, 9, 9>;
template bool keep_psd<27>(Mat<27, 27>&) noexcept;
}  // namespace adcs
