/* adcs C interface (C99): the flight laws of include/adcs for C flight frameworks (NASA cFS
 * applications and the like), without heap or exceptions crossing the boundary.
 *
 * Each controller family has
 *   - a parameter struct, an input struct and an output struct of plain C arrays in SI units,
 *     named as in the C++ headers (sigma_BN, omega_BN_B, ...). Matrices are row-major C arrays:
 *     P[i][j] is row i, column j; G_s_B[i][j] is the B-frame component i of wheel j's spin axis;
 *   - an opaque state the CALLER allocates (static storage, a task's stack, a cFS app's global),
 *     of the size and alignment given by ADCS_<FAMILY>_STATE_SIZE / _ALIGN: the C++ component
 *     plus a 4-byte init tag, rounded up to the alignment. The library checks these constants
 *     against the C++ types at compile time (src/c/adcs_c*.cpp, static_assert: equality), on every
 *     platform it is built for (x86-64, Cortex-M7 double, Cortex-M4F single precision; the same
 *     numbers on all three);
 *   - adcs_<family>_init(params, state): validates the parameters and constructs the controller in
 *     the state. It returns ADCS_STATUS_OK, or ADCS_STATUS_INVALID_PARAMETER for a refused set
 *     (the state is then initialised but every step refuses to run and commands the safe output);
 *   - adcs_<family>_step(state, in, out): one sample at the family's period. The returned status
 *     is the C++ step's (adcs::Status), with the numeric values promised below. The output is
 *     always finite: on a failed step it is the family's failure command (zero torque by default,
 *     or the last good command, params.on_failure). A NULL pointer, or a state that init never
 *     wrote, returns ADCS_STATUS_INVALID_PARAMETER and writes nothing.
 *   No call allocates, blocks, or throws; every call is reentrant for distinct states.
 *
 * Families: MRP PD with reaction-wheel momentum feedback (4 wheels; the attitude law of the
 * rigid-wheel scenarios, `adcs::MrpPd<4, S>`), the reaction-wheel torque allocation
 * (`adcs::RwTorqueAllocator<4, S>`), seed 002's prescribed-performance adaptive RBF law
 * (`adcs::PpcNeuralT<S>`), seed 001's adaptive law for 4 CMGs + 3 wheels
 * (`adcs::HybridAdaptive<4, 3, S>`), seed 003's prescribed-time SE(3) law
 * (`adcs::PrescribedTimeSe3T<S>`) and seed 004's drag-free ADRC (`adcs::DragFreeAdrcT<S>`), each in
 * double (suffix none) and single precision (suffix f, for FPUs without double: Cortex-M4F). The
 * papers' baseline laws (seed 002's ATC and ESO-based ADRC, seed 003's FTSMC) and the estimators
 * are C++ only (docs/TARGET.md).
 */
#ifndef ADCS_C_ADCS_H
#define ADCS_C_ADCS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Status: the numeric values are part of the ABI and never change. ----------------------- */
typedef int32_t adcs_status;
#define ADCS_STATUS_OK 0                  /* result computed as specified */
#define ADCS_STATUS_NON_FINITE_INPUT 1    /* NaN/Inf in the input: failure command, state untouched */
#define ADCS_STATUS_OUT_OF_RANGE 2        /* finite input outside its domain: failure command */
#define ADCS_STATUS_SINGULAR 3            /* a matrix to invert was singular */
#define ADCS_STATUS_ILL_CONDITIONED 4     /* usable: a regularised result */
#define ADCS_STATUS_CONSTRAINT_VIOLATED 5 /* usable: a constraint was reached */
#define ADCS_STATUS_SATURATED 6           /* usable: the command was clipped or scaled to a limit */
#define ADCS_STATUS_NOT_CONVERGED 7       /* a bounded iteration hit its limit */
#define ADCS_STATUS_INVALID_PARAMETER 8   /* refused parameters, NULL pointer or uninitialised state */
#define ADCS_STATUS_REQUEST_NOT_MET 9     /* finite bounded output that misses the request */

/* Non-zero for the statuses whose output may be applied as the requested command
 * (ok, ill_conditioned, constraint_violated, saturated); adcs::usable() in C++. */
int adcs_status_usable(adcs_status s);
/* Short stable name ("ok", "non_finite_input", ...); "unknown" for any other value. */
const char* adcs_status_name(adcs_status s);

/* What a failed step commands (adcs::FailurePolicy). */
typedef int32_t adcs_failure_policy;
#define ADCS_FAILURE_SAFE_COMMAND 0 /* the family's safe command: zero torque */
#define ADCS_FAILURE_HOLD_LAST 1    /* the last good command (zero after init) */

/* ---- Caller-allocated opaque state ---------------------------------------------------------- */
#if defined(__cplusplus)
#define ADCS_C_STATE(name, size, align) \
  typedef struct name { alignas(align) unsigned char opaque[size]; } name
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#define ADCS_C_STATE(name, size, align) \
  typedef struct name { _Alignas(align) unsigned char opaque[size]; } name
