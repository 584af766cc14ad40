// Damped-least-squares inverse kinematics with mj_jacSite: moves the arm's site "ee"
// (models/arm3.xml) onto the mocap body "target", printing the error per iteration.

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
  int ee = mj_name2id(m, mjOBJ_SITE, "ee");
  int body = mj_name2id(m, mjOBJ_BODY, "target");
  const mjtNum* target = m->body_pos + 3 * body;
  printf("target %.6f %.6f %.6f\n", target[0], target[1], target[2]);

  // start from a bent configuration; one DLS step at a time to print the error
  d->qpos[0] = 0.3;
  d->qpos[1] = 0.8;
  d->qpos[2] = -0.5;
  double err = 0;
  for (int it = 0; it < 30; it++) {
    err = ik_solve(m, d, ee, target, 0.05, 1);
    if (it < 6 || it % 10 == 9) printf("iteration %2d  error %.9f\n", it + 1, err);
  }
  mj_forward(m, d);
  printf("qpos %.6f %.6f %.6f\n", d->qpos[0], d->qpos[1], d->qpos[2]);
  printf("ee   %.6f %.6f %.6f\n", d->site_xpos[3 * ee], d->site_xpos[3 * ee + 1],
         d->site_xpos[3 * ee + 2]);
  printf("%s\n", err < 1e-4 ? "reached" : "not reached");
  mj_deleteData(d);
  mj_deleteModel(m);
  return err < 1e-4 ? 0 : 2;
}
