// Replay core of seed 001 hybrid adaptive in float (replay_hybrid.hpp, HybridAdaptive<4, 3, float>):
// the one translation unit that compiles the System and its flight code, per side. The host build
// links it into replay_hybrid_f_host and into record_inputs; the Cortex-M4F build into
// replay_hybrid_f.elf.
#include "replay_hybrid.hpp"
#include "replay_runtime.hpp"

namespace {
replay::HybridSystem<float> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kHybridF = replay::ApiOf<replay::HybridSystem<float>, &g_system>::make();
