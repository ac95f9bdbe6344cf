// Replay core of seed 002's ATC baseline in float (replay_euler_f.hpp, AdaptiveTrackingT<float>): the one translation unit that compiles the
// System and its flight code, per side. The host build links it into replay_atc_f_host and into
// record_inputs; the Cortex-M4F build into replay_atc_f.elf.
#include "replay_euler_f.hpp"
#include "replay_runtime.hpp"

namespace {
replay::EulerFloatSystem<adcs::AdaptiveTrackingT<float>> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kAtcF = replay::ApiOf<replay::EulerFloatSystem<adcs::AdaptiveTrackingT<float>>, &g_system>::make();
