// The workload rujoco's function order is recorded on (cargo xtask order): what a program does
// first with a model, phase by phase, so that the code of each phase can be laid out together.
//   order_train STEPS MJB XML ...   for each pair (MJB saved from XML: `loader mjbsave`):
//                                   mj_loadModel of MJB, mj_loadXML of XML, mj_makeData, then
//                                   STEPS driven steps (full physics, then smooth), mj_forward
//                                   and mj_inverse; the recorder splits the run at those calls
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void quiet(const char* msg) { (void)msg; }

static void drive(const mjModel* m, mjData* d, int steps) {
  for (int i = 0; i < steps; i++) {
    for (int u = 0; u < m->nu; u++) d->ctrl[u] = 0.5 * sin(0.01 * i + u);
    mj_step(m, d);
  }
}

static void run(int steps, const char* mjb, const char* xml) {
  mj_deleteModel(mj_loadModel(mjb, NULL));
  char err[1000];
  mjModel* m = mj_loadXML(xml, NULL, err, sizeof err);
  if (!m) return;
  mjData* d = mj_makeData(m);
  if (m->nkey) mj_resetDataKeyframe(m, d, 0);
  drive(m, d, steps);
  m->opt.disableflags |= mjDSBL_CONSTRAINT | mjDSBL_CONTACT;
  drive(m, d, steps / 2);
  mj_forward(m, d);
  mj_inverse(m, d);
  mj_deleteData(d);
  mj_deleteModel(m);
}

int main(int argc, char** argv) {
  mju_user_warning = quiet;
  if (argc < 4 || argc % 2 != 0) {
    fprintf(stderr, "usage: order_train STEPS MJB XML...\n");
    return 2;
  }
  int steps = atoi(argv[1]);
  for (int i = 2; i + 1 < argc; i += 2) run(steps, argv[i], argv[i + 1]);
  return 0;
}