#elif defined(__GNUC__)
#define ADCS_C_STATE(name, size, align) \
  typedef struct name { unsigned char opaque[size] __attribute__((aligned(align))); } name
#else
#error "adcs.h: C99 needs __attribute__((aligned)) (GCC, clang) for the state objects; or compile as C11"
#endif

/* ---- MRP PD with gyroscopic compensation, 4 reaction wheels (adcs/control/mrp_pd.hpp) --------
 * L_r = -K sigma_BR - P omega_BR_B + J_rw_B (domega_RN_B - omega_BN_B x omega_RN_B)
 *       + omega_BN_B x (J_rw_B omega_BN_B + G_s_B h_s),  h_s = J_s (G_s_B^T omega_BN_B + Omega)
 * (Schaub & Junkins eq. (8.106)-(8.110)). Runs at params.period_s. */
typedef struct adcs_mrp_pd4_params {
  double K;                 /* [N m] attitude gain on sigma_BR, > 0 */
  double P[3][3];           /* [N m s] rate gain on omega_BR_B, symmetric positive definite */
  double J_rw_B[3][3];      /* [kg m^2] J - sum J_s g g^T, B components, SPD */
  double G_s_B[3][4];       /* [-] wheel spin axes (unit columns), B components */
  double J_s[4];            /* [kg m^2] wheel spin inertias, >= 0 */
  double period_s;          /* [s] sample period, > 0 */
  adcs_failure_policy on_failure;
} adcs_mrp_pd4_params;
typedef struct adcs_mrp_pd4_input {
  double sigma_BN[3];       /* [-] measured attitude MRP */
  double omega_BN_B[3];     /* [rad/s] measured body rate, B components */
  double Omega_rad_s[4];    /* [rad/s] wheel speeds relative to the body */
  double sigma_RN[3];       /* [-] reference attitude MRP */
  double omega_RN_N[3];     /* [rad/s] reference rate, N components */
  double domega_RN_N[3];    /* [rad/s^2] reference angular acceleration, N components */
} adcs_mrp_pd4_input;
typedef struct adcs_mrp_pd4_output {
  double torque_B_Nm[3];    /* [N m] commanded body torque, B components */
} adcs_mrp_pd4_output;
#define ADCS_MRP_PD4_STATE_SIZE 352
#define ADCS_MRP_PD4_STATE_ALIGN 16
ADCS_C_STATE(adcs_mrp_pd4_state, ADCS_MRP_PD4_STATE_SIZE, ADCS_MRP_PD4_STATE_ALIGN);
adcs_status adcs_mrp_pd4_init(const adcs_mrp_pd4_params* params, adcs_mrp_pd4_state* state);
adcs_status adcs_mrp_pd4_step(adcs_mrp_pd4_state* state, const adcs_mrp_pd4_input* in,
                              adcs_mrp_pd4_output* out);

/* The same law in single precision (every field float; the law computes in float). */
typedef struct adcs_mrp_pd4f_params {
  float K;
  float P[3][3];
  float J_rw_B[3][3];
  float G_s_B[3][4];
  float J_s[4];
  float period_s;
  adcs_failure_policy on_failure;
} adcs_mrp_pd4f_params;
typedef struct adcs_mrp_pd4f_input {
  float sigma_BN[3];
  float omega_BN_B[3];
  float Omega_rad_s[4];
  float sigma_RN[3];
  float omega_RN_N[3];
  float domega_RN_N[3];
} adcs_mrp_pd4f_input;
typedef struct adcs_mrp_pd4f_output {
  float torque_B_Nm[3];
} adcs_mrp_pd4f_output;
#define ADCS_MRP_PD4F_STATE_SIZE 192
#define ADCS_MRP_PD4F_STATE_ALIGN 16
ADCS_C_STATE(adcs_mrp_pd4f_state, ADCS_MRP_PD4F_STATE_SIZE, ADCS_MRP_PD4F_STATE_ALIGN);
adcs_status adcs_mrp_pd4f_init(const adcs_mrp_pd4f_params* params, adcs_mrp_pd4f_state* state);
adcs_status adcs_mrp_pd4f_step(adcs_mrp_pd4f_state* state, const adcs_mrp_pd4f_input* in,
                               adcs_mrp_pd4f_output* out);

/* ---- Reaction-wheel torque allocation, 4 wheels ----------------------------------------------
 * u_s = -G_s^+ torque_B (minimum norm), scaled as a whole into |u_s,j| <= torque_limit, which
 * keeps the torque direction (ADCS_STATUS_SATURATED). Memoryless: no period. Its failure
 * command is u_s = 0 (the wheels coast). */
