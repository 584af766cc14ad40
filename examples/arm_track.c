// IK plus PD tracking under mj_step: the target circles in the plane; each control step solves
// DLS IK (on a scratch mjData) for the desired joint angles and drives the three motors of
// models/arm3.xml with a PD law, clamped to their control ranges.

#include <math.h>
#include <stdio.h>

#include <mujoco/mujoco.h>

#include "ik.h"

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "models/arm3.xml";
  char error[1000] = "";
  mjModel* m = mj_loadXML(path, NULL, error, sizeof(error));
  if (!m) {
    printf("cannot load %s: %s\n", path, error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  mjData* ik = mj_makeData(m);
  int ee = mj_name2id(m, mjOBJ_SITE, "ee");
  int key = mj_name2id(m, mjOBJ_KEY, "home");
  if (key >= 0) mj_resetDataKeyframe(m, d, key);

  const double kp = 20, kd = 3;
  double worst = 0;
  printf("  time    target x  target y   ee x      ee y     error\n");
  for (int step = 1; step <= 2500; step++) {
    double t = d->time;
    double target[3] = {0.45 + 0.15 * cos(t), 0.15 + 0.15 * sin(t), 0.05};

    // desired angles: IK from the current configuration
    for (int i = 0; i < m->nq; i++) ik->qpos[i] = d->qpos[i];
    ik_solve(m, ik, ee, target, 0.05, 3);

    for (int i = 0; i < m->nu; i++) {
      int j = m->actuator_trnid[2 * i];
      int qa = m->jnt_qposadr[j], va = m->jnt_dofadr[j];
      double u = kp * (ik->qpos[qa] - d->qpos[qa]) - kd * d->qvel[va];
      double lo = m->actuator_ctrlrange[2 * i], hi = m->actuator_ctrlrange[2 * i + 1];
      d->ctrl[i] = u < lo ? lo : u > hi ? hi : u;
    }
    mj_step(m, d);

    const mjtNum* p = d->site_xpos + 3 * ee;
    double err = sqrt((p[0] - target[0]) * (p[0] - target[0]) + (p[1] - target[1]) * (p[1] - target[1]));
    if (step > 1000 && err > worst) worst = err;
    if (step % 250 == 0) {
      printf("%6.3f  %9.6f %9.6f %9.6f %9.6f  %.6f\n", d->time, target[0], target[1], p[0], p[1], err);
    }
  }
  printf("worst tracking error after 2 s: %.6f\n", worst);
  mj_deleteData(ik);
  mj_deleteData(d);
  mj_deleteModel(m);
  return worst < 0.05 ? 0 : 2;
}
