// Replay core of seed 004 in float (replay_dragfree.hpp, DragFreeSystem<float>: DragFreeEskfT,
// SaturatedEsfT and DragFreeAdrcT in float): the one translation unit that compiles the System
// and its flight code, per side. The host build links it into replay_dragfree_f_host and into
// record_inputs; the Cortex-M4F build into replay_dragfree_f.elf.
#include "replay_dragfree.hpp"
#include "replay_runtime.hpp"

namespace {
replay::DragFreeSystem<float> g_system;  // static storage: its bytes show in the ELF's .bss
}

const replay::Api replay::kDragFreeF = replay::ApiOf<replay::DragFreeSystem<float>, &g_system>::make();
