// Replay core of seed 001 hybrid adaptive (HybridAdaptive<4, 3>, double): the one translation unit that compiles
// the System (replay_hybrid.hpp) and its flight code, per side. The host build links it into
// replay_hybrid_host and into record_inputs; the Cortex-M7 build into replay_hybrid.elf.
#include "replay_hybrid.hpp"
#include "replay_runtime.hpp"

namespace {
replay::HybridSystem<double> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kHybrid = replay::ApiOf<replay::HybridSystem<double>, &g_system>::make();
