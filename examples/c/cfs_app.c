/* A cFS-style attitude control application in C99 over the adcs C interface (adcs/c/adcs.h):
 *   - AppInit: load the parameter "table" (here: built from the vehicle, as a table load would),
 *     initialise the caller-allocated controller states (static storage: no heap, as in flight);
 *   - AppMain: one pass per scheduler wake-up at 10 Hz: read the sensors, run the attitude law and
 *     the wheel allocation, send the wheel commands, count statuses in the housekeeping packet.
 * The spacecraft is the C plant of cubesat_plant.h, propagated between wake-ups. The application
 * flies the slew twice, with the double and with the single-precision law, and checks every
 * recorded command and the final attitude against the C++ components' results (cfs_expected.h,
 * written by cfs_reference.cpp): bit for bit on the host, where both run the same compiled
 * arithmetic; within CFS_TOL_DOUBLE / CFS_TOL_FLOAT of the largest command on the Cortex-M7
 * (QEMU mps2-an500) and the Cortex-M4F (mps2-an386; its double law runs in software double).
 * Exit status 0 only if every check passes (ctest: example_c_cfs_app, target_c_example_m7, target_c_example_m4f). */
#include <math.h>
#include <stdio.h>

#include "adcs/c/adcs.h"
#include "cfs_expected.h"
#include "cfs_loop.h"
#include "cubesat_plant.h"

#ifdef ADCS_C_EXAMPLE_EXACT
#define CFS_TOL_DOUBLE 0.0
#define CFS_TOL_FLOAT 0.0
#else
/* Host vs Cortex-M7/M4F: the reference is computed with the target's arithmetic (no FMA
 * contraction, no SSE reordering: cmake/TargetCheck.cmake), and measured bit-identical on both
 * cores, in double and in float. The bounds leave room for newlib's and glibc's cos/tan rounding
 * the geometry differently in the last bit (TOOLCHAIN-NOTES: ~1e-15), which the stable closed
 * loop keeps from growing over the 2,400 steps: ~1,000x that in double, and in float ~1,000x
 * float's own 2^-24 ~ 6e-8 rounding. */
#define CFS_TOL_DOUBLE 1e-12
#define CFS_TOL_FLOAT 1e-4
#endif

/* Housekeeping telemetry, as a cFS app would publish it. */
typedef struct {
  unsigned long wakeups, law_not_usable, alloc_saturated, alloc_not_usable;
  double final_error_rad;
} cfs_hk;

static adcs_mrp_pd4_state g_law;        /* caller-allocated: ADCS_MRP_PD4_STATE_SIZE bytes */
static adcs_rw_alloc4_state g_alloc;
static adcs_mrp_pd4f_state g_law_f;
static adcs_rw_alloc4f_state g_alloc_f;
static cubesat_vehicle g_vehicle;
static int g_failures;

static void check(int ok, const char* what, int index) {
  if (!ok) {
    if (g_failures < 10) printf("cfs_app: FAILED: %s (%d)\n", what, index);
    ++g_failures;
  }
}

static void reference_sigma(double sigma_RN[3]) {
  const double t = tan(CFS_SLEW_RAD / 4.0), n = sqrt(14.0);
  sigma_RN[0] = t * 1.0 / n;
  sigma_RN[1] = t * 2.0 / n;
  sigma_RN[2] = t * 3.0 / n;
}

static int app_init_double(void) {
  adcs_mrp_pd4_params law;
  adcs_rw_alloc4_params alloc;
  int i, j;
  law.K = 4.0 * 0.25 * CFS_OMEGA_N * CFS_OMEGA_N; /* near the target sigma ~ phi/4: K = 4 J_max w_n^2 */
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) {
      law.P[i][j] = (i == j) ? 2.0 * CFS_OMEGA_N * g_vehicle.J_B[i][i] : 0.0; /* P_i = 2 J_i w_n */
      law.J_rw_B[i][j] = g_vehicle.J_rw_B[i][j];
    }
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 4; ++j) law.G_s_B[i][j] = alloc.G_s_B[i][j] = g_vehicle.G_s_B[i][j];
  for (j = 0; j < 4; ++j) law.J_s[j] = g_vehicle.J_s[j];
  law.period_s = CFS_PERIOD_S;
  law.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  alloc.torque_limit = CFS_WHEEL_LIMIT_NM;
  return adcs_mrp_pd4_init(&law, &g_law) == ADCS_STATUS_OK && adcs_rw_alloc4_init(&alloc, &g_alloc) == ADCS_STATUS_OK;
}

