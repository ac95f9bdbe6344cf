// Replay core of seed 003 prescribed-time SE(3) (PrescribedTimeSe3 + sat/Q): the one translation unit that compiles
// the System (replay_se3.hpp) and its flight code, per side. The host build links it into
// replay_se3_host and into record_inputs; the Cortex-M7 build into replay_se3.elf.
#include "replay_se3.hpp"
#include "replay_runtime.hpp"

namespace {
replay::Se3System g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kSe3 = replay::ApiOf<replay::Se3System, &g_system>::make();
