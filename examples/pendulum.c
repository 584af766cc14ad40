// Simulates the pendulum of models/pendulum.xml for 10,000 steps from its "tilted" keyframe
// and prints the hinge angle every 1000 steps.
//
// Build against rujoco:  gcc pendulum.c -I include -L target/release -lmujoco -lm
// Run:                   LD_LIBRARY_PATH=target/release ./a.out [models/pendulum.xml]

#include <stdio.h>

#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "models/pendulum.xml";
  char error[1000] = "";
  mjModel* m = mj_loadXML(path, NULL, error, sizeof(error));
  if (!m) {
    printf("cannot load %s: %s\n", path, error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  int key = mj_name2id(m, mjOBJ_KEY, "tilted");
  if (key >= 0) mj_resetDataKeyframe(m, d, key);

  int hinge = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "hinge")];
  printf("step      time     angle      velocity\n");
  for (int step = 1; step <= 10000; step++) {
    mj_step(m, d);
    if (step % 1000 == 0) {
      printf("%5d  %8.3f  %9.6f  %9.6f\n", step, d->time, d->qpos[hinge], d->qvel[hinge]);
    }
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