static int app_init_float(void) {
  adcs_mrp_pd4f_params law;
  adcs_rw_alloc4f_params alloc;
  int i, j;
  law.K = (float)(4.0 * 0.25 * CFS_OMEGA_N * CFS_OMEGA_N);
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) {
      law.P[i][j] = (float)((i == j) ? 2.0 * CFS_OMEGA_N * g_vehicle.J_B[i][i] : 0.0);
      law.J_rw_B[i][j] = (float)g_vehicle.J_rw_B[i][j];
    }
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 4; ++j) law.G_s_B[i][j] = alloc.G_s_B[i][j] = (float)g_vehicle.G_s_B[i][j];
  for (j = 0; j < 4; ++j) law.J_s[j] = (float)g_vehicle.J_s[j];
  law.period_s = (float)CFS_PERIOD_S;
  law.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  alloc.torque_limit = (float)CFS_WHEEL_LIMIT_NM;
  return adcs_mrp_pd4f_init(&law, &g_law_f) == ADCS_STATUS_OK && adcs_rw_alloc4f_init(&alloc, &g_alloc_f) == ADCS_STATUS_OK;
}

/* One wake-up of the double-precision app: sensors -> law -> allocation -> wheel commands. */
static void app_main_double(const cubesat_state* x, const double sigma_RN[3], double u[4], cfs_hk* hk) {
  adcs_mrp_pd4_input in;
  adcs_mrp_pd4_output torque;
  adcs_rw_alloc4_input request;
  adcs_rw_alloc4_output wheels;
  adcs_status s;
  int i;
  for (i = 0; i < 3; ++i) {
    in.sigma_BN[i] = x->sigma_BN[i];
    in.omega_BN_B[i] = x->omega_BN_B[i];
    in.sigma_RN[i] = sigma_RN[i];
    in.omega_RN_N[i] = 0.0;
    in.domega_RN_N[i] = 0.0;
  }
  for (i = 0; i < 4; ++i) in.Omega_rad_s[i] = x->Omega_rad_s[i];
  ++hk->wakeups;
  if (!adcs_status_usable(adcs_mrp_pd4_step(&g_law, &in, &torque))) ++hk->law_not_usable; /* torque is safe */
  for (i = 0; i < 3; ++i) request.torque_B_Nm[i] = torque.torque_B_Nm[i];
  s = adcs_rw_alloc4_step(&g_alloc, &request, &wheels);
  if (s == ADCS_STATUS_SATURATED) ++hk->alloc_saturated;
  if (!adcs_status_usable(s)) ++hk->alloc_not_usable; /* wheels coast: u = 0 */
  for (i = 0; i < 4; ++i) u[i] = wheels.u_s_Nm[i];
}

static void app_main_float(const cubesat_state* x, const double sigma_RN[3], double u[4], cfs_hk* hk) {
  adcs_mrp_pd4f_input in;
  adcs_mrp_pd4f_output torque;
  adcs_rw_alloc4f_input request;
  adcs_rw_alloc4f_output wheels;
  adcs_status s;
  int i;
  for (i = 0; i < 3; ++i) {
    in.sigma_BN[i] = (float)x->sigma_BN[i];
    in.omega_BN_B[i] = (float)x->omega_BN_B[i];
    in.sigma_RN[i] = (float)sigma_RN[i];
    in.omega_RN_N[i] = 0.0f;
    in.domega_RN_N[i] = 0.0f;
  }
  for (i = 0; i < 4; ++i) in.Omega_rad_s[i] = (float)x->Omega_rad_s[i];
  ++hk->wakeups;
  if (!adcs_status_usable(adcs_mrp_pd4f_step(&g_law_f, &in, &torque))) ++hk->law_not_usable;
  for (i = 0; i < 3; ++i) request.torque_B_Nm[i] = torque.torque_B_Nm[i];
  s = adcs_rw_alloc4f_step(&g_alloc_f, &request, &wheels);
  if (s == ADCS_STATUS_SATURATED) ++hk->alloc_saturated;
  if (!adcs_status_usable(s)) ++hk->alloc_not_usable;
  for (i = 0; i < 4; ++i) u[i] = (double)wheels.u_s_Nm[i];
}

