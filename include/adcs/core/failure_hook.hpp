#pragma once
// A replaceable failure hook (Sophus-style) for violated preconditions and invariants that are
// programming errors, e.g. a parameter struct rejected by a constructor. Flight code never
// throws or aborts by itself: it calls the hook and returns a Status. The default hook only
// counts; ground code installs one that prints and aborts, flight software one that raises an
// FDIR event.
#include <cstdint>

namespace adcs {

//! Signature of a failure hook. Must not throw.
using FailureHook = void (*)(const char* file, int line, const char* message) noexcept;

namespace detail {
inline std::uint32_t& failure_count() noexcept {
  static std::uint32_t count = 0;
  return count;
}
inline void default_failure_hook(const char*, int, const char*) noexcept { ++failure_count(); }
inline FailureHook& failure_hook_slot() noexcept {
  static FailureHook hook = &default_failure_hook;
  return hook;
}
}  // namespace detail

//! Installs `hook` (nullptr restores the default) and returns the previous one.
inline FailureHook set_failure_hook(FailureHook hook) noexcept {
  FailureHook previous = detail::failure_hook_slot();
  detail::failure_hook_slot() = hook ? hook : &detail::default_failure_hook;
  return previous;
}

//! Number of failures seen by the default hook since start-up.
inline std::uint32_t default_failure_count() noexcept { return detail::failure_count(); }

//! Reports a failure through the installed hook.
inline void report_failure(const char* file, int line, const char* message) noexcept {
  detail::failure_hook_slot()(file, line, message);
}

}  // namespace adcs

//! Checks a precondition; on failure calls the hook and evaluates to false.
#define ADCS_CHECK(cond, message) \
  ((cond) ? true : (::adcs::report_failure(__FILE__, __LINE__, (message)), false))