typedef struct adcs_rw_alloc4_params {
  double G_s_B[3][4];       /* [-] wheel spin axes (unit columns), B components; must span R^3 */
  double torque_limit;      /* [N m] per-wheel motor torque limit, finite, > 0 */
} adcs_rw_alloc4_params;
typedef struct adcs_rw_alloc4_input {
  double torque_B_Nm[3];    /* [N m] requested body torque (the attitude law's output) */
} adcs_rw_alloc4_input;
typedef struct adcs_rw_alloc4_output {
  double u_s_Nm[4];         /* [N m] motor torque on each wheel */
} adcs_rw_alloc4_output;
#define ADCS_RW_ALLOC4_STATE_SIZE 272
#define ADCS_RW_ALLOC4_STATE_ALIGN 16
ADCS_C_STATE(adcs_rw_alloc4_state, ADCS_RW_ALLOC4_STATE_SIZE, ADCS_RW_ALLOC4_STATE_ALIGN);
adcs_status adcs_rw_alloc4_init(const adcs_rw_alloc4_params* params, adcs_rw_alloc4_state* state);
adcs_status adcs_rw_alloc4_step(adcs_rw_alloc4_state* state, const adcs_rw_alloc4_input* in,
                                adcs_rw_alloc4_output* out);

typedef struct adcs_rw_alloc4f_params {
  float G_s_B[3][4];
  float torque_limit;
} adcs_rw_alloc4f_params;
typedef struct adcs_rw_alloc4f_input {
  float torque_B_Nm[3];
} adcs_rw_alloc4f_input;
typedef struct adcs_rw_alloc4f_output {
  float u_s_Nm[4];
} adcs_rw_alloc4f_output;
#define ADCS_RW_ALLOC4F_STATE_SIZE 160
#define ADCS_RW_ALLOC4F_STATE_ALIGN 16
ADCS_C_STATE(adcs_rw_alloc4f_state, ADCS_RW_ALLOC4F_STATE_SIZE, ADCS_RW_ALLOC4F_STATE_ALIGN);
adcs_status adcs_rw_alloc4f_init(const adcs_rw_alloc4f_params* params, adcs_rw_alloc4f_state* state);
adcs_status adcs_rw_alloc4f_step(adcs_rw_alloc4f_state* state, const adcs_rw_alloc4f_input* in,
                                 adcs_rw_alloc4f_output* out);

/* ---- Seed 002: prescribed-performance adaptive RBF attitude tracking, PPATC --------------------
 * (adcs/control/ppc_neural.hpp, seed 002 eq. (12)) in x-y-z Euler angles: the error e = theta -
 * theta_d is kept inside the funnel rho(t) = (rho0 - rho_inf) e^(-k t) + rho_inf by the transform
 * epsilon = S^-1(e/rho); a 7-node RBF network (input [e; e_dot] in degrees) and an adaptive bound
 * compensate the lumped disturbance. Runs at params.period_s (the paper's 1e-4 s). The funnel
 * branches are fixed by the first step's error; a violated funnel is re-opened from the current
 * error when funnel_recovery = ADCS_FUNNEL_REOPEN (the step then returns
 * ADCS_STATUS_CONSTRAINT_VIOLATED), or refused with ADCS_STATUS_OUT_OF_RANGE (seed 002's law). */
typedef int32_t adcs_angle_units;
#define ADCS_ANGLE_UNITS_RADIANS 0 /* the law's quantities in radians (reproduces every claim) */
#define ADCS_ANGLE_UNITS_DEGREES 1 /* the law's angle-valued quantities in degrees */
typedef int32_t adcs_funnel_recovery;
#define ADCS_FUNNEL_NONE 0   /* seed 002's law: out_of_range until the error is back inside */
#define ADCS_FUNNEL_REOPEN 1 /* re-open a violated funnel from the current error (the default) */
typedef struct adcs_ppc_params {
  double J_kgm2[3][3];          /* [kg m^2] inertia used in B^-1 = J G and the drift A; SPD */
  double lambda[3];             /* [1/s] lambda of s = lambda eps + eps_dot, > 0 */
  double K[3];                  /* [law units] robust gain K, > 0 */
  double rbf_centers[6][7];     /* RBF centres c_j (column j), input units [deg; deg/s] */
  double rbf_widths[7];         /* RBF widths b_j, > 0 */
  double tau_w[3];              /* [-] weight adaptation gains, >= 0 */
  double tau_mu;                /* [-] bound adaptation gain, >= 0 */
  double beta;                  /* [-] weight leakage, >= 0 */
  double gamma;                 /* [-] bound leakage, >= 0 */
  double sigma;                 /* [-] robust-term constant, > 0 */
  adcs_angle_units units;
  double period_s;              /* [s] control period, > 0 */
  double rho0_rad[3];           /* [rad] rho(0) per axis, > rho_inf */
  double rho_inf_rad[3];        /* [rad] steady funnel half-width per axis, > 0 */
  double k_rho[3];              /* [1/s] funnel decay rate per axis, > 0 */
  double delta[3];              /* [-] overshoot parameters in [0, 1] (seed 002: 0) */
  int32_t robust_clamp;         /* non-zero: clamp z at a funnel edge (flagged) instead of refusing */
  adcs_funnel_recovery funnel_recovery;
  adcs_failure_policy on_failure;
} adcs_ppc_params;
typedef struct adcs_ppc_input {
  double t_s;                   /* [s] time since the manoeuvre started (rho(t) is measured from it) */
  double theta_BN_rad[3];       /* [rad] x-y-z Euler angles of B relative to N */
  double omega_BN_B[3];         /* [rad/s] body rate, B components */
  double theta_d_rad[3];        /* [rad] reference angles */
  double theta_dot_d_rad_s[3];  /* [rad/s] their rates */
  double theta_ddot_d_rad_s2[3]; /* [rad/s^2] their accelerations */
} adcs_ppc_input;
typedef struct adcs_ppc_output {
  double torque_B_Nm[3];        /* [N m] control torque, B components */
} adcs_ppc_output;
#define ADCS_PPC_STATE_SIZE 2832
#define ADCS_PPC_STATE_ALIGN 16
ADCS_C_STATE(adcs_ppc_state, ADCS_PPC_STATE_SIZE, ADCS_PPC_STATE_ALIGN);
adcs_status adcs_ppc_init(const adcs_ppc_params* params, adcs_ppc_state* state);
adcs_status adcs_ppc_step(adcs_ppc_state* state, const adcs_ppc_input* in, adcs_ppc_output* out);