/* The scheduler: wake the app every CFS_PERIOD_S, the spacecraft moving in between. */
static void fly(int single, const double* expected_u, const double* expected_final, double tol, const char* name) {
  cubesat_state x = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 0.0}};
  cfs_hk hk = {0, 0, 0, 0, 0.0};
  double sigma_RN[3], u[4], u_max = 0.0, worst = 0.0, worst_state = 0.0;
  const double* xs = &x.sigma_BN[0];
  int k, j, s;
  reference_sigma(sigma_RN);
  for (k = 0; k < CFS_RECORDS * 4; ++k) u_max = fmax(u_max, fabs(expected_u[k]));
  for (k = 0; k < CFS_STEPS; ++k) {
    if (single)
      app_main_float(&x, sigma_RN, u, &hk);
    else
      app_main_double(&x, sigma_RN, u, &hk);
    for (j = 0; j < 4; ++j) check(fabs(u[j]) <= CFS_WHEEL_LIMIT_NM, "wheel torque above its limit", k);
    if (k % CFS_RECORD_EVERY == 0)
      for (j = 0; j < 4; ++j) {
        const double d = fabs(u[j] - expected_u[(k / CFS_RECORD_EVERY) * 4 + j]);
        worst = fmax(worst, d / u_max);
        check(d <= tol * u_max, "command differs from the C++ components'", k);
      }
    for (s = 0; s < CFS_SUBSTEPS; ++s) cubesat_rk4(&g_vehicle, CFS_PERIOD_S / CFS_SUBSTEPS, u, &x);
  }
  for (j = 0; j < 3; ++j) { /* the attitude reached: sigma is O(0.1), so tol is relative as well */
    const double d = fabs(xs[j] - expected_final[j]);
    worst_state = fmax(worst_state, d);
    check(d <= tol, "final attitude differs", j);
  }
  hk.final_error_rad = cubesat_angle_between(x.sigma_BN, sigma_RN);
  printf("cfs_app %s: %lu wake-ups, law not usable %lu, allocation saturated %lu / not usable %lu, "
         "final error %.3g rad; difference to C++: commands %.3g of the largest, final sigma_BN %.3g\n",
         name, hk.wakeups, hk.law_not_usable, hk.alloc_saturated, hk.alloc_not_usable, hk.final_error_rad, worst,
         worst_state);
  check(hk.law_not_usable == 0 && hk.alloc_not_usable == 0, "a step was not usable", 0);
  check(hk.final_error_rad < 1e-4, "the slew did not converge to 1e-4 rad", 0);
}

int main(void) {
  static adcs_mrp_pd4_state never_initialised; /* static: zero, as init never ran */
  static adcs_mrp_pd4_input in;                 /* all zero */
  adcs_mrp_pd4_output out = {{1.0, 2.0, 3.0}};
  cubesat_vehicle_init(&g_vehicle);
  if (!app_init_double() || !app_init_float()) {
    printf("cfs_app: FAILED: a parameter table was refused\n");
    return 1;
  }
  /* The boundary's refusals: a state init never wrote, and NULL pointers, write nothing. */
  check(adcs_mrp_pd4_step(&never_initialised, &in, &out) == ADCS_STATUS_INVALID_PARAMETER && out.torque_B_Nm[0] == 1.0,
        "step on an uninitialised state", 0);
  check(adcs_mrp_pd4_step(&g_law, NULL, &out) == ADCS_STATUS_INVALID_PARAMETER, "NULL input", 0);
  fly(0, cfs_expected_double_u, cfs_expected_double_final, CFS_TOL_DOUBLE, "double");
  fly(1, cfs_expected_float_u, cfs_expected_float_final, CFS_TOL_FLOAT, "float");
  printf("cfs_app: state objects: mrp_pd4 %d B (align %d), mrp_pd4f %d B, rw_alloc4 %d B, rw_alloc4f %d B; %s\n",
         (int)sizeof(adcs_mrp_pd4_state), ADCS_MRP_PD4_STATE_ALIGN, (int)sizeof(adcs_mrp_pd4f_state),
         (int)sizeof(adcs_rw_alloc4_state), (int)sizeof(adcs_rw_alloc4f_state), g_failures ? "FAILED" : "passed");
  return g_failures ? 1 : 0;
}
