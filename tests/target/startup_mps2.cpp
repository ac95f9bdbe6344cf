// Bare-metal start-up of the replay programs on QEMU's mps2-an500 (Cortex-M7, hard float),
// replacing newlib's rdimon crt0, which neither provides the vector table an M-profile core reads
// at reset nor enables the FPU, and which moves SP to the emulator's SYS_HEAPINFO answer
// (/work/shared/TOOLCHAIN-NOTES.md). Linked with -nostartfiles and mps2_an500.ld.
//
// Reset: enable CP10/CP11 (FPU) before any floating-point instruction, copy .data from its load
// address, zero .bss, open the semihosting stdio handles, run the static constructors, build
// argv from the semihosting command line (QEMU -append), exit(main(argc, argv)) — newlib's exit
// reports the code to QEMU via semihosting. Faults print a message and exit with status 1.
#include <cstdint>
#include <cstdlib>

extern "C" {
extern std::uint32_t __data_load__, __data_start__, __data_end__, __bss_start__, __bss_end__, __stack_top__;
void initialise_monitor_handles(void);
void __libc_init_array(void);
// The program's main under another C++ name: ISO C++ forbids calling main itself.
int program_main(int argc, char** argv) __asm__("main");

// crti.o/crtbegin.o are not linked (-nostartfiles): __libc_init_array still calls _init.
void _init(void) {}
void _fini(void) {}
void* __dso_handle = nullptr;
}

namespace {

// ARM semihosting (ARM DUI 0471, "Semihosting operations"): BKPT 0xAB on M-profile, r0 = operation,
// r1 = argument; QEMU implements it with -semihosting-config enable=on.
int semihost(int op, const void* arg) {
  register int r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}
constexpr int kSysWrite0 = 0x04, kSysGetCmdline = 0x15, kSysExit = 0x18;
constexpr int kAdpStoppedRunTimeError = 0x20023;  // QEMU exits with status 1

constexpr int kMaxArgs = 16;
char g_cmdline[256];
char* g_argv[kMaxArgs + 1];

//! Splits the semihosting command line ("<kernel> <-append words>") at spaces.
int build_argv() {
  struct {
    char* buf;
    int size;
  } block{g_cmdline, static_cast<int>(sizeof g_cmdline) - 1};
  if (semihost(kSysGetCmdline, &block) != 0) block.size = 0;
  g_cmdline[block.size > 0 ? block.size : 0] = '\0';
  int argc = 0;
  for (char* p = g_cmdline; *p && argc < kMaxArgs;) {
    while (*p == ' ') *p++ = '\0';
    if (!*p) break;
    g_argv[argc++] = p;
    while (*p && *p != ' ') ++p;
  }
  g_argv[argc] = nullptr;
  return argc;
}

}  // namespace

extern "C" {

[[noreturn]] void reset_continue() {
  const std::uint32_t* src = &__data_load__;
  for (std::uint32_t* dst = &__data_start__; dst < &__data_end__;) *dst++ = *src++;
  for (std::uint32_t* dst = &__bss_start__; dst < &__bss_end__;) *dst++ = 0;
  initialise_monitor_handles();
  __libc_init_array();
  const int argc = build_argv();
  std::exit(program_main(argc, g_argv));
}

// Naked: the compiler may use FP registers even for plain copies (vldr/vstr), so nothing but
// this assembly runs before CPACR grants CP10/CP11 full access (ARMv7-M ARM B3.2.20).
__attribute__((naked, noreturn)) void Reset_Handler() {
  __asm__ volatile(
      "ldr r0, =0xE000ED88\n"  // CPACR
      "ldr r1, [r0]\n"
      "orr r1, r1, #(0xF << 20)\n"
      "str r1, [r0]\n"
      "dsb\n"
      "isb\n"
      "b reset_continue\n");
}

[[noreturn]] void Fault_Handler() {
  semihost(kSysWrite0, "replay: fault exception (HardFault/MemManage/BusFault/UsageFault/NMI)\n");
  for (;;) semihost(kSysExit, reinterpret_cast<const void*>(kAdpStoppedRunTimeError));
}

[[noreturn]] void Unexpected_Handler() {
  semihost(kSysWrite0, "replay: unexpected exception\n");
  for (;;) semihost(kSysExit, reinterpret_cast<const void*>(kAdpStoppedRunTimeError));
}

// ARMv7-M vector table (B1.5.3): initial SP, then the 15 system exceptions. No interrupts are
// enabled, so no external vectors are needed.
using Vector = void (*)();
__attribute__((section(".isr_vector"), used)) const Vector g_vectors[16] = {
    reinterpret_cast<Vector>(&__stack_top__),  // initial main stack pointer
    Reset_Handler,
    Fault_Handler,       // NMI
    Fault_Handler,       // HardFault
    Fault_Handler,       // MemManage
    Fault_Handler,       // BusFault
    Fault_Handler,       // UsageFault
    nullptr, nullptr, nullptr, nullptr,
    Unexpected_Handler,  // SVCall
    Unexpected_Handler,  // DebugMonitor
    nullptr,
    Unexpected_Handler,  // PendSV
    Unexpected_Handler,  // SysTick (its interrupt is never enabled)
};
}
