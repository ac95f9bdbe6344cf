// Replay core of the rigid-wheel attitude chain in float (replay_attitude.hpp): the one translation
// unit that compiles the System and its flight code, per side. The host build links it into
// replay_attitude_f_host and into record_inputs; the Cortex-M4F build into replay_attitude_f.elf.
#include "replay_attitude.hpp"
#include "replay_runtime.hpp"

namespace {
replay::AttitudeSystem<float> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kAttitudeF = replay::ApiOf<replay::AttitudeSystem<float>, &g_system>::make();
