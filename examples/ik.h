// Damped-least-squares inverse kinematics of a site's position (used by arm_ik.c and
// arm_track.c):  dq = J^T (J J^T + lambda^2 I)^-1 e,  e = target - site position.

#include <math.h>
#include <string.h>

#include <mujoco/mujoco.h>

// Solves the symmetric positive definite 3x3 system A x = b (Cholesky, in place on A).
static void solve3(double A[9], double x[3], const double b[3]) {
  double L[9] = {0};
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j <= i; j++) {
      double s = A[3 * i + j];
      for (int k = 0; k < j; k++) s -= L[3 * i + k] * L[3 * j + k];
      L[3 * i + j] = (i == j) ? sqrt(s) : s / L[3 * j + j];
    }
  }
  double y[3];
  for (int i = 0; i < 3; i++) {
    y[i] = b[i];
    for (int k = 0; k < i; k++) y[i] -= L[3 * i + k] * y[k];
    y[i] /= L[3 * i + i];
  }
  for (int i = 2; i >= 0; i--) {
    x[i] = y[i];
    for (int k = i + 1; k < 3; k++) x[i] -= L[3 * k + i] * x[k];
    x[i] /= L[3 * i + i];
  }
}

// Runs `iters` DLS iterations on d->qpos (d is scratch); returns the final error norm.
static double ik_solve(const mjModel* m, mjData* d, int site, const double target[3],
                       double lambda, int iters) {
  int nv = m->nv;
  double jacp[3 * 16], dq[16], err = 0;
  if (nv > 16) return -1;
  for (int it = 0; it <= iters; it++) {
    mj_forward(m, d);
    double e[3];
    for (int i = 0; i < 3; i++) e[i] = target[i] - d->site_xpos[3 * site + i];
    err = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    if (it == iters) break;
    mj_jacSite(m, d, jacp, NULL, site);
    double A[9], w[3];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        double s = 0;
        for (int k = 0; k < nv; k++) s += jacp[i * nv + k] * jacp[j * nv + k];
        A[3 * i + j] = s + (i == j ? lambda * lambda : 0);
      }
    }
    solve3(A, w, e);
    for (int k = 0; k < nv; k++) dq[k] = jacp[k] * w[0] + jacp[nv + k] * w[1] + jacp[2 * nv + k] * w[2];
    mj_integratePos(m, d->qpos, dq, 1);
  }
  return err;
}
