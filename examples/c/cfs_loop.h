/* What the C application (cfs_app.c) and its C++ reference (cfs_reference.cpp) share: the
 * scenario's numbers. Both fly the cubesat of cubesat_plant.h through a 30 deg slew about
 * (1, 2, 3)/sqrt(14) with the attitude law at 10 Hz and RK4 substeps of 10 ms; the reference
 * records every CFS_RECORD_EVERY-th wheel command and the final state, which the application
 * asserts (host: bit for bit; Cortex-M7 under QEMU: within the tolerances of cfs_app.c). */
#ifndef ADCS_EXAMPLE_CFS_LOOP_H
#define ADCS_EXAMPLE_CFS_LOOP_H

#define CFS_PERIOD_S 0.1       /* [s] the scheduler's wake-up period (10 Hz) */
#define CFS_SUBSTEPS 10        /* RK4 steps of the plant per period */
#define CFS_STEPS 2400         /* 240 s: the slew and its settling */
#define CFS_RECORD_EVERY 10    /* recorded commands: one per second */
#define CFS_RECORDS (CFS_STEPS / CFS_RECORD_EVERY)
#define CFS_WHEEL_LIMIT_NM 3e-3 /* [N m] per-wheel motor torque limit */
#define CFS_OMEGA_N 0.1        /* [rad/s] closed-loop natural frequency per axis (critically damped) */
#define CFS_SLEW_RAD 0.52359877559829882 /* 30 deg */

#endif