/* The same law in single precision (every field float; the law computes in float). */
typedef struct adcs_ppcf_params {
  float J_kgm2[3][3];
  float lambda[3];
  float K[3];
  float rbf_centers[6][7];
  float rbf_widths[7];
  float tau_w[3];
  float tau_mu;
  float beta;
  float gamma;
  float sigma;
  adcs_angle_units units;
  float period_s;
  float rho0_rad[3];
  float rho_inf_rad[3];
  float k_rho[3];
  float delta[3];
  int32_t robust_clamp;
  adcs_funnel_recovery funnel_recovery;
  adcs_failure_policy on_failure;
} adcs_ppcf_params;
typedef struct adcs_ppcf_input {
  float t_s;
  float theta_BN_rad[3];
  float omega_BN_B[3];
  float theta_d_rad[3];
  float theta_dot_d_rad_s[3];
  float theta_ddot_d_rad_s2[3];
} adcs_ppcf_input;
typedef struct adcs_ppcf_output {
  float torque_B_Nm[3];
} adcs_ppcf_output;
#define ADCS_PPCF_STATE_SIZE 1360
#define ADCS_PPCF_STATE_ALIGN 4
ADCS_C_STATE(adcs_ppcf_state, ADCS_PPCF_STATE_SIZE, ADCS_PPCF_STATE_ALIGN);
adcs_status adcs_ppcf_init(const adcs_ppcf_params* params, adcs_ppcf_state* state);
adcs_status adcs_ppcf_step(adcs_ppcf_state* state, const adcs_ppcf_input* in, adcs_ppcf_output* out);

/* ---- Seed 001: adaptive MIMO law for a hybrid CMG + reaction-wheel spacecraft, 4 CMGs + 3 wheels -
 * (adcs/control/hybrid_adaptive.hpp, seed 001 eqs. (24)-(26)): u = X^+ v with X = G*n + Y_G
 * Theta_G_hat, v = -K e - F*n - Y_F Theta_F_hat + sigma_ddot_d, e = [sigma - sigma_d; sigma_dot -
 * sigma_dot_d]; the momentum estimate Theta_F_hat and the installation-deviation estimates
 * Theta_G_hat (smooth projection) adapt every step. The command is the gimbal rates and the
 * wheel accelerations. Runs at params.period_s (the paper's 1 ms).
 * The gains K (closed-loop eigenvalues) and P (A_1^T P + P A_1 = -Q_L) are designed on the
 * ground, in double, by adcs_hybrid_design_gains below (or adcs::design_hybrid_adaptive_gains in
 * C++), and uploaded with the parameters: init checks them (P SPD, the Lyapunov equation, A_1
 * Hurwitz) and runs no pole placement or Lyapunov solve, so the float family computes no double
 * on board. Geometry: the NOMINAL cluster, all the law knows (columns are the units' axes). */
