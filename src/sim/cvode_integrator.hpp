#pragma once
// CVODE (SUNDIALS) integrator for any Plant (docs/CONTRACTS.md), with the same interface as
// Rk4Integrator: reset(t0, x0) then advance(t1, u, x) with the input u held over [t, t1].
//
// Adams + fixed-point iteration for non-stiff plants (no Jacobian, nothing allocated per step), or
// BDF + dense direct solver for stiff ones, with the plant's analytic jacobian() when it has one
// (else CVODE's difference quotients). Every SUNDIALS return code is checked; failures throw
// SimError("CVodeXxx failed: flag N (NAME): <CVODE's message>").
#include <cvode/cvode_ls.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "adcs/core/types.hpp"
#include "sim/plant_traits.hpp"
#include "sim/sim_error.hpp"
#include "sim/sundials_context.hpp"

namespace adcs::sim {

struct CvodeOptions {
  enum class Method {
    adams_fixed_point,  //!< non-stiff: Adams-Moulton, fixed-point iteration (no Jacobian)
    bdf_dense,          //!< stiff: BDF, Newton iteration with a dense direct linear solver
  };
  Method method = Method::adams_fixed_point;
  double rtol = 1e-10;      //!< [-] relative tolerance
  double atol = 1e-12;      //!< [state units] absolute tolerance, every component
  long max_steps = 500000;  //!< [-] max internal steps per advance() (CVodeSetMaxNumSteps;
                            //!<     0 = CVODE default 500, < 0 = unlimited)
  double max_step = 0.0;    //!< [s] max internal step size, 0 = no limit
  bool analytic_jacobian = true;  //!< bdf_dense only: use Plant::jacobian() when it exists
};

//! Owns a SUNContext, the state N_Vector, the CVODE memory and its solver objects.
//! The plant is held by pointer: it must outlive the integrator. Not copyable; movable.
//! After a SimError from advance(), call reset() before advancing again.
template <class Plant>
class CvodeIntegrator {
 public:
  using State = typename Plant::State;
  using Input = typename Plant::Input;
  static constexpr int kStateSize = Plant::kStateSize;
  static_assert(kStateSize > 0, "CvodeIntegrator needs a fixed, positive Plant::kStateSize");

  //! Creates and configures every SUNDIALS object (CVodeInit at t = 0, x = 0). Throws SimError.
  explicit CvodeIntegrator(const Plant& plant, CvodeOptions options = {})
      : options_(options),
        callback_(std::make_unique<Callback>(Callback{&plant, Input::Zero(), false, 0.0})),
        y_(kStateSize, context_.get()),
        cvode_(options.method == CvodeOptions::Method::bdf_dense ? CV_BDF : CV_ADAMS,
               context_.get()) {
    state_map() = State::Zero();
    void* mem = cvode_.get();
    cvode_.check(CVodeInit(mem, &CvodeIntegrator::rhs, 0.0, y_.get()), "CVodeInit");
    // Why: the callbacks need the plant and the held input; the Callback lives on the heap so the
    // pointer CVODE keeps stays valid when the integrator is moved.
    cvode_.check(CVodeSetUserData(mem, callback_.get()), "CVodeSetUserData");
    cvode_.check(CVodeSStolerances(mem, options.rtol, options.atol), "CVodeSStolerances");
    cvode_.check(CVodeSetMaxNumSteps(mem, options.max_steps), "CVodeSetMaxNumSteps");
    cvode_.check(CVodeSetMaxStep(mem, options.max_step), "CVodeSetMaxStep");
    if (options.method == CvodeOptions::Method::bdf_dense) {
      matrix_.reset(check_created(SUNDenseMatrix(kStateSize, kStateSize, context_.get()),
                                  "SUNDenseMatrix"));
      linear_solver_.reset(check_created(
          SUNLinSol_Dense(y_.get(), matrix_.get(), context_.get()), "SUNLinSol_Dense"));
      cvode_.check_ls(CVodeSetLinearSolver(mem, linear_solver_.get(), matrix_.get()),
                      "CVodeSetLinearSolver");
      if constexpr (has_jacobian_v<Plant>) {
        if (options.analytic_jacobian)
          cvode_.check_ls(CVodeSetJacFn(mem, &CvodeIntegrator::jac<Plant>), "CVodeSetJacFn");
      }
    } else {
      // m = 0: plain fixed-point iteration, no Anderson acceleration vectors.
      nonlinear_solver_.reset(check_created(SUNNonlinSol_FixedPoint(y_.get(), 0, context_.get()),
                                            "SUNNonlinSol_FixedPoint"));
      cvode_.check(CVodeSetNonlinearSolver(mem, nonlinear_solver_.get()),
                   "CVodeSetNonlinearSolver");
    }
  }

  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;
  CvodeIntegrator(CvodeIntegrator&&) noexcept = default;
  //! Why swap: member-wise move assignment would free our SUNContext before our CVODE memory;
  //! swapping hands the old objects to `other`, whose destructor frees them in the right order.
  CvodeIntegrator& operator=(CvodeIntegrator&& other) noexcept {
    using std::swap;
    swap(options_, other.options_);
    swap(callback_, other.callback_);
    swap(context_, other.context_);
    swap(y_, other.y_);
    swap(matrix_, other.matrix_);
    swap(linear_solver_, other.linear_solver_);
    swap(nonlinear_solver_, other.nonlinear_solver_);
    swap(cvode_, other.cvode_);
    swap(t_, other.t_);
    swap(steps_before_reinit_, other.steps_before_reinit_);
    swap(input_held_, other.input_held_);
    return *this;
  }
  ~CvodeIntegrator() = default;

