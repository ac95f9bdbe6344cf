// Replay core of the ESO-based ADRC of the cross pairing in float (replay_euler_f.hpp,
// EsoAdrcAttitudeT<float>): the one translation unit that compiles the
// System and its flight code, per side. The host build links it into replay_eso_adrc_f_host and into
// record_inputs; the Cortex-M4F build into replay_eso_adrc_f.elf.
#include "replay_euler_f.hpp"
#include "replay_runtime.hpp"

namespace {
replay::EulerFloatSystem<adcs::EsoAdrcAttitudeT<float>> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kEsoAdrcF = replay::ApiOf<replay::EulerFloatSystem<adcs::EsoAdrcAttitudeT<float>>, &g_system>::make();