typedef int32_t adcs_adaptation_step;
#define ADCS_ADAPTATION_EXPLICIT_EULER 0 /* theta+ = theta + T theta_dot (seed 001's discretisation) */
#define ADCS_ADAPTATION_NORMALIZED 1     /* the step scaled by 1 / (1 + lambda / max_step_gain) */
typedef struct adcs_hybrid43_params {
  double A_cg[3][4];            /* [-] gimbal axes g_i (column i), B components */
  double A_cs0[3][4];           /* [-] rotor spin axes at gamma_i = 0 */
  double A_ct0[3][4];           /* [-] transverse axes at gamma_i = 0 */
  double A_ws[3][3];            /* [-] wheel spin axes (column j) */
  double I_cs[4];               /* [kg m^2] CMG inertia about s_i, >= 0 (0: in J_s) */
  double I_ct[4];               /* [kg m^2] CMG inertia about t_i, >= 0 */
  double I_cg[4];               /* [kg m^2] CMG inertia about g_i, >= 0 */
  double h_cw[4];               /* [N m s] CMG rotor momenta, > 0 */
  double I_wws[3];              /* [kg m^2] wheel spin inertias, > 0 */
  double J_s[3][3];             /* [kg m^2] body inertia, SPD */
  double K[3][6];               /* [1/s^2, 1/s] designed gain [K_p K_d] */
  double P[6][6];               /* [-] designed Lyapunov matrix, SPD */
  double Q_L[6][6];             /* [-] the Lyapunov weight P was designed for, SPD (seed 001: I_6) */
  double alpha_F;               /* [-] momentum adaptation gain, >= 0 (seed 001: 1e7) */
  double alpha_G;               /* [-] deviation adaptation gain, >= 0 (seed 001: 1e3) */
  double beta_G;                /* [-] projection radius^2, > 0 (seed 001: 0.05) */
  double delta_G;               /* [-] projection boundary layer, > 0 (seed 001: 0.1) */
  double H_I_n[3];              /* [N m s] nominal inertial momentum (0 when the wheels start at rest) */
  double period_s;              /* [s] control period T_c, > 0 (seed 001: 1e-3) */
  double steering_sigma_threshold; /* [-] sigma_min(X) below which damping starts, >= 0 (1e-3) */
  double steering_lambda_max;   /* [-] damping at sigma_min = 0, >= 0 (1e-2) */
  double steering_max_torque_error; /* [-] bound on |Xu - v|/|v| of a usable command, (0, 1] (0.1) */
  adcs_adaptation_step adaptation_step;
  double max_step_gain;         /* [-] loop-gain bound of the normalized step, > 0 (0.2) */
  adcs_failure_policy on_failure;
} adcs_hybrid43_params;
typedef struct adcs_hybrid43_input {
  double sigma_BN[3];           /* [-] measured attitude MRP */
  double omega_BN_B[3];         /* [rad/s] measured body rate, B components */
  double gamma_rad[4];          /* [rad] gimbal angles */
  double Omega_rad_s[3];        /* [rad/s] wheel speeds relative to the body (checked finite) */
  double sigma_d[3];            /* [-] reference MRP */
  double sigma_dot_d[3];        /* [1/s] its rate */
  double sigma_ddot_d[3];       /* [1/s^2] its second derivative */
} adcs_hybrid43_input;
typedef struct adcs_hybrid43_output {
  double gamma_dot_rad_s[4];    /* [rad/s] gimbal rate commands */
  double Omega_dot_rad_s2[3];   /* [rad/s^2] wheel acceleration commands */
} adcs_hybrid43_output;
#define ADCS_HYBRID43_STATE_SIZE 2240
#define ADCS_HYBRID43_STATE_ALIGN 16
ADCS_C_STATE(adcs_hybrid43_state, ADCS_HYBRID43_STATE_SIZE, ADCS_HYBRID43_STATE_ALIGN);
adcs_status adcs_hybrid43_init(const adcs_hybrid43_params* params, adcs_hybrid43_state* state);
adcs_status adcs_hybrid43_step(adcs_hybrid43_state* state, const adcs_hybrid43_input* in,
                               adcs_hybrid43_output* out);

/* The same law in single precision (every field float; the law computes in float; K and P are
 * the double design rounded once). */
typedef struct adcs_hybrid43f_params {
  float A_cg[3][4];
  float A_cs0[3][4];
  float A_ct0[3][4];
  float A_ws[3][3];
  float I_cs[4];
  float I_ct[4];
  float I_cg[4];
  float h_cw[4];
  float I_wws[3];
  float J_s[3][3];
  float K[3][6];
  float P[6][6];
  float Q_L[6][6];
  float alpha_F;
  float alpha_G;
  float beta_G;
  float delta_G;
  float H_I_n[3];
  float period_s;
  float steering_sigma_threshold;
  float steering_lambda_max;
  float steering_max_torque_error;
  adcs_adaptation_step adaptation_step;
  float max_step_gain;
  adcs_failure_policy on_failure;
} adcs_hybrid43f_params;
typedef struct adcs_hybrid43f_input {
  float sigma_BN[3];
  float omega_BN_B[3];
  float gamma_rad[4];
  float Omega_rad_s[3];
  float sigma_d[3];
  float sigma_dot_d[3];
  float sigma_ddot_d[3];
} adcs_hybrid43f_input;
typedef struct adcs_hybrid43f_output {
  float gamma_dot_rad_s[4];
  float Omega_dot_rad_s2[3];
} adcs_hybrid43f_output;
#define ADCS_HYBRID43F_STATE_SIZE 1216
#define ADCS_HYBRID43F_STATE_ALIGN 16
ADCS_C_STATE(adcs_hybrid43f_state, ADCS_HYBRID43F_STATE_SIZE, ADCS_HYBRID43F_STATE_ALIGN);
adcs_status adcs_hybrid43f_init(const adcs_hybrid43f_params* params, adcs_hybrid43f_state* state);
adcs_status adcs_hybrid43f_step(adcs_hybrid43f_state* state, const adcs_hybrid43f_input* in,
                                adcs_hybrid43f_output* out);

