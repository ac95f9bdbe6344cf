/* The 12U cubesat of examples/cubesat_mrp_pd.cpp written in C99 for the C example: a rigid body
 * with four reaction wheels in a 30 deg pyramid, integrated by RK4 with the wheel torques held.
 * It stands in for the spacecraft and its sensors; the C application (cfs_app.c) and its C++
 * reference (cfs_reference.cpp) link this same file, so both fly the same plant. */
#ifndef ADCS_EXAMPLE_CUBESAT_PLANT_H
#define ADCS_EXAMPLE_CUBESAT_PLANT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cubesat_vehicle {
  double J_B[3][3];    /* [kg m^2] inertia including the wheels, B components */
  double G_s_B[3][4];  /* [-] wheel spin axes (unit columns), B components */
  double J_s[4];       /* [kg m^2] wheel spin inertias */
  double J_rw_B[3][3]; /* [kg m^2] J_B - sum J_s g g^T */
  double J_rw_inv[3][3];
} cubesat_vehicle;

typedef struct cubesat_state {
  double sigma_BN[3];    /* [-] attitude MRP (shadow set switched at |sigma| > 1) */
  double omega_BN_B[3];  /* [rad/s] body rate */
  double Omega_rad_s[4]; /* [rad/s] wheel speeds relative to the body */
} cubesat_state;

/* J = diag(0.20, 0.25, 0.15) kg m^2, wheels at elevation 30 deg and azimuths 0, 90, 180, 270 deg,
 * J_s = 2e-5 kg m^2 each. */
void cubesat_vehicle_init(cubesat_vehicle* v);
/* One RK4 step of h seconds with the wheel motor torques u_s_Nm held. */
void cubesat_rk4(const cubesat_vehicle* v, double h, const double u_s_Nm[4], cubesat_state* x);
/* Principal rotation angle [rad] between two MRP attitudes. */
double cubesat_angle_between(const double sigma_a[3], const double sigma_b[3]);

#ifdef __cplusplus
}
#endif
#endif
