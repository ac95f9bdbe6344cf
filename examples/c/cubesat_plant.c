/* See cubesat_plant.h. Rigid body with reaction wheels (Schaub & Junkins eq. (4.128)-(4.130)):
 *   h_s = J_s (G_s^T omega + Omega),  H = J_rw omega + G_s h_s,
 *   J_rw omega_dot = -omega x H - G_s u_s,  Omega_dot = u_s / J_s - G_s^T omega_dot,
 *   sigma_dot = 1/4 [(1 - sigma.sigma) omega + 2 sigma x omega + 2 (sigma.omega) sigma]. */
#include "cubesat_plant.h"

#include <math.h>

static void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void mat_vec(const double M[3][3], const double v[3], double r[3]) {
  int i;
  for (i = 0; i < 3; ++i) r[i] = M[i][0] * v[0] + M[i][1] * v[1] + M[i][2] * v[2];
}

void cubesat_vehicle_init(cubesat_vehicle* v) {
  const double pi = 3.14159265358979323846, elevation = 30.0 * pi / 180.0;
  const double J_diag[3] = {0.20, 0.25, 0.15};
  double det;
  int i, j, k;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) v->J_B[i][j] = (i == j) ? J_diag[i] : 0.0;
  for (j = 0; j < 4; ++j) {
    const double a = 2.0 * pi * j / 4.0;
    v->G_s_B[0][j] = cos(elevation) * cos(a);
    v->G_s_B[1][j] = cos(elevation) * sin(a);
    v->G_s_B[2][j] = sin(elevation);
    v->J_s[j] = 2e-5;
  }
  for (i = 0; i < 3; ++i)
    for (k = 0; k < 3; ++k) {
      v->J_rw_B[i][k] = v->J_B[i][k];
      for (j = 0; j < 4; ++j) v->J_rw_B[i][k] -= v->J_s[j] * v->G_s_B[i][j] * v->G_s_B[k][j];
    }
  /* 3x3 inverse by cofactors (J_rw is symmetric positive definite). */
  det = v->J_rw_B[0][0] * (v->J_rw_B[1][1] * v->J_rw_B[2][2] - v->J_rw_B[1][2] * v->J_rw_B[2][1]) -
        v->J_rw_B[0][1] * (v->J_rw_B[1][0] * v->J_rw_B[2][2] - v->J_rw_B[1][2] * v->J_rw_B[2][0]) +
        v->J_rw_B[0][2] * (v->J_rw_B[1][0] * v->J_rw_B[2][1] - v->J_rw_B[1][1] * v->J_rw_B[2][0]);
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      v->J_rw_inv[i][j] = (v->J_rw_B[r0][c0] * v->J_rw_B[r1][c1] - v->J_rw_B[r0][c1] * v->J_rw_B[r1][c0]) / det;
    }
}

static void derivative(const cubesat_vehicle* v, const cubesat_state* x, const double u[4], cubesat_state* d) {
  double H[3], wxH[3], rhs[3], sxw[3], h_s;
  const double* w = x->omega_BN_B;
  const double* s = x->sigma_BN;
  int i, j;
  mat_vec(v->J_rw_B, w, H);
  for (j = 0; j < 4; ++j) {
    h_s = v->J_s[j] * (v->G_s_B[0][j] * w[0] + v->G_s_B[1][j] * w[1] + v->G_s_B[2][j] * w[2] + x->Omega_rad_s[j]);
    for (i = 0; i < 3; ++i) H[i] += v->G_s_B[i][j] * h_s;
  }
  cross(w, H, wxH);
  for (i = 0; i < 3; ++i) {
    rhs[i] = -wxH[i];
    for (j = 0; j < 4; ++j) rhs[i] -= v->G_s_B[i][j] * u[j];
  }
  mat_vec(v->J_rw_inv, rhs, d->omega_BN_B);
  for (j = 0; j < 4; ++j)
    d->Omega_rad_s[j] = u[j] / v->J_s[j] - (v->G_s_B[0][j] * d->omega_BN_B[0] + v->G_s_B[1][j] * d->omega_BN_B[1] +
                                            v->G_s_B[2][j] * d->omega_BN_B[2]);
  cross(s, w, sxw);
  for (i = 0; i < 3; ++i) d->sigma_BN[i] = 0.25 * ((1.0 - dot(s, s)) * w[i] + 2.0 * sxw[i] + 2.0 * dot(s, w) * s[i]);
}

/* x + a k, on the 10 numbers of the state. */
static cubesat_state axpy(const cubesat_state* x, double a, const cubesat_state* k) {
  cubesat_state r;
  const double* xs = &x->sigma_BN[0];
  const double* ks = &k->sigma_BN[0];
  double* rs = &r.sigma_BN[0];
  int i;
  for (i = 0; i < 10; ++i) rs[i] = xs[i] + a * ks[i];
  return r;
}

void cubesat_rk4(const cubesat_vehicle* v, double h, const double u_s_Nm[4], cubesat_state* x) {
  cubesat_state k1, k2, k3, k4, t;
  double* xs = &x->sigma_BN[0];
  const double *a = &k1.sigma_BN[0], *b = &k2.sigma_BN[0], *c = &k3.sigma_BN[0], *e = &k4.sigma_BN[0];
  double s2;
  int i;
  derivative(v, x, u_s_Nm, &k1);
  t = axpy(x, 0.5 * h, &k1);
  derivative(v, &t, u_s_Nm, &k2);
  t = axpy(x, 0.5 * h, &k2);
  derivative(v, &t, u_s_Nm, &k3);
  t = axpy(x, h, &k3);
  derivative(v, &t, u_s_Nm, &k4);
  for (i = 0; i < 10; ++i) xs[i] += h / 6.0 * (a[i] + 2.0 * b[i] + 2.0 * c[i] + e[i]);
  s2 = dot(x->sigma_BN, x->sigma_BN);
  if (s2 > 1.0)
    for (i = 0; i < 3; ++i) x->sigma_BN[i] = -x->sigma_BN[i] / s2; /* shadow set */
}

double cubesat_angle_between(const double sa[3], const double sb[3]) {
  /* sigma_a - sigma_b as an MRP (Schaub & Junkins eq. (3.159)), then 4 atan |sigma|. */
  const double na = dot(sa, sa), nb = dot(sb, sb), ab = dot(sa, sb);
  double axb[3], d[3], den;
  int i;
  cross(sa, sb, axb);
  den = 1.0 + na * nb + 2.0 * ab;
  for (i = 0; i < 3; ++i) d[i] = ((1.0 - nb) * sa[i] - (1.0 - na) * sb[i] + 2.0 * axb[i]) / den;
  return 4.0 * atan(sqrt(dot(d, d)));
}
