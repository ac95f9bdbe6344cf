// Replay core of seed 002 PPATC in float (replay_ppc.hpp, PpcNeuralT<float>): the one translation
// unit that compiles the System and its flight code, per side. The host build links it into
// replay_ppc_f_host and into record_inputs; the Cortex-M4F build into replay_ppc_f.elf.
#include "replay_ppc.hpp"
#include "replay_runtime.hpp"

namespace {
replay::PpcSystem<float> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kPpcF = replay::ApiOf<replay::PpcSystem<float>, &g_system>::make();
