#pragma once
// What a controller outputs after a step that produced no command (a status that is not
// usable(): non_finite_input, out_of_range, singular, invalid_parameter, request_not_met, ...).
// One rule for every controller in include/adcs (docs/FAILURE-POLICY.md has the table):
//
//   safe_command (default)  the controller family's safe command: zero torque / force for the
//                           torque and wrench laws (MrpPd, PpcNeural, AdaptiveTracking,
//                           PrescribedTimeSe3, FtsmcSe3), zero gimbal rate and zero wheel
//                           acceleration for HybridAdaptive, zero actuation for DragFreeAdrc and
//                           Pid. The spacecraft coasts with its momentum: nothing the law got wrong
//                           is applied for another period;
//   hold_last               the last good command again (the papers' zero-order-hold reading).
//                           Only safe when the failure is brief and the law's state is still
//                           valid; it tumbled a 10 Hz cubesat whose PPC law had left its funnel
//                           (issue 15), so it is an explicit choice, never the default.
//
// In both cases the law's internal state (estimates, integrators, funnel) is left untouched, as
// each step() documents, and the status tells the caller what happened.
#include <cstdint>

namespace adcs {

enum class FailurePolicy : std::uint8_t {
  safe_command = 0,  //!< the family's safe command (default)
  hold_last = 1,     //!< the last good command (zero after reset())
};

//! The command to output after a failed step: `last_good` under hold_last, `safe` otherwise.
template <class Command>
Command failure_command(FailurePolicy policy, const Command& last_good, const Command& safe) noexcept {
  return policy == FailurePolicy::hold_last ? last_good : safe;
}

}  // namespace adcs