  //! Restarts the integration at (t0 [s], x0) with CVodeReInit (history discarded: use after the
  //! command changed or the state was re-parameterised). Throws SimError on non-finite t0 or x0.
  void reset(double t0, const State& x0) {
    if (!std::isfinite(t0) || !adcs::all_finite(x0))
      throw SimError("CvodeIntegrator::reset: non-finite t0 or x0");
    state_map() = x0;
    reinit(t0);
    input_held_ = false;
    callback_->non_finite_derivative = false;
  }

  //! Integrates from time() to exactly t1 [s] with u held, writing x(t1) to x. The stop time is
  //! set to t1 on every call, so CVODE never evaluates the plant beyond t1. If u differs from the
  //! input of the previous advance() since reset(), CVODE is re-initialised at time() first (its
  //! multistep history assumed the old input). Throws SimError (t1 < time(), or any CVODE error).
  void advance(double t1, const Input& u, State& x) {
    if (!(t1 >= t_) || !std::isfinite(t1))
      throw SimError("CvodeIntegrator::advance: t1 = " + format_double(t1) +
                     " s is not a finite time at or after the current time " +
                     format_double(t_) + " s");
    if (input_held_ && u != callback_->u) reinit(t_);
    callback_->u = u;
    input_held_ = true;
    if (t1 > t_) {
      void* mem = cvode_.get();
      // CVodeClearStopTime does not exist before SUNDIALS 6.5.1, and CVODE forgets the stop time
      // once reached: set it on every interval.
      cvode_.check(CVodeSetStopTime(mem, t1), "CVodeSetStopTime");
      sunrealtype t_reached = t_;
      const int flag = CVode(mem, t1, y_.get(), &t_reached, CV_NORMAL);
      if (flag < 0) {
        t_ = t_reached;  // y_ holds the solution at t_reached
        cvode_.check(flag, "CVode",
                     callback_->non_finite_derivative
                         ? "non-finite plant derivative at t = " +
                               format_double(callback_->non_finite_t) + " s"
                         : std::string{});
      }
      t_ = t1;
    }
    x = state_map();
  }

  //! Current time [s]: t0 of the last reset(), or t1 of the last advance().
  double time() const noexcept { return t_; }

  //! Cumulative number of internal CVODE steps since construction (summed across re-inits).
  long steps() const {
    long n = 0;
    cvode_.check(CVodeGetNumSteps(cvode_.get(), &n), "CVodeGetNumSteps");
    return steps_before_reinit_ + n;
  }

