// Replay core of seed 004 ESKF + saturated ESF + fusion + ADRC: the one translation unit that compiles
// the System (replay_dragfree.hpp) and its flight code, per side. The host build links it into
// replay_dragfree_host and into record_inputs; the Cortex-M7 build into replay_dragfree.elf.
#include "replay_dragfree.hpp"
#include "replay_runtime.hpp"

namespace {
replay::DragFreeSystem<double> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kDragFree = replay::ApiOf<replay::DragFreeSystem<double>, &g_system>::make();
