// Forward kinematics of the three-link arm (models/arm3.xml): sets joint angles, runs
// mj_forward and prints the end-effector site "ee", next to the closed-form planar result.

#include <math.h>
#include <stdio.h>

#include <mujoco/mujoco.h>

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

  // joint angles in radians: shoulder, elbow, wrist
  const double configs[][3] = {
      {0, 0, 0}, {0.5, 0, 0}, {0.3, -0.6, 0.9}, {-1.2, 1.5, -0.4}, {2.0, -2.5, 1.0}};
  printf("   q1        q2        q3    |  ee x      ee y      ee z   | closed form x, y\n");
  for (int c = 0; c < 5; c++) {
    const double* q = configs[c];
    for (int j = 0; j < 3; j++) d->qpos[j] = q[j];
    mj_forward(m, d);
    const mjtNum* p = d->site_xpos + 3 * ee;
    double a1 = q[0], a2 = q[0] + q[1], a3 = q[0] + q[1] + q[2];
    double x = 0.4 * cos(a1) + 0.3 * cos(a2) + 0.2 * cos(a3);
    double y = 0.4 * sin(a1) + 0.3 * sin(a2) + 0.2 * sin(a3);
    printf("%9.6f %9.6f %9.6f | %9.6f %9.6f %9.6f | %9.6f %9.6f\n", q[0], q[1], q[2], p[0], p[1],
           p[2], x, y);
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