/* Ground design of the gains above, in double (seed 001 section 3): K places one eigenvalue pair
 * per axis, poles_re[a][k] + i poles_im[a][k] (k = 0, 1: a conjugate pair or two real values, in
 * the open left half-plane; seed 001: x -0.2 +/- 0.2i, y -0.3 +/- 0.3i, z -0.2 sqrt2 and -0.3 sqrt2),
 * and P solves A_1^T P + P A_1 = -Q_L. ADCS_STATUS_OK, or ADCS_STATUS_INVALID_PARAMETER (a NULL
 * pointer, poles not as stated, Q_L not SPD) with K and P untouched. For the ground segment or a
 * double FPU's start-up: it runs a Schur-based solve, never called by a step. */
adcs_status adcs_hybrid_design_gains(const double poles_re[3][2], const double poles_im[3][2],
                                     const double Q_L[6][6], double K[3][6], double P[6][6]);

/* ---- Seed 003: prescribed-time backstepping on SE(3) with input-quantization compensation --------
 * (adcs/control/prescribed_time_se3.hpp, BsPdTC, seed 003 eqs. (29)-(47)): the wrench u = [M; F]
 * (body torque and force) that drives the chaser's pose to the desired pose, from the SE(3)
 * error eta = log(g_d^-1 g) and its rate, with an adaptive estimate psi_hat of the squared
 * disturbance bound. Runs at params.period_s (seed 003: 0.125 s). The command is the law's
 * own; saturation and the actuator's quantizer stay with the caller (zeta >= the quantizer's
 * error bound, adcs::quantization_compensation_gain). Channels are [rotation x3; translation x3].
 * In float, note what the input costs: ECI positions of ~6.8e6 m carry 0.5 m and inertial
 * velocities of ~7.7 km/s 4.9e-4 m/s, so the relative position is known to ~0.5 m per sample
 * (docs/TARGET.md: the attitude holds in float, the position does not). */
typedef struct adcs_se3_ptc_params {
  double p;                     /* [-] power, 0 < p < 1 (Table 1: 0.5) */
  double T_s;                   /* [s] prescribed time T, > 0 */
  double K2[6];                 /* [1/s] >= 0 */
  double Lambda[6];             /* [-] low-power gain, >= 0 */
  double Upsilon[6];            /* [-] high-power gain, >= 0 */
  double eps1;                  /* [rad | m] switch of S(z1), > 0 */
  double K3[6];                 /* [1/s] >= 0 */
  double Lambda2[6];            /* [-] >= 0 */
  double Upsilon2[6];           /* [-] >= 0 */
  double eps2;                  /* switch of S(z2), > 0 */
  double zeta[6];               /* [N m | N] quantization compensation gain, >= the quantizer's bound */
  double eps_q;                 /* tanh width of u2, > 0 */
  double a;                     /* robust-term scale, > 0 */
  double gamma;                 /* adaptation gain, >= 0 */
  double sigma1;                /* [1/s] leakage, >= 0 */
  double sigma2;                /* cubic leakage, >= 0 */
  double psi_hat0;              /* psi_hat(0), >= 0 */
  double period_s;              /* [s] control period, > 0 */
  double J0_kgm2[3][3];         /* [kg m^2] the controller's model of the chaser's inertia, SPD */
  double m0_kg;                 /* [kg] its mass, > 0 */
  double mu_m3_s2;              /* [m^3/s^2] Earth's gravitational parameter (3.986e14), > 0 */
  double J2;                    /* [-] second zonal harmonic (1.08263e-3; 0: point mass) */
  double R_E_m;                 /* [m] Earth's equatorial radius (6378e3), > 0 */
  adcs_failure_policy on_failure;
} adcs_se3_ptc_params;
typedef struct adcs_se3_ptc_input {
  double C_NB[3][3];            /* [-] chaser attitude: active rotation body -> ECI */
  double R_N_m[3];              /* [m] chaser position, ECI */
  double omega_BN_B[3];         /* [rad/s] chaser body rate, body components */
  double v_B_m_s[3];            /* [m/s] chaser inertial velocity, body components */
  double C_ND[3][3];            /* [-] desired attitude: active rotation desired body -> ECI */
  double R_d_N_m[3];            /* [m] desired position, ECI */
  double omega_DN_D[3];         /* [rad/s] desired body rate, desired-body components */
  double v_D_m_s[3];            /* [m/s] desired inertial velocity, desired-body components */
  double omega_dot_D[3];        /* [rad/s^2] its rate */
  double v_dot_D_m_s2[3];       /* [m/s^2] its rate */
} adcs_se3_ptc_input;
typedef struct adcs_se3_ptc_output {
  double torque_B_Nm[3];        /* [N m] control torque M, body components */
  double force_B_N[3];          /* [N] control force F, body components */
} adcs_se3_ptc_output;
#define ADCS_SE3_PTC_STATE_SIZE 1216
#define ADCS_SE3_PTC_STATE_ALIGN 16
ADCS_C_STATE(adcs_se3_ptc_state, ADCS_SE3_PTC_STATE_SIZE, ADCS_SE3_PTC_STATE_ALIGN);
adcs_status adcs_se3_ptc_init(const adcs_se3_ptc_params* params, adcs_se3_ptc_state* state);
adcs_status adcs_se3_ptc_step(adcs_se3_ptc_state* state, const adcs_se3_ptc_input* in, adcs_se3_ptc_output* out);

