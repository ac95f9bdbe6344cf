#include "sim/sundials_context.hpp"

#include <cvode/cvode_ls.h>

#include <cstdlib>
#include <utility>

namespace adcs::sim {

namespace {

// CVode*ReturnFlagName returns a malloc'd string that the caller must free (checked for 6.4.1).
std::string take_name(char* name) {
  if (name == nullptr) return "unknown";
  std::string s(name);
  std::free(name);
  return s;
}

[[noreturn]] void throw_flag(const char* call, int flag, const std::string& name,
                             const std::string& detail) {
  std::string what = std::string(call) + " failed: flag " + std::to_string(flag) + " (" + name + ")";
  if (!detail.empty()) what += ": " + detail;
  throw SimError(what);
}

#if SUNDIALS_VERSION_MAJOR < 7
// Why: CVODE's default handler prints to stderr; we keep the text and put it in the SimError.
void capture_error(int error_code, const char* /*module*/, const char* function, char* msg,
                   void* eh_data) {
  auto* log = static_cast<CvodeMemory::Log*>(eh_data);
  if (error_code == CV_WARNING) ++log->warnings;
  log->last_message = std::string(function != nullptr ? function : "?") + ": " +
                      (msg != nullptr ? msg : "");
}
#endif

}  // namespace

std::string cvode_flag_name(int flag) { return take_name(CVodeGetReturnFlagName(flag)); }
std::string cvode_ls_flag_name(int flag) { return take_name(CVodeGetLinReturnFlagName(flag)); }

void check_cvode(int flag, const char* call, const std::string& detail) {
  if (flag < 0) throw_flag(call, flag, cvode_flag_name(flag), detail);
}

void check_cvode_ls(int flag, const char* call, const std::string& detail) {
  if (flag < 0) throw_flag(call, flag, cvode_ls_flag_name(flag), detail);
}

void throw_null(const char* call) { throw SimError(std::string(call) + " failed: returned NULL"); }

// ---- SundialsContext ------------------------------------------------------------------------------

SundialsContext::SundialsContext() {
#if SUNDIALS_VERSION_MAJOR >= 7
  const int flag = SUNContext_Create(SUN_COMM_NULL, &ctx_);
#else
  const int flag = SUNContext_Create(nullptr, &ctx_);
#endif
  if (flag != 0 || ctx_ == nullptr)
    throw SimError("SUNContext_Create failed: flag " + std::to_string(flag));
}

SundialsContext::~SundialsContext() {
  if (ctx_ != nullptr) SUNContext_Free(&ctx_);
}

SundialsContext::SundialsContext(SundialsContext&& other) noexcept
    : ctx_(std::exchange(other.ctx_, nullptr)) {}

SundialsContext& SundialsContext::operator=(SundialsContext&& other) noexcept {
  if (this != &other) {
    if (ctx_ != nullptr) SUNContext_Free(&ctx_);
    ctx_ = std::exchange(other.ctx_, nullptr);
  }
  return *this;
}

// ---- SerialVector ---------------------------------------------------------------------------------

SerialVector::SerialVector(sunindextype length, SUNContext ctx)
    : v_(check_created(N_VNew_Serial(length, ctx), "N_VNew_Serial")) {}

SerialVector::~SerialVector() {
  if (v_ != nullptr) N_VDestroy(v_);
}

SerialVector::SerialVector(SerialVector&& other) noexcept : v_(std::exchange(other.v_, nullptr)) {}

SerialVector& SerialVector::operator=(SerialVector&& other) noexcept {
  if (this != &other) {
    if (v_ != nullptr) N_VDestroy(v_);
    v_ = std::exchange(other.v_, nullptr);
  }
  return *this;
}

// ---- Deleters -------------------------------------------------------------------------------------

namespace detail {
void MatrixDeleter::operator()(std::remove_pointer_t<SUNMatrix>* m) const noexcept {
  SUNMatDestroy(m);
}
void LinearSolverDeleter::operator()(std::remove_pointer_t<SUNLinearSolver>* ls) const noexcept {
  SUNLinSolFree(ls);
}
void NonlinearSolverDeleter::operator()(
    std::remove_pointer_t<SUNNonlinearSolver>* nls) const noexcept {
  SUNNonlinSolFree(nls);
}
}  // namespace detail

// ---- CvodeMemory ----------------------------------------------------------------------------------

CvodeMemory::CvodeMemory(int lmm, SUNContext ctx)
    : mem_(check_created(CVodeCreate(lmm, ctx), "CVodeCreate")), log_(std::make_unique<Log>()) {
#if SUNDIALS_VERSION_MAJOR < 7
  const int flag = CVodeSetErrHandlerFn(mem_, capture_error, log_.get());
  if (flag < 0) {
    CVodeFree(&mem_);
    check_cvode(flag, "CVodeSetErrHandlerFn");
  }
#endif
}

CvodeMemory::~CvodeMemory() {
  if (mem_ != nullptr) CVodeFree(&mem_);
}

CvodeMemory::CvodeMemory(CvodeMemory&& other) noexcept
    : mem_(std::exchange(other.mem_, nullptr)), log_(std::move(other.log_)) {}

CvodeMemory& CvodeMemory::operator=(CvodeMemory&& other) noexcept {
  if (this != &other) {
    if (mem_ != nullptr) CVodeFree(&mem_);
    mem_ = std::exchange(other.mem_, nullptr);
    log_ = std::move(other.log_);
  }
  return *this;
}

void CvodeMemory::check(int flag, const char* call, const std::string& extra) const {
  if (flag >= 0) return;
  std::string detail = log_ ? log_->last_message : std::string{};
  if (!extra.empty()) detail += (detail.empty() ? "" : "; ") + extra;
  check_cvode(flag, call, detail);
}

void CvodeMemory::check_ls(int flag, const char* call) const {
  if (flag < 0) check_cvode_ls(flag, call, log_ ? log_->last_message : std::string{});
}

}  // namespace adcs::sim
