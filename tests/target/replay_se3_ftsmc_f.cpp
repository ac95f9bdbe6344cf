// Replay core of seed 003's FTSMC baseline in float (replay_se3_f.hpp, FtsmcSe3T<float>): the one
// translation unit that compiles the System and its flight code, per side. The host build links
// it into replay_se3_ftsmc_f_host and into record_inputs; the Cortex-M4F build into
// replay_se3_ftsmc_f.elf.
#include "replay_se3_f.hpp"
#include "replay_runtime.hpp"

namespace {
replay::Se3FloatSystem<adcs::FtsmcSe3T<float>> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kSe3FtsmcF = replay::ApiOf<replay::Se3FloatSystem<adcs::FtsmcSe3T<float>>, &g_system>::make();