/* The same law in single precision (every field float; the law computes in float). */
typedef struct adcs_se3_ptcf_params {
  float p;
  float T_s;
  float K2[6];
  float Lambda[6];
  float Upsilon[6];
  float eps1;
  float K3[6];
  float Lambda2[6];
  float Upsilon2[6];
  float eps2;
  float zeta[6];
  float eps_q;
  float a;
  float gamma;
  float sigma1;
  float sigma2;
  float psi_hat0;
  float period_s;
  float J0_kgm2[3][3];
  float m0_kg;
  float mu_m3_s2;
  float J2;
  float R_E_m;
  adcs_failure_policy on_failure;
} adcs_se3_ptcf_params;
typedef struct adcs_se3_ptcf_input {
  float C_NB[3][3];
  float R_N_m[3];
  float omega_BN_B[3];
  float v_B_m_s[3];
  float C_ND[3][3];
  float R_d_N_m[3];
  float omega_DN_D[3];
  float v_D_m_s[3];
  float omega_dot_D[3];
  float v_dot_D_m_s2[3];
} adcs_se3_ptcf_input;
typedef struct adcs_se3_ptcf_output {
  float torque_B_Nm[3];
  float force_B_N[3];
} adcs_se3_ptcf_output;
#define ADCS_SE3_PTCF_STATE_SIZE 588
#define ADCS_SE3_PTCF_STATE_ALIGN 4
ADCS_C_STATE(adcs_se3_ptcf_state, ADCS_SE3_PTCF_STATE_SIZE, ADCS_SE3_PTCF_STATE_ALIGN);
adcs_status adcs_se3_ptcf_init(const adcs_se3_ptcf_params* params, adcs_se3_ptcf_state* state);
adcs_status adcs_se3_ptcf_step(adcs_se3_ptcf_state* state, const adcs_se3_ptcf_input* in,
                               adcs_se3_ptcf_output* out);

/* ---- Seed 004: the drag-free satellite's ADRC (adcs/control/adrc.hpp) ----------------------
 * One sample (params.period_s; 0.1 s in the paper) of seed 004's active-disturbance-rejection law,
 * eqs. (44)-(46): a nonlinear PID on Han's fal per loop and axis (spacecraft attitude, drag-free
 * translation, test-mass attitude) plus compensation of the estimated disturbances,
 *   T_Csc = I_sc X_att - T_Dsc_hat,  F_Csc = -X_df + m_sc h_idf - F_D_hat,
 *   T_Ctm = I_tm X_tm - T_Dtm_hat - I_tm h_itm,
 * each component clipped to [-limit, limit] (ADCS_STATUS_SATURATED when one was). The law reads
 * the estimates of Algorithm 1 (the 27-state extended-state filter, after fusion) and Algorithm 2
 * (the drag per axis); those filters are C++ only (adcs/estimate/drag_free_eskf.hpp,
 * saturated_esf.hpp, fusion.hpp). A zero-initialised parameter set is refused (masses, inertias,
 * period, alpha, delta, limit), but a zero gain is a valid choice that switches its term off: set
 * every gain (the paper's: attitude {0.001, 0.00005, 0.01}, drag_free {0.5, 0.005, 1.9},
 * tm_attitude {0.0001, 0, 0.0021}, alpha 0.5, delta 0.01, limit 0.03, integral scaled_sum). */