  //! Number of CVODE warnings so far (e.g. "t + h = t on the next step"); they do not throw.
  long warnings() const noexcept { return cvode_.warning_count(); }

  const CvodeOptions& options() const noexcept { return options_; }

 private:
  //! What the C callbacks see through CVODE's user-data pointer.
  struct Callback {
    const Plant* plant;
    Input u;                             //!< held (ZOH) input of the current interval
    bool non_finite_derivative = false;  //!< latched by rhs() until reset()
    double non_finite_t = 0.0;           //!< [s] time of the first non-finite derivative
  };
  using JacobianMatrix = Eigen::Matrix<double, kStateSize, kStateSize, Eigen::ColMajor>;

  Eigen::Map<State> state_map() noexcept { return Eigen::Map<State>(y_.data()); }
  Eigen::Map<const State> state_map() const noexcept { return Eigen::Map<const State>(y_.data()); }

  void reinit(double t0) {
    long n = 0;
    cvode_.check(CVodeGetNumSteps(cvode_.get(), &n), "CVodeGetNumSteps");
    cvode_.check(CVodeReInit(cvode_.get(), t0, y_.get()), "CVodeReInit");
    steps_before_reinit_ += n;  // CVodeReInit zeroes CVODE's counters
    t_ = t0;
  }

  // Return codes: 0 = ok, < 0 = unrecoverable. A non-finite derivative is a plant failure: it is
  // latched, and every later call fails too until reset(). Why the latch: SUNDIALS 6.4's
  // fixed-point solver reports an unrecoverable RHS failure to CVODE as a recoverable convergence
  // failure, so CVODE would shrink the step towards the point where the plant breaks and creep up
  // to it until CV_TOO_MUCH_WORK (500000 steps), hiding the cause. Latched, CVODE gives up after
  // a few step reductions (CV_CONV_FAILURE with fixed point, CV_RHSFUNC_FAIL with Newton), and
  // advance() names the time of the first non-finite derivative in the SimError.
  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
    auto* cb = static_cast<Callback*>(user_data);
    if (cb->non_finite_derivative) return -1;
    const State x = Eigen::Map<const State>(N_VGetArrayPointer(y));
    State xdot;
    cb->plant->derivative(t, x, cb->u, xdot);
    if (!adcs::all_finite(xdot)) {
      cb->non_finite_derivative = true;
      cb->non_finite_t = t;
      return -1;
    }
    Eigen::Map<State>(N_VGetArrayPointer(ydot)) = xdot;
    return 0;
  }

  // A member template so that it is instantiated only when used, i.e. when the plant has
  // jacobian() (also under an explicit instantiation of the class).
  template <class P = Plant>
  static int jac(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* user_data,
                 N_Vector /*tmp1*/, N_Vector /*tmp2*/, N_Vector /*tmp3*/) noexcept {
    const auto* cb = static_cast<const Callback*>(user_data);
    const State x = Eigen::Map<const State>(N_VGetArrayPointer(y));
    adcs::Mat<kStateSize, kStateSize> jacobian;
    static_cast<const P*>(cb->plant)->jacobian(t, x, cb->u, jacobian);
    if (!adcs::all_finite(jacobian)) return -1;  // CVode fails with CV_LSETUP_FAIL
    // SUNDenseMatrix stores its N*N entries column-major, like Eigen's default.
    Eigen::Map<JacobianMatrix>(SUNDenseMatrix_Data(J)) = jacobian;
    return 0;
  }

  // Declaration order is destruction order reversed: CVODE memory goes first, the context last.
  CvodeOptions options_;
  std::unique_ptr<Callback> callback_;
  SundialsContext context_;
  SerialVector y_;
  MatrixPtr matrix_;
  LinearSolverPtr linear_solver_;
  NonlinearSolverPtr nonlinear_solver_;
  CvodeMemory cvode_;
  double t_ = 0.0;                //!< [s] time of the state in y_
  long steps_before_reinit_ = 0;  //!< CVODE steps taken before the last CVodeReInit
  bool input_held_ = false;       //!< an advance() has set the input since the last reset()
};

}  // namespace adcs::sim
