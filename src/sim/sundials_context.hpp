#pragma once
// RAII owners for the SUNDIALS objects the CVODE wrapper needs, and the checked-call helpers that
// turn every SUNDIALS return code into an adcs::sim::SimError naming the call.
//
// Why a separate, non-template file: the ownership and error plumbing does not depend on the plant,
// so it is compiled once (sundials_context.cpp) instead of in every CvodeIntegrator<Plant>.
// Written against SUNDIALS 6.4 (Debian 12); the few 7.x differences are behind
// SUNDIALS_VERSION_MAJOR in the .cpp.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <memory>
#include <string>
#include <type_traits>

#include "sim/sim_error.hpp"

namespace adcs::sim {

// ---- Checked calls ------------------------------------------------------------------------------

//! Name of a CVODE return flag ("CV_TOO_MUCH_WORK"), from CVodeGetReturnFlagName.
std::string cvode_flag_name(int flag);
//! Name of a CVLS return flag ("CVLS_MEM_NULL"), from CVodeGetLinReturnFlagName.
std::string cvode_ls_flag_name(int flag);

//! Throws SimError("<call> failed: flag <flag> (<name>)[: <detail>]") when flag < 0 (CVODE
//! reports errors as negative flags; 0 and positive flags such as CV_TSTOP_RETURN are success).
void check_cvode(int flag, const char* call, const std::string& detail = {});
//! Same for the CVLS functions (CVodeSetLinearSolver, CVodeSetJacFn), whose flags have their own
//! names.
void check_cvode_ls(int flag, const char* call, const std::string& detail = {});
//! Throws SimError("<call> failed: returned NULL") for SUNDIALS constructors, which report failure
//! by returning NULL.
[[noreturn]] void throw_null(const char* call);
template <class Ptr>
Ptr check_created(Ptr p, const char* call) {
  if (p == nullptr) throw_null(call);
  return p;
}

// ---- Owners -------------------------------------------------------------------------------------

//! Owns a SUNContext (the SUNDIALS 6+ simulation context every object is created in).
//! Invariant: get() is a valid context for the lifetime of the object (moved-from: nullptr).
class SundialsContext {
 public:
  SundialsContext();  //!< Throws SimError if SUNContext_Create fails.
  ~SundialsContext();
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  SundialsContext(SundialsContext&& other) noexcept;
  SundialsContext& operator=(SundialsContext&& other) noexcept;

  SUNContext get() const noexcept { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

//! Owns a serial N_Vector of fixed length.
class SerialVector {
 public:
  SerialVector(sunindextype length, SUNContext ctx);  //!< Throws SimError if N_VNew_Serial fails.
  ~SerialVector();
  SerialVector(const SerialVector&) = delete;
  SerialVector& operator=(const SerialVector&) = delete;
  SerialVector(SerialVector&& other) noexcept;
  SerialVector& operator=(SerialVector&& other) noexcept;

  N_Vector get() const noexcept { return v_; }
  //! Contiguous storage of the vector (length() doubles).
  double* data() const noexcept { return N_VGetArrayPointer(v_); }
  sunindextype length() const noexcept { return N_VGetLength(v_); }

 private:
  N_Vector v_ = nullptr;
};

namespace detail {
struct MatrixDeleter {
  void operator()(std::remove_pointer_t<SUNMatrix>* m) const noexcept;
};
struct LinearSolverDeleter {
  void operator()(std::remove_pointer_t<SUNLinearSolver>* ls) const noexcept;
};
struct NonlinearSolverDeleter {
  void operator()(std::remove_pointer_t<SUNNonlinearSolver>* nls) const noexcept;
};
}  // namespace detail

using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, detail::MatrixDeleter>;
using LinearSolverPtr =
    std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, detail::LinearSolverDeleter>;
using NonlinearSolverPtr =
    std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, detail::NonlinearSolverDeleter>;

//! Owns a CVODE memory block (CVodeCreate/CVodeFree) and captures CVODE's error messages instead of
//! letting CVODE print them, so that check() can put the message into the SimError.
class CvodeMemory {
 public:
  //! lmm is CV_ADAMS or CV_BDF. Throws SimError if CVodeCreate fails.
  CvodeMemory(int lmm, SUNContext ctx);
  ~CvodeMemory();
  CvodeMemory(const CvodeMemory&) = delete;
  CvodeMemory& operator=(const CvodeMemory&) = delete;
  CvodeMemory(CvodeMemory&& other) noexcept;
  CvodeMemory& operator=(CvodeMemory&& other) noexcept;

  void* get() const noexcept { return mem_; }
  //! check_cvode() with CVODE's last captured message (and `extra`, if any) as detail.
  void check(int flag, const char* call, const std::string& extra = {}) const;
  //! check_cvode_ls() with CVODE's last captured message as detail.
  void check_ls(int flag, const char* call) const;
  //! Number of warnings CVODE reported (e.g. "t + h = t on the next step"); they do not throw.
  long warning_count() const noexcept { return log_ ? log_->warnings : 0; }

  //! What the error handler writes to. Heap-allocated so its address survives a move.
  struct Log {
    std::string last_message;
    long warnings = 0;
  };

 private:
  void* mem_ = nullptr;
  std::unique_ptr<Log> log_;
};

}  // namespace adcs::sim