typedef int32_t adcs_adrc_integral;
#define ADCS_ADRC_INTEGRAL_SCALED_SUM 0 /* e_i = h sum(e_p), with halved integral gains (spec B.7) */
#define ADCS_ADRC_INTEGRAL_RAW_SUM 1    /* e_i = sum(e_p), the paper's literal form */
typedef int32_t adcs_adrc_x_law;
#define ADCS_ADRC_X_NLPID 0             /* the paper's NLPID on the X force too, eq. (45) */
#define ADCS_ADRC_X_PID 1               /* Fig. 9 baseline: linear PID on X, no compensation */
#define ADCS_ADRC_X_PID_COMPENSATED 2   /* Fig. 9 baseline: the same PID + disturbance compensation */
typedef struct adcs_drag_free_adrc_params {
  double m_tm_kg;               /* [kg] test mass, > 0 */
  double m_sc_kg;               /* [kg] spacecraft mass, > 0 */
  double I_tm_kgm2[3][3];       /* [kg m^2] test-mass inertia, SPD */
  double I_sc_kgm2[3][3];       /* [kg m^2] spacecraft inertia, SPD */
  double K_trans_N_m[3][3];     /* [N/m] test-mass translational stiffness, finite */
  double D_trans_Ns_m[3][3];    /* [N s/m] its damping, finite */
  double K_rot_Nm_rad[3][3];    /* [N m/rad] rotational stiffness, finite (any sign) */
  double D_rot_Nms_rad[3][3];   /* [N m s/rad] its damping, finite (any sign) */
  double period_s;              /* [s] h, sample and actuation period, > 0 */
  double attitude[3];           /* spacecraft attitude loop: k_p, k_i, k_d, each finite >= 0 */
  double drag_free[3];          /* drag-free (translation) loop: k_p, k_i, k_d */
  double tm_attitude[3];        /* test-mass attitude loop: k_p, k_i (unused), k_d */
  double alpha;                 /* [-] fal exponent, in (0, 1] */
  double delta;                 /* fal linear zone, > 0 */
  adcs_adrc_integral integral;
  double limit;                 /* [N m | N] each command component within +-limit, > 0 */
  adcs_adrc_x_law x_law;
  double pid_kp;                /* [N/m] Fig. 9 PID (x_law != NLPID), finite >= 0 */
  double pid_ki;                /* [N/(m s)] */
  double pid_kd;                /* [N s/m] */
  adcs_failure_policy on_failure;
} adcs_drag_free_adrc_params;
typedef struct adcs_drag_free_adrc_input {
  /* Algorithm 1's posterior after fusion, 3 components each, in this order (adcs::DragFreeIndex):
   * phi_sc [rad], phi_sc_dot [rad/s], T_Dsc [N m], r [m], r_dot [m/s], F_Dsc [N], phi_rel [rad],
   * phi_rel_dot [rad/s], T_Dtm [N m]. */
  double x_hat[27];
  double F_D_hat_N[3];          /* [N] Algorithm 2's predicted drag per axis */
  double phi_sc_cmd_rad[3];     /* [rad] spacecraft attitude command */
} adcs_drag_free_adrc_input;
typedef struct adcs_drag_free_adrc_output {
  double T_Csc_Nm[3];           /* [N m] spacecraft control torque */
  double F_Csc_N[3];            /* [N] spacecraft control force */
  double T_Ctm_Nm[3];           /* [N m] test-mass control torque */
} adcs_drag_free_adrc_output;
#define ADCS_DRAG_FREE_ADRC_STATE_SIZE 872
#define ADCS_DRAG_FREE_ADRC_STATE_ALIGN 8
ADCS_C_STATE(adcs_drag_free_adrc_state, ADCS_DRAG_FREE_ADRC_STATE_SIZE, ADCS_DRAG_FREE_ADRC_STATE_ALIGN);
adcs_status adcs_drag_free_adrc_init(const adcs_drag_free_adrc_params* params, adcs_drag_free_adrc_state* state);
adcs_status adcs_drag_free_adrc_step(adcs_drag_free_adrc_state* state, const adcs_drag_free_adrc_input* in,
                                     adcs_drag_free_adrc_output* out);

/* The same law in single precision (every field float; the law computes in float). */
typedef struct adcs_drag_free_adrcf_params {
  float m_tm_kg;
  float m_sc_kg;
  float I_tm_kgm2[3][3];
  float I_sc_kgm2[3][3];
  float K_trans_N_m[3][3];
  float D_trans_Ns_m[3][3];
  float K_rot_Nm_rad[3][3];
  float D_rot_Nms_rad[3][3];
  float period_s;
  float attitude[3];
  float drag_free[3];
  float tm_attitude[3];
  float alpha;
  float delta;
  adcs_adrc_integral integral;
  float limit;
  adcs_adrc_x_law x_law;
  float pid_kp;
  float pid_ki;
  float pid_kd;
  adcs_failure_policy on_failure;
} adcs_drag_free_adrcf_params;
typedef struct adcs_drag_free_adrcf_input {
  float x_hat[27];
  float F_D_hat_N[3];
  float phi_sc_cmd_rad[3];
} adcs_drag_free_adrcf_input;
typedef struct adcs_drag_free_adrcf_output {
  float T_Csc_Nm[3];
  float F_Csc_N[3];
  float T_Ctm_Nm[3];
} adcs_drag_free_adrcf_output;
#define ADCS_DRAG_FREE_ADRCF_STATE_SIZE 436
#define ADCS_DRAG_FREE_ADRCF_STATE_ALIGN 4
ADCS_C_STATE(adcs_drag_free_adrcf_state, ADCS_DRAG_FREE_ADRCF_STATE_SIZE, ADCS_DRAG_FREE_ADRCF_STATE_ALIGN);
adcs_status adcs_drag_free_adrcf_init(const adcs_drag_free_adrcf_params* params, adcs_drag_free_adrcf_state* state);
adcs_status adcs_drag_free_adrcf_step(adcs_drag_free_adrcf_state* state, const adcs_drag_free_adrcf_input* in,
                                      adcs_drag_free_adrcf_output* out);

#ifdef __cplusplus
}
#endif
#endif /* ADCS_C_ADCS_H */
