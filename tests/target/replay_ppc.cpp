// Replay core of seed 002 PPATC (PpcNeural): the one translation unit that compiles
// the System (replay_ppc.hpp) and its flight code, per side. The host build links it into
// replay_ppc_host and into record_inputs; the Cortex-M7 build into replay_ppc.elf.
#include "replay_ppc.hpp"
#include "replay_runtime.hpp"

namespace {
replay::PpcSystem<double> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kPpc = replay::ApiOf<replay::PpcSystem<double>, &g_system>::make();
