// Replay core of the rigid-wheel attitude chain in double (replay_attitude.hpp): the one translation
// unit that compiles the System and its flight code, per side. The host build links it into
// replay_attitude_host and into record_inputs; the Cortex-M7 build into replay_attitude.elf.
#include "replay_attitude.hpp"
#include "replay_runtime.hpp"

namespace {
replay::AttitudeSystem<double> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kAttitude = replay::ApiOf<replay::AttitudeSystem<double>, &g_system>::make();
