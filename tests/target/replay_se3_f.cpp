// Replay core of seed 003 in float (replay_se3_f.hpp, PrescribedTimeSe3T<float>): the one
// translation unit that compiles the System and its flight code, per side. The host build links
// it into replay_se3_f_host and into record_inputs; the Cortex-M4F build into replay_se3_f.elf.
#include "replay_se3_f.hpp"
#include "replay_runtime.hpp"

namespace {
replay::Se3FloatSystem<adcs::PrescribedTimeSe3T<float>> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kSe3F = replay::ApiOf<replay::Se3FloatSystem<adcs::PrescribedTimeSe3T<float>>, &g_system>::make();
